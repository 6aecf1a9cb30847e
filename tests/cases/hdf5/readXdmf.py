"""Opens an mpmFoam XDMF series the way a user does in ParaView 5.11 (the
"XDMF Reader"), loads the last time, and saves what it read for the test to
check against the run's own OpenFOAM output:

    pvbatch readXdmf.py CASE/materialPoints.xmf OUT.npz

OUT.npz: times, nPoints, pointId, stress (9 components per point, as
ParaView expands the file's symmetric tensors), U, the lattice's bounds,
dimensions and cell arrays alpha.solid, U.solid (VTK order, x fastest),
and every cell array's name.
"""
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import XDMFReader
from vtk.util.numpy_support import vtk_to_numpy

reader = XDMFReader(FileNames=[sys.argv[1]])
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues)
reader.UpdatePipeline(times[-1])
data = servermanager.Fetch(reader)
blocks = {}
for b in range(data.GetNumberOfBlocks()):
    name = data.GetMetaData(b).Get(data.NAME()).split("[")[0]
    blocks[name] = data.GetBlock(b)
pts, lat = blocks["materialPoints"], blocks["lattice"]
pd, cd = pts.GetPointData(), lat.GetCellData()
out = {
    "times": np.array(times),
    "nPoints": pts.GetNumberOfPoints(),
    "pointId": vtk_to_numpy(pd.GetArray("pointId")),
    "stress": vtk_to_numpy(pd.GetArray("stress")),
    "U": vtk_to_numpy(pd.GetArray("U")),
    "bounds": np.array(lat.GetBounds()),
    "dimensions": np.array(lat.GetDimensions()),
    "cellArrays": np.array([cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())]),
}
for f in ("alpha.solid", "U.solid"):
    out[f] = vtk_to_numpy(cd.GetArray(f))
np.savez(sys.argv[2], **out)
print("XDMF: %d times, last %g: %d points, lattice %s, cell arrays %s"
      % (len(times), times[-1], out["nPoints"], out["dimensions"], list(out["cellArrays"])))

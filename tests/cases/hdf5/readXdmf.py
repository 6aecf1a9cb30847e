"""Opens an mpmFoam XDMF series the way a user does in ParaView 5.11 (the
"XDMF Reader"), loads the last time, and saves what it read for the test to
check against the run's own OpenFOAM output:

    pvbatch readXdmf.py CASE/materialPoints.xmf OUT.npz

OUT.npz: times, nPoints, pointId, stress (9 components per point, as
ParaView expands the file's symmetric tensors), U, the lattice's bounds,
dimensions and cell arrays alpha.solid, U.solid (VTK order, x fastest),
every cell array as cell:<name> (the fluid's U, alpha.water, p_rgh, ...),
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
# The block names at every time, as a pipeline selecting /Root/<name>
# sees them (they must not change from one time to the next)
names = []
for t in times:
    reader.UpdatePipeline(t)
    d = servermanager.Fetch(reader)
    names.append(",".join(d.GetMetaData(b).Get(d.NAME()) for b in range(d.GetNumberOfBlocks())))
reader.UpdatePipeline(times[-1])
data = servermanager.Fetch(reader)
blocks = {}
for b in range(data.GetNumberOfBlocks()):
    blocks[data.GetMetaData(b).Get(data.NAME())] = data.GetBlock(b)
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
    "blockNames": np.array(names),
}
for f in ("alpha.solid", "U.solid"):
    out[f] = vtk_to_numpy(cd.GetArray(f))
for i in range(cd.GetNumberOfArrays()):
    out["cell:" + cd.GetArrayName(i)] = vtk_to_numpy(cd.GetArray(i))
np.savez(sys.argv[2], **out)
print("XDMF: %d times (%s), last %g: %d points, lattice %s, cell arrays %s; blocks %s"
      % (len(times), " ".join("%g" % t for t in times), times[-1], out["nPoints"], out["dimensions"],
         list(out["cellArrays"]), " | ".join(names)))

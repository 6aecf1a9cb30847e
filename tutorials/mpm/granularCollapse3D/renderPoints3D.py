# pvbatch script: 3D picture of the deposit of the granular collapse at the
# last write time, and its runout.
#
#     xvfb-run -a pvbatch renderPoints3D.py [case] [output.png]
#
# Reads the seeded cloud at t = 0 with ParaView's OpenFOAM reader (the
# lagrangian cloud mpmSetParticles wrote) and the last time of the run's
# HDF5 checkpoints through their XDMF series (pointOutput hdf5: no
# reconstructPar needed), matches the points by pointId and colours the
# final points by their displacement |x - x0|. The
# quadrant facing the camera (x < 0, y < 0) is cut away to show the inside
# of the deposit: the undisturbed core and the flowing layer over it. The
# initial column is drawn in red, the floor in grey.
#
# Prints the runout (front radius r_f: the largest distance of a point from
# the axis, plus half the point spacing), the final height H_f, and the
# spread of the front around the axis (r_f per 10 deg sector).
import os
import sys

# etc/python (mpmRender): of the tree this script is in, or of etc/bashrc's
sys.path[:0] = [os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "etc", "python"),
                os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python")]
from mpmRender import show_points, style_scalar_bar, white_view  # noqa: E402

import numpy as np
from paraview import servermanager
from paraview.simple import (
    GetScalarBar, MergeBlocks,
    OpenFOAMReader, Plane, PVTrivialProducer, ReloadFiles, Render,
    SaveScreenshot, Show, Text, UpdatePipeline, XDMFReader,
)
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkPolyLine

R0, H0 = 0.4, 0.4       # initial column: radius, height [m]
DX = 0.01               # point spacing: h/2 (h = 0.02 m, 2 points per cell)

case = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
out = os.path.join(case, sys.argv[2] if len(sys.argv) > 2 else "granularCollapse3D.png")
foam = os.path.join(case, "case.foam")
if not os.path.exists(foam):
    open(foam, "w").close()

reader = OpenFOAMReader(FileName=foam)
reader.SkipZeroTime = 0         # the seeded cloud; takes effect on a reload
ReloadFiles(reader)
reader.Lagrangianpositionswithoutextradata = 1
reader.MeshRegions = ["lagrangian/materialPoints"]
reader.LagrangianArrays = ["pointId", "plasticStrain"]
reader.UpdatePipelineInformation()
if 0.0 not in (reader.TimestepValues or [0.0]):
    sys.exit("renderPoints3D.py: no cloud at t = 0 (the seeded points) in %s" % case)
seeded = MergeBlocks(Input=reader)

# The run's checkpoints: ParaView's "XDMF Reader" on the series file
series = XDMFReader(FileNames=[os.path.join(case, "materialPoints.xmf")])
series.UpdatePipelineInformation()
t0, tEnd = 0.0, max(series.TimestepValues)


def cloud(proxy, t, block=None):
    """Positions (n, 3), pointIds (n,) and plastic strain at time t, sorted
    by pointId; block: the name of the points' block in a multiblock."""
    UpdatePipeline(time=t, proxy=proxy)
    data = servermanager.Fetch(proxy)
    if block is not None:
        data = [data.GetBlock(b) for b in range(data.GetNumberOfBlocks())
                if data.GetMetaData(b).Get(data.NAME()).startswith(block)][0]
    x = numpy_support.vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    ids = numpy_support.vtk_to_numpy(data.GetPointData().GetArray("pointId")).astype(np.int64)
    eps = numpy_support.vtk_to_numpy(data.GetPointData().GetArray("plasticStrain")).astype(float)
    order = np.argsort(ids)
    return x[order], ids[order], eps[order]


x0, id0, _ = cloud(seeded, t0)
x, ids, eps = cloud(series, tEnd, "materialPoints")
if len(x) == 0 or len(x) != len(x0) or not np.array_equal(id0, ids):
    sys.exit("renderPoints3D.py: the clouds at t = %g (%d points) and t = %g (%d) do not match"
             % (t0, len(x0), tEnd, len(x)))
n = len(x)
disp = np.linalg.norm(x - x0, axis=1)

# Runout and final height
r = np.hypot(x[:, 0], x[:, 1])
rf = r.max() + DX / 2
hf = x[:, 2].max() + DX / 2
theta = np.degrees(np.arctan2(x[:, 1], x[:, 0])) % 360
sector = np.array([r[(theta >= a) & (theta < a + 10)].max() for a in range(0, 360, 10)]) + DX / 2
print("Runout at t = %g s (%d points, initial column r0 = %g m, h0 = %g m, a = %g):"
      % (tEnd, n, R0, H0, H0 / R0))
print("    front radius r_f = %.3f m, (r_f - r0)/r0 = %.2f" % (rf, (rf - R0) / R0))
print("    front radius per 10 deg sector: min %.3f, mean %.3f, max %.3f m; "
      "(mean - r0)/r0 = %.2f" % (sector.min(), sector.mean(), sector.max(), (sector.mean() - R0) / R0))
print("    final height H_f = %.3f m, H_f/r0 = %.2f, H_f/h0 = %.2f" % (hf, hf / R0, hf / H0))
print("    points displaced by less than h/4 = 5 mm (undisturbed core): %.1f %%"
      % (100.0 * np.mean(disp < 0.005)))
print("    max plastic strain %.2f, max displacement %.3f m" % (eps.max(), disp.max()))

# Cut away the quadrant facing the camera
keep = ~((x[:, 0] < 0) & (x[:, 1] < 0))
poly = vtkPolyData()
pts = vtkPoints()
pts.SetData(numpy_support.numpy_to_vtk(np.ascontiguousarray(x[keep]), deep=1))
poly.SetPoints(pts)
verts = vtkCellArray()
nk = int(keep.sum())
conn = np.empty(2 * nk, dtype=np.int64)
conn[0::2] = 1
conn[1::2] = np.arange(nk)
verts.SetCells(nk, numpy_support.numpy_to_vtkIdTypeArray(conn, deep=1))
poly.SetVerts(verts)
d = numpy_support.numpy_to_vtk(np.ascontiguousarray(disp[keep]), deep=1)
d.SetName("displacement")
poly.GetPointData().AddArray(d)
deposit = PVTrivialProducer()
deposit.GetClientSideObject().SetOutput(poly)


def polyline(points):
    """A PVTrivialProducer of one polyline through points (m, 3)."""
    pl = vtkPolyData()
    p = vtkPoints()
    for q in points:
        p.InsertNextPoint(*q)
    pl.SetPoints(p)
    line = vtkPolyLine()
    line.GetPointIds().SetNumberOfIds(len(points))
    for i in range(len(points)):
        line.GetPointIds().SetId(i, i)
    cells = vtkCellArray()
    cells.InsertNextCell(line)
    pl.SetLines(cells)
    src = PVTrivialProducer()
    src.GetClientSideObject().SetOutput(pl)
    return src


view = white_view([1600, 900])

# Floor of the box (2 x 2 m) in light grey
F = 1.0
floor = Plane(Origin=[-F, -F, -0.002], Point1=[F, -F, -0.002], Point2=[-F, F, -0.002])
fd = Show(floor, view)
fd.AmbientColor = fd.DiffuseColor = [0.9, 0.9, 0.9]
fd.Ambient, fd.Diffuse = 1.0, 0.0     # flat, unshaded
fd.ColorArrayName = ["POINTS", ""]

dd, lut = show_points(deposit, view, "displacement", 4)
lut.RescaleTransferFunction(0.0, float(disp.max()))
bar = GetScalarBar(lut, view)
style_scalar_bar(bar, "displacement [m]", "%.2f", [0.62, 0.06], 0.33)
dd.SetScalarBarVisibility(view, True)

# Initial column in red: rims at z = 0 and h0, and four generatrices
phi = np.linspace(0, 2 * np.pi, 121)
for z in (0.001, H0):
    src = polyline(np.c_[R0 * np.cos(phi), R0 * np.sin(phi), np.full_like(phi, z)])
    ld = Show(src, view)
    ld.AmbientColor = ld.DiffuseColor = [0.85, 0.1, 0.1]
    ld.LineWidth = 3
    ld.ColorArrayName = ["POINTS", ""]
for a in np.radians([45, 135, 225, 315]):
    src = polyline([(R0 * np.cos(a), R0 * np.sin(a), 0.001), (R0 * np.cos(a), R0 * np.sin(a), H0)])
    ld = Show(src, view)
    ld.AmbientColor = ld.DiffuseColor = [0.85, 0.1, 0.1]
    ld.LineWidth = 3
    ld.ColorArrayName = ["POINTS", ""]

title = Text(Text="3D granular collapse (Drucker-Prager, phi = 30 deg, a = h0/r0 = 1): "
                  "%d material points at t = %g s\ncoloured by displacement from t = 0; red: initial column; "
                  "front quadrant cut away; runout (r_f - r0)/r0 = %.2f" % (n, tEnd, (rf - R0) / R0))
td = Show(title, view)
td.Color = [0, 0, 0]
td.FontSize = 22
td.WindowLocation = "Upper Center"
td.Justification = "Center"

Render(view)        # the first render resets the camera: set it afterwards
view.CameraFocalPoint = [0.0, 0.0, 0.05]
view.CameraPosition = [-1.55, -1.85, 1.35]
view.CameraViewUp = [0, 0, 1]
view.CameraViewAngle = 30
Render(view)
SaveScreenshot(out, view, ImageResolution=[1600, 900])
print("Wrote %s (%d points, t = %g s)" % (out, n, tEnd))

# pvbatch script: renders the material points of the granular column at the
# last write time, coloured by the equivalent plastic strain, with the domain
# outline and the initial column, to granularColumnCollapse_points.png.
#
#     xvfb-run -a pvbatch renderPoints.py [case]
#
# Uses ParaView's built-in OpenFOAM reader on an (empty) case.foam file; the
# cloud needs "Lagrangianpositionswithoutextradata" since mpmFoam writes
# positions without the barycentric extra data.
import os
import sys

# etc/python (mpmRender): of the tree this script is in, or of etc/bashrc's
sys.path[:0] = [os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "etc", "python"),
                os.path.join(os.environ.get("MPMFOAM_DIR", ""), "etc", "python")]
from mpmRender import show_points, style_scalar_bar, white_view  # noqa: E402

from paraview.simple import (
    GetScalarBar, Line,
    MergeBlocks, OpenFOAMReader, Render, SaveScreenshot, Show, Text,
    UpdatePipeline,
)

A0, H0 = 0.2, 0.4       # initial column [m]
L, H = 1.0, 0.5         # domain [m]

case = os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__)))
foam = os.path.join(case, "case.foam")
if not os.path.exists(foam):
    open(foam, "w").close()

reader = OpenFOAMReader(FileName=foam)
reader.Lagrangianpositionswithoutextradata = 1
reader.MeshRegions = ["lagrangian/materialPoints"]
reader.LagrangianArrays = ["plasticStrain", "U", "mass"]
reader.UpdatePipelineInformation()
times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
tEnd = max(times)
UpdatePipeline(time=tEnd, proxy=reader)
points = MergeBlocks(Input=reader)
UpdatePipeline(time=tEnd, proxy=points)
n = points.GetDataInformation().GetNumberOfPoints()
if n == 0:
    sys.exit("renderPoints.py: no material points read at t = %g" % tEnd)

view = white_view([1600, 860])
view.ViewTime = tEnd

disp, lut = show_points(points, view, "plasticStrain", 6)
rng = points.PointData["plasticStrain"].GetRange()
lut.RescaleTransferFunction(0.0, max(rng[1], 1e-12))
bar = GetScalarBar(lut, view)
style_scalar_bar(bar, "equivalent plastic strain", "%.1f", [0.58, 0.62], 0.35)
disp.SetScalarBarVisibility(view, True)


def segment(p1, p2, color, width):
    line = Line(Point1=p1, Point2=p2)
    d = Show(line, view)
    d.AmbientColor = color
    d.DiffuseColor = color
    d.LineWidth = width
    d.ColorArrayName = ["POINTS", ""]


z = 0.02       # in front of the points (z in [0, 0.01])
for p1, p2 in [((0, 0, z), (L, 0, z)), ((L, 0, z), (L, H, z)),
               ((L, H, z), (0, H, z)), ((0, H, z), (0, 0, z))]:
    segment(p1, p2, [0, 0, 0], 3)
for p1, p2 in [((0, H0, z), (A0, H0, z)), ((A0, H0, z), (A0, 0, z))]:
    segment(p1, p2, [0.8, 0.1, 0.1], 3)

# Optional: output file name and title (the underwater tutorial reuses this)
label = sys.argv[3] if len(sys.argv) > 3 else "Granular column collapse (Drucker-Prager, phi = 30 deg)"
title = Text(Text="%s: %d material points at t = %g s; red: initial column" % (label, n, tEnd))
td = Show(title, view)
td.Color = [0, 0, 0]
td.FontSize = 22
td.WindowLocation = "Upper Center"

Render(view)        # the first render resets the camera: set it afterwards
view.CameraPosition = [L/2, H/2, 5]
view.CameraFocalPoint = [L/2, H/2, 0]
view.CameraViewUp = [0, 1, 0]
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.3
Render(view)
out = os.path.join(case, sys.argv[2] if len(sys.argv) > 2 else "granularColumnCollapse_points.png")
SaveScreenshot(out, view, ImageResolution=[1600, 860])
print("Wrote %s (%d points, t = %g s)" % (out, n, tEnd))

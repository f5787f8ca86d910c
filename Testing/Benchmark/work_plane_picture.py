"""The README's picture of a work plane: an office lit by six real luminaires (three
Interlight high-bays, three ERCO spots, from their IES files), relit in ParaView on the
left, the illuminance on the work plane 0.8 m up in false colour on the right.

    ./relight pvbatch Testing/Benchmark/work_plane_picture.py [out.png]
"""

import os
import sys
import tempfile

import relight
from paraview.simple import (  # noqa: I001
    AssignViewToLayout,
    ColorBy,
    CreateLayout,
    CreateView,
    GetColorTransferFunction,
    GetScalarBar,
    LightTaggedRadiosity,
    MarkLights,
    RadiosityMesher,
    RadiosityRelight,
    RadiosityWorkPlane,
    Render,
    SaveScreenshot,
    Show,
    Text,
    XMLPolyDataReader,
)
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

ROOT = os.environ.get("RELIGHT_ROOT", ".")
sys.path.insert(0, os.path.join(ROOT, "Testing", "Benchmark"))
from luminaires_radiance import luminaires, room_faces  # noqa: E402

out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "docs", "images", "work_plane.png")
faces = room_faces()
scene = relight.make_scene([f for f, _ in faces], [(r, r, r) for _, r in faces], [-1] * len(faces))
path = os.path.join(tempfile.mkdtemp(), "office.vtp")
writer = vtkXMLPolyDataWriter()
writer.SetInputData(scene)
writer.SetFileName(path)
writer.Write()

rows = []
for name, ies, (x, y, z) in luminaires():
    rows += [name, "goniometric", f"file={ies}", str(x), str(y), str(z), "0", "0", "-1", "0", "1", "1", "1"]
marked = MarkLights(Input=XMLPolyDataReader(FileName=[path]), Luminaires=rows)
solver = LightTaggedRadiosity(Input=RadiosityMesher(Input=marked, PatchSize=1.0, ElementSize=0.125))
relit = RadiosityRelight(Input=solver)
plane = RadiosityWorkPlane(Input=solver, Height=0.8, UpAxis=2, Spacing=0.1)  # finer than EN 12464-1's, for the eye
plane.UpdatePipeline()
fields = plane.GetFieldDataInformation()
mean = fields.GetArray("IlluminanceMean").GetRange()[0]
uniformity = fields.GetArray("Uniformity").GetRange()[0]

layout = CreateLayout("office")
room = CreateView("RenderView")
AssignViewToLayout(view=room, layout=layout, hint=0)
room_display = Show(relit, room)
ColorBy(room_display, ("POINTS", "DisplayColors"))
room_display.MapScalars = 0
room_display.Ambient = 1.0
room_display.Diffuse = 0.0
room.OrientationAxesVisibility = 0
Render(room)  # the first render places the camera: set it after
room.CameraPosition = [0.5, 0.4, 2.3]
room.CameraFocalPoint = [4.5, 3.5, 0.6]
room.CameraViewUp = [0, 0, 1]
room.CameraViewAngle = 75

layout.SplitHorizontal(0, 0.5)
top = CreateView("RenderView")
AssignViewToLayout(view=top, layout=layout, hint=2)
plane_display = Show(plane, top)
ColorBy(plane_display, ("POINTS", "Illuminance"))
lut = GetColorTransferFunction("Illuminance")
lut.ApplyPreset("Turbo", True)
plane_display.SetScalarBarVisibility(top, True)
bar = GetScalarBar(lut, top)
bar.Title = "lux"
bar.ComponentTitle = ""
outline = Show(marked, top)
outline.SetRepresentationType("Outline")
outline.AmbientColor = outline.DiffuseColor = [1, 1, 1]
note = Text(Text=f"work plane 0.8 m: mean {mean:.0f} lx, U0 {uniformity:.2f}")
note_display = Show(note, top)
note_display.FontSize = 12
note_display.WindowLocation = "Upper Left Corner"
bar.WindowLocation = "Any Location"
bar.Orientation = "Horizontal"
bar.Position = [0.2, 0.02]
bar.RangeLabelFormat = "%.0f"
bar.LabelFormat = "%.0f"
bar.AddRangeLabels = 1
bar.ScalarBarLength = 0.6
top.OrientationAxesVisibility = 0
Render(top)
top.CameraPosition = [3.0, 1.75, 12.0]
top.CameraFocalPoint = [3.0, 1.75, 0.0]
top.CameraViewUp = [0, 1, 0]
top.CameraParallelProjection = 1
top.CameraParallelScale = 2.5
Render(room)
Render(top)
SaveScreenshot(out, layout, ImageResolution=[1200, 480])
print(f"wrote {out}: mean {mean:.1f} lx, uniformity {uniformity:.3f}")

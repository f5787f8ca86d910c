"""Opens the demo scene in ParaView with the whole pipeline ready.

    ./relight paraview --script=Data/demo_pipeline.py

(or Tools > Python Shell > Run Script). Reads the 8-light paper scene, meshes it, solves
the light-tagged solutions and the moving-light basis, and shows the relit result; change
lights in Radiosity Relight's Light Settings table (one row per light: name, r, g, b,
intensity, on) and press Apply.
"""

import os

from paraview.simple import (  # noqa: I001
    _DisableFirstRenderCameraReset,
    ColorBy,
    GetActiveViewOrCreate,
    LightTaggedRadiosity,
    RadiosityMesher,
    RadiosityRelight,
    RenameSource,
    Render,
    SetActiveSource,
    Show,
    XMLPolyDataReader,
)

HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else os.path.join(
    os.environ.get("RELIGHT_ROOT", "."), "Data")

scene = XMLPolyDataReader(FileName=[os.path.join(HERE, "paper_8lights.vtp")])
RenameSource("Scene", scene)
mesher = RadiosityMesher(Input=scene, PatchSize=1.5, ElementSize=0.375)
solver = LightTaggedRadiosity(Input=mesher)
relit = RadiosityRelight(Input=solver)
RenameSource("Relit", relit)
names = ["WarmWhite", "CoolWhite", "Amber", "Rose", "Teal", "Lime", "Violet", "DimWhite"]
settings = []
for name in names:  # each lamp white at its default strength; the picture is metered on it
    settings += [name, "1", "1", "1", "nan", "1"]
relit.LightSettings = settings
# To animate, add keyframes (they take precedence over Light Settings for their lights):
# relit.ScheduleEntries = ["0", "WarmWhite", "1", "0.8", "0.6", "5", "1",
#                        "4", "WarmWhite", "1", "0.8", "0.6", "120", "1"]

view = GetActiveViewOrCreate("RenderView")
_DisableFirstRenderCameraReset()  # keep the camera set below
display = Show(relit, view)
ColorBy(display, ("POINTS", "DisplayColors"))
display.MapScalars = 0
display.Ambient = 1.0
display.Diffuse = 0.0
view.OrientationAxesVisibility = 0
view.CameraPosition = [2.0, 1.5, 0.05]
view.CameraFocalPoint = [2.0, 0.9, 4.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 80.0
SetActiveSource(relit)
Render(view)

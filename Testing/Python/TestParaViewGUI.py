"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): opens the
demo pipeline from Data/, changes a light through the proxy and saves a screenshot.
"""

import os

from paraview.simple import FindSource, GetActiveViewOrCreate, Render, SaveScreenshot

root = os.environ["RELIGHT_ROOT"]
exec(open(os.path.join(root, "Data", "demo_pipeline.py")).read(), {"__name__": "demo", "__file__":
     os.path.join(root, "Data", "demo_pipeline.py")})

relit = FindSource("Relit")
settings = list(relit.LightSettings)
# Turn the warm light off and make the amber one strong and red.
settings[5] = "0"
settings[12:18] = ["Amber", "1", "0.1", "0.05", "80", "1"]
if not os.environ.get("RELIGHT_GUI_UNCHANGED"):  # set only to check the test can fail
    relit.LightSettings = settings
    relit.UpdatePipeline()
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [400, 300]
Render(view)

output = os.environ.get("RELIGHT_OUTPUT", "TestParaViewGUI.png")
SaveScreenshot(output, view, ImageResolution=[400, 300])

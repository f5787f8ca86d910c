"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): opens the
demo pipeline from Data/, changes a light through the proxy and saves a screenshot.
"""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview.simple import FindSource, GetActiveViewOrCreate, Render, SaveScreenshot  # noqa: E402

result = guitest.Result()
demo = guitest.data_file("demo_pipeline.py")
exec(open(demo).read(), {"__name__": "demo", "__file__": demo})

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
SaveScreenshot(guitest.image_path(), view, ImageResolution=[400, 300])
result.finish()

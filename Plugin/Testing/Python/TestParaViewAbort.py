"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): starts a
solve that would take minutes, clicks ParaView's abort button through Qt's event path
(a mouse press and release at the button's place in the window, delivered while the
filter runs), and checks
that the solve stopped with a partial result marked as aborted.
"""

import os
import sys
import time

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import LightTaggedRadiosity, RadiosityMesher, XMLPolyDataReader  # noqa: E402
from PyQt5.QtCore import Qt, QTimer  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QApplication  # noqa: E402

CLICK_AFTER_MS = 3000
BUDGET_S = 120  # the solve would run this long without the click

result = guitest.Result()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_8lights.vtp")])
mesher = RadiosityMesher(Input=scene, PatchSize=0.3, ElementSize=0.1)
mesher.UpdatePipeline()
solver = LightTaggedRadiosity(Input=mesher, SolverMethod="ProgressiveRefinement",
                              ConvergenceThreshold=1e-12, MaximumShots=10000000, TimeBudget=BUDGET_S)

buttons = [w for w in QApplication.instance().allWidgets() if w.objectName() == "AbortButton"]
clicked = {}


def click():
    button = buttons[0]
    clicked["enabled"] = button.isEnabled()
    clicked["time"] = time.time()
    if not os.environ.get("RELIGHT_GUI_NO_CLICK"):  # set only to check the test can fail
        # As a real click arrives: at the window, at the button's place, so that Qt finds
        # the widget under the mouse (a click sent to the widget itself skips that step).
        window = button.window()
        QTest.mouseClick(window.windowHandle(), Qt.LeftButton, Qt.NoModifier,
                         button.mapTo(window, button.rect().center()))


if result.check(len(buttons) == 1, "found %d abort buttons, expected 1" % len(buttons)):
    QTimer.singleShot(CLICK_AFTER_MS, click)
    start = time.time()
    solver.UpdatePipeline()
    end = time.time()
    output = servermanager.Fetch(solver)
    status = output.GetFieldData().GetAbstractArray("SolverStatus")
    status = status.GetValue(0) if status else "(none)"
    result.check("time" in clicked, "the click never happened: the GUI ran no events during the solve")
    result.check(clicked.get("enabled"), "the abort button was disabled during the solve")
    result.check(status == "aborted", "SolverStatus is '%s', expected 'aborted'" % status)
    result.check(end - start < BUDGET_S / 2, "the solve ran %.0f s of its %d s budget" % (end - start, BUDGET_S))
    result.check(output.GetPointData().GetArray("Radiosity_WarmWhite") is not None,
                 "the aborted output has no partial solution")
    result.note("solve stopped %.2f s after the click (%.1f s in all), status '%s'"
                % (end - clicked.get("time", end), end - start, status))
result.finish()

"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): the solver's
output is shown as "Relit Surface" by default, and a light switched off in the display
panel's lights table (a real click on its check box) changes the picture at once: no
Apply, no new solve, no new upload of the solutions.
"""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import (  # noqa: E402
    ColorBy, GetActiveView, LightTaggedRadiosity, RadiosityRelight, RadiosityMesher, Render, SaveScreenshot, SetActiveSource, Show,
    XMLPolyDataReader)
from PyQt5.QtCore import Qt  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QApplication, QCheckBox, QComboBox, QPushButton, QScrollArea, QTableWidget  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

result = guitest.Result()
app = QApplication.instance()



def picture(view, name):
    path = os.path.join(guitest.OUTPUT_DIR, name)
    Render(view)
    SaveScreenshot(path, view, ImageResolution=[300, 225])
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars()).astype(float)


def light_boxes():
    """The on/off boxes of the visible lights tables."""
    tables = [t for t in app.allWidgets() if isinstance(t, QTableWidget) and t.isVisible()
              and t.horizontalHeaderItem(3) is not None and t.horizontalHeaderItem(3).text() == "On"]
    return [box for t in tables for box in (t.cellWidget(r, 3) for r in range(t.rowCount())) if isinstance(box, QCheckBox)]


def click(widget):
    parent = widget.parentWidget()
    while parent is not None and not isinstance(parent, QScrollArea):
        parent = parent.parentWidget()
    if parent is not None:
        parent.ensureWidgetVisible(widget)
    guitest.settle(0.2)
    window = widget.window()
    QTest.mouseClick(window.windowHandle(), Qt.LeftButton, Qt.NoModifier, widget.mapTo(window, widget.rect().center()))
    guitest.settle(0.5)


view = GetActiveView()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_3lights.vtp")])
mesher = RadiosityMesher(Input=scene, PatchSize=1.5, ElementSize=0.375)
solver = LightTaggedRadiosity(Input=mesher, ConvergenceThreshold=0.01)
display = Show(solver, view)
SetActiveSource(solver)
guitest.settle(1.0)
result.check(display.Representation == "Relit Surface",
             "the solver's output is shown as '%s', expected 'Relit Surface'" % display.Representation)
display.RelitExposure = 20.0  # the 3-light room is dim at unit intensity
view.CameraPosition = [2.0, 1.5, 0.05]
view.CameraFocalPoint = [2.0, 0.9, 4.0]
view.CameraViewUp = [0.0, 1.0, 0.0]
view.CameraViewAngle = 80
guitest.settle(0.5)
before = picture(view, "relit_before.png")
solves = solver.GetClientSideObject().GetOutputDataObject(0).GetMTime()
boxes = light_boxes()
if result.check(len(boxes) == 3, "the display panel shows %d light boxes, expected 3" % len(boxes)):
    if not os.environ.get("RELIGHT_GUI_UNCHANGED"):  # set only to check the test can fail
        click(boxes[0])  # WarmWhite off
    after = picture(view, "relit_after.png")
    change = abs(after - before).mean()
    result.check(change > 1.0, "switching WarmWhite off in the panel changed the picture by %.2f / 255" % change)
    result.check(solver.GetClientSideObject().GetOutputDataObject(0).GetMTime() == solves, "the light change ran the solver again")
    settings = list(display.RelitLightSettings)
    result.check(settings[:1] == ["WarmWhite"] and settings[5] == "0" and len(settings) == 6,
                 "the property holds %s (only the light switched off)" % settings)
    result.note("mean change %.2f / 255; property %s" % (change, settings))
# Relit Surface ignores the coloring (the toolbar reads Solid Color, ParaView's "no array"):
# an array picked there would change nothing, so the display moves to Surface to show it.
ColorBy(display, ("POINTS", "Radiosity_WarmWhite"))
guitest.settle(0.5)
result.check(display.Representation == "Surface",
             "an array picked under Relit Surface left the display as '%s'" % display.Representation)
# The same from the toolbar's coloring box, as a user picks it: the legend then carries the
# unit (the toolbar's own steps came after ours and left ParaView's title).
display.Representation = "Relit Surface"
guitest.settle(0.5)
boxes = [b for b in app.allWidgets() if isinstance(b, QComboBox) and b.objectName() == "Variables" and b.isVisible()]
pick = boxes[0].findText("Radiosity_CoolWhite") if boxes else -1
if result.check(pick >= 0, "the toolbar's coloring box lists no Radiosity_CoolWhite (%d boxes)" % len(boxes)):
    boxes[0].setCurrentIndex(pick)
    boxes[0].activated[int].emit(pick)
    guitest.settle(1.0)
    bar = servermanager.vtkSMTransferFunctionProxy.FindScalarBarRepresentation(display.LookupTable.SMProxy, view.SMProxy)
    title = servermanager._getPyProxy(bar).Title if bar else "(no legend)"
    result.check(display.Representation == "Surface" and "W/m" in title,
                 "picked in the toolbar: shown as '%s', legend '%s'" % (display.Representation, title))
    result.note("toolbar pick: %s, legend '%s'" % (display.Representation, title))
# The same under Relit Colors (the relight filter's DisplayColors as they are).
relighter = RadiosityRelight(Input=solver)
relit = Show(relighter, view)
guitest.settle(1.0)
result.check(relit.Representation == "Relit Colors", "the relight output is shown as '%s'" % relit.Representation)
ColorBy(relit, ("POINTS", "Radiosity"))
guitest.settle(0.5)
result.check(relit.Representation == "Surface",
             "an array picked under Relit Colors left the display as '%s'" % relit.Representation)
# The lights' schedule in the relight filter's panel: a table of keyframes under headers;
# Add Keyframe starts from the first light at time 0, then the last a time step on; a
# typed cell that does not read as a schedule row is put back; Apply sets the property.
SetActiveSource(relighter)
guitest.settle(1.0)
found = [t for t in app.allWidgets() if isinstance(t, QTableWidget) and t.objectName() == "ScheduleTable" and t.isVisible()]
adds = [b for b in app.allWidgets() if isinstance(b, QPushButton) and b.objectName() == "AddKeyframe" and b.isVisible()]
if result.check(len(found) == 1 and len(adds) == 1, f"the relight panel shows one schedule table ({len(found)}, {len(adds)})"):
    table = found[0]
    headers = [table.horizontalHeaderItem(c).text() for c in range(table.columnCount())]
    result.check(headers == ["Time", "Light", "Color r, g, b", "Intensity", "On"], f"column headers {headers}")
    adds[0].click()
    adds[0].click()
    guitest.settle(0.3)
    rows = [[table.item(r, c).text() for c in range(table.columnCount())] for r in range(table.rowCount())]
    result.check(rows == [["0", "WarmWhite", "1, 1, 1", "1", "1"], ["1", "WarmWhite", "1, 1, 1", "1", "1"]],
                 f"two keyframes added: {rows}")
    table.item(1, 3).setText("bright")
    result.check(table.item(1, 3).text() == "1", f"'bright' as an intensity is put back: {table.item(1, 3).text()}")
    table.item(1, 3).setText("4")
    table.item(1, 4).setText("off")
    result.check(table.item(1, 4).text() == "0", f"'off' is held as 0: {table.item(1, 4).text()}")
    accept = [b for b in app.allWidgets() if isinstance(b, QPushButton) and b.objectName() == "Accept" and b.isVisible()]
    if result.check(len(accept) == 1 and accept[0].isEnabled(), "a keyframe edit waits for Apply"):
        accept[0].click()
        guitest.settle(1.5)
    given = [str(v) for v in relighter.ScheduleEntries]
    relighter.UpdatePipelineInformation()
    result.check(given == ["0", "WarmWhite", "1", "1", "1", "1", "1", "1", "WarmWhite", "1", "1", "1", "4", "0"]
                 and list(relighter.TimestepValues) == [0.0, 1.0],
                 f"after Apply the property holds {given}, time steps {list(relighter.TimestepValues)}")
    result.note(f"schedule: {given}")
result.finish()

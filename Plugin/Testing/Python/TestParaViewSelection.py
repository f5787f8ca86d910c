"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): cells are
selected in the render view as a user selects them (Select Cells On, a drag over the
view), Mark Lights takes them with its Copy Active Selection button and Apply, and the
marked light is exactly the selected cells."""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import (ExtractSelection, GetActiveViewOrCreate, MarkLights, Render, ResetCamera, SetActiveSource, Show,  # noqa: E402
                             XMLPolyDataReader)
from PyQt5.QtCore import QPoint, Qt  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QAction, QApplication, QMainWindow, QPushButton  # noqa: E402

result = guitest.Result()
app = QApplication.instance()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_3lights.vtp")])
view = GetActiveViewOrCreate("RenderView")
Show(scene, view)
view.CameraPosition = [2.0, 1.25, 3.95]
view.CameraFocalPoint = [2.0, 1.0, 0.0]
view.CameraViewUp = [0, 1, 0]
view.CameraViewAngle = 70
Render(view)
guitest.settle(1.0)

# Select Cells On: ParaView's own action, then a drag across the middle of the view.
windows = [w for w in app.topLevelWidgets() if isinstance(w, QMainWindow)]
actions = [a for w in windows for a in w.findChildren(QAction) if a.text().replace("&", "").startswith("Select Cells On")]
widgets = [w for w in app.allWidgets() if w.metaObject().className() == "QVTKOpenGLNativeWidget" and w.isVisible()]
selected = None
if result.check(actions and widgets, f"found Select Cells On ({len(actions)}) and the render view ({len(widgets)})"):
    actions[0].trigger()
    guitest.settle(0.5)
    target = widgets[0].windowHandle() or widgets[0].window().windowHandle()
    origin = widgets[0].mapTo(widgets[0].window(), QPoint(0, 0)) if widgets[0].windowHandle() is None else QPoint(0, 0)
    size = widgets[0].size()
    start = origin + QPoint(int(size.width() * 0.35), int(size.height() * 0.55))
    end = origin + QPoint(int(size.width() * 0.65), int(size.height() * 0.9))
    QTest.mousePress(target, Qt.LeftButton, Qt.NoModifier, start)
    for k in range(1, 11):
        QTest.mouseMove(target, start + (end - start) * (k / 10.0))
        QTest.qWait(20)
    QTest.mouseRelease(target, Qt.LeftButton, Qt.NoModifier, end)
    guitest.settle(1.0)
    selection = scene.GetSelectionInput(scene.Port)
    if result.check(selection is not None, "the drag made an active selection"):
        extracted = servermanager.Fetch(ExtractSelection(Input=scene, Selection=selection))
        original = extracted.GetCellData().GetArray("vtkOriginalCellIds") if extracted else None
        selected = sorted(int(original.GetValue(i)) for i in range(original.GetNumberOfTuples())) if original else []
        result.note(f"{selection.GetXMLName()}: selected cells {selected}")

marker = MarkLights(Input=scene, LightName="Picked", Emission=[3.0, 2.0, 1.0])
SetActiveSource(marker)
guitest.settle(1.0)
copy = [b for b in app.allWidgets() if isinstance(b, QPushButton) and b.text().replace("&", "") == "Copy Active Selection" and b.isVisible()]
if result.check(len(copy) == 1 and selected, f"the Mark Lights panel shows Copy Active Selection ({len(copy)})"):
    copy[0].click()
    guitest.settle(0.5)
    accept = [b for b in app.allWidgets() if isinstance(b, QPushButton) and b.objectName() == "Accept" and b.isVisible()]
    result.check(len(accept) == 1 and accept[0].isEnabled(), "copying the selection is a change waiting for Apply")
    accept[0].click()
    guitest.settle(2.0)
    out = servermanager.Fetch(marker)
    names = out.GetFieldData().GetAbstractArray("LightNames")
    ids = out.GetCellData().GetArray("LightId")
    listed = [names.GetValue(i) for i in range(names.GetNumberOfValues())] if names else []
    light = listed.index("Picked") if "Picked" in listed else -1
    marked = sorted(c for c in range(out.GetNumberOfCells()) if ids and light >= 0 and ids.GetValue(c) == light)
    result.check(light >= 0 and marked == selected and selected,
                 f"Apply marks exactly the selected cells as light 'Picked': {marked} (selected {selected})")
result.finish()

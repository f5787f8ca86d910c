"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): opens the
demo pipeline from Data/, clicks a light's color button in the lights panel (a color
dialog must open), changes a light through the proxy and saves a screenshot.
"""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview.simple import FindSource, GetActiveViewOrCreate, Render, SaveScreenshot, SetActiveSource  # noqa: E402
from PyQt5.QtCore import Qt, QTimer  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QApplication, QCheckBox, QColorDialog, QDoubleSpinBox, QPushButton, QScrollArea, QTableWidget  # noqa: E402

result = guitest.Result()
demo = guitest.data_file("demo_pipeline.py")
exec(open(demo).read(), {"__name__": "demo", "__file__": demo})

relit = FindSource("Relit")
app = QApplication.instance()
SetActiveSource(relit)
for _ in range(50):
    app.processEvents()


def color_buttons():
    tables = [t for t in app.allWidgets() if isinstance(t, QTableWidget) and t.isVisible()
              and t.horizontalHeaderItem(1) is not None and t.horizontalHeaderItem(1).text() == "Color"]
    return [b for t in tables for b in (t.cellWidget(r, 1) for r in range(t.rowCount())) if isinstance(b, QPushButton)]


def close_dialog(seen):
    dialogs = [d for d in app.topLevelWidgets() if isinstance(d, QColorDialog) and d.isVisible()]
    seen.append(len(dialogs))
    for d in dialogs:
        d.reject()


def click_opens_dialog(button):
    """Scrolls the button into view as a user would (the panel is shorter than its
    contents) and clicks it as a real click arrives: at the window, at its place."""
    parent = button.parentWidget()
    while parent is not None and not isinstance(parent, QScrollArea):
        parent = parent.parentWidget()
    if parent is not None:
        parent.ensureWidgetVisible(button)
    for _ in range(20):
        app.processEvents()
    seen = []
    QTimer.singleShot(300, lambda: close_dialog(seen))
    window = button.window()
    QTest.mouseClick(window.windowHandle(), Qt.LeftButton, Qt.NoModifier, button.mapTo(window, button.rect().center()))
    for _ in range(100):
        if seen:
            break
        app.processEvents()
        QTest.qWait(20)
    return seen == [1]


buttons = color_buttons()
if result.check(len(buttons) == 8, "the lights panel shows %d color buttons, expected 8" % len(buttons)):
    opened = [i for i, button in enumerate(buttons) if click_opens_dialog(button)]
    result.check(len(opened) == 8, "a click on each color button opens the color dialog (opened for %s)" % opened)

# An On box unchecked in the filter's panel is a pending change, as for any property:
# nothing changes until Apply (the rows go through ParaView's property links).
boxes = [b for t in app.allWidgets() if isinstance(t, QTableWidget) and t.isVisible()
         and t.horizontalHeaderItem(3) is not None and t.horizontalHeaderItem(3).text() == "On"
         for b in (t.cellWidget(r, 3) for r in range(t.rowCount())) if isinstance(b, QCheckBox)]
apply_buttons = [b for b in app.allWidgets() if isinstance(b, QPushButton) and b.objectName() == "Accept" and b.isVisible()]
if result.check(len(boxes) == 8 and len(apply_buttons) == 1, "found %d On boxes and %d Apply buttons" % (len(boxes), len(apply_buttons))):
    before = list(relit.LightSettings)
    boxes[1].click()
    for _ in range(20):
        app.processEvents()
    pending = list(relit.LightSettings) == before and apply_buttons[0].isEnabled()
    apply_buttons[0].click()
    for _ in range(50):
        app.processEvents()
    applied = list(relit.LightSettings)
    cool = applied.index("CoolWhite") if "CoolWhite" in applied else -6
    result.check(pending and applied[cool + 5 : cool + 6] == ["0"],
                 "an On box is a pending change until Apply (pending %s; after Apply %s)" % (pending, applied[cool:cool + 6]))
    relit.LightSettings = before  # back to the demo's lights for the screenshot below
    for _ in range(50):
        app.processEvents()

# The columns come from the row's declaration: a number's box writes that part alone, the
# parts not touched going as 'nan' (kept as they are in effect).
spins = [b for t in app.allWidgets() if isinstance(t, QTableWidget) and t.isVisible()
         and t.horizontalHeaderItem(2) is not None and t.horizontalHeaderItem(2).text() == "Intensity"
         for b in (t.cellWidget(r, 2) for r in range(t.rowCount())) if isinstance(b, QDoubleSpinBox)]
if result.check(len(spins) == 8 and len(apply_buttons) == 1, "found %d Intensity boxes" % len(spins)):
    names = [t.item(r, 0).text() for t in app.allWidgets() if isinstance(t, QTableWidget) and t.isVisible()
             and t.horizontalHeaderItem(2) is not None and t.horizontalHeaderItem(2).text() == "Intensity"
             for r in range(t.rowCount())]
    relit.LightSettings = ["Rose", "nan", "nan", "nan", "3", "1"]  # from Python: the panel follows
    for _ in range(50):
        app.processEvents()
    fresh = names.index("Amber")
    spins[fresh].setValue(2.5)
    apply_buttons[0].click()
    for _ in range(50):
        app.processEvents()
    rows = list(relit.LightSettings)
    result.check(rows == ["Amber", "nan", "nan", "nan", "2.5", "1", "Rose", "nan", "nan", "nan", "3", "1"],
                 "an Intensity box writes its part alone, beside a row set from Python: %s" % rows)
    relit.LightSettings = []
    for _ in range(50):
        app.processEvents()
    spins[fresh].setValue(1.5)
    apply_buttons[0].click()
    for _ in range(50):
        app.processEvents()
    result.check(list(relit.LightSettings) == ["Amber", "nan", "nan", "nan", "1.5", "1"],
                 "LightSettings emptied from Python, then a box edited: %s" % list(relit.LightSettings))
    relit.LightSettings = before

settings = list(relit.LightSettings)
# Turn the warm light off and make the amber one strong and red.
settings[5] = "0"
settings[12:18] = ["Amber", "1", "0.1", "0.05", "6", "1"]
if not os.environ.get("RELIGHT_GUI_UNCHANGED"):  # set only to check the test can fail
    relit.LightSettings = settings
    relit.UpdatePipeline()
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [400, 300]
Render(view)
SaveScreenshot(guitest.image_path(), view, ImageResolution=[400, 300])
result.finish()

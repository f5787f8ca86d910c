"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): adds the
mesher to the applied Cornell box (millimetres), types a new Element Size and a new Patch
Size into the Properties panel, and checks that the line under Element Size counts the
elements before Apply, and that Apply then makes exactly that many.
"""

import os
import re
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import RadiosityMesher, SetActiveSource, XMLPolyDataReader  # noqa: E402
from PyQt5.QtCore import Qt  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QApplication, QLabel, QLineEdit  # noqa: E402

result = guitest.Result()
app = QApplication.instance()



def panel_widget(kind, name):
    found = [w for w in app.allWidgets() if isinstance(w, kind) and w.objectName() == name and w.isVisible()]
    return found[0] if len(found) == 1 else None


def retype(edit, text):
    edit.setFocus()
    edit.selectAll()
    QTest.keyClicks(edit, text)
    guitest.settle(0.2)


def shown_count(label):
    digits = re.sub(r"[^\d]", "", label.text())
    return int(digits) if digits else None


scene = XMLPolyDataReader(FileName=[guitest.data_file("cornell_box.vtp")])
scene.UpdatePipeline()
mesher = RadiosityMesher(Input=scene)
SetActiveSource(mesher)
guitest.settle(1.0)
label = panel_widget(QLabel, "ElementEstimate")
edit = panel_widget(QLineEdit, "ElementSizeEdit")
patch_edits = [w for w in app.allWidgets() if isinstance(w, QLineEdit) and w.isVisible()
               and w.parent() is not None and w.parent().objectName() == "PatchSize"]
if result.check(label is not None and edit is not None, "the Element Size box and its estimate are in the panel") \
        and result.check(len(patch_edits) == 1, "found %d Patch Size boxes" % len(patch_edits)):
    first = shown_count(label)
    result.note("at the suggested sizes: '%s'" % label.text())
    if not os.environ.get("RELIGHT_GUI_UNCHANGED"):  # set only to check the test can fail
        retype(edit, "40")
        retype(patch_edits[0], "80")
    typed = shown_count(label)
    result.note("after typing 80 / 40, before Apply: '%s'" % label.text())
    mesher.PatchSize = 80
    mesher.ElementSize = 40
    mesher.UpdatePipeline()
    made = servermanager.Fetch(mesher).GetNumberOfCells()
    result.check(typed is not None and typed != first, "the count follows the typing (%s, then %s)" % (first, typed))
    result.check(typed == made, "the panel said %s elements before Apply; Apply made %d" % (typed, made))
result.finish()

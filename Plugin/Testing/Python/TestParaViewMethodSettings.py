"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): the solver's
settings by name as a user enters them (advanced properties shown). The table has Setting
and Value columns; Add Setting puts the method table's first setting at its default; a name
no method has and a value out of range are put back; Apply sends the rows to the solver."""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview.simple import LightTaggedRadiosity, RadiosityMesher, SetActiveSource, XMLPolyDataReader  # noqa: E402
from PyQt5.QtWidgets import QApplication, QPushButton, QTableWidget, QToolButton  # noqa: E402

result = guitest.Result()
app = QApplication.instance()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_3lights.vtp")])
mesher = RadiosityMesher(Input=scene, PatchSize=1.5, ElementSize=0.75)
solver = LightTaggedRadiosity(Input=mesher)
SetActiveSource(solver)
guitest.settle(1.0)
for button in app.allWidgets():
    if isinstance(button, QToolButton) and button.objectName() == "AdvancedButton" and not button.isChecked():
        button.click()  # the gear: advanced properties, where Method Settings is
guitest.settle(1.0)


def named(kind, name):
    return [w for w in app.allWidgets() if isinstance(w, kind) and w.objectName() == name]


tables = [t for t in named(QTableWidget, "MethodSettingsTable") if t.isVisible()]
if result.check(len(tables) == 1, f"the solver's advanced panel shows one method-settings table ({len(tables)})"):
    table = tables[0]
    headers = [table.horizontalHeaderItem(c).text() for c in range(table.columnCount())]
    tip = table.horizontalHeaderItem(0).toolTip()
    result.check(headers == ["Setting", "Value"] and "RefinementThreshold (Hierarchical, 0 to 1)" in tip,
                 f"column headers {headers}, the Setting column's tip lists the table's settings: {tip}")
    named(QPushButton, "AddMethodSetting")[0].click()
    guitest.settle(0.3)
    cells = [table.item(0, c).text() for c in range(2)]
    result.check(cells == ["RefinementThreshold", "0"], f"Add Setting offers the first setting at its default: {cells}")
    table.item(0, 1).setText("5")
    result.check(table.item(0, 1).text() == "0", f"a value out of its range (0 to 1) is put back: {table.item(0, 1).text()}")
    table.item(0, 0).setText("Separation")
    result.check(table.item(0, 0).text() == "RefinementThreshold",
                 f"a name no method has is put back: {table.item(0, 0).text()}")
    table.item(0, 1).setText("0.01")
    named(QPushButton, "AddMethodSetting")[0].click()
    guitest.settle(0.3)
    second = [table.item(1, c).text() for c in range(2)] if table.rowCount() > 1 else []
    result.check(second == ["ClusterMemoryLimit", "0"], f"a second Add offers the next setting: {second}")
    table.item(1, 0).setText("RefinementThreshold")
    result.check(table.item(1, 0).text() == "ClusterMemoryLimit",
                 f"a name another row holds is put back: {table.item(1, 0).text()}")
    named(QPushButton, "AddMethodSetting")[0].click()
    guitest.settle(0.3)
    result.check(table.rowCount() == 2, f"with every setting in the table, Add adds nothing ({table.rowCount()} rows)")
    table.selectRow(1)
    named(QPushButton, "RemoveMethodSettings")[0].click()
    guitest.settle(0.3)
    accept = [b for b in named(QPushButton, "Accept") if b.isVisible()]
    if result.check(len(accept) == 1 and accept[0].isEnabled(), "an edit of the settings waits for Apply"):
        accept[0].click()
        guitest.settle(1.5)
    given = [str(v) for v in solver.MethodSettings]
    result.check(len(given) == 2 and given[0] == "RefinementThreshold" and abs(float(given[1]) - 0.01) < 1e-12,
                 f"Apply sends the row to the solver: {given}")
result.finish()

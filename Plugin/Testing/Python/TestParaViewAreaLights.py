"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): Mark Lights'
area lights as a user enters them. The table has column headers with units; Add Lamp puts
a lamp under the top of the scene facing down; a typed centre is taken, text that is not
three numbers is put back; Tab past the last cell adds no row; Apply makes the lamp a light
of the scene, and Remove takes it away."""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import GetActiveView, MarkLights, SetActiveSource, XMLPolyDataReader  # noqa: E402
from PyQt5.QtCore import Qt  # noqa: E402
from PyQt5.QtTest import QTest  # noqa: E402
from PyQt5.QtWidgets import QApplication, QPushButton, QTableWidget  # noqa: E402

result = guitest.Result()
app = QApplication.instance()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_3lights.vtp")])
scene.UpdatePipeline()
marker = MarkLights(Input=scene)
SetActiveSource(marker)
guitest.settle(1.0)


def visible(kind, name):
    return [w for w in app.allWidgets() if isinstance(w, kind) and w.objectName() == name and w.isVisible()]


def apply():
    accept = visible(QPushButton, "Accept")
    if result.check(len(accept) == 1 and accept[0].isEnabled(), "an edit of the area lights waits for Apply"):
        accept[0].click()
        guitest.settle(1.5)


def light_names():
    names = servermanager.Fetch(marker).GetFieldData().GetAbstractArray("LightNames")
    return [names.GetValue(i) for i in range(names.GetNumberOfValues())] if names else []


tables = visible(QTableWidget, "AreaLightsTable")
if result.check(len(tables) == 1, f"the Mark Lights panel shows one area-lights table ({len(tables)})"):
    table = tables[0]
    headers = [table.horizontalHeaderItem(c).text() for c in range(table.columnCount())]
    result.check(headers == ["Name", "Shape", "Centre x, y, z", "Facing x, y, z", "Width, height",
                             "Emission r, g, b (W/m²)"], f"column headers {headers}")
    visible(QPushButton, "AddLamp")[0].click()
    guitest.settle(0.3)
    cells = [table.item(0, c).text() if table.item(0, c) else "" for c in range(table.columnCount())]
    result.note(f"a new lamp: {cells}")
    bounds = scene.GetDataInformation().GetBounds()
    top = float(cells[2].split(", ")[1]) if cells[2].count(",") == 2 else 0.0  # y: the paper scene stands on y
    result.check(table.rowCount() == 1 and cells[0] == "Lamp1" and cells[3] == "0, -1, 0"
                 and bounds[3] - 0.05 < top <= bounds[3],
                 f"Add Lamp makes one lamp under the top of the scene (y max {bounds[3]}) facing down: {cells}")
    table.item(0, 2).setText("1, 2.4, 1")
    table.item(0, 4).setText("0.3 0.3")
    table.item(0, 3).setText("down")  # not three numbers: put back
    result.check(table.item(0, 3).text() == "0, -1, 0", f"'down' as a direction is put back: {table.item(0, 3).text()}")
    table.setFocus()
    table.setCurrentCell(0, table.columnCount() - 1)
    QTest.keyClick(table, Qt.Key_Tab)  # ParaView's own table for such a property added a row here
    guitest.settle(0.2)
    result.check(table.rowCount() == 1, f"Tab past the last cell adds no row ({table.rowCount()} rows)")
    table.item(0, 4).setText("0, 0.3")  # a lamp needs a size: put back
    result.check(table.item(0, 4).text() == "0.3, 0.3", f"a width of 0 is put back: {table.item(0, 4).text()}")
    apply()
    expected = ["Lamp1", "0", "1", "2.4", "1", "0", "-1", "0", "0.3", "0.3", "1", "1", "1"]
    given = [str(v) for v in marker.AreaLights]
    numbers_match = len(given) == 13 and given[:2] == expected[:2] and all(
        abs(float(a) - float(b)) < 1e-9 for a, b in zip(given[2:], expected[2:]))
    result.check(numbers_match, f"the property after Apply: {given}")
    result.check("Lamp1" in light_names(), f"Apply adds the lamp as a light: {light_names()}")
    visible(QPushButton, "AddLamp")[0].click()
    guitest.settle(0.3)
    result.check(table.item(1, 0).text() == "Lamp2", f"a second lamp gets a name of its own: {table.item(1, 0).text()}")
    table.selectRow(0)
    visible(QPushButton, "RemoveLamps")[0].click()
    guitest.settle(0.3)
    visible(QPushButton, "AddLamp")[0].click()
    guitest.settle(0.3)
    names = sorted(table.item(r, 0).text() for r in range(table.rowCount()))
    result.check(names == ["Lamp1", "Lamp2"], f"after removing Lamp1 a new lamp takes Lamp1 again, not a copy: {names}")
    for _ in range(2):
        visible(QPushButton, "RemoveLamps")[0].click()
        guitest.settle(0.3)
    apply()
    result.check(table.rowCount() == 0 and len(marker.AreaLights) == 0 and "Lamp1" not in light_names(),
                 f"Remove takes the lamp away: {table.rowCount()} rows, lights {light_names()}")
    # "Up" is the view's: with the camera's up along +z the lamp hangs under the top in z,
    # facing -z (a scan narrower than it is tall got its lamp on its flank by the shortest side).
    view = GetActiveView()
    view.CameraViewUp = [0, 0, 1]
    visible(QPushButton, "AddLamp")[0].click()
    guitest.settle(0.3)
    cells = [table.item(0, c).text() if table.item(0, c) else "" for c in range(table.columnCount())]
    along = float(cells[2].split(", ")[2]) if cells[2].count(",") == 2 else 0.0
    result.check(cells[3] == "0, 0, -1" and bounds[5] - 0.05 * (bounds[5] - bounds[4]) < along <= bounds[5],
                 f"with the view's up along z, Add Lamp hangs it under the top in z (z max {bounds[5]}): {cells}")
    view.CameraViewUp = [0, 1, 0]
result.finish()

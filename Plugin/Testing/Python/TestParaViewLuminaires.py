"""Runs inside the real ParaView GUI (started by RunParaViewGUI.py under Xvfb): Mark Lights'
luminaires as a user enters them. The table has column headers; Add Luminaire puts one
under the top of the scene aimed down, with a File button for its photometric file; typed
parameters (the file, its lumens) and a position are taken, a zero aim is put back; Apply
makes the luminaire a light of the scene, and the solver below gives it a solution of its
own in lux."""

import os
import sys

sys.path.insert(0, os.environ["RELIGHT_TEST_DIR"])
import guitest  # noqa: E402
from paraview import servermanager  # noqa: E402
from paraview.simple import LightTaggedRadiosity, MarkLights, RadiosityMesher, SetActiveSource  # noqa: E402
from paraview.simple import XMLPolyDataReader  # noqa: E402
from PyQt5.QtWidgets import QApplication, QPushButton, QTableWidget  # noqa: E402

result = guitest.Result()
app = QApplication.instance()
scene = XMLPolyDataReader(FileName=[guitest.data_file("paper_1lights.vtp")])
scene.UpdatePipeline()
marker = MarkLights(Input=scene)
SetActiveSource(marker)
guitest.settle(1.0)
photometry = os.path.join(guitest.ROOT, "Data", "Photometry", "erco_sym2.ldt")


def visible(kind, name):
    return [w for w in app.allWidgets() if isinstance(w, kind) and w.objectName() == name and w.isVisible()]


tables = visible(QTableWidget, "LuminairesTable")
if result.check(len(tables) == 1, f"the Mark Lights panel shows one luminaires table ({len(tables)})"):
    table = tables[0]
    headers = [table.horizontalHeaderItem(c).text() for c in range(table.columnCount())]
    result.check(headers == ["Name", "Kind", "Parameters", "File", "Position x, y, z", "Aim x, y, z", "Rotation (°)",
                             "Color r, g, b"], f"column headers {headers}")
    visible(QPushButton, "AddLuminaire")[0].click()
    guitest.settle(0.3)
    cells = [table.item(0, c).text() if table.item(0, c) else "" for c in range(table.columnCount())]
    result.note(f"a new luminaire: {cells}")
    result.check(table.rowCount() == 1 and cells[0] == "Luminaire1" and cells[5] == "0, -1, 0",
                 f"Add Luminaire makes one aimed down (the paper scene stands on y): {cells}")
    result.check(len(visible(QPushButton, "PickPhotometricFile")) == 1, "each row has a File button")
    table.item(0, 2).setText(f"file={photometry}; lumens=2000")
    table.item(0, 4).setText("2, 2.3, 2")
    table.item(0, 5).setText("0 0 0")  # no direction: put back
    result.check(table.item(0, 5).text() == "0, -1, 0", f"a zero aim is put back: {table.item(0, 5).text()}")
    accept = visible(QPushButton, "Accept")
    if result.check(len(accept) == 1 and accept[0].isEnabled(), "an edit of the luminaires waits for Apply"):
        accept[0].click()
        guitest.settle(1.5)
    given = [str(v) for v in marker.Luminaires]
    result.check(len(given) == 13 and given[:3] == ["Luminaire1", "goniometric", f"file={photometry}; lumens=2000"],
                 f"the property after Apply: {given}")
    names = servermanager.Fetch(marker).GetFieldData().GetAbstractArray("LuminaireNames")
    result.check(names is not None and names.GetValue(0) == "Luminaire1", "Apply adds the luminaire to the scene")
    solver = LightTaggedRadiosity(Input=RadiosityMesher(Input=marker))
    solver.UpdatePipeline()
    solved = servermanager.Fetch(solver)
    lights = solved.GetFieldData().GetAbstractArray("LightNames")
    lights = [lights.GetValue(i) for i in range(lights.GetNumberOfValues())] if lights else []
    result.check(lights == ["WarmWhite", "Luminaire1"], f"the solver gives it a solution of its own: {lights}")
    lux = solved.GetPointData().GetArray("Radiosity_Luminaire1")
    result.check(lux is not None and lux.GetRange(0)[1] > 10, "its solution is lit (lm/m²)")
    SetActiveSource(marker)
    guitest.settle(1.0)
    panel = table.parentWidget()
    panel.resize(900, panel.sizeHint().height())
    panel.grab().save(guitest.image_path())  # the table as the panel shows it, for a person to look at
result.finish()

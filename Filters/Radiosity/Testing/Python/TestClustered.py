"""The clustered solver method through the VTK filter: on the paper scene and the Cornell
box it equals progressive refinement with every element its own patch (the exact
transport of the same elements) within 1 % per light; the output contract (names,
SolverMethod report, separate direct part) stays the same."""

import os

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonCore import vtkLogger

import relight
from testlib import check, finish
from relight import cell_areas, cell_array, light_names, read_polydata

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
PROGRESSIVE, CLUSTERED = 1, 3


def solve(meshed, method, **settings):
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputData(meshed)
    solver.SetSolverMethod(method)
    solver.SetConvergenceThreshold(1e-4)
    for name, value in settings.items():
        getattr(solver, "Set" + name)(value)
    solver.Update()
    return solver.GetOutput()


def mesh(path, patch, element):
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(read_polydata(path))
    mesher.SetPatchSize(patch), mesher.SetElementSize(element)
    mesher.Update()
    return mesher.GetOutput()


def each_element_a_patch(meshed):
    copy = type(meshed)()
    copy.DeepCopy(meshed)
    ids = numpy_to_vtk(np.arange(copy.GetNumberOfCells(), dtype=np.int32), deep=1)
    ids.SetName("PatchId")
    copy.GetCellData().AddArray(ids)
    return copy


def compare(label, path, patch, element):
    meshed = mesh(path, patch, element)
    fine = solve(each_element_a_patch(meshed), PROGRESSIVE)
    clustered = solve(meshed, CLUSTERED, SeparateDirect=1)
    method = clustered.GetFieldData().GetAbstractArray("SolverMethod").GetValue(0)
    check(method.startswith("Clustered") and "cluster links" in method, f"{label}: SolverMethod reports '{method}'")
    check(light_names(clustered) == light_names(fine), f"{label}: same light names {light_names(clustered)}")
    areas = cell_areas(clustered)
    for name in light_names(fine):
        a = cell_array(clustered, "Radiosity_" + name).sum(axis=1)
        b = cell_array(fine, "Radiosity_" + name).sum(axis=1)
        difference = np.sum(np.abs(a - b) * areas) / np.sum(b * areas)
        check(difference < 0.01, f"{label}, light {name}: clustered vs progressive {100 * difference:.2f} % (< 1 %)")
        direct = cell_array(clustered, "Direct_" + name).sum(axis=1)
        check(np.all(direct <= a + 1e-9) and np.sum(direct * areas) < np.sum(a * areas),
              f"{label}, light {name}: the direct part is part of the whole and less than it")
    return clustered


compare("paper scene, 3 lights", os.path.join(DATA, "paper_3lights.vtp"), 1.0, 0.25)
cornell = compare("Cornell box", os.path.join(DATA, "cornell_box.vtp"), 100.0, 50.0)
finish("TestClustered")

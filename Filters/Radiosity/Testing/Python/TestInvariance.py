"""The mesh of a real building does not depend on its unit, its turn or its place.

The KIT FZK-Haus (Debian's assimp-testmodels, an IFC nobody here made) is meshed in metres
and again scaled to millimetres, turned 37 degrees and moved 1 km, with VTK's float points
as a user's transform gives them. Every variant must give the same elements per input
polygon and the same patches (which input polygons share each patch). Float storage moves
points by up to 1e-7 of their magnitude: straight corners went bent, lengths that were
whole multiples of the element size gained a row, and planes a hair apart joined or not
depending on where rounding boundaries fell."""

import os

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter

import relight
from testlib import check, finish

house = relight.import_scene("/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc", require_lights=False)
source = numpy_to_vtk(np.arange(house.GetNumberOfCells(), dtype=np.int32), deep=True)
source.SetName("SourceId")
house.GetCellData().AddArray(source)


def moved(scale, degrees, shift):
    transform = vtkTransform()
    transform.Translate(shift, -shift / 2, shift / 3)
    transform.RotateZ(degrees)
    transform.Scale(scale, scale, scale)
    mover = vtkTransformPolyDataFilter()
    mover.SetTransform(transform)
    mover.SetInputData(house)
    mover.Update()
    return mover.GetOutput()


def meshed(data, scale):
    """(elements per input polygon, the set of input-polygon groups that share a patch)"""
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(data)
    mesher.SetPatchSize(5.0 * scale)
    mesher.SetElementSize(1.25 * scale)
    mesher.Update()
    out = mesher.GetOutput()
    ids = vtk_to_numpy(out.GetCellData().GetArray("SourceId"))
    patches = vtk_to_numpy(out.GetCellData().GetArray("PatchId"))
    groups = {}
    for polygon, patch in zip(ids, patches):
        groups.setdefault(patch, set()).add(int(polygon))
    return np.bincount(ids, minlength=house.GetNumberOfCells()), sorted(tuple(sorted(g)) for g in groups.values())


counts, groups = meshed(house, 1.0)
for name, scale, degrees, shift in (("millimetres", 1000.0, 0, 0), ("turned 37 degrees", 1.0, 37, 0),
                                    ("millimetres and turned", 1000.0, 37, 0), ("turned and moved 1 km", 1.0, 37, 1000.0)):
    other, other_groups = meshed(moved(scale, degrees, shift * scale), scale)
    changed = np.nonzero(other != counts)[0]
    check(changed.size == 0, f"{name}: {other.sum()} elements against {counts.sum()}; "
                             f"polygons meshed otherwise: {changed[:5].tolist()}")
    check(other_groups == groups, f"{name}: {len(other_groups)} patches against {len(groups)}, "
                                  f"{len(set(other_groups) ^ set(groups))} groupings differ")
# The panel's live count (EstimateElements) is what Apply makes on this triangulated model:
# triangle pairs merged, contacts cut. It counted the unmerged triangles before (186,142
# against 155,822 at 1.0 / 0.25).
estimator = relight.vtkRadiosityMesher()
estimator.SetInputData(house)
before_any_update = estimator.EstimateElements(5.0, 1.25)  # it gave 0 until UpdateInformation
for patch, element in ((5.0, 1.25), (1.0, 0.25)):
    estimator.SetPatchSize(patch)
    estimator.SetElementSize(element)
    estimator.Update()
    made = estimator.GetOutput().GetNumberOfCells()
    check(estimator.EstimateElements(patch, element) == made,
          f"the estimate at {patch} / {element} is what the mesher makes: {estimator.EstimateElements(patch, element):.0f} "
          f"and {made}")
    if patch == 5.0:
        check(before_any_update == made, f"the estimate before any update is the same: {before_any_update:.0f}")


# A scene in site coordinates (UTM-referenced BIM: millions of metres, double points) solves
# as at the origin. The "touching" tolerance grew with the coordinates (1e-6 of the farthest,
# 3 m at 3e6 m) and hid surfaces as enclosed: 141 shots instead of 646, 9 % of the light gone.
def solved(scene):
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(scene)
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    solver.Update()
    data = solver.GetOutput().GetPointData()
    names = sorted(data.GetArrayName(i) for i in range(data.GetNumberOfArrays())
                   if data.GetArrayName(i).startswith("Radiosity_"))
    return solver.GetLastShots(), np.array([vtk_to_numpy(data.GetArray(n)).sum() for n in names])


paper = relight.read_polydata(os.path.join(os.environ["RELIGHT_ROOT"], "Data", "paper_3lights.vtp"))
shots, power = solved(paper)
for offset in (3e5, 3e6):
    far = type(paper)()
    far.DeepCopy(paper)
    points = vtk_to_numpy(far.GetPoints().GetData()).astype(np.float64) + np.array([offset, -offset, offset])
    far.GetPoints().SetData(numpy_to_vtk(points, deep=True))
    far_shots, far_power = solved(far)
    difference = np.abs(far_power / power - 1).max()
    check(far_shots == shots and difference < 1e-5,
          f"the paper scene moved by {offset:.0e} m (double points): {far_shots} shots against {shots}, "
          f"power per light within {difference:.1e} (< 1e-5; the arrays are float)")


# Float points far from the origin, as a user's transform gives them: the paper scene turned
# about a skew axis and moved. At 100 m its corners sit a float step (8e-6 m) off their
# planes, far above the solver's flatness tests (1e-9 of the scene), so patches counted as
# curved and light was lost (-0.35 %); at 10 km (a millimetre) walls gained rows of elements
# and the box no longer stood on the floor (1,956 or 1,652 elements against 1,686).
def turned_float(shift):
    transform = vtkTransform()
    transform.PostMultiply()
    transform.RotateWXYZ(37, 0.3, 0.8, 0.2)
    transform.Translate(*shift)
    mover = vtkTransformPolyDataFilter()
    mover.SetTransform(transform)
    mover.SetInputData(paper)
    mover.SetOutputPointsPrecision(0)  # single, as VTK's filters and most files keep points
    mover.Update()
    return mover.GetOutput()


def elements(scene):
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(scene)
    mesher.Update()
    return mesher.GetOutput().GetNumberOfCells(), len(np.unique(relight.cell_array(mesher.GetOutput(), "PatchId")))


at_origin = turned_float((0, 0, 0))
made, (shots, power) = elements(at_origin), solved(at_origin)
for shift, bound in (((100, -30, 50), 1e-4), ((1e4, -3e3, 5e3), 1e-2)):
    far = turned_float(shift)
    far_made, (_, far_power) = elements(far), solved(far)
    difference = np.abs(far_power / power - 1).max()
    check(far_made == made, f"turned, float points moved by {shift}: {far_made} (elements, patches) against {made}")
    check(difference < bound, f"turned, float points moved by {shift}: power per light within {difference:.1e} "
                              f"(< {bound:g}: a float step there is {np.ldexp(max(map(abs, shift)), -23):.0e} m)")


# Tessellated curved objects (a triangulated cylinder, a sphere of triangle pairs, an annulus),
# as CAD exports give them, turned and moved 10 km as float points. A float step there (1e-3
# m) turns a 5 cm triangle's normal by 2e-2, where one fixed angle decided which triangles
# pair into quads and which polygons share a plane: the triangle pairs fell from 2,794 to 80
# and the elements rose from 34,794 to 82,967. Pairs and planes are now judged by lengths
# against the float noise, and planes founded by the polygons whose normals are known best.
def curved_objects():
    from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkTriangleFilter
    from vtkmodules.vtkFiltersSources import vtkCylinderSource, vtkDiskSource, vtkSphereSource
    cylinder, sphere, disk = vtkCylinderSource(), vtkSphereSource(), vtkDiskSource()
    cylinder.SetResolution(96), cylinder.SetHeight(2), cylinder.SetRadius(0.6), cylinder.SetCenter(-1.2, 0, 0)
    sphere.SetThetaResolution(60), sphere.SetPhiResolution(40), sphere.SetRadius(0.5), sphere.SetCenter(1.2, 0, 0)
    disk.SetInnerRadius(0.2), disk.SetOuterRadius(0.9), disk.SetCircumferentialResolution(64), disk.SetRadialResolution(6)
    both = vtkAppendPolyData()
    for piece in (cylinder, sphere, disk):
        triangles = vtkTriangleFilter()
        triangles.SetInputConnection(piece.GetOutputPort())
        both.AddInputConnection(triangles.GetOutputPort())
    both.Update()
    model = both.GetOutput()
    count = model.GetNumberOfCells()
    reflectance = numpy_to_vtk(np.full((count, 3), 0.6), deep=True)
    reflectance.SetName("Reflectance")
    light = numpy_to_vtk(np.full(count, -1, dtype=np.int32), deep=True)
    light.SetName("LightId")
    model.GetCellData().AddArray(reflectance)
    model.GetCellData().AddArray(light)
    room = relight.in_room(model)
    b = room.GetBounds()
    lamp = relight.area_light("Lamp", centre=(0, b[3] - 0.01, 0), normal=(0, -1, 0), size=0.5, intensity=10)
    return relight.mark_lights(room, lamp)


def mesh_counts(scene):
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(scene)
    mesher.Update()
    out = mesher.GetOutput()
    pairs = out.GetFieldData().GetArray("MergedTrianglePairs").GetValue(0)
    return np.array([out.GetNumberOfCells(), len(np.unique(relight.cell_array(out, "PatchId"))), pairs])


paper = curved_objects()
made = mesh_counts(turned_float((0, 0, 0)))
far = mesh_counts(turned_float((1e4, -3e3, 5e3)))
off = np.abs(far / made - 1)
check(off[0] < 2e-3 and off[1] < 1e-2 and off[2] < 2e-3,
      f"curved objects turned, float points moved by (1e4, -3e3, 5e3): {far.tolist()} (elements, patches, triangle "
      f"pairs) against {made.tolist()} at the origin")
finish("TestInvariance")

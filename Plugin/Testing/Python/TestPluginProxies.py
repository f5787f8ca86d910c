"""End-to-end test of the RadiosityRelight ParaView plugin proxies.

Usage:
    pvbatch Plugin/Testing/Python/TestPluginProxies.py <plugin.so> <cornell_box.vtp> [screenshot.png]

Loads the plugin, runs reader -> RadiosityMesher -> LightTaggedRadiosity ->
RadiosityRelight on the Cornell box (millimetres), fetches the results and
checks the arrays and the relighting arithmetic. Exits non-zero on failure and
prints a line containing 'passed' on success.
"""

import math
import os
import xml.etree.ElementTree as ET
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403  (LoadPlugin, Show, Render, ...)
from paraview import servermanager

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Testing", "Python"))  # the tests' shared helpers
from settingstable import setting_rows  # noqa: E402

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.util.vtkConstants import VTK_UNSIGNED_CHAR

LIGHT = "Ceiling"
COLOR = (1.0, 0.8, 0.6)
INTENSITY = 2.0
ENABLED = 1
REL_TOL = 1e-5


class TestFailure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise TestFailure(message)


def get_array(attributes, name, where, count):
    """Returns the vtkDataArray `name` of `attributes`; it must have 3 components
    and `count` tuples."""
    array = attributes.GetArray(name)
    check(array is not None, "%s: missing array '%s'" % (where, name))
    check(array.GetNumberOfComponents() == 3,
          "%s: array '%s' has %d components, expected 3"
          % (where, name, array.GetNumberOfComponents()))
    check(array.GetNumberOfTuples() == count,
          "%s: array '%s' has %d tuples, expected %d"
          % (where, name, array.GetNumberOfTuples(), count))
    return array


def check_finite(dataset, label):
    """No NaN (or Inf) in any floating-point point or cell array."""
    for kind, attributes in (("point", dataset.GetPointData()), ("cell", dataset.GetCellData())):
        for i in range(attributes.GetNumberOfArrays()):
            array = attributes.GetArray(i)
            if array is None:  # not a vtkDataArray (e.g. a string array)
                continue
            values = numpy_support.vtk_to_numpy(array)
            if values.dtype.kind == "f":
                check(np.all(np.isfinite(values)),
                      "%s: %s array '%s' contains NaN or Inf"
                      % (label, kind, array.GetName()))


def check_setting_names(settings, proxies):
    """Every setting docs/settings.md lists is a property of its proxy, and every
    settable property is in the table (TestNames.py checks the XML against C++)."""
    table = {row[0]: row[2] for row in setting_rows(settings)}
    check(len(table) == 8, "docs/settings.md lists %d proxies, expected 8" % len(table))
    for proxy in proxies:
        xml_name = proxy.SMProxy.GetXMLName()
        listed = table.get(xml_name, [])
        for name in listed:
            check(hasattr(proxy, name), f"docs/settings.md names {xml_name}.{name}, which ParaView's Python lacks")
        iterator = proxy.SMProxy.NewPropertyIterator()
        iterator.Begin()
        while not iterator.IsAtEnd():
            name, prop = iterator.GetKey(), iterator.GetProperty()
            iterator.Next()
            if not prop.GetInformationOnly() and not prop.IsA("vtkSMInputProperty"):
                check(name in listed, f"{xml_name}.{name} is missing from docs/settings.md")

def grab(view):
    """The view's picture as an array of RGB values."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    path = os.path.join(tempfile.mkdtemp(), "view.png")
    SaveScreenshot(path, view, ImageResolution=[300, 300])
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    return numpy_support.vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())[:, :3].astype(float)


def check_relit_schedule(view, display):
    """Relit Surface follows the lights' schedule at the view's time (on the GPU, no filter)."""
    display.RelitExposure = 0.5
    # `enabled` as the schedule file takes it ('on', 'yes'): a copied CSV row keeps its lamp on.
    display.RelitScheduleEntries = ["0", LIGHT, "1", "1", "1", "0", "on", "4", LIGHT, "1", "1", "1", "8", "yes"]
    view.ResetCamera()
    shown = {}
    for time in (1.0, 3.0):
        view.ViewTime = time
        shown[time] = grab(view).mean()
        display.UpdatePropertyInformation()
        info = list(display.RelitLightSettingsInfo)
        check(info[:1] == [LIGHT] and float(info[4]) == 2.0 * time,
              "at view time %g Relit Surface has %s, expected %s at intensity %g" % (time, info, LIGHT, 2.0 * time))
    check(shown[3.0] > shown[1.0] + 1.0,
          "the relit picture at time 3 (mean %.3g) is not brighter than at time 1 (%.3g)" % (shown[3.0], shown[1.0]))
    print("Relit Surface schedule: intensity 2 -> 6 from view time 1 to 3, mean picture %.3g -> %.3g"
          % (shown[1.0], shown[3.0]))
    display.RelitScheduleEntries = ["0", LIGHT, "1", "1", "1", "1", "maybe"]
    Render(view)
    display.UpdatePropertyInformation()
    check(list(display.RelitLightSettingsInfo) == [],
          "an unreadable 'enabled' in the schedule is an error, not a lamp silently off: %s"
          % list(display.RelitLightSettingsInfo))
    display.RelitScheduleEntries = []
    view.ViewTime = 0.0


def check_failed_solve(view, solver, display):
    """A solve that fails returns 0, as VTK filters do: its own output is empty, and the
    update stops there, so the relight downstream keeps its last picture (as after any
    failed filter in ParaView); setting the solver right brings the picture back."""
    before = display.GetRepresentedDataInformation().GetNumberOfPoints()
    threshold = solver.ConvergenceThreshold
    solver.ConvergenceThreshold = float("nan")
    Render(view)
    solver.UpdatePipeline()
    failed = solver.GetDataInformation().GetNumberOfPoints()
    during = display.GetRepresentedDataInformation().GetNumberOfPoints()
    check(during == before, "the relight's display shows %d points after the failed solve, its last %d" % (during, before))
    check(before > 0 and failed == 0,
          "after a failed solve the solver's output has %d points (the relight showed %d), expected none" % (failed, before))
    solver.ConvergenceThreshold = threshold
    Render(view)
    after = display.GetRepresentedDataInformation().GetNumberOfPoints()
    check(after == before, "a solve set right shows the relit scene again: %d points, %d before" % (after, before))
    print("a failed solve leaves an empty output (the relight's display: %d points); set right, it shows %d again"
          % (during, after))


def write_room_obj():
    """A 2 x 2 x 2 m box (inward faces, Kd 0.5) with a 0.5 m ceiling lamp (Ke 10) as OBJ+MTL."""
    folder = tempfile.mkdtemp()
    with open(os.path.join(folder, "room.mtl"), "w") as f:
        f.write("newmtl Wall\nKd 0.5 0.5 0.5\nnewmtl Lamp\nKd 0.8 0.8 0.8\nKe 10 10 10\n")
    corners = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2),
               (0.75, 0.75, 1.99), (0.75, 1.25, 1.99), (1.25, 1.25, 1.99), (1.25, 0.75, 1.99)]
    walls = [(1, 2, 3, 4), (5, 8, 7, 6), (1, 5, 6, 2), (3, 7, 8, 4), (1, 4, 8, 5), (2, 6, 7, 3)]
    lines = ["mtllib room.mtl"] + ["v %g %g %g" % c for c in corners] + ["usemtl Wall"]
    lines += ["f %d %d %d %d" % w for w in walls] + ["usemtl Lamp", "f 9 10 11 12"]
    path = os.path.join(folder, "room.obj")
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def check_scene_files(scene_reader):
    """File -> Open: an OBJ with an emissive material through the three filters, and the
    reader factory choosing the plugin's reader for an IFC (which only it reads)."""
    mesher = RadiosityMesher(Input=scene_reader, PatchSize=1.0, ElementSize=0.5)
    solver = LightTaggedRadiosity(Input=mesher, ConvergenceThreshold=1e-3)
    relit = servermanager.Fetch(RadiosityRelight(Input=solver))
    names = relit.GetFieldData().GetAbstractArray("LightNames")
    values = numpy_support.vtk_to_numpy(relit.GetCellData().GetArray("Radiosity"))
    check(names is not None and names.GetValue(0) == "Lamp" and values.max() > 0,
          "an OBJ read by the plugin's reader solves and relights (light 'Lamp')")
    # A method's setting by name, as ParaView sends it (name, value rows): said unused
    # where another method runs.
    by_name = LightTaggedRadiosity(Input=mesher, SolverMethod="Hierarchical",
                                   MethodSettings=["ClusterMemoryLimit", "1e9"])
    listed = servermanager.Fetch(by_name).GetFieldData().GetAbstractArray("Warnings")
    said = [listed.GetValue(i) for i in range(listed.GetNumberOfValues())] if listed else []
    check(any("ClusterMemoryLimit 1e+09 was not used" in w for w in said),
          f"MethodSettings reaches SetMethodSetting: {said}")
    glb = os.path.join(tempfile.mkdtemp(), "room.glb")
    SaveData(glb, proxy=RadiosityRelight(Input=solver))
    head = open(glb, "rb").read(4096) if os.path.exists(glb) else b""
    check(head[:4] == b"glTF" and b"_RADIOSITY_LAMP" in head,
          "File > Save Data as .glb writes the relightable glTF (a _RADIOSITY_LAMP attribute)")
    ifc = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc"
    opened = OpenDataFile(ifc)
    check(opened is not None and opened.GetXMLName() == "RadiositySceneReader",
          "File > Open of an IFC picks the plugin's reader (%s)" % (opened.GetXMLName() if opened else None))


def make_pipeline(data_path):
    """The Cornell box meshed, solved and relit (one light set by LightSettings), and the
    plugin's reader on an OBJ; the settings table checked against these proxies."""
    reader = XMLPolyDataReader(registrationName="cornell_box.vtp", FileName=[data_path])
    mesher = RadiosityMesher(registrationName="Mesher", Input=reader)
    mesher.PatchSize = 100.0   # Cornell box is in millimetres
    mesher.ElementSize = 50.0
    solver = LightTaggedRadiosity(registrationName="Solver", Input=mesher)
    solver.MaximumShots = 200
    mode = solver.GetProperty("SolutionMode").GetData()
    check(mode == "LightTagged", "default SolutionMode is %r, expected 'LightTagged'" % (mode,))
    relight = RadiosityRelight(registrationName="Relight", Input=solver)
    scene_reader = RadiositySceneReader(FileName=write_room_obj())
    check_setting_names(os.path.join(os.path.dirname(os.path.abspath(data_path)), "..", "docs", "settings.md"),
                       (scene_reader, MarkLights(Input=scene_reader), mesher, solver, relight))
    # One row of the repeatable string-vector property:
    # Name, Red, Green, Blue, Intensity, Enabled (all passed as strings).
    relight.LightSettings = [LIGHT] + [repr(float(c)) for c in COLOR] + [
        repr(float(INTENSITY)), str(int(ENABLED))]
    check(len(relight.LightSettings) == 6,
          "LightSettings has %d elements, expected 6" % len(relight.LightSettings))

    UpdatePipeline(proxy=relight)
    return reader, mesher, solver, relight, scene_reader


def check_information(relight):
    """The information properties: the lights' names and the settings in effect."""
    relight.UpdatePipelineInformation()  # pulls the information_only properties
    names = list(relight.LightNamesInfo)  # one element per light, not a joined string
    check(LIGHT in names, "LightNamesInfo is %r, expected it to list '%s'" % (names, LIGHT))
    n_lights = relight.GetProperty("NumberOfLights").GetElement(0)
    check(n_lights == len(names),
          "NumberOfLights is %d but LightNamesInfo lists %d names" % (n_lights, len(names)))
    # The settings in effect read back, defaults included: ours for LIGHT, the filter's
    # (the solver's default color split into a hue and an intensity, on) for any other light.
    effective = list(relight.LightSettingsInfo)
    rows = {effective[i]: effective[i + 1:i + 6] for i in range(0, len(effective), 6)}
    check(sorted(rows) == sorted(names), "LightSettingsInfo has rows for %s, expected %s" % (sorted(rows), names))
    ours = [float(v) for v in rows.get(LIGHT, ["nan"] * 5)]
    check(np.allclose(ours, list(COLOR) + [INTENSITY, ENABLED]),
          "LightSettingsInfo reads back %s for %s, expected what was set" % (ours, LIGHT))
    relight.GetProperty("LightSettings").SMProperty.ResetToDomainDefaults()
    check(list(relight.LightSettings) == effective,
          "LightSettings reset to the settings in effect reads %s" % list(relight.LightSettings))
    return names


def check_settings_read_back(solver, relight):
    """A new relight filter reads the data's lights back without taking them as settings."""
    # A script reads the data's lights back after the first update, as a reader's
    # arrays; they are not sent back as settings (which would pin today's defaults and
    # modify the filter), and a setting of the user's is kept.
    unset = RadiosityRelight(Input=solver)
    check(list(unset.LightSettings) == [], "a new relight filter holds settings %s" % list(unset.LightSettings))
    UpdatePipeline(proxy=unset)
    stamp = unset.GetClientSideObject().GetMTime()
    unset.UpdatePropertyInformation()
    check(len(unset.LightSettings) == 6 and list(unset.LightSettings) == list(unset.LightSettingsInfo),
          "after an update LightSettings reads %s, the data's lights are %s"
          % (list(unset.LightSettings), list(unset.LightSettingsInfo)))
    UpdatePipeline(proxy=unset)
    check(unset.GetClientSideObject().GetMTime() == stamp, "reading the lights back modified the filter")
    unset.Exposure = 2.0  # another property pushed: the copy must not go with it
    UpdatePipeline(proxy=unset)
    unset.UpdatePropertyInformation()
    check(unset.NumberOfLightSettings == 0, "the copy reached the filter as %d settings of its own"
          % unset.NumberOfLightSettings)
    # A state file keeps what the user set, not the copy (it would come back as settings).
    state = os.path.join(tempfile.mkdtemp(), "relight.pvsm")
    SaveState(state)
    saved = [p for p in ET.parse(state).getroot().iter("Property") if p.get("name") == "LightSettings"
             and p.get("id", "").startswith(unset.GetGlobalIDAsString() + ".")]
    values = [e.get("value") for p in saved for e in p.iter("Element")]
    check(len(saved) == 1 and not values, "the state file holds the copied lights: %s" % values)
    Delete(unset)
    check(len(relight.LightSettings) == 6 and float(relight.LightSettings[4]) == INTENSITY,
          "the user's setting reads back %s after updates" % list(relight.LightSettings))


def check_sizes_in_script(data_path):
    """A mesher on a reader that has not run meshes at the sizes the GUI would suggest."""
    # Sizes that follow the scene in a script too: a mesher on a reader that has not
    # run keeps 0 and meshes at the sizes the GUI would suggest (100 and 25 mm).
    fresh = XMLPolyDataReader(FileName=[data_path])
    unsized = RadiosityMesher(Input=fresh)
    meshed = servermanager.Fetch(unsized)
    used = [meshed.GetFieldData().GetArray(name).GetValue(0) for name in ("MesherPatchSize", "MesherElementSize")]
    check([unsized.PatchSize, unsized.ElementSize] == [0.0, 0.0] and used == [100.0, 25.0],
          "a mesher on a reader that has not run meshes at %s (properties %s, %s); expected 100, 25 mm"
          % (used, unsized.PatchSize, unsized.ElementSize))
    # ...and after the update the script reads what was suggested and what was used.
    unsized.UpdatePropertyInformation()
    check([unsized.SuggestedPatchSize, unsized.SuggestedElementSize, unsized.MesherPatchSize,
           unsized.MesherElementSize] == [100.0, 25.0, 100.0, 25.0] and unsized.SuggestedElements > 0,
          "after an update the mesher reads suggested %s, %s (%s elements), used %s, %s; expected 100, 25 mm"
          % (unsized.SuggestedPatchSize, unsized.SuggestedElementSize, unsized.SuggestedElements,
             unsized.MesherPatchSize, unsized.MesherElementSize))
    for proxy in (unsized, fresh):
        Delete(proxy)


def check_suggested_sizes(reader):
    """A mesher added to an executed input starts from sizes that follow the scene."""
    # Sizes that follow the scene: a mesher added to an executed input starts from
    # them (the Cornell box is about 556 mm wide: diagonal 962, a sixth rounded to 100).
    reader.UpdatePipeline()
    suggested = RadiosityMesher(Input=reader)
    check(suggested.PatchSize == 100.0 and suggested.ElementSize == 25.0,
          "a mesher on the Cornell box (mm) starts at PatchSize %g, ElementSize %g; expected 100, 25"
          % (suggested.PatchSize, suggested.ElementSize))
    sizes = CellSize(Input=reader, ComputeArea=1, ComputeLength=0, ComputeVolume=0, ComputeVertexCount=0)
    area = numpy_support.vtk_to_numpy(servermanager.Fetch(sizes).GetCellData().GetArray("Area")).sum()
    Delete(sizes)
    check(abs(suggested.InputArea - area) < 1e-6 * area,
          "InputArea is %g mm², vtkCellSizeFilter sums %g" % (suggested.InputArea, area))
    mesh = RadiosityMesher(Input=reader, PatchSize=100.0, ElementSize=25.0)
    elements = servermanager.Fetch(mesh).GetNumberOfCells()
    Delete(mesh)
    check(0.5 * elements < suggested.SuggestedElements < 1.5 * elements,  # an estimate before meshing
          "SuggestedElements is %g, the mesher makes %d" % (suggested.SuggestedElements, elements))
    print("Cornell box suggestion: PatchSize %g, ElementSize %g, about %d elements (meshed: %d) over %.3g mm²"
          % (suggested.PatchSize, suggested.ElementSize, suggested.SuggestedElements, elements, suggested.InputArea))
    Delete(suggested)


def check_schedule(solver):
    """A light schedule makes the relight filter time-aware."""
    schedule = RadiosityRelight(Input=solver)
    schedule.ScheduleEntries = ["0", LIGHT, "1", "1", "1", "1", "1", "4", LIGHT, "1", "0", "0", "2", "1"]
    schedule.UpdatePipelineInformation()
    check(list(schedule.TimestepValues) == [0.0, 4.0],
          "schedule time steps are %r, expected [0, 4]" % (list(schedule.TimestepValues),))
    schedule.UpdatePipeline(2.0)
    Delete(schedule)


def check_moving_light(mesher):
    """A moving light through the relight filter's second input."""
    basis_solver = LightTaggedRadiosity(Input=mesher, PatchBasis=1, MaximumShots=200)
    lamp = PointSource(Center=[278.0, 400.0, 280.0], NumberOfPoints=1, Radius=0.0)
    moving = RadiosityRelight(Input=basis_solver, MovingLights=lamp)
    moving.LightSettings = [LIGHT, "1", "1", "1", "1", "0"]  # the ceiling lamp off
    moving.UpdatePipeline()
    moved = servermanager.Fetch(moving).GetCellData().GetArray("Radiosity")
    check(moved is not None and moved.GetRange(0)[1] > 0,
          "a moving light on the second input lights the scene with the ceiling lamp off")
    for proxy in (moving, lamp, basis_solver):
        Delete(proxy)


def check_results(solver, relight):
    """The fetched outputs: arrays, finite values, the relighting arithmetic, lit elements."""
    solved = servermanager.Fetch(solver)
    relit = servermanager.Fetch(relight)
    check(solved is not None and solved.IsA("vtkPolyData"), "solver output is not vtkPolyData")
    check(relit is not None and relit.IsA("vtkPolyData"), "relight output is not vtkPolyData")
    check(solved.GetNumberOfCells() > 0, "solver output has no cells")
    history = servermanager.Fetch(solver, idx=1)  # the convergence table, for a line chart
    check(history is not None and history.IsA("vtkTable") and history.GetNumberOfRows() > 0
          and history.GetColumnByName("Remaining_" + LIGHT) is not None,
          "solver port 1 is not the convergence table")
    check(relit.GetNumberOfCells() == solved.GetNumberOfCells(),
          "relight output has %d cells, solver output %d"
          % (relit.GetNumberOfCells(), solved.GetNumberOfCells()))
    check(relit.GetNumberOfPoints() == solved.GetNumberOfPoints(),
          "relight output has %d points, solver output %d"
          % (relit.GetNumberOfPoints(), solved.GetNumberOfPoints()))

    per_light = "Radiosity_" + LIGHT
    get_array(solved.GetPointData(), per_light, "solver point data", solved.GetNumberOfPoints())
    solved_cells = get_array(solved.GetCellData(), per_light, "solver cell data",
                             solved.GetNumberOfCells())

    for kind, attributes, count in (("point", relit.GetPointData(), relit.GetNumberOfPoints()),
                                    ("cell", relit.GetCellData(), relit.GetNumberOfCells())):
        where = "relight %s data" % kind
        get_array(attributes, "Radiosity", where, count)
        colors = get_array(attributes, "DisplayColors", where, count)
        check(colors.GetDataType() == VTK_UNSIGNED_CHAR,
              "%s: DisplayColors is %s, expected unsigned char"
              % (where, colors.GetDataTypeAsString()))

    check_finite(solved, "solver output")
    check_finite(relit, "relight output")

    # --- relighting arithmetic --------------------------------------------
    base = numpy_support.vtk_to_numpy(solved_cells).astype(np.float64)
    relit_cells = numpy_support.vtk_to_numpy(
        relit.GetCellData().GetArray("Radiosity")).astype(np.float64)
    expected = base * (np.asarray(COLOR, dtype=np.float64) * INTENSITY)[np.newaxis, :]
    scale = max(float(np.max(np.abs(expected))), 1e-300)
    error = np.abs(relit_cells - expected)
    allowed = REL_TOL * np.abs(expected) + 1e-12 * scale
    bad = np.nonzero(np.any(error > allowed, axis=1))[0]
    check(bad.size == 0,
          "relit cell Radiosity != color * intensity * %s at %d cells; first: cell %d "
          "relit %s expected %s" % (per_light, bad.size, bad[0] if bad.size else -1,
                                    relit_cells[bad[0]] if bad.size else None,
                                    expected[bad[0]] if bad.size else None))

    # Mean over the element cells that are not lights (all cells if LightId
    # was not passed through): light must have reached the room.
    light_id = relit.GetCellData().GetArray("LightId")
    mask = np.ones(relit.GetNumberOfCells(), dtype=bool)
    if light_id is not None:
        mask = numpy_support.vtk_to_numpy(light_id).reshape(-1) < 0
        check(np.any(mask), "no non-light cells in the relight output")
    mean = float(np.mean(relit_cells[mask]))
    check(math.isfinite(mean) and mean > 0.0,
          "mean relit Radiosity of the element cells is %r, expected > 0" % mean)
    return relit, mean


def check_render(solver, relight, relit, screenshot):
    """Show() gives the relit pictures; a failed solve."""
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = [600, 600]
    view.OrientationAxesVisibility = 0
    # The solver's output shows relit, as in the GUI (the filter's RepresentationType hint).
    solved_display = Show(solver, view)
    check(solved_display.Representation == "Relit Surface",
          "Show(solver) in pvbatch is '%s', not the relit picture ('Relit Surface')" % solved_display.Representation)
    check_relit_schedule(view, solved_display)
    Hide(solver, view)
    display = Show(relight, view)
    check(display.Representation == "Relit Colors",
          "Show(relight) in pvbatch is '%s', not the filter's colors ('Relit Colors')" % display.Representation)
    bounds = relit.GetBounds()
    centre = [0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
              0.5 * (bounds[4] + bounds[5])]
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4])
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1], bounds[4] - 2.0 * size]  # open side, z = min
    view.CameraViewUp = [0.0, 1.0, 0.0]
    view.ResetCamera()
    shown = grab(view)
    # The same colors the long way: a plain surface colored by DisplayColors as they are.
    display.Representation = "Surface"
    ColorBy(display, ("POINTS", "DisplayColors"))
    display.MapScalars = 0  # show the sRGB DisplayColors as they are
    display.Ambient = 1.0   # radiosity is view independent: no extra shading
    display.Diffuse = 0.0
    display.SetScalarBarVisibility(view, False)
    by_hand = grab(view)
    difference = np.abs(shown - by_hand).mean()
    check(shown.max() > 50 and difference < 0.5,
          "Show(relight) differs from DisplayColors shown as they are by %.3g (of 255) on average" % difference)
    print("Show(relight): 'Relit Colors', %.3g of 255 from DisplayColors shown by hand (brightest %d)"
          % (difference, shown.max()))
    if screenshot:
        SaveScreenshot(screenshot, view, ImageResolution=[600, 600])
    check_failed_solve(view, solver, display)
    # Release the view before the interpreter exits: with an X/GLX build,
    # a render window still alive at exit can abort with GLXBadContext.
    Delete(display)
    Delete(view)
    del display, view


def check_method_settings_in_state(data_path):
    """A state file keeps a solver's settings by name, and loading it gives them to the
    solver again (said unused where another method runs, as when first set)."""
    reader = XMLPolyDataReader(FileName=[data_path])
    mesher = RadiosityMesher(Input=reader, PatchSize=200.0, ElementSize=100.0)
    LightTaggedRadiosity(registrationName="ByName", Input=mesher, SolverMethod="Hierarchical",
                         MethodSettings=["ClusterMemoryLimit", "2e9"])
    state = os.path.join(tempfile.mkdtemp(), "method_settings.pvsm")
    SaveState(state)
    ResetSession()
    LoadState(state)
    loaded = FindSource("ByName")
    rows = [str(v) for v in loaded.MethodSettings] if loaded else []
    check(rows == ["ClusterMemoryLimit", "2e9"] or rows == ["ClusterMemoryLimit", "2000000000"],
          f"MethodSettings from the state file: {rows}")
    listed = servermanager.Fetch(loaded).GetFieldData().GetAbstractArray("Warnings")
    said = [listed.GetValue(i) for i in range(listed.GetNumberOfValues())] if listed else []
    check(any("ClusterMemoryLimit 2e+09 was not used" in w for w in said),
          f"the loaded solver has the setting by name: {said}")


def main(argv):
    if len(argv) < 3:
        print("usage: pvbatch %s <plugin.so> <cornell_box.vtp> [screenshot.png]" % argv[0])
        return 2
    plugin_path, data_path = argv[1], argv[2]
    screenshot = argv[3] if len(argv) > 3 else None
    LoadPlugin(plugin_path, ns=globals())
    for name in ("RadiosityMesher", "LightTaggedRadiosity", "RadiosityRelight"):
        check(name in globals(), "plugin did not provide the filter '%s'" % name)
    reader, mesher, solver, relight, scene_reader = make_pipeline(data_path)
    names = check_information(relight)
    check_settings_read_back(solver, relight)
    check_sizes_in_script(data_path)
    check_suggested_sizes(reader)
    check_schedule(solver)
    check_moving_light(mesher)
    relit, mean = check_results(solver, relight)
    check_render(solver, relight, relit, screenshot)
    check_scene_files(scene_reader)
    check_method_settings_in_state(data_path)  # last: it resets the session
    print("TestPluginProxies passed: %d elements, %d points, light(s) %s, "
          "mean relit radiosity %.6g" % (relit.GetNumberOfCells(), relit.GetNumberOfPoints(),
                                         ";".join(names), mean))
    return 0


if __name__ == "__main__":
    try:
        status = main(sys.argv)
    except TestFailure as failure:
        print("TestPluginProxies FAILED: %s" % failure)
        status = 1
    except Exception:
        import traceback
        traceback.print_exc()
        print("TestPluginProxies FAILED with an exception")
        status = 1
    sys.stdout.flush()
    if status != 0:
        sys.exit(status)
    # On success just end the script: pvbatch then exits with status 0.

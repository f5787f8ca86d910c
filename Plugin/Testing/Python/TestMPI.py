"""ParaView's MPI server: 2 ranks of pvbatch mesh, solve and relight the paper
scene, as read (all on rank 0; rank 1 holds no cells) and spread over both ranks by
RedistributeDataSet. Each must give the serial answer: the same mesh gives the same
radiosity to 1e-6, a mesh cut differently by the pieces within 1 % at every element's
centre; no rank reports an error. The work is divided: each rank receives for about half
of the elements, whichever rank holds them."""

import os
import re
import shutil
import sys
import subprocess
import tempfile

import numpy as np
from vtkmodules.vtkCommonCore import vtkLogger
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

import relight
from relight import cell_array, cell_centroids, light_names, point_array, read_polydata
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Testing", "Python"))
from testlib import check, finish  # noqa: E402  (the tests' shared helpers)

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
ROOT = os.environ.get("RELIGHT_ROOT", ".")
SCENE = os.path.join(ROOT, "Data", "paper_3lights.vtp")
PLUGIN_DIR = os.environ["RELIGHT_PLUGIN_DIR"]
folder = tempfile.mkdtemp()


def parallel_run(mode, ranks=2, extra=(), scene=SCENE):
    out = os.path.join(folder, f"{mode}.vtp")
    env = dict(os.environ, PV_PLUGIN_PATH=PLUGIN_DIR)
    # A hang (a rank left waiting in a collective) fails by the timeout.
    run = subprocess.run([shutil.which("mpiexec"), "--allow-run-as-root", "--oversubscribe", "-np", str(ranks),
                          "pvbatch", "--mpi", os.path.join(os.path.dirname(os.path.abspath(__file__)), "mpi_solve.py"), scene, out, mode, *extra],
                         capture_output=True, text=True, env=env, timeout=300)
    errors = [line for line in (run.stdout + run.stderr).splitlines() if "ERR|" in line or "Traceback" in line]
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(out)
    reader.Update()
    parallel_run.log = run.stdout + run.stderr
    return reader.GetOutput(), errors, run.returncode


def shares(log):
    """{rank: (elements it received for, elements in all)} from the solver's log lines"""
    found = re.findall(r"rank (\d+) of \d+ received for (\d+) of (\d+) elements", log)
    return {int(r): (int(mine), int(total)) for r, mine, total in found}


def by_centre(data, name):
    """{rounded element centre: its radiosity}"""
    centres = np.round(cell_centroids(data), 6)
    values = cell_array(data, name)
    return {tuple(c): v for c, v in zip(centres, values)}


def serial_run(gather_rays):
    """Progressive refinement on one process, as mpi_solve.py solves (its .glb and .exr too)."""
    solver = relight.solve(read_polydata(SCENE), 1.0, 0.5, ConvergenceThreshold=1e-4, MaximumShots=0,
                           SolverMethod=relight.vtkLightTaggedRadiosity.PROGRESSIVE_REFINEMENT,
                           GatherRays=gather_rays)
    serial = relight.vtkRadiosityRelight()
    serial.SetInputConnection(solver.GetOutputPort())
    serial.Update()
    glb, exr = os.path.join(folder, f"serial{gather_rays}.glb"), os.path.join(folder, f"serial{gather_rays}.exr")
    relight.write_gltf(serial.GetOutput(), glb, exposure=2.0)
    relight.write_exr(serial.GetOutput(), exr, ((2, 1.2, 9), (2, 1.2, 2), (0, 1, 0), 40), size=(160, 120),
                      light_layers=True)
    return serial.GetOutput(), glb, exr


# The whole scene on two ranks is the serial answer, final gather included. Redistributed,
# the pieces mesh a little differently, and the gather would sample other points of another
# mesh: that run holds the element solution (GatherRays 0, see mpi_solve.py) to the serial one.
for mode, tolerance in (("whole", 1e-6), ("redistributed", 1e-2)):
    reference, glb, exr = serial_run(64 if mode == "whole" else 0)
    names = light_names(reference)
    result, errors, code = parallel_run(mode)
    check(code == 0 and not errors, f"{mode}: 2 ranks finish with no error ({code}; {errors[:2]})")
    ranks = point_array(result, "ProcessId").astype(int).ravel() if result.GetNumberOfPoints() else np.array([])
    per_rank = [int((ranks == r).sum()) for r in range(2)]
    spread = per_rank[1] == 0 if mode == "whole" else min(per_rank) > 0
    check(spread, f"{mode}: points per rank {per_rank}")
    share = shares(parallel_run.log)
    total = result.GetNumberOfCells()
    check(sorted(share) == [0, 1] and sum(m for m, _ in share.values()) == total
          and all(abs(m - total / 2) <= 0.05 * total and t == total for m, t in share.values()),
          f"{mode}: each rank received for its half of the {total} elements: {share}")
    check(light_names(result) == names if result.GetNumberOfCells() else False, f"{mode}: the lights are {names}")
    worst = 0.0
    for name in ["Radiosity"] + ["Radiosity_" + n for n in names]:
        mine, theirs = by_centre(result, name), by_centre(reference, name)
        common = [c for c in theirs if c in mine]
        scale = max(np.abs(v).max() for v in theirs.values())
        worst = max([worst] + [np.abs(mine[c] - theirs[c]).max() / scale for c in common])
        check(len(common) >= 0.9 * len(theirs), f"{mode}: {len(common)} of {len(theirs)} elements found at the serial centres ({name})")
    check(worst <= tolerance, f"{mode}: largest difference from the serial run {worst:.2e} of the peak (at most {tolerance:g})")
    # The writers gather every piece on rank 0: the same file as one process writes.
    out = os.path.join(folder, f"{mode}.vtp")
    if mode == "whole":
        check(open(out + ".glb", "rb").read() == open(glb, "rb").read(), "whole: the .glb equals one process's, byte for byte")
    else:
        check(os.path.getsize(out + ".glb") > 0.9 * os.path.getsize(glb), "redistributed: the .glb holds the whole scene")
    for layer in ["", *names]:
        ours, theirs = relight.read_exr(out + ".exr", layer), relight.read_exr(exr, layer)
        difference = np.abs(ours - theirs).mean() / theirs.mean()
        check(difference <= (1e-6 if mode == "whole" else 1e-2),
              f"{mode}: the .exr layer '{layer}' is within {difference:.1e} of one process's (mean)")

# Moving lights and a dynamic object on a spread scene: every rank relights its piece with
# the whole scene's occluders and the basis of all patches, as one process does.
movers = relight.point_lights([(1.0, 1.2, 2.0), (3.0, 1.0, 1.0)], intensity=3.0, color=(1.0, 0.8, 0.6))
blocker = relight.make_scene([[(0.7, 0.6, 1.7), (1.3, 0.6, 1.7), (1.3, 0.6, 2.3), (0.7, 0.6, 2.3)]], [(0.5, 0.5, 0.5)], [-1])
files = [os.path.join(folder, name) for name in ("movers.vtp", "blocker.vtp")]
for data, path in zip((movers, blocker), files):
    writer = vtkXMLPolyDataWriter()
    writer.SetInputData(data)
    writer.SetFileName(path)
    writer.Write()
basis = relight.solve(read_polydata(SCENE), 1.0, 0.5, ConvergenceThreshold=1e-4, MaximumShots=0, PatchBasis=True,
                      SolverMethod=relight.vtkLightTaggedRadiosity.PROGRESSIVE_REFINEMENT)
moving = relight.vtkRadiosityRelight()
moving.SetInputConnection(0, basis.GetOutputPort())
moving.SetInputData(1, movers)
moving.SetInputData(2, blocker)
moving.Update()
still = serial_run(64)[0]
for mode, tolerance in (("moving-whole", 1e-6), ("moving", 1e-2)):
    result, errors, code = parallel_run(mode, extra=files)
    check(code == 0 and not errors, f"{mode}: 2 ranks finish with no error ({code}; {errors[:2]})")
    mine, theirs, without = (by_centre(d, "Radiosity") for d in (result, moving.GetOutput(), still))
    common = [c for c in theirs if c in mine]
    scale = max(np.abs(v).max() for v in theirs.values())
    worst = max(np.abs(mine[c] - theirs[c]).max() / scale for c in common) if common else 1.0
    lit = max(np.abs(theirs[c] - without[c]).max() / scale for c in common) if common else 0.0
    check(len(common) >= 0.9 * len(theirs) and worst <= tolerance < lit,
          f"{mode}: relit with moving lights and a blocker within {worst:.2e} of one process (at most {tolerance:g}) "
          f"at {len(common)} elements; the moving lights change it by {lit:.2f} of the peak")

# MaximumElements bounds the whole scene, not each rank's piece: one element size for all.
result, errors, code = parallel_run("budget")
check(code == 0 and 150 <= result.GetNumberOfCells() <= 300,
      f"MaximumElements 300 on 2 ranks: {result.GetNumberOfCells()} elements in all ({errors[:1]})")

# Mark Lights before the mesher: an empty piece passes through, and a failure on rank 0
# fails every rank (each returns 0, so none runs the mesher's collectives, where the other
# would wait for ever).
result, errors, code = parallel_run("marked")
check(code == 0 and not errors and "Desk" in light_names(result), f"Mark Lights on 2 ranks: lights {light_names(result)}, errors {errors[:1]}")
result, errors, code = parallel_run("broken")
stopped = [e for e in errors if "LightMarker" in e and "returned failure" in e]
check(result.GetNumberOfCells() == 0 and any("MaterialPattern needs" in e for e in errors) and len(stopped) == 2,
      f"a Mark Lights error on rank 0 ends the run on both ranks: {[e[-90:] for e in errors][:3]}")
# The plugin's reader runs on rank 0 alone (a file is not split into pieces): a file it
# cannot read fails the mesher on every rank, none left waiting in its collectives.
result, errors, code = parallel_run("unreadable")
check(result.GetNumberOfCells() == 0 and any("Cannot import" in e for e in errors)
      and any("Cannot mesh" in e for e in errors),
      f"an unreadable file on 2 ranks ends the run on both: {[e[-80:] for e in errors][:3]}")
# Float points of a scene in two parts, one room at the origin and one 50 km away (a site
# model): the ranks mesh with the float noise of the whole scene, not each of its own piece
# (the piece at the origin took its noise for 1e4 times finer; the solver then used the
# first piece's).
from vtkmodules.vtkFiltersCore import vtkAppendPolyData  # noqa: E402
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter  # noqa: E402
from vtkmodules.vtkCommonTransforms import vtkTransform  # noqa: E402


def write_pieces(name, datasets):
    """A parallel file of one piece per dataset (a rank each, as a .pvtp gives them)."""
    pieces, declared = [], []
    for n, data in enumerate(datasets):
        pieces.append(os.path.join(folder, f"{name}_{n}.vtp"))
        writer = vtkXMLPolyDataWriter()
        writer.SetInputData(data)
        writer.SetFileName(pieces[-1])
        writer.SetDataModeToAscii()
        writer.Write()
    cells = datasets[0].GetCellData()
    for i in range(cells.GetNumberOfArrays()):
        array = cells.GetAbstractArray(i)
        declared.append(f'<PDataArray type="{array.GetDataTypeAsString().replace("double", "Float64").replace("float", "Float32").replace("int", "Int32")}" '
                        f'Name="{array.GetName()}" NumberOfComponents="{array.GetNumberOfComponents()}"/>')
    kind = "Float32" if datasets[-1].GetPoints().GetDataType() == 10 else "Float64"
    path = os.path.join(folder, f"{name}.pvtp")
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="PPolyData" version="0.1" byte_order="LittleEndian">\n'
                f'<PPolyData GhostLevel="0">\n<PPoints><PDataArray type="{kind}" NumberOfComponents="3"/></PPoints>\n'
                f'<PCellData>{"".join(declared)}</PCellData>\n'
                + "".join(f'<Piece Source="{os.path.basename(p)}"/>\n' for p in pieces) + "</PPolyData>\n</VTKFile>\n")
    return path, pieces


room, moved_rooms = read_polydata(SCENE), []
for shift in (0.0, 5e4):
    move = vtkTransform()
    move.Translate(shift, 0.0, 0.0)
    moved = vtkTransformPolyDataFilter()
    moved.SetTransform(move)
    moved.SetInputData(room)
    moved.SetOutputPointsPrecision(0)  # float (SINGLE_PRECISION), as most files give
    moved.Update()
    moved_rooms.append(moved.GetOutput())
far, pieces = write_pieces("far", moved_rooms)
whole = vtkAppendPolyData()
for path in pieces:
    whole.AddInputData(read_polydata(path))
whole.Update()
alone = relight.solve(whole.GetOutput(), 1.0, 0.5).GetOutput()
for mode in ("pieces", "redistributed"):  # a piece per rank as read, and spread by RedistributeDataSet
    result, errors, code = parallel_run(mode, scene=far)
    quanta = [d.GetFieldData().GetArray("PointQuantum").GetValue(0) if d.GetFieldData().GetArray("PointQuantum") else None
              for d in (result, alone)]
    ranks = point_array(result, "ProcessId").astype(int).ravel() if result.GetNumberOfPoints() else np.array([])
    check(code == 0 and not errors and len(set(ranks.tolist())) == 2 and quanta[0] == quanta[1] and quanta[1] > 1e-3,
          f"a float scene 50 km wide on 2 ranks ({mode}): the float noise of the whole, {quanta[0]}, as one process "
          f"({quanta[1]}); errors {errors[:1]}")

# Coincident copies on another rank (the floor, a box top and a lamp of the room, doubled in
# a second piece, as merged exports give them): left out as one process leaves them, where
# each rank alone kept its copy, lit it fully and created energy (a second lamp, doubled
# light). The result equals the serial run of the two pieces appended.
from vtkmodules.vtkFiltersCore import vtkExtractCells  # noqa: E402
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter  # noqa: E402
from vtkmodules.vtkCommonCore import vtkIdList as _IdList  # noqa: E402
copied = vtkExtractCells()
copied.SetInputData(room)
ids = _IdList()
for cell in (0, 7, 12):
    ids.InsertNextId(cell)
copied.SetCellList(ids)
surface = vtkGeometryFilter()
surface.SetInputConnection(copied.GetOutputPort())
surface.Update()
extra = surface.GetOutput().GetCellData()
for name in [extra.GetArrayName(i) for i in range(extra.GetNumberOfArrays())]:
    if not room.GetCellData().HasArray(name):
        extra.RemoveArray(name)  # the ids vtkExtractCells adds: the pieces must declare the same arrays
doubled, pieces = write_pieces("doubled", [room, surface.GetOutput()])
whole = vtkAppendPolyData()
for path in pieces:
    whole.AddInputData(read_polydata(path))
whole.Update()
alone = relight.solve(whole.GetOutput(), 1.0, 0.5, ConvergenceThreshold=1e-4, MaximumShots=0,
                      SolverMethod=relight.vtkLightTaggedRadiosity.PROGRESSIVE_REFINEMENT)
single = relight.vtkRadiosityRelight()
single.SetInputConnection(alone.GetOutputPort())
single.Update()
result, errors, code = parallel_run("pieces", scene=doubled)
mine, theirs = by_centre(result, "Radiosity"), by_centre(single.GetOutput(), "Radiosity")
common = [c for c in theirs if c in mine]
scale = max(np.abs(v).max() for v in theirs.values())
worst = max(np.abs(mine[c] - theirs[c]).max() / scale for c in common) if common else 1.0
field = result.GetFieldData().GetAbstractArray("Warnings")
listed = [field.GetValue(i) for i in range(field.GetNumberOfValues())] if field else []
# Said by rank 1, which holds the copies, and listed on the output the client shows (rank 0's).
said = "3 cells repeat another cell's corners" in parallel_run.log and any("3 cells repeat" in w for w in listed)
check(code == 0 and not errors and result.GetNumberOfCells() == single.GetOutput().GetNumberOfCells()
      and len(common) == len(theirs) and worst <= 1e-6 and said,
      f"copies on another rank: {result.GetNumberOfCells()} elements (one process {single.GetOutput().GetNumberOfCells()}), "
      f"largest difference {worst:.1e} of the peak, copies said {said}; errors {errors[:1]}")
finish("TestMPI")

"""./relight bench peers: our solver against the tool a user would pick instead, Blender
Cycles baking each light's diffuse lighting to point colors, on the same mesh, both
judged against a Mitsuba 3 reference at probe points.

A scene is a JSON of polygons, lights and probes with its Mitsuba reference: the furnished
room of `./relight bench scale` (66 polygons, 8 lamps; `ScaleBench --export`), and four
tessellated spheres in a room (`PolygonsBench --export`: a curved scene of many small
triangles). It is meshed once by vtkRadiosityMesher (--element, --patch). k = 1, 3, 8
lights are the first k lamps; the other lamps stay as plain reflectors, as in the
reference. Ours: mesh + solve, one child process per k (so its peak memory is its own),
at the common element size and at --element-sizes (our own error against time). Cycles:
blender_bake.py in the bench-only venv bakes every lamp alone at each sample count on
exactly our points of the common mesh; the time for k lights is the sum of the first k
bakes (light groups do not apply to baking).

Both methods' point values are taken to a probe the same way: interpolated in the mesh
cell that holds the probe and faces its way. Error, as in ScaleBench: per light,
sum |B - B_ref| / sum B_ref over the probes (B the sum of R, G, B), averaged over the k
lights. Times are process CPU seconds / 2 (the 2-core machine's time when quiet)
with wall seconds beside them.

Writes NAME.csv (every run), NAME.txt (the tables) and NAME.png in --out
(`--report-only` writes the last two again from NAME.csv).
  --room out/bench/room.json --reference out/bench/room_reference.csv --name peers
  --blender out/blender-venv/bin/python --samples 16,64,256,1024 --ks 1,3,8
  --element 0.15 --element-sizes 0.3,0.075 --patch 0.4 --method Auto
"""

import argparse
import csv
import json
import math
import pathlib
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = pathlib.Path(__file__).resolve().parent
CORES = 2  # times are process CPU seconds / CORES: this machine's time when quiet


# ---------------------------------------------------------------- our side (child process)

def room_scene(room, lights):
    """The room as a relight input scene; lamps from `lights` on are plain reflectors."""
    import relight

    polygons = room["polygons"]
    return relight.make_scene([p["points"] for p in polygons], [p["reflectance"] for p in polygons],
                              [p["light"] if p["light"] < lights else -1 for p in polygons],
                              [f"Lamp{i}" for i in range(lights)])


def relight_seconds(solver, lights, repeats=21):
    """Median wall time of one relight after a light's intensity changes (what a color,
    intensity or on/off change costs once solved)."""
    import relight

    relit = relight.vtkRadiosityRelight()
    relit.SetInputConnection(solver.GetOutputPort())
    relit.Update()
    times = []
    for i in range(repeats):
        relit.SetLightIntensity(i % lights, 1.0 + (i % 2))
        start = time.perf_counter()
        relit.Update()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def solve_ours(args):
    """Child process: mesh + solve the room with the first k lamps; saves the point
    radiosity, the mesh (for Blender and the probes), the times and the peak memory."""
    import relight
    from vtkmodules.util.numpy_support import vtk_to_numpy

    room = json.loads(pathlib.Path(args.room).read_text())
    k = args.solve_only
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(room_scene(room, k))
    mesher.SetPatchSize(args.patch)
    mesher.SetElementSize(args.element)
    mesher.SetLampGrading(0)  # one mesh for every k: the lamps left out would grade it otherwise
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    getattr(solver, "SetSolverMethodTo" + args.method)()
    cpu, wall = time.process_time(), time.perf_counter()
    solver.Update()
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    out = solver.GetOutput()
    polys = out.GetPolys()
    method = out.GetFieldData().GetAbstractArray("SolverMethod").GetValue(0).split(":")[0]
    np.savez(args.mesh_out,
             points=vtk_to_numpy(out.GetPoints().GetData()).astype(float),
             offsets=vtk_to_numpy(polys.GetOffsetsArray()).astype(np.int64),
             connectivity=vtk_to_numpy(polys.GetConnectivityArray()).astype(np.int64),
             reflectance=vtk_to_numpy(out.GetCellData().GetArray("Reflectance")).astype(float),
             light=vtk_to_numpy(out.GetCellData().GetArray("LightId")).astype(np.int64),
             b=np.stack([relight.point_array(out, f"Radiosity_Lamp{j}").astype(float) for j in range(k)]),
             cpu=cpu, wall=wall, relight=relight_seconds(solver, k), method=method,
             peak_rss_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0)


def run_ours(args, k, mesh_path, element):
    """Runs solve_ours for k lights in a child process and loads what it saved."""
    command = [sys.executable, __file__, "--solve-only", str(k), "--mesh-out", str(mesh_path),
               "--room", args.room, "--element", str(element), "--patch", str(args.patch), "--method", args.method]
    subprocess.run(command, check=True)
    return dict(np.load(mesh_path))


# ---------------------------------------------------------------- probes and errors

def read_reference(path, probes, lights):
    """Mitsuba's `probe,light,r,g,b` rows as a (probes, lights) array of R + G + B (NaN
    where it has none)."""
    values = np.full((probes, lights), np.nan)
    with open(path) as f:
        for row in csv.DictReader(f):
            probe, light = int(row["probe"]), int(row["light"])
            if probe < probes and light < lights:
                values[probe, light] = float(row["r"]) + float(row["g"]) + float(row["b"])
    return values


def mesh_polydata(mesh):
    """The saved mesh as a vtkPolyData (points and polygons only)."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData

    data = vtkPolyData()
    points = vtkPoints()
    points.SetData(numpy_to_vtk(mesh["points"], deep=True))
    cells = vtkCellArray()
    cells.SetData(numpy_to_vtkIdTypeArray(mesh["offsets"], deep=True),
                  numpy_to_vtkIdTypeArray(mesh["connectivity"], deep=True))
    data.SetPoints(points)
    data.SetPolys(cells)
    return data


def probe_weights(mesh, probes):
    """Interpolation weights, (point ids, weights), each (probes, 8): each probe's value is the point
    values interpolated in the mesh cell that holds it and faces the probe's way (a
    locator alone may give the back of a touching surface). Rows of probes that no cell
    holds stay zero and are dropped by the caller. (Not a dense probes x points matrix: Linux
    keeps a process's peak memory across exec, so the children started after it would
    report it as theirs.)"""
    from vtkmodules.vtkCommonCore import reference, vtkIdList
    from vtkmodules.vtkCommonDataModel import vtkGenericCell, vtkStaticCellLocator

    data = mesh_polydata(mesh)
    locator = vtkStaticCellLocator()
    locator.SetDataSet(data)
    locator.BuildLocator()
    offsets, connectivity, points = mesh["offsets"], mesh["connectivity"], mesh["points"]
    found, cell, closest, pcoords, w = vtkIdList(), vtkGenericCell(), [0.0] * 3, [0.0] * 3, [0.0] * 8
    sub, dist2 = reference(0), reference(0.0)

    # Every cell's normal at once: numpy's per-call cost made one cross product per
    # candidate cell most of this bench's smoke run (31 of 42 s).
    first = np.asarray(offsets[:-1])
    a, b, c = (points[connectivity[first + k]] for k in range(3))
    normals = np.cross(b - a, c - a)
    normals /= np.maximum(np.linalg.norm(normals, axis=1), 1e-300)[:, None]

    def facing(cell_id, n):
        return float(np.dot(normals[cell_id], n)) > 0.9 * float(np.linalg.norm(n))

    ids, weights = np.zeros((len(probes), 8), np.int64), np.zeros((len(probes), 8))
    for i, probe in enumerate(probes):
        x, n = np.asarray(probe["point"]), np.asarray(probe["normal"])
        locator.FindCellsWithinBounds(list(np.ravel(np.column_stack((x - 1e-4, x + 1e-4)))), found)
        best_distance = 1e-6  # squared: the probe lies on the cell, within 1 mm
        for c in (found.GetId(j) for j in range(found.GetNumberOfIds())):
            if not facing(c, n):
                continue
            data.GetCell(c, cell)
            cell.EvaluatePosition(list(x), closest, sub, pcoords, dist2, w)
            if dist2.get() < best_distance:
                best_distance = dist2.get()
                corners = offsets[c + 1] - offsets[c]
                ids[i], weights[i] = 0, 0
                ids[i, :corners], weights[i, :corners] = connectivity[offsets[c]:offsets[c + 1]], w[:corners]
    return ids, weights


def some_probes(weights, keep):
    """The weights of the probes `keep` selects."""
    return weights[0][keep], weights[1][keep]


def held(weights):
    """The probes a cell holds."""
    return weights[1].sum(axis=1) > 0


def light_errors(values, reference):
    """Per light: sum |B - B_ref| / sum B_ref over the probes (rows) both have."""
    errors = []
    for j in range(values.shape[1]):
        ok = ~np.isnan(reference[:, j])
        judged = ok.any()  # without a reference (the suite's smoke run) nothing is judged
        errors.append(np.abs(values[ok, j] - reference[ok, j]).sum() / reference[ok, j].sum() if judged else np.nan)
    return np.array(errors)


def at_probes(weights, point_values):
    """(lights, points, 3) point radiosity -> (probes, lights) R + G + B at the probes."""
    ids, w = weights
    return np.stack([(b.sum(axis=1)[ids] * w).sum(axis=1) for b in point_values], axis=1)


# ---------------------------------------------------------------- Cycles

def ours_row(solved, k, element, weights, reference):
    """One of our solves as a row of the report (probes no cell of this mesh holds are left
    out of its error)."""
    inside = held(weights)
    errors = light_errors(at_probes(some_probes(weights, inside), solved["b"]), reference[inside, :k])
    row = dict(method="ours", k=k, samples="", element=element, elements=len(solved["offsets"]) - 1,
               time_s=float(solved["cpu"]) / CORES, wall_s=float(solved["wall"]), error_pct=100 * errors.mean(),
               peak_mb=float(solved["peak_rss_mb"]), relight_ms=1e3 * float(solved["relight"]))
    print(f"ours, k = {k}, element {element:g} m ({row['elements']:,} elements, {inside.sum():,} probes): "
          f"{solved['method']}, {row['time_s']:.2f} s ({row['wall_s']:.2f} s wall), {row['error_pct']:.2f} % "
          f"from Mitsuba, {row['peak_mb']:.0f} MB peak, relight {row['relight_ms']:.2f} ms", flush=True)
    return row


def run_cycles(args, mesh_path, lights):
    """blender_bake.py in the bench venv; returns its results (a failed bake ends the bench:
    Blender is installed, so that is a fault to see, not a skip)."""
    out_path = pathlib.Path(mesh_path).with_name("cycles.npz")
    command = [args.blender, str(HERE / "blender_bake.py"), str(mesh_path), str(out_path),
               "--samples", args.samples, "--lights", ",".join(map(str, range(lights))), "--threads", str(CORES)]
    if subprocess.run(command).returncode != 0:
        sys.exit("the Cycles bake failed (its messages are above)")
    return dict(np.load(out_path))


def time_to_reach(times, errors, target):
    """Time at which the error-time curve reaches `target`, interpolated on log-log between
    the two runs around it; beyond the runs, extrapolated along the last two (flagged)."""
    order = np.argsort(times)
    t, e = np.log(np.asarray(times)[order]), np.log(np.asarray(errors)[order])
    goal = math.log(target)
    if goal >= e[0]:
        return math.exp(t[0]), "at most"
    for i in range(len(t) - 1):
        if e[i] >= goal >= e[i + 1]:
            f = (goal - e[i]) / (e[i + 1] - e[i])
            return math.exp(t[i] + f * (t[i + 1] - t[i])), ""
    slope = (e[-1] - e[-2]) / (t[-1] - t[-2])
    if slope >= 0:
        return math.inf, "not reached"
    return math.exp(t[-1] + (goal - e[-1]) / slope), "extrapolated"


# ---------------------------------------------------------------- report

def cycles_runs(cycles, weights, reference, ks, element, elements):
    """Per k and sample count: the 2-core time, wall time and mean error of the first k
    lights' bakes. Returns rows of dicts."""
    bakes = cycles["bakes"]  # rows: samples, light, CPU s, wall s
    rows = []
    for samples in sorted({int(s) for s in bakes[:, 0]}):
        lights = max(ks)
        values = at_probes(weights, [cycles[f"b_{samples}_{j}"] for j in range(lights)])
        errors = light_errors(values, reference[:, :lights])
        for k in ks:
            mine = bakes[(bakes[:, 0] == samples) & (bakes[:, 1] < k)]
            rows.append(dict(method="Cycles", k=k, samples=samples, element=element,
                             elements=elements,
                             time_s=mine[:, 2].sum() / CORES,
                             wall_s=mine[:, 3].sum(), error_pct=100 * errors[:k].mean(),
                             peak_mb=float(cycles["peak_rss_mb"]), relight_ms=""))
    return rows


def summary(ours_rows, cycles_rows, fixed_error, ks):
    """The markdown table of the report: per k, ours, Cycles to our error and to a fixed
    error, memory, and what a moved lamp costs (re-solve against re-bake)."""
    lines = ["| k | ours: time, error | Cycles to our error | ratio | Cycles to "
             f"{fixed_error:g} % | ratio | peak memory ours / Cycles | relight (ours) | a moved lamp: "
             "ours re-solve (all k) / Cycles re-bake (that lamp, at our error) |",
             "|---|---|---|---|---|---|---|---|---|"]
    for k in ks:
        o = next(r for r in ours_rows if r["k"] == k)
        c = [r for r in cycles_rows if r["k"] == k]
        cells = [str(k), f"{o['time_s']:.2f} s, {o['error_pct']:.2f} %"]
        reach = {}
        for target in (o["error_pct"], fixed_error):
            if c:
                t, note = time_to_reach([r["time_s"] for r in c], [r["error_pct"] for r in c], target)
                reach[target] = t
                ratio = f"{t / o['time_s']:.0f}×"
                if o["error_pct"] > target:  # ours would need a finer mesh, so more time
                    ratio = f"at most {ratio} (ours {o['error_pct']:.2f} %)"
                cells += [f"{t:.1f} s{' (' + note + ')' if note else ''}", ratio]
            else:
                cells += ["—", "—"]
        cells.append(f"{o['peak_mb']:.0f} MB / {c[0]['peak_mb']:.0f} MB" if c else f"{o['peak_mb']:.0f} MB / —")
        cells.append(f"{o['relight_ms']:.2f} ms")
        # A moved lamp: ours solves all k lights again (one tagged pass), Cycles bakes that
        # lamp again at the same quality (1/k of its time for k lamps).
        cells.append(f"{o['time_s']:.2f} s / {reach[o['error_pct']] / k:.1f} s" if c else f"{o['time_s']:.2f} s / —")
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines)


def plot(rows, path, ks, fixed_error, title):
    """Error against time, log-log: a line per k for Cycles (labelled with the samples per
    bake), a star per k for ours, and the fixed error of the table dashed."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        from matplotlib.ticker import FuncFormatter, NullFormatter
    except ImportError:
        print("matplotlib missing: no plot")
        return
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    ax.axhline(fixed_error, color="grey", linestyle="--", linewidth=0.8)
    for k, color in zip(ks, ("tab:blue", "tab:orange", "tab:green", "tab:red")):
        c = sorted((r for r in rows if r["method"] == "Cycles" and r["k"] == k), key=lambda r: r["time_s"])
        if c:
            ax.loglog([r["time_s"] for r in c], [r["error_pct"] for r in c], "o-", color=color,
                      label=f"Cycles bakes, k = {k}")
            for r in c:
                ax.annotate(str(r["samples"]), (r["time_s"], r["error_pct"]), textcoords="offset points",
                            xytext=(4, 4), fontsize=7, color=color)
        o = sorted((r for r in rows if r["method"] == "ours" and r["k"] == k), key=lambda r: r["time_s"])
        ax.loglog([r["time_s"] for r in o], [r["error_pct"] for r in o], "*:", markersize=12, color=color,
                  label=f"ours, k = {k}")
        for r in o if k == max(ks) else ():  # one set of labels: the k curves of ours lie together
            ax.annotate(f"{r['element']:g} m", (r["time_s"], r["error_pct"]), textcoords="offset points",
                        xytext=(6, -10), fontsize=7, color=color)
    ax.set_xlabel("time (process CPU seconds / 2: the 2-core machine's time)")
    ax.set_ylabel("mean error vs Mitsuba 3 at the probes (%)")
    ax.set_title(f"{title}: error against time\n(numbers: Cycles' samples per bake, our element size)", fontsize=9)
    plain = FuncFormatter(lambda value, _: f"{value:g}")  # 2, 3, 10 rather than 2 x 10^0
    ax.xaxis.set_major_formatter(plain)
    ax.xaxis.set_minor_formatter(NullFormatter())
    ax.yaxis.set_major_formatter(plain)
    ax.yaxis.set_minor_formatter(plain)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def sizes_table(ours):
    """Ours over element sizes: the time and error of each mesh (the first table's mesh is
    the one Cycles bakes on)."""
    lines = ["| k | element | elements | time | mean error vs Mitsuba |", "|---|---|---|---|---|"]
    for r in sorted(ours, key=lambda r: (r["k"], -r["element"])):
        elements = f"{int(r['elements']):,}" if r["elements"] != "" else "?"
        lines.append(f"| {r['k']} | {r['element']:g} m | {elements} | {r['time_s']:.2f} s | {r['error_pct']:.2f} % |")
    return "\n".join(lines)


def report(rows, args):
    """Prints the tables, writes them to NAME.txt and draws NAME.png."""
    out, ks = pathlib.Path(args.out), sorted(int(k) for k in args.ks.split(","))
    ours = [r for r in rows if r["method"] == "ours"]
    common = [r for r in ours if r["element"] == args.element or math.isnan(r["element"])]
    table = summary(common, [r for r in rows if r["method"] == "Cycles"],
                    args.fixed_error, ks) + "\n\n" + sizes_table(ours)
    print(table)
    (out / f"{args.name}.txt").write_text(table + "\n")
    plot(rows, out / f"{args.name}.png", ks, args.fixed_error, args.title)


def write_rows(rows, path):
    """peers.csv: one row per run, times to the millisecond, errors to 0.001 %."""
    with open(path, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        for row in rows:
            writer.writerow({key: round(value, 4 if key == "relight_ms" else 3) if isinstance(value, float) else value
                             for key, value in row.items()})


def read_rows(path):
    """peers.csv back as the rows main() wrote."""
    numbers = ("time_s", "wall_s", "error_pct", "peak_mb", "relight_ms", "element")
    # A csv written before ours ran over element sizes has no element column: its runs
    # were at the common mesh's.
    older = {"element": "nan", "elements": ""}
    with open(path) as f:
        rows = []
        for r in csv.DictReader(f):
            r = dict(older, **r)
            rows.append(dict(r, k=int(r["k"]), **{n: float(r[n]) if r[n] else "" for n in numbers}))
        return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--room", default="out/bench/room.json")
    parser.add_argument("--reference", default="out/bench/room_reference.csv")
    parser.add_argument("--blender", default="", help="the bench venv's python with bpy ('' skips Cycles)")
    parser.add_argument("--out", default="out/bench")
    parser.add_argument("--samples", default="16,64,256,1024")
    parser.add_argument("--ks", default="1,3,8")
    parser.add_argument("--element", type=float, default=0.15, help="the element size of the mesh both use")
    parser.add_argument("--element-sizes", default="0.3,0.075",
                        help="other element sizes ours is also solved at (its own error against time)")
    parser.add_argument("--method", default="Auto", help="our SolverMethod (Auto, Hierarchical, Clustered, ...)")
    parser.add_argument("--name", default="peers", help="the stem of the files written in --out")
    parser.add_argument("--title", default="Furnished room", help="the scene, for the plot's title")
    parser.add_argument("--patch", type=float, default=0.4)
    parser.add_argument("--fixed-error", type=float, default=2.0, help="the fixed error of the table (%%)")
    parser.add_argument("--report-only", action="store_true",
                        help="only write NAME.txt and NAME.png again from NAME.csv")
    parser.add_argument("--solve-only", type=int, default=0, help=argparse.SUPPRESS)
    parser.add_argument("--mesh-out", default="", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.solve_only:
        solve_ours(args)
        return
    ks = sorted(int(k) for k in args.ks.split(","))
    if args.report_only:
        report(read_rows(pathlib.Path(args.out) / f"{args.name}.csv"), args)
        return
    room = json.loads(pathlib.Path(args.room).read_text())
    probes = room["probes"]
    if pathlib.Path(args.reference).is_file():
        reference = read_reference(args.reference, len(probes), max(ks))
    else:
        print(f"no Mitsuba reference at {args.reference}: times only, errors not judged", flush=True)
        reference = np.full((len(probes), max(ks)), np.nan)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    sizes = sorted({args.element, *(float(e) for e in args.element_sizes.split(",") if e)}, reverse=True)
    with tempfile.TemporaryDirectory() as tmp:
        ours = {k: run_ours(args, k, pathlib.Path(tmp) / f"ours{k}.npz", args.element) for k in ks}
        mesh = ours[max(ks)]  # every lamp marked: Blender's scene
        for k in ks:
            if not np.array_equal(ours[k]["connectivity"], mesh["connectivity"]):
                sys.exit(f"the mesh with {k} lights differs from the one with {max(ks)}: no common points to compare on")
        weights = probe_weights(mesh, probes)
        used = held(weights) & (~np.isnan(reference).all(axis=1) | np.isnan(reference).all())
        print(f"{len(mesh['offsets']) - 1:,} elements, {len(mesh['points']):,} points; {used.sum():,} of "
              f"{sum(p['seen'] for p in probes):,} seen probes lie in a cell facing their way", flush=True)
        weights, reference = some_probes(weights, used), reference[used]
        rows = []
        for element in sizes:  # ours over element sizes: what accuracy costs us in time
            for k in ks:
                solved = ours[k] if element == args.element else run_ours(
                    args, k, pathlib.Path(tmp) / f"ours{k}_{element:g}.npz", element)
                rows.append(ours_row(solved, k, element, weights if element == args.element else
                                     some_probes(probe_weights(solved, probes), used), reference))
        cycles = run_cycles(args, pathlib.Path(tmp) / f"ours{max(ks)}.npz", max(ks)) if args.blender else None
    if cycles is None:
        print("Cycles: not run (no --blender python given); ours only")
        cycles_rows = []
    else:
        cycles_rows = cycles_runs(cycles, weights, reference, ks, args.element, len(mesh["offsets"]) - 1)
        for r in cycles_rows:
            print(f"Cycles, k = {r['k']}, {r['samples']} samples per bake: {r['time_s']:.1f} s "
                  f"({r['wall_s']:.1f} s wall), {r['error_pct']:.2f} % from Mitsuba", flush=True)
        print(f"Cycles: {float(cycles['setup_s']):.1f} s (CPU / {CORES}) to load bpy and build the scene once, "
              f"not counted above", flush=True)
    rows += cycles_rows
    write_rows(rows, out / f"{args.name}.csv")
    report(rows, args)
    print(f"wrote {args.name}.csv, .txt and .png in {out}")


if __name__ == "__main__":
    main()

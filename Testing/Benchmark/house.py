"""A real third-party building: KIT's FZK-Haus (IFC from Debian's assimp-testmodels, read by
relight.import_scene through assimp), 6 ceiling lamps, solved at the defaults (Auto picks the clustered method), two pictures from inside. Run:
./relight python Testing/Benchmark/house.py [--element 0.25] [--patch 0.5] [--time-budget 0] [--out out/bench]
    [--reference]  (error against Mitsuba 3 at 600 probe points; needs out/mitsuba-venv)"""

import argparse, pathlib, resource, subprocess
import numpy as np
import relight
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkOBBTree

IFC = pathlib.Path("/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc")
UP = 1  # assimp writes the IFC Y-up (checked below: the smallest extent is the height)
DIRS = [np.array(d, float) for d in ((1, 0, 0), (-1, 0, 0), (0, 0, 1), (0, 0, -1))]


class Rays:
    """Ray queries against the house (vtkOBBTree): all hits along a segment, with the
    normal of the hit cell, so floors, ceilings and wall sides can be told apart."""

    def __init__(self, scene):
        self.tree = vtkOBBTree()
        self.tree.SetDataSet(scene)
        self.tree.BuildLocator()
        normals = vtkPolyDataNormals()  # cell normals, each cell keeping its own orientation
        normals.SetInputData(scene)
        normals.ComputeCellNormalsOn(), normals.ComputePointNormalsOff(), normals.SplittingOff(), normals.ConsistencyOff()
        normals.Update()
        self.normals = vtk_to_numpy(normals.GetOutput().GetCellData().GetArray("Normals"))

    def hits(self, start, direction, length):
        """[(distance, normal)] sorted by distance."""
        points, cells = vtkPoints(), vtkIdList()
        self.tree.IntersectWithLine(start, start + direction * length, points, cells)
        out = [(np.dot(np.array(points.GetPoint(i)) - start, direction), self.normals[cells.GetId(i)])
               for i in range(points.GetNumberOfPoints())]
        return sorted(((d, n) for d, n in out if d > 1e-6), key=lambda h: h[0])

    def first(self, start, direction, length=15.0):  # (inf, None) if nothing is hit
        h = self.hits(start, direction, length)
        return h[0] if h else (np.inf, None)

    def indoors(self, p):
        """Every horizontal ray meets the front of a wall: p is inside a closed room."""
        return all(n is not None and np.dot(n, d) < 0 for d in DIRS for _, n in [self.first(p, d)])


def lamp_at(rays, x, z, floor):
    """A lamp position above floor (x, floor, z), or None: the lowest ceiling over the
    0.3 m square must be 2.2-3.2 m up and face down (sloped roofs included), the room
    must be closed and walls at least 0.4 m away (the quad's half width is 0.15 m)."""
    up = np.eye(3)[UP]
    tops = []
    for dx, dz in ((0, 0), (-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)):
        d, n = rays.first(np.array([x + dx, floor + 0.5, z + dz]), up)
        if n is None or n[UP] > -0.3:
            return None
        tops.append(floor + 0.5 + d)
    p = np.array([x, min(tops) - 0.02, z])
    if not 2.2 <= p[UP] - floor <= 3.2 or not rays.indoors(np.array([x, floor + 1.2, z])):
        return None
    # Only near-vertical hits count as walls: under a sloped roof a level ray meets the roof.
    walls = [d for d, n in (rays.first(p, v) for v in DIRS) if n is not None and abs(n[UP]) < 0.5]
    return p if min(walls, default=np.inf) >= 0.4 else None


def find_lamps(rays, bounds, count=6, step=0.4):
    """Floors = up-facing hits of vertical rays; keep lamp spots on the two storeys with
    the most spots and spread 3 per storey by farthest-point sampling."""
    spots = {}
    for x in np.arange(bounds[0] + step / 2, bounds[1], step):
        for z in np.arange(bounds[4] + step / 2, bounds[5], step):
            start = np.array([x, bounds[2] - 1, z])
            for d, n in rays.hits(start, np.eye(3)[UP], bounds[3] - bounds[2] + 2):
                p = lamp_at(rays, x, z, start[UP] + d) if n[UP] > 0.9 else None
                if p is not None:
                    spots.setdefault(round(start[UP] + d, 1), []).append(p)
    storeys = sorted(sorted(spots, key=lambda f: -len(spots[f]))[:2])
    lamps = []
    for f in storeys:
        cand = np.array(spots[f])
        chosen = [cand[np.argmin(np.linalg.norm(cand - cand.mean(axis=0), axis=1))]]
        while len(chosen) < count // len(storeys):
            dist = np.min([np.linalg.norm(cand - c, axis=1) for c in chosen], axis=0)
            chosen.append(cand[np.argmax(dist)])
        lamps += [(f, c) for c in chosen]
    return lamps


def add_lamps(house, lamps, half=0.15):
    """0.3 m square ceiling lamps facing down (Mark Lights' area lights), Lamp0, Lamp1, ..."""
    marker = relight.vtkRadiosityLightMarker()
    marker.SetInputData(house)
    down = -np.eye(3)[UP]
    for i, (_, p) in enumerate(lamps):
        marker.AddAreaLight(f"Lamp{i}", 0, *p, *down, 2 * half, 2 * half, 1, 1, 1)
    marker.Update()
    return marker.GetOutput()


def setting(text):
    """'Name=Value' -> (Name, int or float Value); argparse's error for anything else."""
    name, equals, value = text.partition("=")
    try:
        number = float(value)
    except ValueError:
        number = None
    if not name or not equals or number is None:
        raise argparse.ArgumentTypeError(f"expected NAME=NUMBER, e.g. FormFactorSamples=8, not {text!r}")
    return name, int(number) if number.is_integer() and "." not in value else number


def solve(scene, patch, element, cluster_angle=30.0, time_budget=0.0, method="Auto", separation=3.0, gather_rays=256,
          lamp_grading=0.2, gather_sweeps=1, gather_cache=None, settings=(), shadow_grading=0.0):
    """Mesh + solve at the solver's default settings (Auto picks the clustered method here);
    keeps warnings and errors."""
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(scene)
    mesher.SetPatchSize(patch), mesher.SetElementSize(element), mesher.SetClusterAngle(cluster_angle)
    mesher.SetLampGrading(lamp_grading)
    mesher.SetShadowGrading(shadow_grading)
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    solver.SetTimeBudget(time_budget)
    solver.SetClusterSeparation(separation)
    solver.SetGatherRays(gather_rays)
    solver.SetGatherSweeps(gather_sweeps)
    if gather_cache is not None:
        solver.SetGatherCache(gather_cache)
    for name, value in settings:
        getattr(solver, "Set" + name)(value)
    getattr(solver, f"SetSolverMethodTo{method}")()
    catchers = [relight.ErrorCatcher(mesher), relight.ErrorCatcher(solver)]
    solver.Update()
    if any(c.errors for c in catchers):
        raise RuntimeError([e for c in catchers for e in c.errors][0])
    return solver, [w for c in catchers for w in c.warnings]


def camera(rays, floor, lamp):
    """Stand against the wall behind the lamp, eye 1.5 m up, look at the far wall."""
    eye = np.array([lamp[0], floor + 1.5, lamp[2]])
    dist = [rays.first(eye, d)[0] for d in DIRS]
    ahead = int(np.argmax(dist))
    back = ahead ^ 1  # DIRS come in opposite pairs
    eye = eye - DIRS[ahead] * max(dist[back] - 0.2, 0.0)
    focal = eye + DIRS[ahead] * dist[ahead] - np.eye(3)[UP] * 0.4
    return tuple(eye), tuple(focal), tuple(np.eye(3)[UP]), 80.0


def solve_steps(result):
    """Where the solve's time went, as the solver booked it: 'links 12.1 s, ...'."""
    fields = result.GetFieldData()
    names, seconds = fields.GetAbstractArray("SolveSteps"), fields.GetArray("SolveStepSeconds")
    return ", ".join(f"{names.GetValue(i)} {seconds.GetValue(i):.1f} s" for i in range(names.GetNumberOfValues()))


def render(solver, shots, out):
    """All lamps on at unit exitance; exposure puts the 99th percentile of the lit
    surfaces at 0.8 so walls are visible and only the lamps (and walls right by them) clip."""
    relit = relight.vtkRadiosityRelight()
    relit.SetInputConnection(solver.GetOutputPort())  # intensity 1, white: the Emission
    relit.Update()
    b = relight.point_array(relit.GetOutput(), "Radiosity").max(axis=1)
    lit = b[(b > 0) & (b < 0.5)]  # the lamps themselves are at 1
    relit.SetExposure(0.8 / np.percentile(lit, 99))
    relit.Update()
    for i, cam in enumerate(shots, 1):
        relight.render_png(relit.GetOutput(), out / f"house_inside_{i}.png", cam)
    return relit.GetExposure()


def stronger_reference(scene, csv, python, spp, result, cells, names, average):
    """A second Mitsuba render of the same probes (another seed, `spp` paths): how far the two
    are apart, the noise that implies, and our error against their path-weighted mean."""
    import combine_references, house_reference
    first, total = house_reference.PATHS, house_reference.PATHS + spp
    second = csv.with_name(csv.stem + f"_seed1_{spp}.csv")
    house_reference.render(scene, second, python, spp=spp, seed=1)
    combined = csv.with_name(csv.stem + f"_combined_{total}.csv")
    noise = combine_references.combine(csv, first, second, spp, combined)
    print(f"the two Mitsuba renders ({first} and {spp} paths) {100 * noise['apart']:.2f} % apart: noise about "
          f"{100 * noise['noise_a']:.2f} % and {100 * noise['noise_b']:.2f} %, their mean {100 * noise['noise_mean']:.2f} %")
    errors, median, _ = house_reference.compare(result, cells, combined, names, average > 0)
    print(f"error against their mean ({total} paths): " + ", ".join(f"{n} {100 * e:.1f} %" for n, e in errors.items()))
    return dict(strong_error_pct=round(100 * float(np.mean(list(errors.values()))), 2),
                strong_lit_median_ratio=round(median, 3), strong_reference_paths=total,
                strong_reference_noise_pct=round(100 * noise["noise_mean"], 2),
                reference_noise_pct=round(100 * noise["noise_a"], 2))


RADIANCE_RAYS = 512  # Radiance's ambient rays at a probe, in two draws of half as many


def accuracy(result, out, python, names, average, traced=False, radiance=False, second_spp=0):
    """Mean per-light error against Mitsuba at probe points (or element means), and how ours
    compares where the house is lit (median ratio); with `radiance`, the same against
    Radiance's rtrace at the same probes, and how far the two references are apart; with
    `second_spp`, the same against a stronger Mitsuba reference (stronger_reference)."""
    import house_reference
    stem = "house_average" if average else ("house_traced" if traced else "house")
    scene, csv = out / f"{stem}_room.json", out / f"{stem}_reference.csv"
    cells = house_reference.export(result, scene, average=average, traced=traced)
    house_reference.render(scene, csv, python)
    errors, median, lit = house_reference.compare(result, cells, csv, names, average > 0)
    print("error against Mitsuba: " + ", ".join(f"{n} {100 * e:.1f} %" for n, e in errors.items()))
    row = dict(mean_error_pct=round(100 * float(np.mean(list(errors.values()))), 2),
               lit_median_ratio=round(median, 3), lit_probes=lit)
    if second_spp > 0:
        row.update(stronger_reference(scene, csv, python, second_spp, result, cells, names, average))
    if radiance:
        row.update(radiance_reference(scene, csv, python, result, cells, names, average, row))
    return row


def radiance_reference(scene, mitsuba_csv, python, result, cells, names, average, row):
    """Radiance's rtrace at the same probes, as two draws of RADIANCE_RAYS / 2 ambient rays
    (another probe order each): their difference is Radiance's noise, their mean the
    reference. How far it is from Mitsuba's, against what the two references' noise alone
    would put between them (Mitsuba's from --second-reference, else unknown)."""
    import combine_references, house_reference
    half = RADIANCE_RAYS // 2
    draws = [mitsuba_csv.with_name(mitsuba_csv.stem.replace("reference", f"radiance_{half}_seed{seed}") + ".csv")
             for seed in (0, 1)]
    for seed, draw in enumerate(draws):
        house_reference.render(scene, draw, python, spp=half, script="radiance_reference.py", seed=seed)
    mean = draws[0].with_name(draws[0].name.replace(f"_{half}_seed0", f"_{RADIANCE_RAYS}"))
    noise = combine_references.combine(draws[0], half, draws[1], half, mean)["noise_mean"]
    theirs, their_median, _ = house_reference.compare(result, cells, mean, names, average > 0)
    apart = float(np.mean(house_reference.references_apart(mitsuba_csv, mean)))
    print("error against Radiance: " + ", ".join(f"{n} {100 * e:.1f} %" for n, e in theirs.items()))
    out = dict(radiance_error_pct=round(100 * float(np.mean(list(theirs.values()))), 2),
               radiance_lit_median_ratio=round(their_median, 3), radiance_noise_pct=round(100 * noise, 2),
               references_apart_pct=round(100 * apart, 2))
    mitsuba = row.get("reference_noise_pct")
    if mitsuba is None:
        print(f"Radiance against Mitsuba {100 * apart:.2f} % apart; Radiance's noise {100 * noise:.2f} % "
              "(Mitsuba's: run with --second-reference)")
        return out
    # Two independent draws differ by the root of their squared noises (the benches' measure):
    # what is apart beyond that is the two renderers' models.
    expected = np.hypot(noise, mitsuba / 100)
    models = np.sqrt(max(0.0, apart ** 2 - expected ** 2))
    print(f"Radiance against Mitsuba {100 * apart:.2f} % apart; their noise alone would put them "
          f"{100 * expected:.2f} % apart (Radiance {100 * noise:.2f} %, Mitsuba {mitsuba:.2f} %): "
          f"{'within' if apart <= expected else 'beyond'} their noise, the models' own difference about {100 * models:.2f} %")
    out.update(references_noise_pct=round(100 * expected, 2), references_models_pct=round(100 * models, 2))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element", type=float, default=0.25, help="ElementSize, m (0.1 gives ~830k elements)")
    parser.add_argument("--patch", type=float, default=0.5, help="PatchSize, m")
    parser.add_argument("--ifc", default=str(IFC),
                        help="another building (IFC2x3, as assimp reads it; lamps placed by the same rules), e.g. "
                             "buildingSMART's Duplex_A_20110907.ifc; give it its own --out")
    parser.add_argument("--out", default="out/bench")
    parser.add_argument("--cluster-angle", type=float, default=30.0, help="the mesher's ClusterAngle (0: no face clusters)")
    parser.add_argument("--time-budget", type=float, default=0.0, help="the solver's TimeBudget, s (0: solve to convergence)")
    parser.add_argument("--method", default="Auto", help="SolverMethod: Auto, ProgressiveRefinement, Hierarchical, Clustered")
    parser.add_argument("--cluster-separation", type=float, default=3.0,
                        help="ClusterSeparation (clustered method): larger is more accurate and slower")
    parser.add_argument("--gather-rays", type=int, default=256, help="GatherRays: the final gather's rays per point (0: off)")
    parser.add_argument("--gather-cache", type=float, default=None,
                        help="GatherCache: the gather's irradiance cache (0: every point gathers; default: the solver's)")
    parser.add_argument("--gather-sweeps", type=int, default=1, help="GatherSweeps: the gather's passes over the elements")
    parser.add_argument("--lamp-grading", type=float, default=0.2,
                        help="the mesher's LampGrading: finer elements by the lamps (0: one size everywhere)")
    parser.add_argument("--shadow-grading", type=float, default=0.0,
                        help="the mesher's ShadowGrading: finer elements where a shadow's edge crosses a patch (0: off)")
    parser.add_argument("--accuracy", choices=["preview", "draft", "default", "fine", "reference"],
                        help="the one knob (relight.levels): sets the element size (times --element), LampGrading, ShadowGrading, "
                             "GatherRays and ClusterSeparation, over their flags")
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE", type=setting,
                        help="any other solver setting, e.g. FormFactorSamples=8 (shadow rays per link); repeatable")
    parser.add_argument("--reference", action="store_true", help="compare with Mitsuba 3 at probe points (rendered once per mesh)")
    parser.add_argument("--element-average", type=int, default=0, metavar="N",
                        help="with --reference: compare element means (Mitsuba at N points spread over each probe's "
                             "element, ours the element's value) instead of centroids")
    parser.add_argument("--traced-probes", action="store_true",
                        help="with --reference: probes where rays from the lamps meet surfaces, and one bounce further "
                             "(drawn independently of our elements), ours interpolated there")
    parser.add_argument("--radiance", action="store_true",
                        help="with --reference: also Radiance's rtrace (pyradiance, in the same venv) at the same probes, in "
                             "two draws whose difference gives its noise")
    parser.add_argument("--second-reference", type=int, default=0, metavar="SPP",
                        help="with --reference: a second Mitsuba render of the same probes at SPP paths (another "
                             "seed): the two renders' noise, and our error against their mean as well")
    parser.add_argument("--save", metavar="PATH.vtp", help="also write the solved mesh (every array) to PATH.vtp")
    parser.add_argument("--mitsuba-python", default="out/mitsuba-venv/bin/python", help="a Python with mitsuba installed")
    args = parser.parse_args()
    if args.accuracy:
        chosen = relight.levels.level(args.accuracy)
        args.element = min(args.element * chosen.element_scale, args.patch)
        args.lamp_grading, args.gather_rays = chosen.lamp_grading, chosen.gather_rays
        args.shadow_grading = chosen.shadow_grading
        args.cluster_separation, args.gather_sweeps = chosen.cluster_separation, chosen.gather_sweeps
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    house = relight.import_scene(args.ifc, require_lights=False)
    extent = np.ptp(np.reshape(house.GetBounds(), (3, 2)), axis=1)
    assert np.argmin(extent) == UP, f"expected Y-up, extents {extent}"
    print(house.GetFieldData().GetAbstractArray("ImportSummary").GetValue(0))
    rays = Rays(house)
    lamps = find_lamps(rays, house.GetBounds())
    print("\n".join(f"Lamp{i}: {np.round(p, 2)} (floor at {f} m)" for i, (f, p) in enumerate(lamps)))
    k = len(lamps)
    scene = add_lamps(house, lamps)
    solver, warnings = solve(scene, args.patch, args.element, args.cluster_angle, args.time_budget, args.method,
                             args.cluster_separation, args.gather_rays, args.lamp_grading, args.gather_sweeps,
                             args.gather_cache, args.set, args.shadow_grading)
    result = solver.GetOutput()
    method = result.GetFieldData().GetAbstractArray("SolverMethod").GetValue(0)
    commit = subprocess.run(["git", "describe", "--always", "--dirty"], capture_output=True, text=True).stdout.strip()
    row = dict(commit=commit or "?", accuracy=args.accuracy or "", polygons=scene.GetNumberOfCells(),
               elements=result.GetNumberOfCells(),
               patches=len(np.unique(relight.cell_array(result, "PatchId"))), lights=k,
               element=args.element, patch=args.patch, method=args.method, separation=args.cluster_separation,
               gather_rays=args.gather_rays, gather_sweeps=args.gather_sweeps, gather_cache=args.gather_cache, settings=" ".join(f"{n}={v}" for n, v in args.set), lamp_grading=args.lamp_grading, shadow_grading=args.shadow_grading, solve_s=round(solver.GetLastSolveSeconds(), 2),
               steps=solve_steps(result), shots=solver.GetLastShots(), converged=bool(solver.GetLastConverged()),
               peak_mib=round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024),
               warnings=len(warnings))
    if args.save:
        from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter
        writer = vtkXMLPolyDataWriter()
        writer.SetFileName(args.save)
        writer.SetInputData(result)
        if not writer.Write():
            raise OSError(f"could not write {args.save}")
    if args.reference:
        row.update(accuracy(result, out, args.mitsuba_python, [f"Lamp{i}" for i in range(k)], args.element_average,
                            args.traced_probes, args.radiance, args.second_reference))
    exposure = render(solver, [camera(rays, *lamps[0]), camera(rays, *lamps[-1])], out)  # one per storey
    summary = "\n".join([f"{key}: {value}" for key, value in row.items()] + [f"SolverMethod: {method}",
                         f"exposure: {exposure:.4g}"] + [f"warning: {w.strip().splitlines()[-1]}" for w in warnings])
    print(summary)
    (out / "house.txt").write_text(summary + "\n")
    csv = out / "house.csv"
    if csv.exists() and csv.read_text().split("\n", 1)[0] != ",".join(row):
        csv.rename(csv.with_suffix(".old.csv"))  # its columns differ (--reference adds three)
    header = "" if csv.exists() else ",".join(row) + "\n"  # append: one row per run
    with csv.open("a") as f:
        f.write(header + ",".join(str(v) for v in row.values()) + "\n")


if __name__ == "__main__":
    main()

"""What accuracy costs in time on rooms: ``./relight bench accuracy``.

Sweeps element size, form-factor method and samples, and the convergence threshold on
(a) a scene with a closed-form answer (the furnace: a closed box, every face emitting,
uniform reflectance: B = E / (1 - rho) everywhere) and (b) the Cornell box and the
3-light paper scene against a converged fine reference. For each setting it measures
the solve time and the error, and writes

- ``accuracy.csv``: one row per (scene, setting, light);
- ``accuracy.png``: error against time, Pareto front marked;
- ``accuracy.md``: the fastest setting for 10 %, 3 % and 1 % error.

Errors on the reference scenes are per light and per pixel of a ray-cast view of the
linear radiosity (independent of the mesh): |B - B_ref| / mean(B_ref); "mean" averages
that over the pixels that see a surface, "max" is its largest value (shadow edges).
"""

import argparse
import csv
import pathlib
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLogger

from relight import (
    cell_array,
    exr_writer,
    furnace_box,
    light_names,
    read_polydata,
    solve as solve_scene,
)

# The demo's camera for its own scene (Wrapping/Python/demos/demo.py).
sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "Wrapping" / "Python" / "demos"))
from demo import CAMERA as DEMO_CAMERA  # noqa: E402

METHODS = {"Analytic": 0, "Hemicube": 1, "MonteCarlo": 2}

# Cameras for the image comparison: (position, focal point, view up, view angle).
CAMERAS = {
    "cornell": ((278, 273, -800), (278, 273, 0), (0, 1, 0), 39.3),
    "paper3": DEMO_CAMERA,
}


def solve(scene, patch, element, method, samples, threshold, ambient=False, max_shots=20000, force=False):
    return solve_scene(scene, patch, element, FormFactorMethod=METHODS[method], FormFactorSamples=samples,
                       ConvergenceThreshold=threshold, MaximumShots=max_shots, AmbientTerm=ambient,
                       ForceAllEffects=force)


def images(data, camera, size):
    """Linear radiosity image per light: {name: (h, w, 3) array}."""
    writer = exr_writer(data, camera, size)
    result = {}
    for name in light_names(data):
        writer.SetArrayName("Radiosity_" + name)
        rgb = vtkFloatArray()
        if not writer.RenderImage(rgb):
            raise RuntimeError("rendering failed")
        result[name] = vtk_to_numpy(rgb).reshape(size[1], size[0], 3).astype(np.float64)
    return result


def image_errors(image, reference):
    seen = reference.sum(axis=2) > 0
    scale = reference[seen].mean()
    error = np.abs(image - reference).mean(axis=2)[seen] / scale
    return float(error.mean()), float(error.max())


def settings(quick):
    """(label, element scale, method, samples, threshold, ambient, force all effects)."""
    if quick:
        return [("A16 t1e-2", 1.0, "Analytic", 16, 1e-2, False, False),
                ("H32 t1e-2", 1.0, "Hemicube", 32, 1e-2, False, False),
                ("M2k t1e-2", 1.0, "MonteCarlo", 2000, 1e-2, False, False),
                ("A4 t1e-2", 1.0, "Analytic", 4, 1e-2, False, False),
                ("A4 t1e-2 forced", 1.0, "Analytic", 4, 1e-2, False, True)]
    methods = [("Analytic", 4), ("Analytic", 16), ("Analytic", 64), ("Hemicube", 64),
               ("Hemicube", 128), ("MonteCarlo", 10000), ("MonteCarlo", 100000)]
    out = []
    for scale in (2.0, 1.0, 0.5):
        for method, samples in methods:
            for threshold in (3e-2, 1e-3):
                label = f"{method[0]}{samples} e{scale:g} t{threshold:g}"
                out.append((label, scale, method, samples, threshold, False, False))
    for threshold in (1e-1, 3e-2):  # the ambient term on early, unconverged results
        out.append((f"A16 e1 t{threshold:g} ambient", 1.0, "Analytic", 16, threshold, True, False))
    out.append(("A16 e1 t0.1", 1.0, "Analytic", 16, 1e-1, False, False))  # the same without it
    # The defaults with every effect forced on: what simulating only what is needed saves.
    out.append(("A4 e1 t0.001 forced", 1.0, "Analytic", 4, 1e-3, False, True))
    return out


def pareto(points):
    """Indices of the points no other point beats in both time and error."""
    order = sorted(range(len(points)), key=lambda i: (points[i][0], points[i][1]))
    front, best = [], float("inf")
    for i in order:
        if points[i][1] < best:
            front.append(i)
            best = points[i][1]
    return front


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--data", default="Data")
    parser.add_argument("--out", default="out/bench")
    parser.add_argument("--quick", action="store_true", help="a few settings, small references (CI)")
    args = parser.parse_args()
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_WARNING)
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    data = pathlib.Path(args.data)
    size = (96, 96) if args.quick else (240, 240)

    # scene: (polydata, base patch size, base element size, reference element, closed form)
    scenes = {
        "furnace": (furnace_box(2.0, 0.8), 1.0, 0.5, None, 1.0 / (1.0 - 0.8)),
        "cornell": (read_polydata(data / "cornell_box.vtp"), 100.0, 50.0, 25.0 if args.quick else 12.5, None),
        "paper3": (read_polydata(data / "paper_3lights.vtp"), 1.5, 0.375, 0.375 if args.quick else 0.125, None),
    }
    if args.quick:
        del scenes["paper3"]
    rows = []
    for scene_name, (scene, patch, element, reference_element, exact) in scenes.items():
        reference = None
        if reference_element is not None:
            start = time.perf_counter()
            ref = solve(scene, patch, reference_element, "Analytic", 16 if args.quick else 32,
                        1e-3 if args.quick else 1e-4)
            reference = images(ref.GetOutput(), CAMERAS[scene_name], size)
            print(f"{scene_name}: reference ({ref.GetOutput().GetNumberOfCells()} elements, "
                  f"{ref.GetLastShots()} shots) in {time.perf_counter() - start:.1f} s")
        for label, scale, method, samples, threshold, ambient, force in settings(args.quick):
            solver = solve(scene, max(patch, element * scale), element * scale, method, samples,
                           threshold, ambient, force=force)
            result = solver.GetOutput()
            seconds = solver.GetLastSolveSeconds()
            if exact is not None:
                b = cell_array(result, "Radiosity_Light0")
                error = np.abs(b - exact) / exact
                errors = {"Light0": (float(error.mean()), float(error.max()))}
            else:
                mine = images(result, CAMERAS[scene_name], size)
                errors = {name: image_errors(mine[name], reference[name]) for name in reference}
            for light, (mean, worst) in errors.items():
                rows.append({
                    "scene": scene_name, "setting": label, "light": light,
                    "element": element * scale, "method": method, "samples": samples,
                    "threshold": threshold, "ambient": int(ambient), "force_all": int(force),
                    "rays": solver.GetLastRays(),
                    "elements": result.GetNumberOfCells(), "shots": solver.GetLastShots(),
                    "seconds": seconds, "mean_error": mean, "max_error": worst,
                })
            worst_mean = max(m for m, _ in errors.values())
            print(f"{scene_name:8s} {label:24s} {result.GetNumberOfCells():6d} el "
                  f"{solver.GetLastShots():5d} shots {seconds:8.3f} s  mean error {worst_mean:7.2%}")

    with open(out / "accuracy.csv", "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    summary = summarize(rows)
    (out / "accuracy.md").write_text(summary)
    plot(rows, out / "accuracy.png")
    print(summary)
    print(f"wrote {out / 'accuracy.csv'}, {out / 'accuracy.png'}, {out / 'accuracy.md'}")


def per_setting(rows, scene):
    """(seconds, worst mean error over lights, row) per setting of one scene."""
    settings = {}
    for r in rows:
        if r["scene"] != scene or r["force_all"]:
            continue
        seconds, error, first = settings.get(r["setting"], (r["seconds"], 0.0, r))
        settings[r["setting"]] = (seconds, max(error, r["mean_error"]), first)
    return list(settings.values())


def summarize(rows):
    lines = ["# Accuracy against time", "",
             "Fastest setting that reaches each mean error (worst light), per scene.", "",
             "| scene | target | setting | element | method (samples) | threshold | time (s) | mean error |",
             "|---|---|---|---|---|---|---|---|"]
    for scene in sorted({r["scene"] for r in rows}):
        points = per_setting(rows, scene)
        for target in (0.10, 0.03, 0.01):
            good = [p for p in points if p[1] <= target]
            if not good:
                lines.append(f"| {scene} | {target:.0%} | none reached | | | | | |")
                continue
            seconds, error, r = min(good, key=lambda p: p[0])
            lines.append(f"| {scene} | {target:.0%} | {r['setting']} | {r['element']:g} | "
                         f"{r['method']} ({r['samples']}) | {r['threshold']:g} | {seconds:.3f} | {error:.2%} |")
    lines += ["", "## What simulating only the needed effects saves", "",
              "The default setting with every effect Auto against ForceAllEffects (same answer "
              "within the solver tolerance, less work).", "",
              "| scene | setting | rays (auto) | rays (forced) | time auto (s) | time forced (s) | error auto | error forced |",
              "|---|---|---|---|---|---|---|---|"]
    for scene in sorted({r["scene"] for r in rows}):
        forced = [r for r in rows if r["scene"] == scene and r["force_all"]]
        for f in forced:
            base = f["setting"].replace(" forced", "")
            auto = [r for r in rows if r["scene"] == scene and r["setting"] == base and r["light"] == f["light"]]
            if auto:
                a = auto[0]
                lines.append(f"| {scene} | {base} ({f['light']}) | {a['rays']} | {f['rays']} | {a['seconds']:.3f} | "
                             f"{f['seconds']:.3f} | {a['mean_error']:.2%} | {f['mean_error']:.2%} |")
    return "\n".join(lines) + "\n"


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    scenes = sorted({r["scene"] for r in rows})
    fig, axes = plt.subplots(1, len(scenes), figsize=(5.2 * len(scenes), 4.4), squeeze=False)
    colors = {"Analytic": "tab:blue", "Hemicube": "tab:orange", "MonteCarlo": "tab:green"}
    for ax, scene in zip(axes[0], scenes):
        points = per_setting(rows, scene)
        for seconds, error, r in points:
            ax.scatter(seconds, max(error, 1e-6), color=colors[r["method"]], s=18 + 6 * r["samples"] ** 0.25,
                       marker="o" if not r["ambient"] else "^", alpha=0.8)
        front = pareto([(p[0], p[1]) for p in points])
        xs = [points[i][0] for i in front]
        ys = [max(points[i][1], 1e-6) for i in front]
        ax.step(xs, ys, where="post", color="black", linewidth=1.2, label="Pareto front")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("solve time (s)")
        ax.set_ylabel("mean error (worst light)")
        ax.set_title(scene)
        ax.grid(True, which="both", alpha=0.3)
        for method, color in colors.items():
            ax.scatter([], [], color=color, label=method)
        ax.legend(fontsize=8)
    fig.suptitle("What accuracy costs in time (marker size: samples; triangles: ambient term)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()

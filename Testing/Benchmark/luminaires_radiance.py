#!/usr/bin/env python3
"""Luminaires against Radiance: an office lit by real manufacturers' IES files, the
illuminance at the work surfaces ours against Radiance's rtrace (pyradiance from PyPI,
bench-only, in a venv), per luminaire, with Radiance's own noise beside it.

Usage:
  ./relight python Testing/Benchmark/luminaires_radiance.py [--radiance out/radiance-venv]
      [--element 0.25] [--ad 4096] [--out out/bench-luminaires]

The office: 6 x 4 x 3 m, z up, floor 0.2, walls 0.5, ceiling 0.7 (grey, matte), six
luminaires 0.1 m under the ceiling in a 3 x 2 grid, aimed down: three of Interlight's OVNI
high-bay (absolute photometry, 5300 lm) and three of ERCO's Lightcast spot (a narrow beam,
0-90 quadrant table), each its own light. ies2rad turns each file into a Radiance light
(its luminous opening a disk of the file's size, where ours is a point), rtrace -I gives the
irradiance a hair above each probe, times 179 lm/W (Radiance's white efficacy) in lux.
Probes: the floor's and the walls' mesh points on a 0.5 m grid, away from the corners.
Ours: the point array Radiosity_<light> over the reflectance (illuminance, lux, as the
solution of a luminaire at its lumens is in lm/m^2). Radiance's noise: two runs with
uncorrelated sampling (-u+), their mean difference. The work plane: relight.work_plane at
0.8 m (EN 12464-1's grid inside a 0.5 m border) against rtrace at the same points in the
air, facing up. Direct light alone (ours: Direct_<light>
with SeparateDirect; Radiance: -ab 0) has no noise on either side: it checks the candela
tables, their turn and their scale.
"""
import argparse
import glob
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np

import relight
from vtkmodules.util.numpy_support import vtk_to_numpy

ROOT = pathlib.Path(__file__).resolve().parents[2]
PHOTOMETRY = ROOT / "Data" / "Photometry"
SIZE = (6.0, 4.0, 3.0)
RHO = {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}
EFFICACY = 179.0  # Radiance's lumens per watt of white light (ies2rad, rtrace)


def room_faces():
    """(corners facing inwards, reflectance) per face of the office."""
    x, y, z = SIZE
    faces = [([(0, 0, 0), (0, y, 0), (x, y, 0), (x, 0, 0)], RHO["floor"]),
             ([(0, 0, z), (x, 0, z), (x, y, z), (0, y, z)], RHO["ceiling"]),
             ([(0, 0, 0), (x, 0, 0), (x, 0, z), (0, 0, z)], RHO["walls"]),
             ([(0, y, 0), (0, y, z), (x, y, z), (x, y, 0)], RHO["walls"]),
             ([(0, 0, 0), (0, 0, z), (0, y, z), (0, y, 0)], RHO["walls"]),
             ([(x, 0, 0), (x, y, 0), (x, y, z), (x, 0, z)], RHO["walls"])]
    return [(corners[::-1], rho) for corners, rho in faces]  # listed facing out: turned to face in


def luminaires():
    """(name, IES file, position) of the six."""
    rows = []
    for i, gx in enumerate((1.0, 3.0, 5.0)):
        for j, gy in enumerate((1.0, 3.0)):
            kind = "Ovni" if (i + j) % 2 == 0 else "Erco"
            path = PHOTOMETRY / ("interlight_ovni_absolute.ies" if kind == "Ovni" else "erco_lm63_2002_tabs.ies")
            rows.append((f"{kind}{i}{j}", path, (gx, gy, SIZE[2] - 0.1)))
    return rows


def solve(element):
    faces = room_faces()
    scene = relight.make_scene([f for f, _ in faces], [(r, r, r) for _, r in faces], [-1] * len(faces))
    lights = [relight.luminaire(name, path, position, aim=(0, 0, -1)) for name, path, position in luminaires()]
    start = time.perf_counter()
    solver = relight.solve(relight.mark_lights(scene, *lights), patch_size=1.0, element_size=element, SeparateDirect=1)
    return solver.GetOutput(), time.perf_counter() - start


def cost(element, runs=3):
    """Solve seconds of the office with the six luminaires, and with six area lights (disks
    of the luminaires' openings, facing down) in their places: medians of `runs`, one run."""
    faces = room_faces()
    scene = relight.make_scene([f for f, _ in faces], [(r, r, r) for _, r in faces], [-1] * len(faces))
    lit = relight.mark_lights(scene, *[relight.luminaire(n, p, q) for n, p, q in luminaires()])
    disks = relight.mark_lights(scene, *[relight.area_light(n, centre=q, normal=(0, 0, -1), size=0.3, disk=True)
                                         for n, _, q in luminaires()])
    seconds = {"luminaires": [], "area lights": []}
    for _ in range(runs):
        for label, marked in (("luminaires", lit), ("area lights", disks)):
            start = time.perf_counter()
            relight.solve(marked, patch_size=1.0, element_size=element, lamp_grading=0)
            seconds[label].append(time.perf_counter() - start)
    return {label: float(np.median(values)) for label, values in seconds.items()}


def probes(out):
    """Mesh points on a 0.5 m grid of the floor and the walls, 0.5 m from every edge."""
    points = vtk_to_numpy(out.GetPoints().GetData()).astype(float)
    chosen, normals = [], []
    x, y, z = SIZE
    for p, point in enumerate(points):
        on_grid = np.allclose(np.round(point * 2) / 2, point, atol=1e-6)
        inside = [0.5 - 1e-6 <= point[a] <= SIZE[a] - 0.5 + 1e-6 for a in range(3)]
        if not on_grid:
            continue
        if abs(point[2]) < 1e-9 and inside[0] and inside[1]:
            chosen.append(p), normals.append((0, 0, 1))
        elif abs(point[1]) < 1e-9 and inside[0] and inside[2]:
            chosen.append(p), normals.append((0, 1, 0))
        elif abs(point[0] - x) < 1e-9 and inside[1] and inside[2]:
            chosen.append(p), normals.append((-1, 0, 0))
    return np.array(chosen), np.array(normals, float), points[chosen]


def radiance_tool(venv, name):
    found = glob.glob(str(pathlib.Path(venv) / "lib" / "python3*" / "site-packages" / "pyradiance" / "bin" / name))
    if not found:
        sys.exit(f"no {name} in {venv}: make it with python3 -m venv {venv} && {venv}/bin/pip install pyradiance")
    return found[0]


def radiance_illuminance(venv, light, at, normals, plane_points, ad, folder):
    """rtrace -I, in lux, at `at` facing `normals` and at the work plane's points facing up,
    for one luminaire alone: twice with every bounce, once direct light alone."""
    name, path, position = light
    bin_dir = pathlib.Path(radiance_tool(venv, "rtrace")).parent
    env = dict(os.environ, RAYPATH=".:" + str(bin_dir.parent / "lib"), PATH=f"{bin_dir}:{os.environ['PATH']}")
    subprocess.run([radiance_tool(venv, "ies2rad"), "-dm", "-o", name, str(path)], cwd=folder, env=env, check=True,
                   capture_output=True)
    lines = ["void plastic floor 0 0 5 {0} {0} {0} 0 0".format(RHO["floor"]),
             "void plastic walls 0 0 5 {0} {0} {0} 0 0".format(RHO["walls"]),
             "void plastic ceiling 0 0 5 {0} {0} {0} 0 0".format(RHO["ceiling"]),
             f"!xform -t {position[0]} {position[1]} {position[2]} {name}.rad"]
    for i, (corners, rho) in enumerate(room_faces()):
        material = [k for k, v in RHO.items() if v == rho][0]
        lines.append(f"{material} polygon f{i} 0 0 12 " + " ".join(str(c) for p in corners for c in p))
    (pathlib.Path(folder) / "scene.rad").write_text("\n".join(lines) + "\n")
    with open(pathlib.Path(folder) / "scene.oct", "wb") as octree:
        subprocess.run([radiance_tool(venv, "oconv"), "scene.rad"], cwd=folder, env=env, stdout=octree, check=True)
    lifted = [p + 1e-4 * n for p, n in zip(at, normals)] + list(plane_points)
    facing = list(normals) + [np.array([0.0, 0.0, 1.0])] * len(plane_points)
    rays = "\n".join(" ".join(f"{v:.9g}" for v in (*p, *n)) for p, n in zip(lifted, facing)) + "\n"
    # Twice with every bounce (their difference: the noise), once direct light alone.
    return [rtrace_lux(venv, "scene.oct", rays, bounces, ad, folder, env) for bounces in (8, 8, 0)]


def rtrace_lux(venv, octree, rays, bounces, ad, folder, env):
    """rtrace -I in lux (times Radiance's white efficacy) for `rays` ("x y z dx dy dz" lines),
    every probe gathered anew (-aa 0) with uncorrelated sampling (-u+)."""
    command = [radiance_tool(venv, "rtrace"), "-h", "-I+", "-u+", "-ab", str(bounces), "-ad", str(ad), "-as", "0", "-aa",
               "0", "-lw", "1e-6", "-lr", "-8", "-dj", "0.7", "-ds", "0.05", "-dt", "0", "-dc", "1", "-st", "0", "-n",
               str(os.cpu_count() or 1), octree]
    done = subprocess.run(command, input=rays, cwd=folder, env=env, capture_output=True, text=True, check=True)
    rgb = np.array([[float(v) for v in line.split()[:3]] for line in done.stdout.splitlines() if line.strip()])
    return EFFICACY * rgb.mean(axis=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--radiance", default=str(ROOT / "out" / "radiance-venv"), help="a venv with pyradiance")
    parser.add_argument("--element", type=float, default=0.25, help="element size (m)")
    parser.add_argument("--ad", type=int, default=4096, help="rtrace's ambient rays at each probe")
    parser.add_argument("--out", default=str(ROOT / "out" / "bench-luminaires"))
    parser.add_argument("--cost", type=float, default=0,
                        help="only time the solve at this element size against area lights in the same places")
    args = parser.parse_args()
    if args.cost > 0:
        times = cost(args.cost)
        print(f"element {args.cost} m: luminaires {times['luminaires']:.2f} s, area lights {times['area lights']:.2f} s, "
              f"ratio {times['luminaires'] / times['area lights']:.2f} (medians of 3, one run)")
        return
    out_dir = pathlib.Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    solved, seconds = solve(args.element)
    ids, normals, at = probes(solved)
    probe_rho = np.where(normals[:, 2] > 0.5, RHO["floor"], RHO["walls"])
    print(f"solved {solved.GetNumberOfCells()} elements, 6 luminaires in {seconds:.2f} s; {len(ids)} probes")
    rows, errors, noises, directs, planes, plane_noises = [], [], [], [], [], []
    plane = relight.work_plane(solved, height=0.8, up="z")
    plane_points = vtk_to_numpy(plane.GetPoints().GetData()).astype(float)
    with tempfile.TemporaryDirectory() as folder:
        for light in luminaires():
            name = light[0]
            ours = relight.point_array(solved, "Radiosity_" + name)[ids, 0] / probe_rho
            runs = radiance_illuminance(args.radiance, light, at, normals, plane_points, args.ad, folder)
            first, second, direct = (run[:len(ids)] for run in runs)
            plane_theirs = 0.5 * (runs[0][len(ids):] + runs[1][len(ids):])
            plane_noise = 0.5 * np.abs(runs[0][len(ids):] - runs[1][len(ids):]).mean() / plane_theirs.mean()
            plane_ours = relight.point_array(plane, "Illuminance_" + name)[:, 0]
            plane_error = np.abs(plane_ours - plane_theirs).mean() / plane_theirs.mean()
            planes.append(plane_error), plane_noises.append(plane_noise)
            ours_direct = relight.point_array(solved, "Direct_" + name)[ids, 0] / probe_rho
            direct_error = np.abs(ours_direct - direct).mean() / direct.mean()
            directs.append(direct_error)
            theirs = 0.5 * (first + second)
            error = np.abs(ours - theirs).mean() / theirs.mean()
            noise = 0.5 * np.abs(first - second).mean() / theirs.mean()
            errors.append(error), noises.append(noise)
            floor = normals[:, 2] > 0.5
            rows.append(f"{name}: mean illuminance ours {ours[floor].mean():8.1f} lx, Radiance {theirs[floor].mean():8.1f} lx "
                        f"on the floor; mean |difference| {100 * error:.2f} % of the mean, Radiance's noise {100 * noise:.2f} %; "
                        f"direct light alone {100 * direct_error:.2f} %; work plane (0.8 m, {len(plane_points)} points) "
                        f"{100 * plane_error:.2f} %, Radiance's noise there {100 * plane_noise:.2f} %")
            print(rows[-1], flush=True)
    summary = (f"mean over the luminaires: {100 * np.mean(errors):.2f} % from Radiance (its noise {100 * np.mean(noises):.2f} %; "
               f"direct light alone {100 * np.mean(directs):.2f} %); work plane {100 * np.mean(planes):.2f} % "
               f"(Radiance's noise {100 * np.mean(plane_noises):.2f} %), "
               f"element {args.element} m, solve {seconds:.2f} s")
    print(summary)
    (out_dir / "luminaires_radiance.txt").write_text("\n".join(rows + [summary]) + "\n")


if __name__ == "__main__":
    main()

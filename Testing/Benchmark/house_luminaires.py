#!/usr/bin/env python3
"""A real building lit by a manufacturer's luminaires, against Radiance: KIT's FZK-Haus as
IFC4 (through IfcOpenShell), an ERCO downlight (its IES file) under the ceiling of each of
its rooms, each its own light, and a work plane 0.8 m up in every room; the illuminance at
the planes' points ours against Radiance's rtrace (pyradiance, bench-only, in a venv).

Usage:
  ./relight python Testing/Benchmark/house_luminaires.py [--radiance out/radiance-venv]
      [--ad 2048] [--out out/bench-house-luminaires]

Radiance gets the building's surfaces as our solver does (the imported triangles, each
surface style a matte plastic of its colour) and each luminaire through ies2rad. Per
luminaire, two rtrace runs with uncorrelated sampling give its noise. Reported per room
(its own luminaire) and for all luminaires together.
"""
import argparse
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
sys.path.insert(0, str(ROOT / "Testing" / "Benchmark"))
from luminaires_radiance import radiance_tool, rtrace_lux  # noqa: E402

HOUSE = ROOT / "Data" / "IFC" / "AC20-FZK-Haus.ifc"
DOWNLIGHT = ROOT / "Data" / "Photometry" / "erco_lm63_1986_noversion.ies"  # ERCO Double Focus, 2200 lm lamp


def rooms_of(scene):
    fields = scene.GetFieldData()
    names, bounds = fields.GetAbstractArray("RoomNames"), fields.GetArray("RoomBounds")
    return {names.GetValue(i): bounds.GetTuple(i) for i in range(names.GetNumberOfValues())}


def ascii_name(name):
    return "".join(c if c.isascii() and c.isalnum() else "_" for c in name)


def place(rooms):
    """A downlight 0.1 m under the top of each room's box (the attic's: 2.3 m over its floor)."""
    lights = []
    for name, b in rooms.items():
        top = b[5] - 0.1 if b[5] - b[4] < 3.0 else b[4] + 2.3
        lights.append((ascii_name(name), name, ((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, top)))
    return lights


def write_radiance(scene, lights, folder):
    """The imported surfaces as Radiance polygons, one plastic per reflectance, and one
    octree per luminaire (its ies2rad description placed)."""
    points = vtk_to_numpy(scene.GetPoints().GetData()).astype(float)
    rho = relight.cell_array(scene, "Reflectance")
    cells = scene.GetPolys()
    offsets, connectivity = vtk_to_numpy(cells.GetOffsetsArray()), vtk_to_numpy(cells.GetConnectivityArray())
    materials, lines = {}, []
    for c in range(scene.GetNumberOfCells()):
        key = tuple(round(float(v), 4) for v in rho[c])
        if key not in materials:
            materials[key] = f"m{len(materials)}"
            lines.append(f"void plastic {materials[key]} 0 0 5 {key[0]} {key[1]} {key[2]} 0 0")
        ids = connectivity[offsets[c]:offsets[c + 1]]
        coords = " ".join(f"{x:.7g}" for i in ids for x in points[i])
        lines.append(f"{materials[key]} polygon p{c} 0 0 {3 * len(ids)} {coords}")
    (folder / "house.rad").write_text("\n".join(lines) + "\n")


def rtrace(venv, light, at, ad, folder, runs=2):
    name, _, position = light
    bin_dir = pathlib.Path(radiance_tool(venv, "rtrace")).parent
    env = dict(os.environ, RAYPATH=".:" + str(bin_dir.parent / "lib"), PATH=f"{bin_dir}:{os.environ['PATH']}")
    subprocess.run([radiance_tool(venv, "ies2rad"), "-dm", "-o", name, str(DOWNLIGHT)], cwd=folder, env=env,
                   check=True, capture_output=True)
    (folder / f"{name}_scene.rad").write_text(
        f"!xform -t {position[0]} {position[1]} {position[2]} {name}.rad\n!cat house.rad\n")
    with open(folder / f"{name}.oct", "wb") as octree:
        subprocess.run([radiance_tool(venv, "oconv"), f"{name}_scene.rad"], cwd=folder, env=env, stdout=octree, check=True)
    rays = "\n".join(f"{p[0]:.9g} {p[1]:.9g} {p[2]:.9g} 0 0 1" for p in at) + "\n"
    return [rtrace_lux(venv, f"{name}.oct", rays, 8, ad, folder, env) for _ in range(runs)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--radiance", default=str(ROOT / "out" / "radiance-venv"))
    parser.add_argument("--ad", type=int, default=2048)
    parser.add_argument("--out", default=str(ROOT / "out" / "bench-house-luminaires"))
    args = parser.parse_args()
    out_dir = pathlib.Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    house = relight.import_scene(HOUSE, require_lights=False)
    rooms = rooms_of(house)
    lights = place(rooms)
    marked = relight.mark_lights(house, *[relight.luminaire(n, DOWNLIGHT, position=p) for n, _, p in lights])
    start = time.perf_counter()
    solver = relight.solve(marked)
    seconds = time.perf_counter() - start
    solved = solver.GetOutput()
    planes = {room: relight.work_plane(solver, room=room, up="z") for _, room, _ in lights}
    at = np.vstack([vtk_to_numpy(p.GetPoints().GetData()).astype(float) for p in planes.values()])
    which = np.concatenate([[room] * planes[room].GetNumberOfPoints() for room in planes])
    print(f"{HOUSE.name}: {solved.GetNumberOfCells()} elements, {len(lights)} luminaires, solved in {seconds:.1f} s; "
          f"{len(at)} work-plane points in {len(planes)} rooms", flush=True)
    rows, own, own_noise = [], [], []
    ours_total, theirs_total = np.zeros(len(at)), np.zeros(len(at))
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        write_radiance(house, lights, folder)
        for light in lights:
            name, room, _ = light
            ours = np.concatenate([relight.point_array(planes[r], "Illuminance_" + name)[:, 0] for r in planes])
            first, second = rtrace(args.radiance, light, at, args.ad, folder)
            theirs = 0.5 * (first + second)
            ours_total += ours
            theirs_total += theirs
            mine = which == room
            error = np.abs(ours[mine] - theirs[mine]).mean() / theirs[mine].mean()
            noise = 0.5 * np.abs(first[mine] - second[mine]).mean() / theirs[mine].mean()
            own.append(error), own_noise.append(noise)
            rows.append(f"{room:>12}: its work plane {ours[mine].mean():7.1f} lx ours, {theirs[mine].mean():7.1f} lx "
                        f"Radiance; mean |difference| {100 * error:.2f} % (Radiance's noise {100 * noise:.2f} %)")
            print(rows[-1], flush=True)
    total = np.abs(ours_total - theirs_total).mean() / theirs_total.mean()
    summary = (f"per room, its own luminaire: {100 * np.mean(own):.2f} % from Radiance (its noise "
               f"{100 * np.mean(own_noise):.2f} %); all {len(lights)} together over every plane: {100 * total:.2f} %; "
               f"solve {seconds:.1f} s")
    print(summary)
    (out_dir / "house_luminaires.txt").write_text("\n".join(rows + [summary]) + "\n")


if __name__ == "__main__":
    main()

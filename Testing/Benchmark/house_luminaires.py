#!/usr/bin/env python3
"""A real building lit by a manufacturer's luminaires in light groups, against Radiance:
KIT's FZK-Haus as IFC4 (through IfcOpenShell), ERCO downlights (their IES file) on a grid
under the ceiling of each room, each its own light, switched in 8 groups (a room each, the
room with the largest box, the attic, in two halves), and a work plane 0.8 m up in every room; the illuminance of
each group at the planes' points ours (the sum of its lights' solutions, as a light scene
weighs them) against Radiance's rtrace of the group (pyradiance, bench-only, in a venv).

Usage:
  ./relight python Testing/Benchmark/house_luminaires.py [--radiance out/radiance-venv]
      [--ad 2048] [--ab 16] [--spacing 2.5] [--out out/bench-house-luminaires] [--cost]

Radiance gets the building's surfaces as our solver does (the imported triangles, each
surface style a matte plastic of its colour) and each luminaire through ies2rad. Per
group, two rtrace runs with uncorrelated sampling give its noise. Reported per group (at
its own room's plane) and for all groups together.
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


def first_hit(locator, start, end):
    """The first surface on the segment from `start` to `end`, as its distance, or None."""
    from vtkmodules.vtkCommonCore import vtkPoints

    points = vtkPoints()
    locator.IntersectWithLine(start, end, 1e-6, points, None)
    if points.GetNumberOfPoints() == 0:
        return None
    return min(np.linalg.norm(np.array(points.GetPoint(i)) - start) for i in range(points.GetNumberOfPoints()))


def place(scene, rooms, spacing):
    """Downlights 0.1 m under the ceiling of each room (under its box's top where the room
    is open above; in the attic at most 2.3 m over its floor), on a grid at most `spacing` apart over the room's box, where a floor lies under
    the spot and a ceiling at least 2 m over it (not over an open hall, not outside a
    sloping roof), as (name, room, position, group): a group per room, the largest room's
    split into its two halves along its longer side (8 groups in the FZK-Haus's seven rooms)."""
    from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator

    locator = vtkStaticCellLocator()
    locator.SetDataSet(scene)
    locator.BuildLocator()
    largest = max(rooms, key=lambda r: (rooms[r][1] - rooms[r][0]) * (rooms[r][3] - rooms[r][2]))
    lights = []
    for name, b in rooms.items():
        nx, ny = (max(1, int(np.ceil((b[2 * a + 1] - b[2 * a]) / spacing))) for a in (0, 1))
        longer_x = b[1] - b[0] >= b[3] - b[2]
        for i in range(nx):
            for j in range(ny):
                x, y = b[0] + (i + 0.5) * (b[1] - b[0]) / nx, b[2] + (j + 0.5) * (b[3] - b[2]) / ny
                spot = np.array([x, y, b[4] + 1.0])
                down = first_hit(locator, spot, spot - [0, 0, 1.2])
                up = first_hit(locator, spot, spot + [0, 0, 10.0])
                if down is None or up is None or up < 1.0:
                    continue
                top = min(spot[2] + up, b[4] + 2.4 if b[5] - b[4] >= 3.0 else b[5]) - 0.1  # a pendant where it is higher
                group = ascii_name(name)
                if name == largest:
                    group += "_A" if (x < (b[0] + b[1]) / 2 if longer_x else y < (b[2] + b[3]) / 2) else "_B"
                lights.append((f"{ascii_name(name)}_{i}_{j}", name, (x, y, top), group))
    return lights


def write_radiance(scene, folder):
    """The imported surfaces as Radiance polygons, one plastic per reflectance."""
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


def rtrace(venv, group, members, at, ad, ab, folder, runs=2):
    """Radiance's illuminance at `at` (facing up) from the group's luminaires alone: `runs`
    times with every bounce, then once their direct light alone."""
    bin_dir = pathlib.Path(radiance_tool(venv, "rtrace")).parent
    env = dict(os.environ, RAYPATH=".:" + str(bin_dir.parent / "lib"), PATH=f"{bin_dir}:{os.environ['PATH']}")
    if not (folder / "downlight.rad").exists():
        subprocess.run([radiance_tool(venv, "ies2rad"), "-dm", "-o", "downlight", str(DOWNLIGHT)], cwd=folder, env=env,
                       check=True, capture_output=True)
    placed = "".join(f"!xform -t {p[0]} {p[1]} {p[2]} downlight.rad\n" for _, _, p, _ in members)
    (folder / f"{group}_scene.rad").write_text(placed + "!cat house.rad\n")
    with open(folder / f"{group}.oct", "wb") as octree:
        subprocess.run([radiance_tool(venv, "oconv"), f"{group}_scene.rad"], cwd=folder, env=env, stdout=octree, check=True)
    rays = "\n".join(f"{p[0]:.9g} {p[1]:.9g} {p[2]:.9g} 0 0 1" for p in at) + "\n"
    return [rtrace_lux(venv, f"{group}.oct", rays, bounces, ad, folder, env) for bounces in [ab] * runs + [0]]


def cost(house, lights, runs=2):
    """Solve seconds at the defaults with the luminaires, and with area lights in their places
    (disks of 0.15 m facing down, each its own light): means of `runs`, taken in turn."""
    lit = relight.mark_lights(house, *[relight.luminaire(n, DOWNLIGHT, position=p) for n, _, p, _ in lights])
    disks = relight.mark_lights(house, *[relight.area_light(n, centre=p, normal=(0, 0, -1), size=0.15, disk=True)
                                         for n, _, p, _ in lights])
    seconds = {"luminaires": [], "area lights": []}
    for _ in range(runs):
        for label, marked in (("luminaires", lit), ("area lights", disks)):
            start = time.perf_counter()
            relight.solve(marked)
            seconds[label].append(time.perf_counter() - start)
    return {label: float(np.mean(values)) for label, values in seconds.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--radiance", default=str(ROOT / "out" / "radiance-venv"))
    parser.add_argument("--ad", type=int, default=2048)
    parser.add_argument("--ab", type=int, default=16,
                        help="Radiance's bounces (8 gave the same to 0.1 %% here; ours run until they converge)")
    parser.add_argument("--spacing", type=float, default=2.5, help="the downlights' grid in each room, at most (m)")
    parser.add_argument("--out", default=str(ROOT / "out" / "bench-house-luminaires"))
    parser.add_argument("--cost", action="store_true", help="only time the solve against area lights in the same places")
    args = parser.parse_args()
    out_dir = pathlib.Path(args.out)
    out_dir.mkdir(parents=True, exist_ok=True)
    venv = str(pathlib.Path(args.radiance).resolve())
    house = relight.import_scene(HOUSE, require_lights=False)
    rooms = rooms_of(house)
    lights = place(house, rooms, args.spacing)
    if args.cost:
        times = cost(house, lights)
        print(f"{len(lights)} luminaires {times['luminaires']:.1f} s, area lights {times['area lights']:.1f} s, "
              f"ratio {times['luminaires'] / times['area lights']:.2f} (means of 2, one run)")
        return
    groups = {}
    for light in lights:
        groups.setdefault(light[3], []).append(light)
    marked = relight.mark_lights(house, *[relight.luminaire(n, DOWNLIGHT, position=p) for n, _, p, _ in lights])
    start = time.perf_counter()
    solver = relight.solve(marked)
    seconds = time.perf_counter() - start
    solved = solver.GetOutput()
    planes, direct = {}, {}
    for room in rooms:
        try:
            planes[room] = relight.work_plane(solver, room=room, up="z")
            direct[room] = relight.work_plane(solver, room=room, up="z", rays=0)  # no reflected light
        except RuntimeError as error:  # no point of its box stands in it
            print(f"{room}: no work plane ({error})")
    at = np.vstack([vtk_to_numpy(p.GetPoints().GetData()).astype(float) for p in planes.values()])
    which = np.concatenate([[room] * planes[room].GetNumberOfPoints() for room in planes])
    print(f"{HOUSE.name}: {solved.GetNumberOfCells()} elements, {len(lights)} luminaires in {len(groups)} groups, "
          f"solved in {seconds:.1f} s; {len(at)} work-plane points in {len(planes)} rooms", flush=True)
    rows, own, own_noise, own_direct = [], [], [], []
    ours_total, theirs_total = np.zeros(len(at)), np.zeros(len(at))
    with tempfile.TemporaryDirectory() as folder:
        folder = pathlib.Path(folder)
        write_radiance(house, folder)
        for group, members in groups.items():
            room = members[0][1]
            if room not in planes:
                continue

            def at_planes(source):
                # The mean of the channels, as rtrace_lux takes Radiance's (the roof's inside is
                # orange: its red channel alone reflects twice the mean).
                return sum(np.concatenate([relight.point_array(source[r], "Illuminance_" + m[0]).mean(axis=1)
                                           for r in source]) for m in members)
            ours, ours_direct = at_planes(planes), at_planes(direct)
            first, second, theirs_direct = rtrace(venv, group, members, at, args.ad, args.ab, folder)
            theirs = 0.5 * (first + second)
            ours_total += ours
            theirs_total += theirs
            mine = which == room
            error = np.abs(ours[mine] - theirs[mine]).mean() / theirs[mine].mean()
            noise = 0.5 * np.abs(first[mine] - second[mine]).mean() / theirs[mine].mean()
            direct_error = np.abs(ours_direct[mine] - theirs_direct[mine]).mean() / theirs_direct[mine].mean()
            own.append(error), own_noise.append(noise), own_direct.append(direct_error)
            rows.append(f"{group:>14} ({len(members)} in {room}): its room's plane {ours[mine].mean():7.1f} lx ours, "
                        f"{theirs[mine].mean():7.1f} lx Radiance; mean |difference| {100 * error:.2f} % "
                        f"(Radiance's noise {100 * noise:.2f} %); direct light alone {ours_direct[mine].mean():7.1f} / "
                        f"{theirs_direct[mine].mean():7.1f} lx, {100 * direct_error:.2f} %")
            print(rows[-1], flush=True)
    total = np.abs(ours_total - theirs_total).mean() / theirs_total.mean()
    summary = (f"per group, at its room's plane: {100 * np.mean(own):.2f} % from Radiance (its noise "
               f"{100 * np.mean(own_noise):.2f} %; direct light alone {100 * np.mean(own_direct):.2f} %); all {len(groups)} groups on, over every plane: {100 * total:.2f} %; "
               f"solve {seconds:.1f} s")
    print(summary)
    (out_dir / "house_luminaires.txt").write_text("\n".join(rows + [summary]) + "\n")


if __name__ == "__main__":
    main()

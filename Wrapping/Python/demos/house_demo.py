"""A real building: ``./relight demo house``.

KIT's FZK-Haus (an IFC model from Debian's ``assimp-testmodels``) is read with
``import_scene`` (through assimp), six ceiling lamps are added with Mark Lights, the
house is meshed coarsely and solved once, and then relit through four settings, each
rendered from inside both storeys (PNG) and once as HDR (OpenEXR).
"""

import argparse
import pathlib
import time

import numpy as np

from relight import (
    import_scene,
    light_names,
    point_array,
    render_png,
    solve,
    vtkRadiosityLightMarker,
    vtkRadiosityRelight,
    write_exr,
)

IFC = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc"
# Lamp spots from Testing/Benchmark/house.py's search of the rooms (a ceiling 2.2-3.2 m
# up, walls at least 0.4 m away), three per storey; the model is Y-up, in metres.
LAMPS = [
    ("Ground 1", (6.0, 2.48, -5.2)),
    ("Ground 2", (11.2, 2.48, -9.2)),
    ("Ground 3", (1.2, 2.48, -8.8)),
    ("Upper 1", (5.6, 5.836, -5.2)),
    ("Upper 2", (11.2, 4.912, -6.8)),
    ("Upper 3", (0.8, 4.912, -3.2)),
]
# Standing against a wall of each storey, eye 1.5 m up, looking across the room.
CAMERAS = [
    ((7.21, 1.5, -5.2), (1.51, 1.1, -5.2), (0.0, 1.0, 0.0), 80.0),
    ((0.5, 4.2, -3.2), (11.4, 3.8, -3.2), (0.0, 1.0, 0.0), 80.0),
]
LAMP_SIZE = 0.3  # m, square
WARM, COOL = (1.0, 0.78, 0.55), (0.7, 0.85, 1.0)


def settings(names):
    """(title, {light: (color, intensity relative to the exposure's, on)}) per picture."""
    ground = {n: n.startswith("Ground") for n in names}
    return [
        ("all lamps, white", {n: ((1, 1, 1), 1.0, True) for n in names}),
        ("ground floor warm", {n: (WARM, 2.0, ground[n]) for n in names}),
        ("upper floor cool", {n: (COOL, 2.0, not ground[n]) for n in names}),
        ("one lamp per storey", {n: (WARM, 3.0, n.endswith("1")) for n in names}),
    ]


def add_lamps(house):
    marker = vtkRadiosityLightMarker()
    marker.SetInputData(house)
    for name, centre in LAMPS:
        marker.AddAreaLight(name, 0, *centre, 0, -1, 0, LAMP_SIZE, LAMP_SIZE, 1, 1, 1)
    marker.Update()
    return marker.GetOutput()


def exposure_for(relit):
    """Puts the 99th percentile of the lit walls at 0.8 (the lamps, at 1, are left out)."""
    relit.SetExposure(1.0)
    relit.Update()
    b = point_array(relit.GetOutput(), "Radiosity").max(axis=1)
    lit = b[(b > 0) & (b < 0.5)]
    return 0.8 / np.percentile(lit, 99) if lit.size else 1.0


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="out", help="output folder")
    parser.add_argument("--element", type=float, default=0.5, help="ElementSize in m (0.25: 144k elements, 8 min)")
    parser.add_argument("--patch", type=float, default=1.0, help="PatchSize in m")
    args = parser.parse_args()
    out = pathlib.Path(args.out) / "house"
    out.mkdir(parents=True, exist_ok=True)

    start = time.perf_counter()
    house = import_scene(IFC, require_lights=False)
    scene = add_lamps(house)
    print(f"{house.GetFieldData().GetAbstractArray('ImportSummary').GetValue(0)}; "
          f"{len(LAMPS)} lamps added; {time.perf_counter() - start:.1f} s")
    solver = solve(scene, args.patch, args.element)
    seconds = solver.GetLastSolveSeconds()
    solved = solver.GetOutput()
    method = solved.GetFieldData().GetAbstractArray("SolverMethod").GetValue(0)
    print(f"solve: {solved.GetNumberOfCells()} elements (coarse: element {args.element} m, patch {args.patch} m), "
          f"{seconds:.1f} s, {solver.GetLastShots()} shots, converged: {bool(solver.GetLastConverged())}; {method}")

    relit = vtkRadiosityRelight()
    relit.SetInputConnection(solver.GetOutputPort())
    names = light_names(solved)
    exposure = exposure_for(relit)
    times = []
    for picture, (title, lights) in enumerate(settings(names), 1):
        for name, (color, intensity, on) in lights.items():
            relit.SetLightSetting(name, *color, intensity, int(on))
        relit.SetExposure(exposure)
        begin = time.perf_counter()
        relit.Update()
        times.append(time.perf_counter() - begin)
        for view, camera in enumerate(CAMERAS, 1):
            render_png(relit.GetOutput(), out / f"house_{picture}_view{view}.png", camera)
        print(f"  picture {picture}: {title}")
    write_exr(relit.GetOutput(), out / "house_view1.exr", CAMERAS[0])
    print(f"relight: {1e3 * np.mean(times):.1f} ms per setting ({solved.GetNumberOfCells()} elements, "
          f"k = {len(names)}); {2 * len(times)} PNGs and house_view1.exr in {out}/")


if __name__ == "__main__":
    main()

"""The main job: mesh and solve the 8-light scene once, then relight it many times.

Run with ``./relight demo``. Writes PNG frames and one OpenEXR (HDR) image into the
output folder and prints the sampling time, the per-frame relight time and the memory
each light's solution takes.
"""

import argparse
import pathlib
import time

from relight import (
    FrameRenderer,
    light_names,
    read_polydata,
    render_png,
    vtkLightTaggedRadiosity,
    vtkRadiosityMesher,
    vtkRadiosityRelight,
    write_exr,
)

# Inside the 4 x 2.5 x 4 m room, near the z = 0 wall, looking across it.
CAMERA = ((2.0, 1.5, 0.05), (2.0, 0.9, 4.0), (0.0, 1.0, 0.0), 80.0)
INTENSITY = 1.0  # the lamps' default (unit exitance); the pictures are metered on it


def light_sequence(names):
    """(title, {light index: (color or None, intensity, enabled)}) for each frame."""
    k = len(names)
    everything = {i: (None, INTENSITY, True) for i in range(k)}
    first_half = {i: (None, INTENSITY * 2, i < k // 2) for i in range(k)}
    second_half = {i: (None, INTENSITY * 2, i >= k // 2) for i in range(k)}
    sunset = {i: ((1.0, 0.45, 0.15), INTENSITY * (1.5 if i % 2 else 0.3), True) for i in range(k)}
    night = {i: ((0.35, 0.45, 1.0), INTENSITY * 0.6, True) for i in range(k)}
    single = {i: (None, INTENSITY * 6, i == 0) for i in range(k)}
    return [
        ("all lights, their own colors", everything),
        ("first half of the lights", first_half),
        ("second half of the lights", second_half),
        ("warm, alternating intensities", sunset),
        ("cool blue, dimmed", night),
        (f"only {names[0]}", single),
    ]


def animate(solver, names, out, frames=32):
    """Lights come up one after another, driven by a schedule; PNG frames plus a movie."""
    from vtkmodules.vtkIOImage import vtkPNGWriter

    animated = vtkRadiosityRelight()
    animated.SetInputConnection(solver.GetOutputPort())
    period = frames / len(names)
    colors = solver.GetOutput().GetFieldData().GetArray("LightDefaultColors")
    for i, name in enumerate(names):
        color = colors.GetTuple3(i)
        for t, level in ((i * period - period, 0.1), (i * period, 4.0), (i * period + 2 * period, 0.1)):
            animated.AddScheduleEntry(t, name, *color, INTENSITY * level, 1)
    folder = out / "animation"
    folder.mkdir(exist_ok=True)
    renderer = FrameRenderer(CAMERA, (480, 360))
    movie = None
    try:
        from vtkmodules.vtkIOOggTheora import vtkOggTheoraWriter
        movie = vtkOggTheoraWriter()
        movie.SetFileName(str(out / "relight_animation.ogv"))
        movie.SetRate(8)
        movie.SetQuality(2)
    except ImportError:
        print("no movie encoder in this VTK: writing frames only")
    png = vtkPNGWriter()
    times = []
    for frame in range(frames):
        start = time.perf_counter()
        animated.UpdateTimeStep(float(frame))
        times.append(time.perf_counter() - start)
        image = renderer.render(animated.GetOutput())
        png.SetInputData(image)
        png.SetFileName(str(folder / f"frame_{frame:02d}.png"))
        png.Write()
        if movie is not None:
            movie.SetInputData(image)
            if frame == 0:
                movie.Start()
            movie.Write()
    if movie is not None:
        movie.End()
    renderer.close()
    print(f"animation: {frames} frames in {folder}/" + (f", movie {movie.GetFileName()}" if movie else "") +
          f"; relight per frame {1e3 * sum(times) / len(times):.3f} ms (schedule interpolation included)")


def moving_light(scene_path, out, frames=24):
    """A point light circling the room (paper 2.4): direct light shot per frame, the
    interreflection from the patch basis; the room's own lamps are off."""
    import math

    from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkIOImage import vtkPNGWriter

    mesher = vtkRadiosityMesher()
    mesher.SetInputData(read_polydata(scene_path))
    mesher.SetPatchSize(1.5)
    mesher.SetElementSize(0.375)
    solver = vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    solver.PatchBasisOn()
    start = time.perf_counter()
    solver.Update()
    basis_seconds = time.perf_counter() - start
    basis = solver.GetOutput().GetCellData().GetArray("PatchBasis")
    light = vtkPolyData()
    points = vtkPoints()
    points.InsertNextPoint(2.0, 1.8, 2.0)
    verts = vtkCellArray()
    verts.InsertNextCell(1, [0])
    light.SetPoints(points)
    light.SetVerts(verts)
    for name, values in (("Color", (1.0, 0.85, 0.6)), ("Intensity", (0.6,))):
        array = vtkFloatArray()
        array.SetName(name)
        array.SetNumberOfComponents(len(values))
        array.InsertNextTuple(values)
        light.GetPointData().AddArray(array)
    moving = vtkRadiosityRelight()
    moving.SetInputConnection(0, solver.GetOutputPort())
    moving.SetInputData(1, light)
    for i in range(len(light_names(solver.GetOutput()))):
        moving.SetLightEnabled(i, False)
    folder = out / "moving"
    folder.mkdir(exist_ok=True)
    renderer = FrameRenderer(CAMERA, (480, 360))
    png = vtkPNGWriter()
    times = []
    for frame in range(frames):
        angle = 2 * math.pi * frame / frames
        points.SetPoint(0, 2.0 + 1.4 * math.cos(angle), 1.7, 2.0 + 1.4 * math.sin(angle))
        points.Modified()
        start = time.perf_counter()
        moving.Update()
        times.append(time.perf_counter() - start)
        png.SetInputData(renderer.render(moving.GetOutput()))
        png.SetFileName(str(folder / f"frame_{frame:02d}.png"))
        png.Write()
    renderer.close()
    patches = basis.GetNumberOfComponents() // 3
    print(f"moving light: basis of {patches} patches x {basis.GetNumberOfTuples()} elements "
          f"({basis.GetNumberOfTuples() * basis.GetNumberOfComponents() * 4 / 1024:.0f} KB) solved in "
          f"{basis_seconds:.2f} s; per frame {1e3 * sum(times) / len(times):.2f} ms "
          f"(shadow rays, basis, display colors); {frames} frames in {folder}/")


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--data", default="Data", help="folder with paper_8lights.vtp")
    parser.add_argument("--out", default="out", help="output folder")
    parser.add_argument("--shots", type=int, default=2000)
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    scene = read_polydata(pathlib.Path(args.data) / "paper_8lights.vtp")
    mesher = vtkRadiosityMesher()
    mesher.SetInputData(scene)
    mesher.SetPatchSize(1.5)
    mesher.SetElementSize(0.375)
    solver = vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    solver.SetMaximumShots(args.shots)
    solver.SetConvergenceThreshold(1e-3)
    mesher.Update()
    start = time.perf_counter()
    solver.Update()
    sampling = time.perf_counter() - start
    solved = solver.GetOutput()
    names = light_names(solved)
    print(
        f"scene: {scene.GetNumberOfCells()} polygons -> {solved.GetNumberOfCells()} elements, "
        f"{solved.GetNumberOfPoints()} points, k = {len(names)} lights"
    )
    print(
        f"sampling (light-tagged solve): {sampling:.3f} s, {solver.GetLastShots()} shots, "
        f"converged: {bool(solver.GetLastConverged())}, rays: {solver.GetLastRays()}"
    )

    fields = solved.GetFieldData()
    effects, decisions, reasons = (fields.GetAbstractArray(a) for a in ("Effects", "EffectDecisions", "EffectReasons"))
    for i in range(effects.GetNumberOfValues()):
        print(f"  effect {effects.GetValue(i):20s} {decisions.GetValue(i):9s} {reasons.GetValue(i)}")

    relight = vtkRadiosityRelight()
    relight.SetInputConnection(solver.GetOutputPort())
    frame_times = []
    for frame, (title, lights) in enumerate(light_sequence(names)):
        relight.ResetLights()
        for i, (color, intensity, enabled) in lights.items():
            if color is not None:
                relight.SetLightColor(i, *color)
            relight.SetLightIntensity(i, intensity)
            relight.SetLightEnabled(i, enabled)
        start = time.perf_counter()
        relight.Update()
        frame_times.append(time.perf_counter() - start)
        image = out / f"relight_{frame:02d}.png"
        render_png(relight.GetOutput(), image, CAMERA)
        print(f"frame {frame}: {title:32s} relight {frame_times[-1] * 1e3:7.3f} ms -> {image}")

    animate(solver, names, out)
    moving_light(pathlib.Path(args.data) / "paper_8lights.vtp", out)

    relight.ResetLights()
    for i in range(len(names)):
        relight.SetLightIntensity(i, INTENSITY)
    relight.Update()
    exr = out / "relight_hdr.exr"
    write_exr(relight.GetOutput(), exr, CAMERA)
    print(f"HDR image (linear radiosity, OpenEXR half): {exr}")

    per_light = 4 * 3 * (solved.GetNumberOfPoints() + solved.GetNumberOfCells())
    print(
        f"relight time per frame: mean {1e3 * sum(frame_times) / len(frame_times):.3f} ms, "
        f"best {1e3 * min(frame_times):.3f} ms (k = {len(names)}, "
        f"{solved.GetNumberOfCells()} elements; includes the display-color pass)"
    )
    print(
        f"memory per light: {per_light / 1024:.1f} KiB "
        f"(float RGB at {solved.GetNumberOfPoints()} points + {solved.GetNumberOfCells()} cells), "
        f"{len(names) * per_light / 1024:.1f} KiB for all {len(names)}"
    )


if __name__ == "__main__":
    main()

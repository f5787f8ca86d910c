"""What a light change costs next to a camera move, CPU path against GPU path.

./relight bench render [--cells 1000000] [--lights 8] [--frames 10]

The CPU path is the relight filter + VTK's mapper (DisplayColors): a light change runs
the filter and uploads new colors. The GPU path is vtkRadiosityRelightMapper: a light
change sets uniforms. The scene is a grid of quads with smooth, made-up per-light arrays
(the cost depends on the sizes, not on the values; solving 1M elements would take an
hour here). Prints milliseconds per frame and the ratios, measured in this one run, and
the mean difference between the two pictures."""

import argparse
import csv
import os
import time

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints, vtkStringArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow, vtkWindowToImageFilter

import relight


def lit_grid(cells, lights):
    """A square grid of about `cells` quads with `lights` smooth solution arrays."""
    n = int(round(np.sqrt(cells)))
    xs, ys = np.meshgrid(np.linspace(0, 1, n + 1), np.linspace(0, 1, n + 1))
    points = np.column_stack([xs.ravel(), ys.ravel(), np.zeros(xs.size)])
    data = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_support.numpy_to_vtk(points, deep=True))
    data.SetPoints(vtk_points)
    i, j = np.meshgrid(np.arange(n), np.arange(n))
    corner = (j * (n + 1) + i).ravel()
    quads = np.column_stack([corner, corner + 1, corner + n + 2, corner + n + 1])
    polys = vtkCellArray()
    polys.SetData(numpy_support.numpy_to_vtkIdTypeArray(np.arange(0, 4 * len(quads) + 1, 4, dtype=np.int64), deep=True),
                  numpy_support.numpy_to_vtkIdTypeArray(quads.ravel().astype(np.int64), deep=True))
    data.SetPolys(polys)
    names = vtkStringArray()
    names.SetName("LightNames")
    rng = np.random.default_rng(1)
    for light in range(lights):
        centre = rng.uniform(0, 1, 2)
        falloff = 1.0 / (1.0 + 40 * ((points[:, 0] - centre[0]) ** 2 + (points[:, 1] - centre[1]) ** 2))
        values = np.outer(falloff, rng.uniform(0.3, 1.0, 3)).astype(np.float32)
        array = numpy_support.numpy_to_vtk(values, deep=True)
        array.SetName(f"Radiosity_L{light}")
        data.GetPointData().AddArray(array)
        names.InsertNextValue(f"L{light}")
    data.GetFieldData().AddArray(names)
    defaults = vtkDoubleArray()
    defaults.SetName("LightDefaultColors")
    defaults.SetNumberOfComponents(3)
    for _ in range(lights):
        defaults.InsertNextTuple3(1, 1, 1)
    data.GetFieldData().AddArray(defaults)
    return data, len(quads)


def view(mapper, size):
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetAmbient(1.0)
    actor.GetProperty().SetDiffuse(0.0)
    renderer = vtkRenderer()
    renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.AddRenderer(renderer)
    window.SetSize(*size)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(0.5, -0.6, 0.9)
    camera.SetFocalPoint(0.5, 0.5, 0.0)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    window.Render()
    return window, renderer


def milliseconds_per_frame(window, step, frames):
    start = time.perf_counter()
    for frame in range(frames):
        step(frame)
        window.Render()
    return 1e3 * (time.perf_counter() - start) / frames


def picture(window):
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    return numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(float)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cells", type=int, default=1_000_000)
    parser.add_argument("--lights", type=int, default=8)
    parser.add_argument("--frames", type=int, default=10)
    parser.add_argument("--size", type=int, nargs=2, default=(800, 600))
    parser.add_argument("--out", default="out/bench")
    args = parser.parse_args()
    data, cells = lit_grid(args.cells, args.lights)
    intensity = lambda frame: 1.0 + 0.5 * (frame % 2)  # noqa: E731

    relit = relight.vtkRadiosityRelight()
    relit.SetInputData(data)
    relit.SetExposure(0.8)
    cpu_mapper = vtkPolyDataMapper()
    cpu_mapper.SetInputConnection(relit.GetOutputPort())
    cpu_mapper.SetScalarModeToUsePointData()
    cpu_mapper.SetColorModeToDirectScalars()
    gpu_mapper = relight.vtkRadiosityRelightMapper()
    gpu_mapper.SetInputData(data)
    gpu_mapper.SetExposure(0.8)
    rows = []
    pictures = []
    for label, mapper, light in (("CPU: relight filter + DisplayColors", cpu_mapper, relit),
                                 ("GPU: vtkRadiosityRelightMapper", gpu_mapper, gpu_mapper.GetLights())):
        window, renderer = view(mapper, args.size)
        camera = renderer.GetActiveCamera()
        move = milliseconds_per_frame(window, lambda frame: camera.Azimuth(0.5), args.frames)
        change = milliseconds_per_frame(window, lambda frame: light.SetLightIntensity(frame % args.lights, intensity(frame)),
                                        args.frames)
        light.SetLightIntensity(0, 1.0)
        for i in range(args.lights):
            light.SetLightIntensity(i, 1.0)
        camera.Azimuth(-0.5 * args.frames)
        window.Render()
        pictures.append(picture(window))
        rows.append(dict(path=label, cells=cells, lights=args.lights, camera_ms=round(move, 1), light_ms=round(change, 1),
                         ratio=round(change / move, 2)))
        window.Finalize()
    difference = np.abs(pictures[0] - pictures[1]).mean()
    print(f"{cells:,} quads, {args.lights} lights, {args.size[0]} x {args.size[1]}, {args.frames} frames each:")
    for row in rows:
        print(f"  {row['path']:38s} camera move {row['camera_ms']:8.1f} ms/frame   light change {row['light_ms']:8.1f} "
              f"ms/frame   light / camera {row['ratio']:.2f}")
    print(f"  GPU light change / CPU light change: {rows[1]['light_ms'] / rows[0]['light_ms']:.3f}; "
          f"pictures differ by {difference:.3f} / 255 on average; uploads by the GPU mapper: {gpu_mapper.GetUploadCount()}")
    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "render.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()

"""What a lighting designer reads off a solved scene: ``work_plane`` lays EN 12464-1's
calculation grid at a height over the floor (or in a room of an IFC file) and gathers the
illuminance per light at its points, ``write_work_plane_csv`` writes it as a table."""

from .errors import ErrorCatcher, _numbers
from .staging import AXES
from .vtkRadiosityFilters import vtkRadiosityWorkPlane


def work_plane(solved, height=0.8, border=0.5, spacing=0.0, up=None, rays=256, room=None):
    """The illuminance per light on a calculation grid `height` above the solved scene's
    floor, `border` in from its sides, at most `spacing` apart (0: EN 12464-1's for the
    area), gathered from the solver's output (`solved`: its output data or the solver).
    `up`: "x", "y" or "z" (None: the scene's shortest side). `room`: the name of a room of
    an IFC file (its IfcSpace, field arrays RoomNames and RoomBounds): the plane is laid in
    that room's box instead of the whole scene. Only the points over a floor (at most 1.5
    `height` down) are kept, in a room only those under a ceiling too. `rays`: cosine rays
    per point for the reflected light (0: direct light alone). Returns the grid (vtkPolyData:
    point arrays Illuminance_<light> and Illuminance, field arrays IlluminanceMean,
    IlluminanceMinimum, IlluminanceMaximum, Uniformity). Raises RuntimeError with the
    filter's message where it cannot be laid."""
    plane = vtkRadiosityWorkPlane()
    if hasattr(solved, "GetOutputPort"):
        plane.SetInputConnection(solved.GetOutputPort())
    else:
        plane.SetInputData(solved)
    if up is not None and up not in AXES:
        raise ValueError(f"up must be one of {', '.join(AXES)}, not {up!r}")
    plane.SetHeight(_numbers(height, 1, "work_plane: height", 0.0)[0])
    plane.SetBorder(_numbers(border, 1, "work_plane: border", 0.0)[0])
    plane.SetSpacing(_numbers(spacing, 1, "work_plane: spacing", 0.0)[0])
    plane.SetUpAxis(-1 if up is None else AXES[up])
    plane.SetGatherRays(int(rays))
    if room is not None:
        data = solved.GetOutput() if hasattr(solved, "GetOutput") else solved
        if hasattr(solved, "Update"):
            solved.Update()
        fields = data.GetFieldData()
        names, bounds = fields.GetAbstractArray("RoomNames"), fields.GetArray("RoomBounds")
        rooms = [names.GetValue(i) for i in range(names.GetNumberOfValues())] if names is not None and bounds else []
        if room not in rooms:
            raise ValueError(f"work_plane: no room is called {room!r}; the scene's rooms are {rooms}")
        plane.SetArea(*bounds.GetTuple(rooms.index(room)))
    catcher = ErrorCatcher(plane)
    plane.Update()
    if catcher.failed():
        raise RuntimeError(catcher.first_error())
    return plane.GetOutput()


def write_work_plane_csv(plane, path):
    """The work plane's points and illuminance as CSV: x, y, z, Illuminance, then each
    light's (the mean of its channels), with the statistics as comment lines."""
    from vtkmodules.util.numpy_support import vtk_to_numpy

    points = vtk_to_numpy(plane.GetPoints().GetData())
    data = plane.GetPointData()
    names = [data.GetArrayName(i) for i in range(data.GetNumberOfArrays()) if data.GetArrayName(i).startswith("Illuminance_")]
    columns = [vtk_to_numpy(data.GetArray("Illuminance"))] + [vtk_to_numpy(data.GetArray(n)).mean(axis=1) for n in names]
    fields = plane.GetFieldData()
    with open(path, "w") as out:
        for stat in ("IlluminanceMean", "IlluminanceMinimum", "IlluminanceMaximum", "Uniformity"):
            out.write(f"# {stat}: {fields.GetArray(stat).GetValue(0):.6g}\n")
        out.write(",".join(["x", "y", "z", "Illuminance"] + names) + "\n")
        for i, p in enumerate(points):
            out.write(",".join(f"{v:.6g}" for v in (*p, *(c[i] for c in columns))) + "\n")

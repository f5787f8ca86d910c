"""A solved scene's arrays as numpy: cells' areas and centroids, point and cell arrays, light names."""

from vtkmodules.util.numpy_support import vtk_to_numpy


def cell_areas(data):
    """Area of every cell, as a float64 numpy array."""
    from vtkmodules.vtkFiltersVerdict import vtkCellSizeFilter

    sizes = vtkCellSizeFilter()
    sizes.SetInputData(data)
    sizes.ComputeAreaOn()
    sizes.Update()
    return cell_array(sizes.GetOutput(), "Area").astype("float64")


def cell_centroids(data):
    """Mean of each cell's points, an (n, 3) numpy array."""
    import numpy as np

    out = np.empty((data.GetNumberOfCells(), 3))
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        out[c] = np.mean([data.GetPoint(ids.GetId(i)) for i in range(ids.GetNumberOfIds())], axis=0)
    return out


def light_names(data):
    """The light names in the field array LightNames, in LightId order."""
    names = data.GetFieldData().GetAbstractArray("LightNames")
    return [names.GetValue(i) for i in range(names.GetNumberOfValues())] if names else []


def point_array(data, name):
    """A point array as a numpy array (a view, no copy)."""
    array = data.GetPointData().GetAbstractArray(name)
    if array is None:
        raise KeyError(f"no point array {name!r}")
    return vtk_to_numpy(array)


def cell_array(data, name):
    """A cell array as a numpy array (a view, no copy)."""
    array = data.GetCellData().GetAbstractArray(name)
    if array is None:
        raise KeyError(f"no cell array {name!r}")
    return vtk_to_numpy(array)


def add_light_names(data, names):
    """Adds the field array LightNames (light i's name for its Radiosity_<name> arrays)."""
    from vtkmodules.vtkCommonCore import vtkStringArray

    array = vtkStringArray()
    array.SetName("LightNames")
    for name in names:
        array.InsertNextValue(name)
    data.GetFieldData().AddArray(array)
    return data


def add_field_ints(data, name, values):
    """Adds an integer field array, e.g. LightBanks or StaticLights (one value per light)."""
    from vtkmodules.vtkCommonCore import vtkIntArray

    array = vtkIntArray()
    array.SetName(name)
    for value in values:
        array.InsertNextValue(int(value))
    data.GetFieldData().AddArray(array)
    return data

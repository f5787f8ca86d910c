"""Solutions out: a light-tagged solve written as binary glTF, read back by
parsing the file here and by VTK's glTF loader, and as a layered OpenEXR that OpenEXR's
own exrheader lists. The relit picture must equal the sum of the light layers."""

import json
import os
import shutil
import struct
import subprocess
import tempfile

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkLogger

import relight
from relight import cell_array, light_names, point_array, read_polydata
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
folder = tempfile.mkdtemp()
COLORS = [(1.0, 0.8, 0.6), (0.3, 0.6, 1.0), (1.0, 0.2, 0.1)]
INTENSITIES = [3.0, 1.5, 0.5]
EXPOSURE = 2.5

solver = relight.solve(read_polydata(os.path.join(DATA, "paper_3lights.vtp")), 1.5, 0.75, ConvergenceThreshold=1e-3)
relit_filter = relight.vtkRadiosityRelight()
relit_filter.SetInputConnection(solver.GetOutputPort())
for i, (color, intensity) in enumerate(zip(COLORS, INTENSITIES)):
    relit_filter.SetLightColor(i, *color)
    relit_filter.SetLightIntensity(i, intensity)
relit_filter.Update()
relit = relit_filter.GetOutput()
names = light_names(relit)


def read_glb(path):
    """(JSON document, binary chunk) of a .glb file, checking its framing."""
    data = open(path, "rb").read()
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    json_length, json_type = struct.unpack_from("<I4s", data, 12)
    document = json.loads(data[20:20 + json_length])
    bin_length, bin_type = struct.unpack_from("<I4s", data, 20 + json_length)
    check(magic == b"glTF" and version == 2 and length == len(data) and json_type == b"JSON" and bin_type == b"BIN\0"
          and json_length % 4 == 0 and bin_length % 4 == 0, "GLB framing: magic, version 2, lengths, 4-byte chunks")
    return document, data[28 + json_length:28 + json_length + bin_length]


def accessor(document, binary, index):
    a = document["accessors"][index]
    view = document["bufferViews"][a["bufferView"]]
    dtype, width = {5126: (np.float32, 3), 5125: (np.uint32, 1)}[a["componentType"]]
    values = np.frombuffer(binary, dtype, a["count"] * width, view["byteOffset"])
    return values.reshape(-1, 3) if width == 3 else values


# --- glTF: every light's solution, the relit colors, names and default colors ---------------
glb = os.path.join(folder, "room.glb")
relight.write_gltf(relit, glb, exposure=EXPOSURE)
# Khronos' validator (npm gltf-validator, pinned with the web viewer and run by node).
validator = os.environ.get("RELIGHT_GLTF_VALIDATOR", "")
if check(validator and os.path.exists(validator) and shutil.which("node"), f"Khronos' glTF validator is built ({validator!r})"):
    run = subprocess.run([shutil.which("node"), validator, glb], capture_output=True, text=True, timeout=120)
    issues = json.loads(run.stdout) if run.returncode == 0 else {}
    check(issues.get("numErrors") == 0 and issues.get("numWarnings") == 0,
          f"the .glb passes Khronos' glTF validator: {issues or run.stderr[-300:]}")
document, binary = read_glb(glb)
primitive = document["meshes"][0]["primitives"][0]
lights = document["meshes"][0]["extras"]["relight"]["lights"]
check([entry["name"] for entry in lights] == names, f"extras name every light: {[e['name'] for e in lights]}")
for entry in lights:
    values = accessor(document, binary, primitive["attributes"][entry["attribute"]])
    expected = point_array(relit, "Radiosity_" + entry["name"]).astype(np.float32)
    check(entry["attribute"].startswith("_RADIOSITY_") and np.array_equal(values, expected),
          f"{entry['attribute']}: the unit solution of {entry['name']}, bit for bit in float")
defaults = numpy_support.vtk_to_numpy(relit.GetFieldData().GetArray("LightDefaultColors"))
check(np.allclose([entry["defaultColor"] for entry in lights], defaults), "extras carry the default colors")
check(np.allclose([entry["color"] for entry in lights], [np.asarray(c) * s for c, s in zip(COLORS, INTENSITIES)])
      and all(entry["enabled"] for entry in lights), "extras carry the relight filter's colors x intensities, on")
color = accessor(document, binary, primitive["attributes"]["COLOR_0"])
expected = np.clip(point_array(relit, "Radiosity") * EXPOSURE, 0, 1)
check(np.allclose(color, expected, atol=1e-6), "COLOR_0 is the relit radiosity x exposure, clamped")
# The sum a viewer computes from the light attributes gives the relit picture back.
mix = sum(np.asarray(c) * s * accessor(document, binary, primitive["attributes"][e["attribute"]])
          for c, s, e in zip(COLORS, INTENSITIES, lights))
check(np.allclose(mix, point_array(relit, "Radiosity"), rtol=1e-5, atol=1e-7), "sum of color x intensity x attribute = relit")
indices = accessor(document, binary, primitive["indices"])
positions = accessor(document, binary, primitive["attributes"]["POSITION"]).astype(float)
triangles = positions[indices.reshape(-1, 3)]
area = 0.5 * np.linalg.norm(np.cross(triangles[:, 1] - triangles[:, 0], triangles[:, 2] - triangles[:, 0]), axis=1).sum()
check(abs(area - relight.cell_areas(relit).sum()) < 1e-6 * area, f"the triangles cover the elements' area ({area:.4f} m^2)")
back = relight.import_scene(glb, require_lights=False)
check(np.allclose(back.GetBounds(), relit.GetBounds(), atol=1e-6) and back.GetNumberOfCells() == len(indices) // 3,
      f"VTK's glTF loader reads it back: {back.GetNumberOfCells()} triangles, same bounds")

# --- the solver's own output: colored as the relight filter starts (default colors, metered) --
glb = os.path.join(folder, "solved.glb")
relight.write_gltf(solver.GetOutput(), glb)
document, binary = read_glb(glb)
primitive = document["meshes"][0]["primitives"][0]
extras = document["meshes"][0]["extras"]["relight"]
at_defaults = relight.vtkRadiosityRelight()
at_defaults.SetInputConnection(solver.GetOutputPort())
at_defaults.Update()
metered = numpy_support.vtk_to_numpy(at_defaults.GetOutput().GetFieldData().GetArray("Exposure"))[0]
check(abs(extras["exposure"] - metered) < 1e-6 * metered and metered > 2,
      f"its exposure is metered as the relight filter meters at its defaults: {extras['exposure']:.3f} ({metered:.3f})")
mix = sum(np.asarray(e["defaultColor"]) * point_array(solver.GetOutput(), "Radiosity_" + e["name"]) for e in extras["lights"])
color = accessor(document, binary, primitive["attributes"].get("COLOR_0", primitive["attributes"]["POSITION"]))
check("COLOR_0" in primitive["attributes"] and np.allclose(color, np.clip(mix * extras["exposure"], 0, 1), atol=1e-5),
      "its COLOR_0 is every light at its default color x that exposure, clamped")

# --- a failed write leaves the old file; bad input is an error ------------------------------
size = os.path.getsize(glb)
os.mkdir(glb + ".part")
try:
    relight.write_gltf(relit, glb)
    check(False, "a write that cannot finish raises")
except OSError as error:
    check(os.path.getsize(glb) == size, f"a failed write leaves the old file whole ({error})")
os.rmdir(glb + ".part")
try:
    relight.write_gltf(relight.make_scene([], [], []), os.path.join(folder, "empty.glb"))
    check(False, "an empty scene is refused")
except OSError as error:
    check("no polygons" in str(error), f"an empty scene is refused: {error}")

# --- OpenEXR: one float layer per light beside the relit picture ------------------------------
exr = os.path.join(folder, "room.exr")
camera = ((2.0, 1.5, 0.05), (2.0, 0.9, 4.0), (0.0, 1.0, 0.0), 80.0)
relight.write_exr(relit, exr, camera, size=(64, 48), light_layers=True)
header = subprocess.run(["exrheader", exr], capture_output=True, text=True).stdout
for layer in [""] + names:
    for c in "RGB":
        channel = f"{layer}.{c}" if layer else c
        check(f"{channel}, 32-bit floating-point" in header, f"exrheader lists {channel} as 32-bit float")


def picture(array):
    writer = relight.exr_writer(relit, camera, (64, 48), array)
    image = vtkFloatArray()
    writer.RenderImage(image)
    return numpy_support.vtk_to_numpy(image).astype(float)


layers = sum(np.asarray(c) * s * picture("Radiosity_" + n) for c, s, n in zip(COLORS, INTENSITIES, names))
check(np.allclose(layers, picture("Radiosity"), rtol=1e-5, atol=1e-6), "the relit picture is the sum of the light layers")
# The ray scene is kept between renders of the same points and polygons (an animation's
# frames), and built again when they change: a moved copy is drawn where it now is, and
# the original again as it was.
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonCore import vtkPoints

before = picture("Radiosity")
moved = vtkPolyData()
moved.ShallowCopy(relit)
shifted = vtkPoints()
shifted.DeepCopy(relit.GetPoints())
for p in range(shifted.GetNumberOfPoints()):
    x, y, z = shifted.GetPoint(p)
    shifted.SetPoint(p, x + 0.5, y, z)
moved.SetPoints(shifted)
writer = relight.exr_writer(moved, camera, (64, 48), "Radiosity")
image = vtkFloatArray()
writer.RenderImage(image)
after = numpy_support.vtk_to_numpy(image).astype(float)
writer.SetArrayName("Radiosity_" + names[0])  # another array of the same geometry: an animation's next frame
writer.RenderImage(image)
check(writer.GetRaySceneBuilds() == 1, f"a second render of the same geometry reuses the ray scene "
                                       f"({writer.GetRaySceneBuilds()} built)")
check(np.array_equal(picture("Radiosity"), before) and not np.allclose(after, before),
      "a render after another mesh's is the same picture; the moved mesh is drawn moved")
for p in range(shifted.GetNumberOfPoints()):
    x, y, z = shifted.GetPoint(p)
    shifted.SetPoint(p, x - 0.5, y, z)  # the same points object, changed in place
shifted.Modified()
writer.SetArrayName("Radiosity")
writer.RenderImage(image)
back = numpy_support.vtk_to_numpy(image).astype(float)
check(np.abs(back - before).max() < 1e-3 * before.max() and not np.allclose(back, after),
      "points changed in place are drawn where they now are (the kept ray scene is rebuilt)")
check(writer.GetRaySceneBuilds() == 2, f"...and rebuilt once ({writer.GetRaySceneBuilds()} built)")
# The solver's own output (no relit Radiosity) with one light, and two lights whose names
# differ only by '.' and '_' (EXR's layer separator): every light keeps its layer.
one = relight.solve(read_polydata(os.path.join(DATA, "paper_1lights.vtp")), 1.5, 0.75, ConvergenceThreshold=1e-2).GetOutput()
single = os.path.join(folder, "one.exr")
relight.write_exr(one, single, camera, size=(32, 24), light_layers=True)
header = subprocess.run(["exrheader", single], capture_output=True, text=True).stdout
check(f"{light_names(one)[0]}.R, 32-bit floating-point" in header, f"one light, no relit array: its layer is written")
twins = relight.make_scene([[(0, 0, 0), (4, 0, 0), (4, 4, 0), (0, 4, 0)], [(1, 1, 2), (1, 2, 2), (2, 2, 2), (2, 1, 2)],
                            [(2.5, 2.5, 2), (2.5, 3, 2), (3, 3, 2), (3, 2.5, 2)]],
                           [(0.5, 0.5, 0.5)] * 3, [-1, 0, 1], ["Lamp.1", "Lamp_1"])
twins = relight.solve(twins, 2.0, 1.0, ConvergenceThreshold=1e-2).GetOutput()
twin_file = os.path.join(folder, "twins.exr")
relight.write_exr(twins, twin_file, ((2, -6, 6), (2, 2, 0), (0, 0, 1), 40), size=(32, 24), light_layers=True)
header = subprocess.run(["exrheader", twin_file], capture_output=True, text=True).stdout
check("Lamp_1.R," in header and "Lamp_1_2.R," in header, "lights 'Lamp.1' and 'Lamp_1' get layers Lamp_1 and Lamp_1_2")
try:
    relight.write_exr(relight.furnace_box(), os.path.join(folder, "x.exr"), camera, light_layers=True, array="None")
    check(False, "light layers of a scene without solutions are refused")
except OSError as error:
    check("Radiosity_<light>" in str(error), f"light layers need solutions: {error}")
finish("TestExport")

"""Scene files in: OBJ+MTL, glTF/GLB, PLY and VRML written here with known
contents, the FZK-Haus IFC through assimp and two VRML models of assimp-testmodels, and the
Cornell box as OBJ+MTL and as VRML solving to the same radiosity as Data/cornell_box.vtp. Bad files give an error naming the file and the problem."""

import base64
import json
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

import numpy as np
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import VTK_UNSIGNED_CHAR, vtkLogger
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkSelection, vtkSelectionNode
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkIOImage import vtkPNGWriter

import relight
from relight import cell_areas, cell_array, cell_centroids, light_names, read_polydata
from testlib import check, finish

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
folder = tempfile.mkdtemp()


def write(name, text):
    path = os.path.join(folder, name)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)
    return path


def fields(scene, name):
    array = scene.GetFieldData().GetAbstractArray(name)
    return [array.GetValue(i) for i in range(array.GetNumberOfValues())] if array else []


def import_error(path, **options):
    try:
        relight.import_scene(path, **options)
    except (OSError, ValueError) as error:
        return str(error)
    return None


# --- the Cornell box as OBJ + MTL solves to the same radiosity as the .vtp -----------------------
def write_obj(scene, name):
    """One material per cell (reflectance and emission as written), named after its light."""
    names = light_names(scene)
    rho = cell_array(scene, "Reflectance")
    ids = cell_array(scene, "LightId").astype(int)
    emission = cell_array(scene, "Emission")
    lines, mtl = [f"mtllib {name}.mtl"], []
    for p in range(scene.GetNumberOfPoints()):
        lines.append("v %.17g %.17g %.17g" % scene.GetPoint(p))
    for c in range(scene.GetNumberOfCells()):
        material = names[ids[c]] if ids[c] >= 0 else f"surface{c}"
        mtl += [f"newmtl {material}", "Kd %.17g %.17g %.17g" % tuple(rho[c])]
        if ids[c] >= 0:
            mtl.append("Ke %.17g %.17g %.17g" % tuple(emission[c]))
        cell = scene.GetCell(c)
        lines += [f"usemtl {material}", "f " + " ".join(str(cell.GetPointId(k) + 1) for k in range(cell.GetNumberOfPoints()))]
    write(name + ".mtl", "\n".join(mtl) + "\n")
    return write(name + ".obj", "\n".join(lines) + "\n")


box = read_polydata(os.path.join(DATA, "cornell_box.vtp"))
imported = relight.import_scene(write_obj(box, "cornell"))
check(light_names(imported) == light_names(box), f"light names from the materials: {light_names(imported)}")
check(np.allclose(cell_array(imported, "Reflectance"), cell_array(box, "Reflectance"), atol=1e-12),
      "reflectance as written in the MTL")
reference = relight.solve(box, 100.0, 50.0, ConvergenceThreshold=1e-4).GetOutput()
solved = relight.solve(imported, 100.0, 50.0, ConvergenceThreshold=1e-4).GetOutput()
for name in light_names(box):
    a, b = (cell_array(o, "Radiosity_" + name) for o in (reference, solved))
    check(a.shape == b.shape and np.allclose(a, b, rtol=1e-9, atol=1e-9 * a.max()),
          f"Cornell box from OBJ+MTL solves as the .vtp for {name} (max {a.max():.4g} vs {b.max():.4g})")

# --- OBJ details: objects, negative indices, degenerate faces, units --------------------------
write("two.mtl", "newmtl Bulb\nKd 0.8\nKe 5 5 4\nnewmtl Oak\nKd 1.2 0.4 0.2\n")
two_lamps = write("two.obj", """mtllib two.mtl
v 0 0 0
v 1000 0 0
v 1000 1000 0
v 0 1000 0
usemtl Oak
o Floor
f 1 2 3 4
v 400 400 2000
v 400 600 2000
v 600 600 2000
v 600 400 2000
o Lamp A
usemtl Bulb
f -4 -3 -2 -1
o Lamp B
f 5 6 7
g Junk
f 1 2 2
v 2000 0 0
f 1 2 9
""")
by_material = relight.import_scene(two_lamps, unit="mm")
check(light_names(by_material) == ["Bulb"], f"one light per emissive material: {light_names(by_material)}")
check(abs(by_material.GetBounds()[5] - 2.0) < 1e-12, f"millimetres to metres: top at {by_material.GetBounds()[5]} m")
summary = fields(by_material, "ImportSummary")
check(summary == ["two.obj: 3 polygons, 2 materials, 1 lights, 2 degenerate cells dropped"], f"summary line: {summary}")
warnings = " | ".join(fields(by_material, "Warnings"))
check("'Oak'" in warnings and "clamped" in warnings, f"a Kd above 1 is clamped, naming the material: {warnings}")
check(np.allclose(cell_array(by_material, "Reflectance")[0], [1.0, 0.4, 0.2]), "Oak's reflectance clamped to 1 in red")
check(np.allclose(cell_array(by_material, "Emission")[1], [5, 5, 4]), "Emission is the Ke color")
by_object = relight.import_scene(two_lamps, lights_per_object=True)
check(light_names(by_object) == ["Lamp A", "Lamp B"], f"one light per object: {light_names(by_object)}")

# --- glTF: node transforms, base color, emissive factor x KHR_materials_emissive_strength ------
def gltf_document(binary):
    """A floor (two triangles, white x 0.5/0.4/0.3) and a lamp quad 2 m up under a parent
    node scaled by 2, whose material emits (1, 0.5, 0.25) x strength 4."""
    positions = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0],
                          [0.2, 0.2, 1], [0.2, 0.3, 1], [0.3, 0.3, 1], [0.3, 0.2, 1]], dtype=np.float32)
    indices = np.array([0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7], dtype=np.uint16)
    blob = positions.tobytes() + indices.tobytes()
    buffer = {"byteLength": len(blob)}
    if not binary:
        buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
    document = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [{"name": "Floor", "mesh": 0}, {"name": "Rig", "scale": [2, 2, 2], "children": [2]},
                  {"name": "Lamp", "mesh": 1}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]},
                   {"primitives": [{"attributes": {"POSITION": 0}, "indices": 2, "material": 1}]}],
        "materials": [{"name": "Tiles", "pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.4, 0.3, 1]}},
                      {"name": "Panel", "emissiveFactor": [1, 0.5, 0.25],
                       "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 4}}}],
        "extensionsUsed": ["KHR_materials_emissive_strength"],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},
                        {"buffer": 0, "byteOffset": 96, "byteLength": 24}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"},
                      {"bufferView": 1, "byteOffset": 12, "componentType": 5123, "count": 6, "type": "SCALAR"}],
    }
    return document, blob


document, _ = gltf_document(binary=False)
gltf_path = write("room.gltf", json.dumps(document))
document, blob = gltf_document(binary=True)
text = json.dumps(document).encode()
text += b" " * (-len(text) % 4)
glb = struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(text) + 8 + len(blob)) + \
    struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(blob), b"BIN\0") + blob
glb_path = os.path.join(folder, "room.glb")
with open(glb_path, "wb") as f:
    f.write(glb)
for path in (gltf_path, glb_path):
    scene = relight.import_scene(path)
    kind = os.path.splitext(path)[1]
    ids = cell_array(scene, "LightId").astype(int)
    check(light_names(scene) == ["Panel"] and list(ids) == [-1, -1, 0, 0], f"{kind}: the emissive material is a light")
    check(np.allclose(cell_array(scene, "Emission")[ids == 0], [4, 2, 1]), f"{kind}: emissiveFactor x strength 4 = (4, 2, 1)")
    check(np.allclose(cell_array(scene, "Reflectance")[0], [0.5, 0.4, 0.3]), f"{kind}: baseColorFactor as reflectance")
    check(abs(scene.GetBounds()[5] - 2.0) < 1e-6 and abs(scene.GetBounds()[1] - 1.0) < 1e-6,
          f"{kind}: the parent's scale puts the lamp at z = 2 (bounds {scene.GetBounds()})")

# An emissive texture dims its factor by its mean: a 2 x 1 PNG, one pixel black, one white,
# is half the light in linear values (glTF multiplies factor and texture).
png = vtkPNGWriter()
pixels = vtkImageData()
pixels.SetDimensions(2, 1, 1)
pixels.AllocateScalars(VTK_UNSIGNED_CHAR, 3)
for i, v in enumerate((0, 0, 0, 255, 255, 255)):
    pixels.GetPointData().GetScalars().SetValue(i, v)
png.SetInputData(pixels)
png.WriteToMemoryOn()
png.Write()
document, _ = gltf_document(binary=False)
document["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(bytes(png.GetResult())).decode()}]
document["textures"] = [{"source": 0}]
document["materials"][1]["emissiveTexture"] = {"index": 0}
textured = relight.import_scene(write("textured.gltf", json.dumps(document)))
emission = cell_array(textured, "Emission")[cell_array(textured, "LightId") == 0]
check(np.allclose(emission, [2, 1, 0.5]), f"an emissive texture half white: (4, 2, 1) x 0.5 = (2, 1, 0.5), got {emission[0]}")
# The same for an OBJ's map_Ke, the texture beside the file.
with open(os.path.join(folder, "glow.png"), "wb") as f:
    f.write(bytes(png.GetResult()))
write("glow.mtl", "newmtl Floor\nKd 0.5 0.5 0.5\nnewmtl Glow\nKe 4 2 1\nmap_Ke glow.png\n")
glowing = relight.import_scene(write("glow.obj", "mtllib glow.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                     "v 0.2 0.2 1\nv 0.2 0.3 1\nv 0.3 0.3 1\nusemtl Floor\nf 1 2 3 4\n"
                                     "usemtl Glow\nf 5 6 7\n"))
emission = cell_array(glowing, "Emission")[cell_array(glowing, "LightId") == 0]
check(np.allclose(emission, [2, 1, 0.5]), f"an OBJ's map_Ke half white: Ke (4, 2, 1) x 0.5, got {emission}")

# A file without scenes lists every node; children must come once, with their parent. A
# mirroring scale turns faces inside out unless the corners are reversed (glTF 2.0, 3.7.4).
document, _ = gltf_document(binary=False)
del document["scenes"], document["scene"]
flat = relight.import_scene(write("noscene.gltf", json.dumps(document)))
check(flat.GetNumberOfCells() == 4, f"no scenes: each mesh once ({flat.GetNumberOfCells()} triangles, expected 4)")
document, _ = gltf_document(binary=False)
document["nodes"][0]["scale"] = [-1, 1, 1]
mirrored = relight.import_scene(write("mirror.gltf", json.dumps(document)))
normals = vtkPolyDataNormals()
normals.SetInputData(mirrored)
normals.ComputeCellNormalsOn()
normals.ConsistencyOff()
normals.AutoOrientNormalsOff()
normals.SplittingOff()
normals.Update()
floor_z = numpy_support.vtk_to_numpy(normals.GetOutput().GetCellData().GetArray("Normals"))[0, 2]
check(floor_z > 0.99, f"a floor mirrored in x still faces +z (normal z {floor_z:.2f})")

# --- VRML97: materials by DEF and USE, emissive colors, transforms ---------------------------
def vtk_importer_bounds(path):
    """The bounds of VTK's own importer's actors, in a process of their own: a second
    vtkVRMLImporter in one Python process can crash in VTK 9.2 (not the product's reader,
    which a test below runs twelve times)."""
    script = ("import sys, json; from vtkmodules.vtkIOImport import vtkVRMLImporter; "
              "import vtkmodules.vtkRenderingOpenGL2; i = vtkVRMLImporter(); i.SetFileName(sys.argv[1]); "
              "i.Update(); print(json.dumps(i.GetRenderer().ComputeVisiblePropBounds()))")
    done = subprocess.run([sys.executable, "-c", script, path], capture_output=True, text=True, timeout=120)
    return json.loads(done.stdout.strip().splitlines()[-1])


def vrml_faces(path):
    """Faces of a VRML file counted from its text (coordIndex runs of 3 or more corners),
    not through VTK: the count the import must give."""
    text = re.sub(r"#[^\n]*", "", open(path, encoding="latin-1").read())
    faces = 0
    for block in re.findall(r"coordIndex\s*\[([^\]]*)\]", text):
        run = 0
        for index in [int(v) for v in re.split(r"[\s,]+", block.strip()) if v] + [-1]:
            faces, run = (faces + (run >= 3), 0) if index < 0 else (faces, run + 1)
    return faces


def write_vrml(scene, name):
    """One Shape per cell; a Material DEF'd at its first cell and USEd by the next cells of
    the same colors (VTK's importer ignores USE of a Material); lamps named after lights."""
    names = light_names(scene)
    rho = cell_array(scene, "Reflectance")
    ids = cell_array(scene, "LightId").astype(int)
    emission = cell_array(scene, "Emission")
    defined, shapes = {}, []
    points = ", ".join("%.17g %.17g %.17g" % scene.GetPoint(p) for p in range(scene.GetNumberOfPoints()))
    for c in range(scene.GetNumberOfCells()):
        key = (tuple(rho[c]), tuple(emission[c]) if ids[c] >= 0 else (0, 0, 0))
        if key in defined:
            material = f"USE {defined[key]}"
        else:
            defined[key] = names[ids[c]] if ids[c] >= 0 else f"Surface{len(defined)}"
            emissive = " emissiveColor %.17g %.17g %.17g" % key[1] if ids[c] >= 0 else ""
            material = f"DEF {defined[key]} Material {{ diffuseColor %.17g %.17g %.17g{emissive} }}" % key[0]
        cell = scene.GetCell(c)
        corners = " ".join(str(cell.GetPointId(k)) for k in range(cell.GetNumberOfPoints()))
        coord = f"DEF Corners Coordinate {{ point [ {points} ] }}" if c == 0 else "USE Corners"
        shapes.append(f"Shape {{ appearance Appearance {{ material {material} }} "
                      f"geometry IndexedFaceSet {{ coord {coord} coordIndex [ {corners} -1 ] }} }}")
    return write(name + ".wrl", "#VRML V2.0 utf8\nTransform { children [\n" + "\n".join(shapes) + "\n] }\n")


vrml = relight.import_scene(write_vrml(box, "cornell"))
check(light_names(vrml) == light_names(box), f"VRML: light names from the DEF'd emissive materials: {light_names(vrml)}")
check(np.allclose(cell_array(vrml, "Reflectance"), cell_array(box, "Reflectance"), atol=1e-6),
      "VRML: reflectance from diffuseColor, USEd materials included")
solved = relight.solve(vrml, 100.0, 50.0, ConvergenceThreshold=1e-4).GetOutput()
for name in light_names(box):
    a, b = (cell_array(o, "Radiosity_" + name) for o in (reference, solved))
    check(a.shape == b.shape and np.allclose(a, b, rtol=1e-5, atol=1e-5 * a.max()),
          f"Cornell box from VRML solves as the .vtp for {name} (max {a.max():.4g} vs {b.max():.4g})")
room = relight.import_scene(write("room.wrl", """#VRML V2.0 utf8
DEF Walls Shape {
  appearance Appearance { material DEF Plaster Material { diffuseColor 0.5 0.4 0.3 } }
  geometry IndexedFaceSet { coord DEF C Coordinate { point [ 0 0 0, 2 0 0, 2 2 0, 0 2 0, 0 0 2, 2 0 2, 2 2 2, 0 2 2 ] }
                            coordIndex [ 0 1 2 3 -1, 4 7 6 5 -1, 0 4 5 1 -1, 2 6 7 3 -1, 0 3 7 4 -1, 1 5 6 2 -1 ] }
}
DEF Lamp Transform { translation 1 1 1.99 rotation 0 0 1 0.5 children [
  Shape { appearance Appearance { material DEF Ceiling_Lamp Material { diffuseColor 0.8 0.8 0.8 emissiveColor 10 9 8 } }
          geometry IndexedFaceSet { coord Coordinate { point [ -0.25 -0.25 0, -0.25 0.25 0, 0.25 0.25 0, 0.25 -0.25 0 ] }
                                    coordIndex [ 0 1 2 3 -1 ] } } ] }
"""))
lamp = cell_array(room, "LightId") == 0
centre = cell_centroids(room)[lamp]
check(light_names(room) == ["Ceiling_Lamp"] and lamp.sum() == 1 and np.allclose(cell_array(room, "Emission")[lamp], [10, 9, 8]),
      f"VRML: one light, named after its Material, emitting its emissiveColor: {light_names(room)}")
check(np.allclose(centre, [[1, 1, 1.99]]) and np.allclose(cell_areas(room)[lamp], 0.25),
      f"VRML: the Transform places the lamp ({centre.tolist()})")
check(np.allclose(cell_array(room, "Reflectance")[~lamp], [0.5, 0.4, 0.3]),
      "VRML: a Material without emissiveColor is a surface, not a white lamp (VTK's default ambient color)")
for wrl in ("Wuson.wrl", "MotionCaptureROM.WRL"):
    path = "/usr/share/assimp/models/WRL/" + wrl
    polygons = vrml_faces(path)
    scene = relight.import_scene(path, require_lights=False)
    bounds = vtk_importer_bounds(path)
    check(scene.GetNumberOfCells() == polygons and np.allclose(scene.GetBounds(), bounds, atol=1e-6) and not light_names(scene),
          f"{wrl} (assimp-testmodels): {scene.GetNumberOfCells()} polygons, placed as VTK's importer places its actors, no lights")
check("VRML 1.0" in (import_error(write("old.wrl", "#VRML V1.0 ascii\nSeparator { }\n")) or ""),
      "a VRML 1.0 file is refused by name")


def quad(y, appearance):
    return (f"Shape {{ appearance {appearance} geometry IndexedFaceSet {{ coord Coordinate "
            f"{{ point [0 {y} 0, 1 {y} 0, 1 {y} 1, 0 {y} 1] }} coordIndex [0 1 2 3 -1] }} }}\n")


tricky = relight.import_scene(write("tricky.wrl", "#VRML V2.0 utf8\n# was: DEF Red Material { diffuseColor 0 0 1 }\n"
    + quad(0, "DEF Glow Appearance { material DEF Red Material { # warm }\n diffuseColor 0.9 0.1 0.1 emissiveColor 1 0 0 "
              "ambientIntensity 0 } }")
    + quad(1, "USE Glow") + "# appearance Appearance { material USE Red }\n"
    + quad(2, "Appearance { material DEF Zlamp Material { emissiveColor 1 1 1 } }")
    + quad(3, "Appearance { material DEF Alamp Material { emissiveColor 1 1 1 } }")
    + quad(4, "Appearance { material Material { shininess 0.3 } }")), require_lights=False)
rho, ids = cell_array(tricky, "Reflectance"), cell_array(tricky, "LightId").astype(int).tolist()
check(light_names(tricky) == ["Red", "Zlamp", "Alamp"] and ids == [0, 0, 1, 2, -1]
      and np.allclose(rho[[0, 1]], [0.9, 0.1, 0.1]) and np.allclose(rho[[2, 3, 4]], 0.8),
      f"VRML as VRML resolves it: comments ignored, a USEd Appearance keeps its Material, ambientIntensity 0 "
      f"is no matter, two lamps of one color stay two, a Material without diffuseColor reflects 0.8 "
      f"({light_names(tricky)}, {ids})")
files = ["/usr/share/assimp/models/WRL/" + w for w in ("Wuson.wrl", "MotionCaptureROM.WRL")]
again = [relight.import_scene(f, require_lights=False).GetNumberOfCells() for _ in range(6) for f in files]
check(again == [vrml_faces(f) for f in files] * 6, "VRML files read again and again in one process give the same scenes")

# --- PLY: face colors (8-bit sRGB) as linear reflectance -------------------------------------
ply = write("tiles.ply", """ply
format ascii 1.0
element vertex 4
property float x
property float y
property float z
element face 2
property list uchar int vertex_indices
property uchar red
property uchar green
property uchar blue
end_header
0 0 0
1 0 0
1 1 0
0 1 0
3 0 1 2 255 128 0
3 0 2 3 10 10 10
""")
tiles = relight.import_scene(ply, require_lights=False)
srgb = lambda v: v / 12.92 if v <= 0.04045 else ((v + 0.055) / 1.055) ** 2.4  # noqa: E731
expected = [[srgb(255 / 255), srgb(128 / 255), 0], [srgb(10 / 255)] * 3]
check(np.allclose(cell_array(tiles, "Reflectance"), expected), "PLY face colors as linear reflectance")

# --- the FZK-Haus IFC (Debian's assimp-testmodels) through assimp -----------------------------
ifc = "/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc"
house = relight.import_scene(ifc, require_lights=False)
materials = fields(house, "MaterialNames")
size = [house.GetBounds()[2 * i + 1] - house.GetBounds()[2 * i] for i in range(3)]
check(house.GetNumberOfCells() > 10000 and "Ziegel" in materials and "Glas" in materials,
      f"FZK-Haus through assimp: {house.GetNumberOfCells()} polygons, materials {materials}")
check(14 < max(size) < 20 and min(size) > 5, f"FZK-Haus in metres: {size}")

# A texture beside a model that assimp converts (into a temporary folder) is found there: the
# Collada duck's duckCM.tga (a yellow duck with an orange beak) was looked for in the
# temporary folder and the duck came out white.
duck = relight.import_scene("/usr/share/assimp/models/Collada/duck.dae", require_lights=False)
rgb = np.asarray(cell_array(duck, "Reflectance")).reshape(-1, 3).mean(axis=0)
said = fields(duck, "Warnings")
check(rgb[0] > 0.8 and rgb[2] < 0.2 and not any("texture" in w for w in said),
      f"the Collada duck takes its texture from beside it: reflectance {np.round(rgb, 3)}, warnings {said}")
copied = os.path.join(folder, "untextured")
os.makedirs(copied, exist_ok=True)
shutil.copy("/usr/share/assimp/models/Collada/duck.dae", copied)
said = fields(relight.import_scene(os.path.join(copied, "duck.dae"), require_lights=False), "Warnings")
check(any("duckCM.tga'" in w and "is not in" in w and copied in w for w in said),
      f"...and without it, the warning names the texture and where it was looked for: {said}")

# Textures named otherwise than they lie (found by a new user's trial): a 3DS file names
# IMAGE1.JPG beside IMAGE1.jpg, a Collada file "\\..\\LWO\\...\\EarthCylindric.jpg" for
# ../LWO/.../earthCylindric.jpg, the FBX spider its author's D:\\...\\OBJ\\ folder, which sits
# beside the FBX folder. Each was white before, said as not found.
for model in ("3DS/test1.3ds", "Collada/earthCylindrical.DAE", "FBX/spider.fbx"):
    said = fields(relight.import_scene("/usr/share/assimp/models/" + model, require_lights=False), "Warnings")
    check(not any("texture" in w for w in said), f"{model}: its textures found ({said})")
spiders = [np.asarray(cell_array(relight.import_scene("/usr/share/assimp/models/" + m, require_lights=False),
                                 "Reflectance")).mean(axis=0) for m in ("FBX/spider.fbx", "OBJ/spider.obj")]
check(np.allclose(spiders[0], spiders[1], atol=1e-6) and spiders[0].max() < 0.2,
      f"the FBX spider as colored as the OBJ beside it: {np.round(spiders[0], 4)} and {np.round(spiders[1], 4)}")
# The FBX's own unit (UnitScaleFactor: centimetres per unit), which assimp leaves unapplied:
# the FBX spider came in 100 times the OBJ beside it.
sizes = [relight.import_scene("/usr/share/assimp/models/" + m, require_lights=False).GetBounds()
         for m in ("FBX/spider.fbx", "OBJ/spider.obj")]
check(np.allclose(sizes[0], sizes[1], rtol=1e-6), f"the FBX spider in metres as the OBJ: {np.round(sizes[0], 2)} and {np.round(sizes[1], 2)}")
# Nothing known of a surface's color: white (a perfect reflector) came in silently; now 0.8,
# said. An STL (assimp's white default material); a PLY whose colors are floats, which
# VTK's reader takes as 8-bit values (its blue 1.0 came in as 0.0003).
for model, words in (("STL/Spider_ascii.stl", "gives no material"), ("PLY/float-color.ply", "floating-point")):
    scene = relight.import_scene("/usr/share/assimp/models/" + model, require_lights=False)
    said, rho = fields(scene, "Warnings"), np.asarray(cell_array(scene, "Reflectance"))
    check(np.allclose(rho, 0.8) and any(words in w and "reflectance 0.8" in w for w in said),
          f"{model}: reflectance {np.unique(rho)}, said ({said})")

# --- Mark Lights: by material pattern, cell id, selection; area lights ---------------------------
def marked(scene, name="Light", pattern=None, ids=(), areas=(), selection=None, emission=(1, 1, 1)):
    marker = relight.vtkRadiosityLightMarker()
    marker.SetInputData(scene)
    marker.SetLightName(name)
    if pattern:
        marker.SetMaterialPattern(pattern)
    for i in ids:
        marker.AddCellId(i)
    for area in areas:
        marker.AddAreaLight(*area)
    if selection is not None:
        marker.SetInputData(1, selection)
    marker.SetEmission(*emission)
    catcher = relight.ErrorCatcher(marker)
    marker.Update()
    return marker.GetOutput(), catcher


windows, _ = marked(house, "Windows", pattern="GLAS*", emission=(2, 2, 2))
glass = materials.index("Glas")
is_glass = cell_array(house, "MaterialIds").astype(int) == glass
lit = cell_array(windows, "LightId").astype(int)
check(light_names(windows) == ["Windows"] and np.array_equal(lit >= 0, is_glass) and is_glass.sum() > 0,
      f"FZK-Haus: the pattern 'GLAS*' makes the {is_glass.sum()} glass cells the light 'Windows'")
check(np.allclose(cell_array(windows, "Emission")[is_glass], 2), "the marked cells emit the Emission given")
# Meshed as house.py meshes it (0.5 / 0.25 m), the windows as lamps grading what they light:
# the mesh is made (not refused by the size check), finer than without grading, and the
# panel's estimate counts it exactly.
counts = []
for grading in (0.0, 0.2):
    house_mesher = relight.vtkRadiosityMesher()
    house_mesher.SetInputData(windows)
    house_mesher.SetPatchSize(0.5)
    house_mesher.SetElementSize(0.25)
    house_mesher.SetLampGrading(grading)
    meshing = relight.ErrorCatcher(house_mesher)
    house_mesher.Update()
    counts.append((house_mesher.GetOutput().GetNumberOfCells(), house_mesher.EstimateElements(0.5, 0.25),
                   " ".join(meshing.errors)))
check(not counts[1][2] and counts[1][0] > counts[0][0] > 0 and counts[1][1] == counts[1][0],
      f"FZK-Haus meshed at 0.5 / 0.25 m with its windows grading: {counts[1][0]} elements, estimated "
      f"{counts[1][1]:.0f}, {counts[0][0]} ungraded ({counts[1][2] or 'no error'})")
_, catcher = marked(house, pattern="Lamp*")
check("no cell has a material matching 'Lamp*'" in catcher.first_error() and "'Ziegel'" in catcher.first_error(),
      f"a pattern that matches nothing is an error listing the materials: {catcher.first_error()[:90]}...")

# The box read back from OBJ (2 m cube, no lamp): a disk and a rectangle under the ceiling.
write("room.mtl", "newmtl Wall\nKd 0.5\n")
corners = [(0, 0, 0), (2, 0, 0), (2, 2, 0), (0, 2, 0), (0, 0, 2), (2, 0, 2), (2, 2, 2), (0, 2, 2)]
faces = ["f 1 2 3 4", "f 5 8 7 6", "f 1 5 6 2", "f 3 7 8 4", "f 1 4 8 5", "f 2 6 7 3"]
room = relight.import_scene(write("room.obj", "\n".join(["mtllib room.mtl", "usemtl Wall"] +
                                                        ["v %d %d %d" % c for c in corners] + faces) + "\n"),
                            require_lights=False)
# A point array, as readers add (normals): area lights must extend it too.
normals = numpy_support.numpy_to_vtk(np.ones((room.GetNumberOfPoints(), 3)), deep=True)
normals.SetName("Normals")
room.GetPointData().AddArray(normals)
lamps, catcher = marked(room, areas=[("Disk", 1, 0.6, 1, 1.99, 0, 0, -1, 0.4, 0, 5, 5, 5),
                                     ("Panel", 0, 1.4, 1, 1.99, 0, 0, -1, 0.5, 0.2, 1, 2, 3)])
areas = relight.cell_areas(lamps)
ids = cell_array(lamps, "LightId").astype(int)
check(light_names(lamps) == ["Disk", "Panel"] and list(ids[-2:]) == [0, 1] and all(ids[:-2] == -1),
      f"two area lights appended, named: {light_names(lamps)}")
check(abs(areas[-2] - np.pi * 0.04) < 1e-12 and abs(areas[-1] - 0.1) < 1e-12,
      f"their areas: disk {areas[-2]:.6f} (pi 0.2^2), rectangle {areas[-1]:.6f} (0.5 x 0.2)")
check(not catcher.warnings, f"lamps facing into the room raise no warning ({catcher.warnings})")
check(lamps.GetPointData().GetArray("Normals").GetNumberOfTuples() == lamps.GetNumberOfPoints(),
      f"point arrays grow with the lamps' corners ({lamps.GetNumberOfPoints()} points)")
# The element solution's ledger (GatherRays 0): the final gather at the points is an estimate
# from rays, checked against closed forms in the core's FinalGather tests.
solved = relight.solve(lamps, 0.5, 0.25, ConvergenceThreshold=1e-6, MaximumShots=10**6, GatherRays=0).GetOutput()
rho = cell_array(solved, "Reflectance")[:, 0]
emitted = cell_array(solved, "Emission")[:, 0]
cells = relight.cell_areas(solved)
for light, name in enumerate(light_names(solved)):
    b = cell_array(solved, "Radiosity_" + name)[:, 0]
    unit = np.where(cell_array(solved, "LightId").astype(int) == light, 1.0, 0.0)  # unit-emission solution
    absorbed = np.sum(cells * (1 - rho) * (b - unit) / rho)
    check(abs(absorbed - np.sum(cells * unit)) < 1e-3 * np.sum(cells * unit),
          f"{name}: the closed room absorbs what the area light emits ({absorbed:.5f} of {np.sum(cells * unit):.5f} m^2)")
floor = relight.cell_centroids(solved)[:, 2] < 1e-9
ceiling = (relight.cell_centroids(solved)[:, 2] > 2 - 1e-9)
b = cell_array(solved, "Radiosity_Disk")[:, 0]
check(b[floor].mean() > 1.5 * b[ceiling].mean(), f"the disk faces the floor ({b[floor].mean():.4f} vs ceiling {b[ceiling].mean():.4f})")
_, catcher = marked(room, areas=[("Upside", 0, 1, 1, 1.9995, 0, 0, 1, 0.5, 0.5, 1, 1, 1)])
check(any("faces a surface closer than" in w for w in catcher.warnings), f"a lamp facing the ceiling 0.5 mm away warns: {catcher.warnings}")
_, catcher = marked(room, areas=[("Flat", 0, 1, 1, 1, 0, 0, 0, 0.5, 0.5, 1, 1, 1)])
check("'Flat' needs a finite centre and a non-zero normal" in catcher.first_error(), f"a zero normal: {catcher.first_error()}")
_, catcher = marked(room, ids=[99])
check("cell id 99 is not in 0..5" in catcher.first_error(), f"an id out of range: {catcher.first_error()}")

# Area lights added to a meshed scene get a patch each.
meshed = relight.vtkRadiosityMesher()
meshed.SetInputData(room)
meshed.SetPatchSize(1.0)
meshed.SetElementSize(0.5)
meshed.Update()
three, _ = marked(meshed.GetOutput(), areas=[(f"A{i}", 0, 0.5 + i, 1, 1.99, 0, 0, -1, 0.2, 0.2, 1, 1, 1) for i in range(3)])
patch = cell_array(three, "PatchId").astype(int)
check(len(set(patch[-3:])) == 3 and patch[-3:].min() > patch[:-3].max(),
      f"three area lights on a meshed scene get three new patches ({list(patch[-3:])} after {patch[:-3].max()})")

# Cells taken from the Cornell box's light: that light is left empty, so it goes.
ceiling_cells = [c for c in range(box.GetNumberOfCells()) if cell_array(box, "LightId")[c] >= 0]
moved, _ = marked(box, "Lamp", ids=ceiling_cells)
check(light_names(moved) == ["Lamp"] and set(cell_array(moved, "LightId").astype(int)) == {-1, 0},
      f"a light whose cells all moved is removed, ids without gaps: {light_names(moved)}")
node = vtkSelectionNode()
node.SetFieldType(vtkSelectionNode.CELL)
node.SetContentType(vtkSelectionNode.INDICES)
node.SetSelectionList(numpy_support.numpy_to_vtkIdTypeArray(np.array([2, 3], dtype=np.int64), deep=True))
selection = vtkSelection()
selection.AddNode(node)
picked, _ = marked(room, "Picked", selection=selection)
check(list(cell_array(picked, "LightId").astype(int)) == [-1, -1, 0, 0, -1, -1], "a selection's cells become the light")

# --- bad files: an error naming the file and the problem, nothing half-done ---------------------
cases = [
    ("a missing file", os.path.join(folder, "nowhere.obj"), "does not exist"),
    ("a typo in the name", os.path.join(folder, "earli.obj"), "does not exist or is not a regular file (did you mean 'early.obj'?)"),
    ("an unknown extension", write("scene.xyz", "1 2 3\n"), "'.xyz' is not a scene format"),
    ("a missing MTL", write("lost.obj", "mtllib lost.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "lost.mtl', which is missing"),
    ("a broken MTL", (write("broken.mtl", "newmtl A\nKd 0.5 abc 0.5\n"),
                      write("broken.obj", "mtllib broken.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl A\nf 1 2 3\n"))[1],
     "material library 'broken.mtl', line 2: Kd needs"),
    ("NaN in the OBJ", write("nan.obj", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n"), "nan.obj', line 2: a vertex coordinate is not"),
    ("a face before its vertices", write("early.obj", "v 0 0 0\nf 1 2 3\n"), "early.obj', line 2: face corner '2'"),
    ("a broken glTF", write("broken.gltf", "{ not json"), "broken.gltf' could not be read as glTF"),
    ("no emitter", ply, "no emissive material"),
    ("an IFC that is not one", write("fake.ifc", "this is no IFC\n"), "fake.ifc' could not be converted"),
]
for label, path, fragment in cases:
    error = import_error(path)
    check(error is not None and fragment in error and os.path.basename(path) in error, f"{label}: {error}")
try:
    relight.import_scene(two_lamps, unit="furlong")
    check(False, "an unknown unit is refused")
except ValueError as error:
    check("furlong" in str(error), f"an unknown unit is refused: {error}")
reader = relight.vtkRadiositySceneReader()
reader.SetFileName(os.path.join(folder, "early.obj"))
catcher = relight.ErrorCatcher(reader)
reader.Update()
check(reader.GetOutput().GetNumberOfCells() == 0 and len(catcher.errors) == 1,
      f"the reader's output is empty after an error, with one message ({len(catcher.errors)})")

finish("TestImport")

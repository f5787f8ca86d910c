#!/usr/bin/python3
"""Generate the RadiosityRelight test scenes as XML PolyData (.vtp).

Run with the system interpreter that ships ParaView's vtkmodules:

    /usr/bin/python3 Data/make_scenes.py

The files are written next to this script:

* ``paper_1lights.vtp``, ``paper_3lights.vtp``, ``paper_8lights.vtp`` --
  a test scene in the spirit of Nielsen & Christensen's radiosity relighting
  paper ("Without light sources the test scenes consist of 12 polygons"):
  a closed 4 x 2.5 x 4 m room (6 quads, normals facing into the room) with one
  1.2 x 1.2 x 2.4 m box standing on the floor (6 quads, normals facing out;
  its bottom face lies on the floor and is kept so the count stays 12), plus
  1, 3 or 8 small 0.3 x 0.3 m ceiling lamps hanging 1 cm below the ceiling,
  facing down.  Units: metres, y is up.
* ``cornell_box.vtp`` -- the Cornell box (Cornell Program of Computer
  Graphics measured data), millimetres, y up, open at z = 0.

Recommended mesher settings
---------------------------
Paper scenes: **PatchSize 1.5, ElementSize 0.375** (metres).
  Mesher rule assumed: a quad gets ceil(edge / PatchSize) patches along each
  side, each patch ceil(patch_edge / ElementSize) elements along each side.
  For the 12 non-light polygons this gives (every patch is 4 x 4 elements):
    floor, ceiling  4 x 4 m      -> 3 x 3 patches (1.33 m)       -> 2 x  9 =  18
    4 walls         4 x 2.5 m    -> 3 x 2 patches (1.33x1.25 m)  -> 4 x  6 =  24
    box top/bottom  1.2 x 2.4 m  -> 1 x 2 patches (1.2 m)        -> 2 x  2 =   4
    box long sides  2.4 x 1.2 m  -> 2 x 1 patches                -> 2 x  2 =   4
    box short sides 1.2 x 1.2 m  -> 1 x 1 patch                  -> 2 x  1 =   2
    total                                                 52 patches, 832 elements
  Each 0.3 m lamp adds 1 patch / 1 element.
  The target was ~60 patches / 960 elements (16 elements per patch).  With the
  room fixed at 4 x 2.5 x 4 m the room alone gives 80 patches for any
  PatchSize in [1, 1.25), 64 in [1.25, 1.33) and 42 in [1.33, 2), so 60 cannot
  be hit with a reasonably sized box; 52 / 832 (13 % under, exactly 16
  elements per patch, no edge/size ratio near an integer so float round-off
  cannot change the counts) was the closest clean choice.  The alternative
  PatchSize 1.3 / ElementSize 0.325 with a 1 m cube gives 70 / 1120.
  With the originally planned PatchSize 1.0 / ElementSize 0.25 these files
  give 112 patches / 1640 elements (the script prints both); no box can get
  those settings near 60 / 960, as the room alone is 80 / 1280.
Cornell box: PatchSize 100, ElementSize 25 (millimetres) is a sensible start:
  328 patches / 5248 elements for the 16 non-light polygons (red wall
  triangles estimated), 4 patches / 36 elements for the light.

Cell data in every file: ``Reflectance`` (float, 3 comps, in [0,1]),
``LightId`` (int, -1 for non-emitters, 0..k-1 for the k light quads),
``Emission`` (float, 3 comps, 0 for non-emitters).  Field data:
``LightNames`` (string array of k identifiers).
"""

import math
import os
import re
import sys

from vtkmodules.vtkCommonCore import (
    vtkFloatArray,
    vtkIntArray,
    vtkPoints,
    vtkStringArray,
)
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPolyDataWriter

HERE = os.path.dirname(os.path.abspath(__file__))

# Recommended mesher settings (see module docstring); used for the printed
# counts and asserted so the documentation cannot silently go stale.
PAPER_PATCH, PAPER_ELEMENT = 1.5, 0.375
PAPER_EXPECTED_COUNTS = (52, 832)  # patches, elements of the 12 non-lights
CORNELL_PATCH, CORNELL_ELEMENT = 100.0, 25.0


# --------------------------------------------------------------------------
# Small vector helpers (plain tuples; no numpy dependency needed).
# --------------------------------------------------------------------------
def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    assert n > 0.0, "zero-length vector"
    return tuple(x / n for x in a)


def centroid(pts):
    return tuple(sum(c) / len(pts) for c in zip(*pts))


def newell_normal(pts):
    """Right-hand-rule normal (Newell's method, robust for any planar-ish
    polygon, which is also what VTK's vtkPolygon::ComputeNormal does)."""
    n = [0.0, 0.0, 0.0]
    for i, p in enumerate(pts):
        q = pts[(i + 1) % len(pts)]
        n[0] += (p[1] - q[1]) * (p[2] + q[2])
        n[1] += (p[2] - q[2]) * (p[0] + q[0])
        n[2] += (p[0] - q[0]) * (p[1] + q[1])
    return unit(n)


def box_quads(lo, hi):
    """Six faces of an axis-aligned box, in arbitrary winding (orientation is
    fixed afterwards by Scene.add, so no hand-wound vertex lists here)."""
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    return {
        "bottom": [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)],
        "top":    [(x0, y1, z0), (x1, y1, z0), (x1, y1, z1), (x0, y1, z1)],
        "x0":     [(x0, y0, z0), (x0, y1, z0), (x0, y1, z1), (x0, y0, z1)],
        "x1":     [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)],
        "z0":     [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0)],
        "z1":     [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)],
    }


# --------------------------------------------------------------------------
# Scene assembly
# --------------------------------------------------------------------------
class Scene:
    """Collects polygons with their attributes and enforces orientation."""

    def __init__(self, name):
        self.name = name
        self.polys = []        # list of vertex-tuple lists
        self.labels = []
        self.reflectance = []
        self.light_id = []
        self.emission = []
        self.light_names = []
        self.flipped = []      # labels whose given winding had to be reversed

    def add(self, label, pts, reflectance, expected_dir,
            emission=None, light_name=None):
        """Add one polygon.

        expected_dir is the direction the normal must roughly point to:
        the winding is reversed if the right-hand-rule normal points away
        from it, and afterwards we assert the normal lies within 60 degrees
        of it.  The 60-degree check (rather than just dot > 0) catches a
        wrong expectation or a degenerate polygon instead of silently
        accepting a normal that is nearly perpendicular to what we meant.
        """
        pts = [tuple(float(c) for c in p) for p in pts]
        exp = unit(expected_dir)
        if dot(newell_normal(pts), exp) < 0.0:
            pts = pts[::-1]
            self.flipped.append(label)
        n = newell_normal(pts)
        assert dot(n, exp) > 0.5, \
            f"{self.name}/{label}: normal {n} not along expected {exp}"
        assert all(0.0 <= c <= 1.0 for c in reflectance), label
        self.polys.append(pts)
        self.labels.append(label)
        self.reflectance.append(tuple(reflectance))
        if emission is None:
            self.light_id.append(-1)
            self.emission.append((0.0, 0.0, 0.0))
        else:
            assert re.fullmatch(r"[A-Za-z0-9_]+", light_name), light_name
            self.light_id.append(len(self.light_names))
            self.emission.append(tuple(emission))
            self.light_names.append(light_name)

    def add_room_face(self, label, pts, refl, room_centre):
        # Room surfaces face the inside: towards the room centre.
        self.add(label, pts, refl, sub(room_centre, centroid(pts)))

    def add_block_face(self, label, pts, refl, block_centre):
        # Block surfaces face out: away from the block centre.
        self.add(label, pts, refl, sub(centroid(pts), block_centre))

    def to_polydata(self):
        points = vtkPoints()
        # Double precision keeps the decimal input coordinates exact-ish and
        # avoids float32 round-off when the mesher divides edge lengths.
        points.SetDataTypeToDouble()
        cells = vtkCellArray()
        for pts in self.polys:
            ids = [points.InsertNextPoint(p) for p in pts]
            cells.InsertNextCell(len(ids), ids)
        pd = vtkPolyData()
        pd.SetPoints(points)
        pd.SetPolys(cells)

        refl = vtkFloatArray()
        refl.SetName("Reflectance")
        refl.SetNumberOfComponents(3)
        emis = vtkFloatArray()
        emis.SetName("Emission")
        emis.SetNumberOfComponents(3)
        lid = vtkIntArray()
        lid.SetName("LightId")
        lid.SetNumberOfComponents(1)
        for r, e, i in zip(self.reflectance, self.emission, self.light_id):
            refl.InsertNextTuple3(*r)
            emis.InsertNextTuple3(*e)
            lid.InsertNextValue(i)
        cd = pd.GetCellData()
        cd.AddArray(refl)
        cd.AddArray(lid)
        cd.AddArray(emis)

        names = vtkStringArray()
        names.SetName("LightNames")
        for n in self.light_names:
            names.InsertNextValue(n)
        pd.GetFieldData().AddArray(names)
        return pd

    def write(self, path):
        w = vtkXMLPolyDataWriter()
        w.SetFileName(path)
        w.SetInputData(self.to_polydata())
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()      # raw binary, not base64
        w.SetCompressorTypeToZLib()
        assert w.Write() == 1, f"failed to write {path}"


# --------------------------------------------------------------------------
# Paper scenes (metres, y up)
# --------------------------------------------------------------------------
ROOM = (4.0, 2.5, 4.0)
BOX_LO, BOX_HI = (2.4, 0.0, 1.2), (3.6, 1.2, 3.6)  # 1.2 x 1.2 x 2.4, off-centre
LAMP = 0.3
LAMP_DROP = 0.01  # below the ceiling so the lamp is not coplanar with it

WALL_WHITE = (0.70, 0.70, 0.70)
PAPER_REFL = {
    "floor":   (0.50, 0.50, 0.50),
    "ceiling": (0.75, 0.75, 0.75),
    "wall_x0": (0.65, 0.12, 0.10),   # red
    "wall_x1": (0.15, 0.30, 0.60),   # blue-ish
    "wall_z0": WALL_WHITE,
    "wall_z1": WALL_WHITE,
    "box":     (0.75, 0.65, 0.20),   # yellow-ish
}
LAMP_REFL = (0.8, 0.8, 0.8)

# Lamp palette: (name, emission RGB).  Distinct colors *and* intensities so
# that relighting tests can tell the per-light contributions apart.
LAMP_PALETTE = [
    ("WarmWhite", (1.00, 0.85, 0.65)),
    ("CoolWhite", (0.75, 0.85, 1.00)),
    ("Amber",     (0.90, 0.55, 0.15)),
    ("Rose",      (0.85, 0.40, 0.55)),
    ("Teal",      (0.20, 0.70, 0.65)),
    ("Lime",      (0.55, 0.80, 0.20)),
    ("Violet",    (0.50, 0.30, 0.85)),
    ("DimWhite",  (0.40, 0.40, 0.40)),
]

# Lamp centres (x, z) on the ceiling.  Chosen to spread over the ceiling while
# staying clear of the box footprint x in [2.4, 3.6], z in [1.2, 3.6] (checked
# below), so every lamp sees the floor and the box from above/aside.
LAMP_LAYOUTS = {
    1: [(2.0, 2.0)],
    3: [(1.0, 1.0), (1.0, 3.0), (3.0, 0.6)],
    # 3 x 3 grid minus the two cells above the box, plus one filler.
    8: [(0.6, 0.6), (2.0, 0.6), (3.4, 0.6),
        (0.6, 2.0), (2.0, 2.0),
        (0.6, 3.4), (2.0, 3.4), (1.3, 2.7)],
}


def make_paper_scene(num_lights):
    sx, sy, sz = ROOM
    s = Scene(f"paper_{num_lights}lights")
    centre = (sx / 2, sy / 2, sz / 2)
    room = box_quads((0.0, 0.0, 0.0), ROOM)
    face_refl = {"bottom": "floor", "top": "ceiling", "x0": "wall_x0",
                 "x1": "wall_x1", "z0": "wall_z0", "z1": "wall_z1"}
    for face, pts in room.items():
        key = face_refl[face]
        s.add_room_face(key, pts, PAPER_REFL[key], centre)

    box_centre = centroid([BOX_LO, BOX_HI])
    for face, pts in box_quads(BOX_LO, BOX_HI).items():
        s.add_block_face("box_" + face, pts, PAPER_REFL["box"], box_centre)
    assert len(s.polys) == 12

    y = sy - LAMP_DROP
    h = LAMP / 2
    for i, (cx, cz) in enumerate(LAMP_LAYOUTS[num_lights]):
        # Lamp must be inside the ceiling and not over the box footprint.
        assert h <= cx <= sx - h and h <= cz <= sz - h
        assert (cx + h <= BOX_LO[0] or cx - h >= BOX_HI[0] or
                cz + h <= BOX_LO[2] or cz - h >= BOX_HI[2]), (cx, cz)
        name, emission = LAMP_PALETTE[i]
        pts = [(cx - h, y, cz - h), (cx + h, y, cz - h),
               (cx + h, y, cz + h), (cx - h, y, cz + h)]
        s.add(f"lamp_{name}", pts, LAMP_REFL, (0.0, -1.0, 0.0),
              emission=emission, light_name=name)
    return s


# --------------------------------------------------------------------------
# Cornell box (millimetres, y up, open front at z = 0)
# --------------------------------------------------------------------------
CB_WHITE = (0.725, 0.71, 0.68)
CB_RED = (0.63, 0.065, 0.05)
CB_GREEN = (0.14, 0.45, 0.091)
CB_LIGHT_REFL = (0.78, 0.78, 0.78)
# Original light radiance is (17, 12, 4); we store the color normalised to a
# max of 1 (divide by 17) so Emission is a color in [0,1] and overall
# brightness is left to the relighting intensity controls.  Multiply by 17 to
# recover the reference radiance.
CB_EMISSION = (1.0, 12.0 / 17.0, 4.0 / 17.0)
CB_LIGHT_Y = 548.8 - 0.5  # 0.5 mm below the ceiling: avoid coplanarity


def make_cornell_box():
    s = Scene("cornell_box")
    # Centre of the room's bounding box; every room surface faces it.
    centre = (556.0 / 2, 548.8 / 2, 559.2 / 2)
    s.add_room_face("floor", [(552.8, 0, 0), (0, 0, 0), (0, 0, 559.2),
                              (549.6, 0, 559.2)], CB_WHITE, centre)
    s.add_room_face("ceiling", [(556, 548.8, 0), (556, 548.8, 559.2),
                                (0, 548.8, 559.2), (0, 548.8, 0)],
                    CB_WHITE, centre)
    s.add_room_face("back_wall", [(549.6, 0, 559.2), (0, 0, 559.2),
                                  (0, 548.8, 559.2), (556, 548.8, 559.2)],
                    CB_WHITE, centre)
    s.add_room_face("green_wall", [(0, 0, 559.2), (0, 0, 0),
                                   (0, 548.8, 0), (0, 548.8, 559.2)],
                    CB_GREEN, centre)
    # The measured red wall is not planar (x varies by 3.2 mm between its
    # corners), so it is stored as two exactly planar triangles.
    red = [(552.8, 0, 0), (549.6, 0, 559.2),
           (556, 548.8, 559.2), (556, 548.8, 0)]
    s.add_room_face("red_wall_a", [red[0], red[1], red[2]], CB_RED, centre)
    s.add_room_face("red_wall_b", [red[0], red[2], red[3]], CB_RED, centre)

    blocks = {
        "short_block": [(130, 165, 65), (82, 165, 225),
                        (240, 165, 272), (290, 165, 114)],
        "tall_block": [(423, 330, 247), (265, 330, 296),
                       (314, 330, 456), (472, 330, 406)],
    }
    for bname, top in blocks.items():
        height = top[0][1]
        tc = centroid(top)
        bc = (tc[0], height / 2, tc[2])
        # Top faces straight up (explicit, stricter than centre-based test).
        s.add(f"{bname}_top", top, CB_WHITE, (0.0, 1.0, 0.0))
        # Sides drop from each top edge to the floor; no bottom face.
        for i in range(4):
            a, b = top[i], top[(i + 1) % 4]
            side = [a, b, (b[0], 0, b[2]), (a[0], 0, a[2])]
            s.add_block_face(f"{bname}_side{i}", side, CB_WHITE, bc)

    light = [(343, CB_LIGHT_Y, 227), (343, CB_LIGHT_Y, 332),
             (213, CB_LIGHT_Y, 332), (213, CB_LIGHT_Y, 227)]
    s.add("light", light, CB_LIGHT_REFL, (0.0, -1.0, 0.0),
          emission=CB_EMISSION, light_name="Ceiling")
    return s


# --------------------------------------------------------------------------
# Mesh-size estimate mirroring the mesher's documented rule
# --------------------------------------------------------------------------
def mesh_counts(polys, patch, element):
    """(patches, elements) for the given polygons.

    Quads: ceil(edge/patch) patches along each parametric direction (the
    longer of the two opposite edges), each patch ceil(patch_edge/element)
    elements per side.  Triangles: assumed n x n style subdivision with
    n = ceil(longest edge / patch) -> n^2 patches (an estimate only).
    """
    def n_div(length, size):
        return max(1, math.ceil(length / size - 1e-9))

    patches = elements = 0
    for pts in polys:
        if len(pts) == 4:
            lu = max(norm(sub(pts[1], pts[0])), norm(sub(pts[2], pts[3])))
            lv = max(norm(sub(pts[3], pts[0])), norm(sub(pts[2], pts[1])))
            nu, nv = n_div(lu, patch), n_div(lv, patch)
            eu, ev = n_div(lu / nu, element), n_div(lv / nv, element)
            patches += nu * nv
            elements += nu * nv * eu * ev
        else:
            le = max(norm(sub(pts[(i + 1) % 3], pts[i])) for i in range(3))
            n = n_div(le, patch)
            m = n_div(le / n, element)
            patches += n * n
            elements += n * n * m * m
    return patches, elements


# --------------------------------------------------------------------------
# Read-back checker
# --------------------------------------------------------------------------
def check(path, num_polys, num_lights):
    """Read a written file back and verify the contract the filters rely on."""
    r = vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    pd = r.GetOutput()
    assert pd.GetNumberOfPolys() == num_polys, \
        (path, pd.GetNumberOfPolys(), num_polys)
    assert pd.GetNumberOfCells() == num_polys, "only polys expected"
    cd = pd.GetCellData()

    refl = cd.GetArray("Reflectance")
    lid = cd.GetArray("LightId")
    emis = cd.GetArray("Emission")
    assert refl is not None and refl.IsA("vtkFloatArray")
    assert lid is not None and lid.IsA("vtkIntArray")
    assert emis is not None and emis.IsA("vtkFloatArray")
    assert refl.GetNumberOfComponents() == 3
    assert lid.GetNumberOfComponents() == 1
    assert emis.GetNumberOfComponents() == 3
    for a in (refl, lid, emis):
        assert a.GetNumberOfTuples() == num_polys, a.GetName()

    names = pd.GetFieldData().GetAbstractArray("LightNames")
    assert names is not None and names.IsA("vtkStringArray")
    assert names.GetNumberOfValues() == num_lights
    name_list = [names.GetValue(i) for i in range(num_lights)]
    assert all(re.fullmatch(r"[A-Za-z0-9_]+", n) for n in name_list)
    assert len(set(name_list)) == num_lights, "light names must be unique"

    ymax = pd.GetBounds()[3]
    seen = []
    for c in range(num_polys):
        r3 = refl.GetTuple3(c)
        e3 = emis.GetTuple3(c)
        i = int(lid.GetValue(c))
        assert all(0.0 <= v <= 1.0 for v in r3), (c, r3)
        cell = pd.GetCell(c)
        pts = [pd.GetPoint(cell.GetPointId(k))
               for k in range(cell.GetNumberOfPoints())]
        assert len(pts) in (3, 4), (c, len(pts))
        n = newell_normal(pts)
        # Planar within 1e-6 of the polygon's size (the mesher assumes it).
        size = max(norm(sub(p, pts[0])) for p in pts)
        p0 = centroid(pts)
        assert all(abs(dot(sub(p, p0), n)) <= 1e-6 * size for p in pts), \
            (path, c, "non-planar")
        # Convex: every corner turns the same way around the normal.
        for k in range(len(pts)):
            e1 = sub(pts[(k + 1) % len(pts)], pts[k])
            e2 = sub(pts[(k + 2) % len(pts)], pts[(k + 1) % len(pts)])
            assert dot(cross(e1, e2), n) > 0.0, (path, c, "non-convex")
        if i == -1:
            assert e3 == (0.0, 0.0, 0.0), (c, e3)
        else:
            assert 0 <= i < num_lights and max(e3) > 0.0, (c, i, e3)
            assert min(e3) >= 0.0, (c, e3)
            # Lights face down and sit strictly below the ceiling.
            assert n[1] < -0.999, (path, c, n)
            assert all(p[1] < ymax for p in pts), (path, c, "coplanar")
            seen.append(i)
    assert sorted(seen) == list(range(num_lights)), \
        "each light id must be exactly one quad"
    return name_list


# --------------------------------------------------------------------------
def main():
    scenes = [(make_paper_scene(k), 12 + k, k,
               [(PAPER_PATCH, PAPER_ELEMENT), (1.0, 0.25)])
              for k in (1, 3, 8)]
    scenes.append((make_cornell_box(), 17, 1,
                   [(CORNELL_PATCH, CORNELL_ELEMENT)]))

    for scene, num_polys, num_lights, settings in scenes:
        path = os.path.join(HERE, scene.name + ".vtp")
        assert len(scene.polys) == num_polys
        scene.write(path)
        names = check(path, num_polys, num_lights)

        non_light = [p for p, i in zip(scene.polys, scene.light_id) if i < 0]
        lights = [p for p, i in zip(scene.polys, scene.light_id) if i >= 0]
        print(f"{os.path.basename(path)}: {num_polys} polygons "
              f"({len(non_light)} + {len(lights)} lights: {', '.join(names)})")
        if scene.flipped:
            print(f"  winding reversed for: {', '.join(scene.flipped)}")
        for patch, element in settings:
            pn, en = mesh_counts(non_light, patch, element)
            pl, el = mesh_counts(lights, patch, element)
            print(f"  PatchSize {patch:g} / ElementSize {element:g}: "
                  f"non-lights {pn} patches / {en} elements, "
                  f"lights {pl} / {el}")
        if scene.name.startswith("paper"):
            assert mesh_counts(non_light, PAPER_PATCH, PAPER_ELEMENT) == \
                PAPER_EXPECTED_COUNTS
    print("all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

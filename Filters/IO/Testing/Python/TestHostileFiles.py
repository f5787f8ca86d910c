"""Hostile PLY, glTF, OBJ and VRML files through import_scene: never a crash, never a NaN imported,
one clear error naming the file.

vtkPLYReader trusts a PLY's header and VTK's glTF loader the indices and lengths in the
JSON: a count larger than the file, a list longer than its line, a face index past the
vertices, a buffer shorter than it claims or a node that is its own child end in an
assert, a segfault or endless recursion inside VTK. The corpus is written here (no
binaries committed): the cases an adversarial run found, then random mutations of valid
files (PLY header counts, truncations, flipped bytes; numbers in a .glb's JSON; odd
numbers, cut, repeated or endless lines in an OBJ or its material library; odd words,
cuts and flipped bytes in VRML97). All files
are read by one child process that names each file before it reads it, so a crash is
caught and pinned on its file. For a long run:
    RELIGHT_HOSTILE_CASES=10000 ./relight python Filters/IO/Testing/Python/TestHostileFiles.py
"""

import json
import os
import pathlib
import random
import re
import struct
import subprocess
import sys
import tempfile

from testlib import check, finish

CASES = int(os.environ.get("RELIGHT_HOSTILE_CASES", "300"))
rng = random.Random(int(os.environ.get("RELIGHT_HOSTILE_SEED", "26")))
TRIANGLE = [(0, 0, 0), (1, 0, 0), (0, 1, 0)]


def ascii_ply(vertices, faces, lines):
    header = (f"ply\nformat ascii 1.0\nelement vertex {vertices}\nproperty float x\nproperty float y\n"
              f"property float z\nelement face {faces}\nproperty list uchar int vertex_indices\nend_header\n")
    return (header + "".join(f"{x} {y} {z}\n" for x, y, z in TRIANGLE) + "".join(lines)).encode()


def binary_ply(vertices, faces, lists, count_type="uchar", count_format="B"):
    header = (f"ply\nformat binary_little_endian 1.0\nelement vertex {vertices}\nproperty float x\n"
              f"property float y\nproperty float z\nelement face {faces}\n"
              f"property list {count_type} int vertex_indices\nend_header\n").encode()
    body = b"".join(struct.pack("<3f", *v) for v in TRIANGLE)
    for count, ids in lists:
        body += struct.pack("<" + count_format, count) + b"".join(struct.pack("<i", i) for i in ids)
    return header + body


# name -> (contents, what the error must say; None: it must import)
KNOWN = {
    "good_ascii.ply": (ascii_ply(3, 1, ["3 0 1 2\n"]), None),
    "good_binary.ply": (binary_ply(3, 1, [(3, [0, 1, 2])]), None),
    "claims_a_million_vertices.ply": (ascii_ply(10**6, 1, ["3 0 1 2\n"]), "of 1000000"),
    "claims_a_million_faces.ply": (ascii_ply(3, 10**6, ["3 0 1 2\n"]), "face 2 of 1000000"),
    "list_of_255_with_3.ply": (ascii_ply(3, 1, ["255 0 1 2\n"]), "ends inside face 1 of 1"),
    "negative_count.ply": (ascii_ply(-5, 1, ["3 0 1 2\n"]), "count '-5'"),
    "count_4e9.ply": (ascii_ply(4000000000, 1, ["3 0 1 2\n"]), "count '4000000000'"),
    "index_past_the_vertices.ply": (ascii_ply(3, 1, ["3 0 1 99999\n"]), "names vertex 99999"),
    "binary_claims_a_million.ply": (binary_ply(10**6, 1, [(3, [0, 1, 2])]), "of 1000000"),
    "binary_list_of_255.ply": (binary_ply(3, 1, [(255, [0, 1, 2])]), "ends inside face 1 of 1"),
    "binary_count_0xFFFFFFF0.ply": (binary_ply(3, 1, [(0xFFFFFFF0, [0, 1, 2])], "uint", "I"), "4294967280 items"),
    "binary_index_past_the_vertices.ply": (binary_ply(3, 1, [(3, [0, 1, 70000])]), "names vertex 70000"),
    "binary_truncated.ply": (binary_ply(3, 1, [(3, [0, 1, 2])])[:-7], "ends inside face 1 of 1"),
    "no_end_header.ply": (b"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n", "no 'end_header'"),
    "unknown_type.ply": (ascii_ply(3, 1, ["3 0 1 2\n"]).replace(b"property float z", b"property quad z"),
                         "'quad' is not a PLY type"),
    # Found by a review against VTK 9.2's vtkPLY: what its reader assumes of the layout.
    "upper_case_axes.ply": (ascii_ply(3, 1, ["3 0 1 2\n"]).replace(b"float x", b"float X"), "no single value 'x'"),
    "faces_only.ply": (b"ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n",
                       "first element is not 'vertex'"),
    "faces_without_a_list.ply": (ascii_ply(3, 1, ["3\n"]).replace(b"property list uchar int vertex_indices",
                                                                  b"property uchar red"), "no list 'vertex_indices'"),
    # Blender once wrote the face list under the vertices, without 'element face' (assimp's
    # issue623.ply): said so, not as a file shorter than its header.
    "face_list_under_vertices.ply": (ascii_ply(3, 1, []).replace(b"element face 1\n", b""), "lacks an 'element face' line"),
    "float_index_1e9.ply": (ascii_ply(3, 1, ["3 0 1 1e9\n"]).replace(b"list uchar int", b"list uchar float"),
                            "names vertex 1000000000"),
    "edge_before_face.ply": (ascii_ply(3, 1, ["3 99999\n", "3 0 1 2\n"]).replace(
        b"element face", b"element edge 1\nproperty list uchar int vertex_indices\nelement face"), "comes where"),
    "rewritten_word.ply": (ascii_ply(3, 1, ["3 0vertex_index 1 2\n"]), "not a number"),
    "form_feed_in_header.ply": (ascii_ply(3, 1, ["3 0 1 2\n"]).replace(b"element vertex", b"element\fvertex"),
                                "control character"),
}


def glb(document, binary):
    """A .glb: the JSON chunk (padded with spaces) and the binary chunk (with zeros)."""
    text = json.dumps(document).encode()
    text += b" " * (-len(text) % 4)
    binary += b"\0" * (-len(binary) % 4)
    chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def triangle_gltf(indices=(0, 1, 2)):
    """One triangle: its JSON (buffer 0 without a uri) and its 44 bytes."""
    binary = b"".join(struct.pack("<3f", *v) for v in TRIANGLE) + struct.pack("<3H", *indices) + b"\0\0"
    document = {
        "asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": 44}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
    }
    return document, binary


def damaged(change, indices=(0, 1, 2)):
    document, binary = triangle_gltf(indices)
    change(document)
    return glb(document, binary)


def with_file(uri, length=44):
    """A .gltf whose buffer is the file `uri` (written beside it: 'triangle.bin')."""
    document, _ = triangle_gltf()
    document["buffers"] = [{"uri": uri, "byteLength": length}]
    return json.dumps(document).encode()


def two_json_chunks():
    """A .glb whose first chunk is broken JSON and whose good JSON comes after the binary."""
    document, binary = triangle_gltf()
    good = json.dumps(document).encode()
    good += b" " * (-len(good) % 4)
    bad = b"{broken  "[:8]
    chunks = (struct.pack("<I4s", len(bad), b"JSON") + bad + struct.pack("<I4s", len(binary), b"BIN\0") + binary +
              struct.pack("<I4s", len(good), b"JSON") + good)
    return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def chain(document, depth):
    document["nodes"] = [{"children": [i + 1]} for i in range(depth)] + [{"mesh": 0}]


GLTF = {
    "good.glb": (damaged(lambda d: None), None),
    "good.gltf": (with_file("triangle.bin"), None),
    "missing_bin.gltf": (with_file("missing.bin"), "'missing.bin' is missing"),
    "claims_3600_bytes.gltf": (with_file("triangle.bin", 3600), "claims 3600 bytes and holds 44 (the file is cut short"),
    "uri_outside.gltf": (with_file("../../../../etc/passwd"), "is not in the model's folder"),
    "uri_absolute.gltf": (with_file("/etc/passwd"), "is not in the model's folder"),
    "uri_a_folder.gltf": (with_file("."), "is not a regular file"),
    "count_2^31-1.glb": (damaged(lambda d: d["accessors"][0].update(count=2**31 - 1)), "does not fit its bufferView"),
    "offset_1e12.glb": (damaged(lambda d: d["bufferViews"][0].update(byteOffset=10**12)), "below 2^31"),
    "offset_past_the_buffer.glb": (damaged(lambda d: d["bufferViews"][0].update(byteOffset=40)), "does not fit its buffer"),
    "position_99999.glb": (damaged(lambda d: d["meshes"][0]["primitives"][0]["attributes"].update(POSITION=99999)),
                           "names accessor 99999, and there are 2 accessors"),
    "own_child.glb": (damaged(lambda d: d["nodes"][0].update(children=[0])), "cycle"),
    "two_parents.glb": (damaged(lambda d: d.update(nodes=[{"children": [2]}, {"children": [2]}, {"mesh": 0}])),
                        "more than one parent"),
    "5000_deep.glb": (damaged(lambda d: chain(d, 5000)), "deeper than 1024"),
    "index_past_the_vertices.glb": (damaged(lambda d: None, (0, 1, 99)), "point 99"),
    # Found by a review against VTK 9.2's loader: it reads the first chunk as the JSON, drops
    # entries it cannot read (shifting later indices), keeps offsets in int, wants buffers of
    # exactly their byteLength and reads sparse indices, morph targets and samplers unchecked.
    "json_chunk_after_bin.glb": (two_json_chunks(), "not JSON"),
    "min_of_two_on_vec3.glb": (damaged(lambda d: d["accessors"][0].update(min=[0, 0])), "could read 1 of its 2 accessors"),
    "type_5.glb": (damaged(lambda d: d["accessors"][0].update(type=5)), "no valid componentType, type or count"),
    "offset_2^62.glb": (damaged(lambda d: d["bufferViews"][0].update(byteOffset=2**62, byteLength=2**62)), "below 2^31"),
    "bin_longer_than_claimed.gltf": (with_file("triangle.bin", 40), "claims 40 bytes and holds 44"),
    "sparse.glb": (damaged(lambda d: d["accessors"][0].update(sparse={"count": 1, "indices": {"bufferView": 1, "componentType": 5123},
                                                                       "values": {"bufferView": 0}})), "is sparse"),
    "morph_target_99.glb": (damaged(lambda d: d["meshes"][0]["primitives"][0].update(targets=[{"POSITION": 99}])),
                            "morph target's POSITION names accessor 99"),
    "sampler_output_99.glb": (damaged(lambda d: d.update(animations=[{"samplers": [{"input": 0, "output": 99}],
                                                                     "channels": [{"sampler": 0, "target": {"node": 0, "path": "translation"}}]}])),
                              "sampler's output names accessor 99"),
}


def glb_mutations(count):
    """Numbers in a valid .glb's JSON replaced at random."""
    document, binary = triangle_gltf()
    text = json.dumps(document)
    numbers = [m.span() for m in re.finditer(r"\b\d+\b", text)]
    for i in range(count):
        start, end = rng.choice(numbers)
        value = rng.choice(["0", "1", "2", "3", "-1", "36", "44", "99999", "2147483647", "4294967296", "1000000000000"])
        mutated = json.loads(text[:start] + value + text[end:])
        yield f"glb_mutant_{i:05d}.glb", glb(mutated, binary)


def mutations(count):
    """Random damage to a valid file: a header count, a truncation or flipped data bytes."""
    sources = [ascii_ply(3, 1, ["3 0 1 2\n"]), binary_ply(3, 2, [(3, [0, 1, 2]), (3, [2, 1, 0])])]
    for i in range(count):
        data = bytearray(rng.choice(sources))
        kind = rng.randrange(3)
        if kind == 0:
            old = rng.choice([b"vertex 3", b"face 1", b"face 2"])
            new = rng.choice(["0", "1", "2", "7", "1000000", "-1", "2147483648", "99999999999", "x"])
            data = bytearray(bytes(data).replace(old, old.split()[0] + b" " + new.encode()))
        elif kind == 1:
            data = data[:rng.randrange(len(data))]
        else:
            start = bytes(data).find(b"end_header") + 11
            for _ in range(rng.randrange(1, 4)):
                if start < len(data):
                    data[rng.randrange(start, len(data))] = rng.randrange(256)
        yield f"mutant_{i:05d}.ply", bytes(data)


OBJ = """# a lamp over a floor, with every corner form OBJ has
mtllib room.mtl
o Room
v 0 0 0
v 4 0 0
v 4 0 4
v 0 0 4
v 1.5 2.9 1.5
v 2.5 2.9 1.5
v 2.5 2.9 2.5
v 1.5 2.9 2.5
vt 0 0
vn 0 1 0
usemtl Floor
f 1/1/1 4/1/1 3/1/1 2/1/1
g lamp
usemtl Lamp
f -4//1 -3//1 -2//1 -1//1
"""
MTL = """newmtl Floor
Kd 0.6 0.5 0.4
newmtl Lamp
Kd 0 0 0
Ke 10 9 8
"""


def obj_mutations(count):
    """Random damage to a valid OBJ and its material library: a number replaced by an odd
    one, a line cut, repeated or dropped, a truncation, flipped bytes, one very long line."""
    odd = ["nan", "inf", "-inf", "1e308", "-1e308", "1e-320", "0", "-0", "99999999999", "-2147483649", "x", "",
           "1/", "//", "/1/", "0/0/0", "1.5", "0x10", "+-1"]
    for i in range(count):
        target = rng.randrange(2)
        lines = (OBJ if target == 0 else MTL).splitlines(keepends=True)
        kind = rng.randrange(5)
        if kind == 0:
            line = rng.randrange(len(lines))
            words = lines[line].split()
            if len(words) > 1:
                words[rng.randrange(1, len(words))] = rng.choice(odd)
                lines[line] = " ".join(words) + "\n"
        elif kind == 1:
            line = rng.randrange(len(lines))
            lines[line] = rng.choice([lines[line][:rng.randrange(len(lines[line]) + 1)], lines[line] * 2, ""])
        elif kind == 2:
            lines.insert(rng.randrange(len(lines) + 1), rng.choice(["f 1 2 3 ", "v ", "usemtl ", "Kd "]) + "1 " * 100000 + "\n")
        data = bytearray("".join(lines).encode())
        if kind == 3:
            data = data[:rng.randrange(len(data) + 1)]
        elif kind == 4 and data:
            for _ in range(rng.randrange(1, 4)):
                data[rng.randrange(len(data))] = rng.randrange(256)
        obj = OBJ.encode().replace(b"room.mtl", f"mutant_{i:05d}.mtl".encode()) if target else bytes(data)
        obj = obj if target else obj.replace(b"room.mtl", f"mutant_{i:05d}.mtl".encode())
        yield f"mutant_{i:05d}.obj", obj
        yield f"mutant_{i:05d}.mtl", bytes(data) if target else MTL.encode()


WRL = """#VRML V2.0 utf8
Transform { translation 0 0 0 children [
Shape { appearance Appearance { material DEF Wall Material { diffuseColor 0.6 0.5 0.4 } }
  geometry IndexedFaceSet { coord Coordinate { point [ 0 0 0, 4 0 0, 4 0 4, 0 0 4 ] } coordIndex [ 0 3 2 1 -1 ] } }
Shape { appearance Appearance { material Material { emissiveColor 10 9 8 diffuseColor 0 0 0 } }
  geometry IndexedFaceSet { coord Coordinate { point [ 1.5 2.9 1.5, 2.5 2.9 1.5, 2.5 2.9 2.5, 1.5 2.9 2.5 ] } coordIndex [ 0 1 2 3 -1 ] } }
Shape { appearance Appearance { material USE Wall } geometry Box { size 1 1 1 } }
] }
"""
# VTK's VRML importer (9.2) crashed on all but the last of these (it goes on past a syntax
# error); the last one it read as 'no polygons'.
VRML = {
    "bare_commas.wrl": (WRL.replace("4 0 4, 0 0 4", "4,0,4,0,0,4").encode(), None),
    "material_at_the_top.wrl": (b"#VRML V2.0 utf8\nMaterial { diffuseColor 1 1 1 }\n", "a Material outside any Shape"),
    "faces_at_the_top.wrl": (b"#VRML V2.0 utf8\nIndexedFaceSet { coord Coordinate { point [ 0 0 0, 1 0 0, 0 1 0 ] } "
                             b"coordIndex [ 0 1 2 -1 ] }\n", "an IndexedFaceSet outside any Shape"),
    "use_of_nothing.wrl": (WRL.replace("coord Coordinate", "coord USE Nothing", 1).encode(), "USE Nothing with no DEF"),
    "list_without_bracket.wrl": (WRL.replace("coordIndex [ 0 1 2 3", "coordIndex 1e308 0 1 2 3").encode(),
                                 "a ']' that closes nothing open"),
    "two_numbers_short.wrl": (WRL.replace("0 0 4 ]", "0 ]", 1).encode(), "not a whole number of 3-vectors"),
    # The first checks, written with std::regex, overflowed the stack on these two.
    "long_name.wrl": (WRL.replace("Wall", "W" * 200000).encode(), "a word of 200000 characters"),
    "long_space.wrl": (WRL.replace("Coordinate {", "Coordinate" + " " * 200000 + "{", 1).encode(), None),
    # 100,000 nested Transform nodes: VTK's parser overflowed its stack (at about 1,100
    # levels) after 117 s and the file read as 'no polygons'; 1,000 levels it reads.
    "deep_nesting.wrl": (("#VRML V2.0 utf8\n" + "Transform { children [ " * 100000 + WRL.split("\n", 1)[1] + " ] }" * 100000).encode(),
                         "nested more than 2100 deep"),
    "deep_but_readable.wrl": (("#VRML V2.0 utf8\n" + "Transform { children [ " * 1000 + WRL.split("\n", 1)[1] +
                               " ] }" * 1000).encode(), None),
    # Valid VRML97 the checks must let be: words in strings, a texture in a Sound.
    "words_in_strings.wrl": (WRL.replace("Transform {", 'WorldInfo { info [ "USE freely", "a { b ]" ] }\nTransform {', 1)
                             .encode(), None),
    "texture_in_a_sound.wrl": (WRL.replace("Transform {", 'Sound { source MovieTexture { url "x.mpg" } }\nTransform {', 1)
                               .encode(), None),
    "backslash_before_quote.wrl": (WRL.replace("Transform {", 'WorldInfo { info [ "C:\\\\" ] } # a comment, with { a brace\n'
                                                             'Transform {', 1).encode(), None),
}


def vrml_mutations(count):
    """Random damage to a valid VRML97 file: odd words, a truncation, flipped bytes, a word
    repeated many times."""
    odd = ["nan", "inf", "1e308", "-1", "99999999", "[", "]", "{", "}", "DEF", "USE", "USE Nothing", "",
           "-2147483649", "Shape {", "Material", "IndexedFaceSet"]
    for i in range(count):
        words = WRL.split(" ")
        kind = rng.randrange(4)
        if kind == 0:
            for _ in range(rng.randrange(1, 4)):
                words[rng.randrange(len(words))] = rng.choice(odd)
            data = " ".join(words).encode()
        elif kind == 1:
            data = WRL.encode()[:rng.randrange(len(WRL))]
        elif kind == 2:
            data = bytearray(WRL.encode())
            for _ in range(rng.randrange(1, 4)):
                data[rng.randrange(len(data))] = rng.randrange(256)
            data = bytes(data)
        else:
            k = rng.randrange(len(words))
            words.insert(k, words[k] * rng.randrange(2, 50))
            data = " ".join(words).encode()
        yield f"mutant_{i:05d}.wrl", data


CHILD = r"""
import sys, relight
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
for path in sys.argv[1:]:
    print("start", path, flush=True)
    try:
        scene = relight.import_scene(path, require_lights=False)
        arrays = [scene.GetPoints().GetData()] if scene.GetPoints() else []
        arrays += [scene.GetCellData().GetArray(i) for i in range(scene.GetCellData().GetNumberOfArrays())]
        finite = all(np.isfinite(vtk_to_numpy(a)).all() for a in arrays if a is not None)
        print("ok" if finite else "nan", path, scene.GetNumberOfCells(), flush=True)
    except Exception as error:
        print("error", path, " ".join(str(error).split()), flush=True)  # one line, whatever it holds
"""


def read_all(paths):
    """{path: (status, text)}; the file that took the child down gets 'crash'."""
    results, pending = {}, list(paths)
    while pending:
        child = subprocess.run([sys.executable, "-c", CHILD, *pending], capture_output=True, text=True,
                               errors="replace", timeout=600)  # a reader may print raw bytes
        started = None
        for line in child.stdout.splitlines():
            status, path, *rest = line.split(" ", 2)
            if status == "start":
                started = path
            else:
                results[path] = (status, rest[0] if rest else "")
                started = None
        if child.returncode == 0 or started is None:
            break
        results[started] = ("crash", f"exit {child.returncode}: {child.stderr.strip()[-300:]}")
        pending = pending[pending.index(started) + 1:]
    return results


def main():
    with tempfile.TemporaryDirectory() as folder:
        known = {**KNOWN, **GLTF, **VRML}
        files = {"triangle.bin": triangle_gltf()[1]}
        for name, (data, _) in known.items():
            files[name] = data
        for name, data in mutations(CASES):
            files[name] = data
        for name, data in glb_mutations(CASES):
            files[name] = data
        for name, data in obj_mutations(CASES):
            files[name] = data
        for name, data in vrml_mutations(CASES):
            files[name] = data
        paths = []
        for name, data in files.items():
            path = pathlib.Path(folder) / name
            path.write_bytes(data)
            paths += [] if name.endswith((".bin", ".mtl")) else [str(path)]
        # Not regular files: a FIFO named like a scene blocks any reader for ever, /dev/zero
        # as a material library never ends, a folder as one was silently passed over.
        specials = {"fifo.obj": "is not a regular file", "zero_mtl.obj": "'/dev/zero', which is missing or not a regular file",
                    "folder_mtl.obj": "which is missing or not a regular file"}
        os.mkfifo(pathlib.Path(folder) / "fifo.obj")
        (pathlib.Path(folder) / "sub").mkdir()
        triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
        (pathlib.Path(folder) / "zero_mtl.obj").write_text("mtllib /dev/zero\n" + triangle)
        (pathlib.Path(folder) / "folder_mtl.obj").write_text("mtllib sub\n" + triangle)
        # A stray byte in a name: the error came to Python as "None".
        (pathlib.Path(folder) / "bad_byte_mtl.obj").write_bytes(b"mtllib ro\xa6om.mtl\n" + triangle.encode())
        specials["bad_byte_mtl.obj"] = "'ro\u00a6om.mtl'"  # the byte read as Latin-1
        # A cut IFC: assimp read the building up to the cut without a word.
        house = pathlib.Path("/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc").read_bytes()
        (pathlib.Path(folder) / "cut_house.ifc").write_bytes(house[:300000])
        specials["cut_house.ifc"] = "does not end with END-ISO-10303-21;"
        paths += [str(pathlib.Path(folder) / name) for name in specials]
        known.update({name: (None, expected) for name, expected in specials.items()})
        results = read_all(paths)

        for name, (_, expected) in known.items():
            status, text = results.get(str(pathlib.Path(folder) / name), ("missing", ""))
            if expected is None:
                check(status == "ok", f"{name} imports ({status} {text[:120]})")
            else:
                check(status == "error" and expected in text and name in text,
                      f"{name}: one error naming the file and saying '{expected}' ({status}: {text[:160]})")
        crashed = [p for p, (s, _) in results.items() if s == "crash"]
        silent = [p for p, (s, _) in results.items() if s == "nan"]
        check(not silent, f"no file imports with a NaN or infinite value ({len(silent)}: "
                          f"{[pathlib.Path(p).name for p in silent[:5]]})")
        unclear = [p for p, (s, t) in results.items() if s == "error" and pathlib.Path(p).name not in t]
        missing = [p for p in paths if p not in results]
        check(not crashed, f"{4 * CASES} mutants and {len(known)} known files: no crash "
                           f"({len(crashed)}: {[pathlib.Path(p).name for p in crashed[:5]]} {results.get(crashed[0]) if crashed else ''})")
        check(not unclear, f"every error names its file ({len(unclear)} do not: "
                           f"{[(pathlib.Path(p).name, results[p][1][:100]) for p in unclear[:3]]})")
        check(not missing, f"every file got an answer ({len(missing)} did not)")
        errors = sum(1 for s, _ in results.values() if s == "error")
        print(f"{len(results)} files: {len(results) - errors - len(crashed)} imported, {errors} refused, {len(crashed)} crashed")
    finish("TestHostileFiles")


if __name__ == "__main__":
    main()

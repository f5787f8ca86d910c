"""Hostile scene files opened through ParaView's reader (the plugin's RadiositySceneReader):
an error and an empty output, and pvbatch carries on, where VTK's loaders crashed the
whole application. The files are a few of TestHostileFiles.py's known cases.

Usage:
    pvbatch Plugin/Testing/Python/TestHostileFilesParaView.py <plugin.so>
"""

import os
import sys
import tempfile

from paraview.simple import *  # noqa: F401,F403  (LoadPlugin, RadiositySceneReader, ...)
from paraview import servermanager

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "Filters", "IO", "Testing", "Python"))  # the hostile-file corpus
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "Testing", "Python"))  # the helpers it imports
import TestHostileFiles as corpus  # noqa: E402  (its corpus only: importing it runs no test)

LoadPlugin(sys.argv[1], ns=globals())
failures = []
with tempfile.TemporaryDirectory() as folder:
    with open(os.path.join(folder, "triangle.bin"), "wb") as f:
        f.write(corpus.triangle_gltf()[1])
    cases = {**corpus.KNOWN, **corpus.GLTF}
    for name in ("claims_a_million_vertices.ply", "binary_list_of_255.ply", "faces_only.ply", "missing_bin.gltf",
                 "own_child.glb", "json_chunk_after_bin.glb", "good.glb"):
        path = os.path.join(folder, name)
        with open(path, "wb") as f:
            f.write(cases[name][0])
        reader = RadiositySceneReader(FileName=path)
        reader.UpdatePipeline()
        cells = servermanager.Fetch(reader).GetNumberOfCells()
        expected_ok = cases[name][1] is None
        ok = (cells > 0) if expected_ok else (cells == 0)
        print(f"{'ok  ' if ok else 'FAIL'} {name}: {cells} cells through ParaView's reader")
        if not ok:
            failures.append(name)
        Delete(reader)
if failures:
    print(f"TestHostileFilesParaView: {len(failures)} check(s) failed")
    sys.exit(1)
print("TestHostileFilesParaView: all checks passed")

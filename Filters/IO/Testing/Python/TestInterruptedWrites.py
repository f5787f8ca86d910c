"""The browser viewer's files killed half way through (kill -9, as a user ending a hung
script or the OOM killer would): a writer process is stopped in the middle of writing each
of the page's files in turn, with half of that file written. Every file of the page that was
there stays whole, so the page keeps working; the next export leaves no .part file."""

import base64
import os
import re
import signal
import struct
import subprocess
import sys
import tempfile
import textwrap

import relight
from relight import read_polydata
from testlib import check, finish

from vtkmodules.vtkCommonCore import vtkLogger

vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
DATA = os.path.join(os.environ.get("RELIGHT_ROOT", "."), "Data")
folder = tempfile.mkdtemp()
scene = os.path.join(DATA, "paper_3lights.vtp")
page = os.path.join(folder, "page")
relight.export_viewer(relight.solve(read_polydata(scene), 1.5, 0.375).GetOutput(), page)

# The writer: the same export, its files opened through a wrapper that writes the first
# half of what it is given, says so and waits to be killed, when the file is the one named.
writer = textwrap.dedent("""
    import os, sys, time
    import relight
    import relight.exporting as exporting
    from relight import read_polydata

    stall_in = sys.argv[3]

    class Stalling:
        def __init__(self, f):
            self.f = f
        def __enter__(self):
            return self
        def __exit__(self, *args):
            return self.f.__exit__(*args)
        def write(self, data):
            self.f.write(data[: len(data) // 2])
            self.f.flush()
            print("stalled", flush=True)
            time.sleep(600)
        def __getattr__(self, name):
            return getattr(self.f, name)

    def stalling_open(path, mode="r", *args, **kwargs):
        f = open(path, mode, *args, **kwargs)
        return Stalling(f) if "w" in mode and os.path.basename(path).startswith(stall_in) else f

    exporting.open = stalling_open
    data = relight.solve(read_polydata(sys.argv[1]), 1.5, 0.375).GetOutput()
    relight.export_viewer(data, sys.argv[2])
""")


def glb_whole(data):
    if len(data) < 20:
        return False
    magic, version, length = struct.unpack_from("<4sII", data, 0)
    return magic == b"glTF" and version == 2 and length == len(data)


WEB = os.path.join(os.path.dirname(relight.__file__), "web")


def page_whole():
    """scene.js holds a whole .glb; the page and the viewer are the package's, byte for byte."""
    text = open(os.path.join(page, "scene.js")).read()
    found = re.match(r'window\.RELIGHT_GLB = "([A-Za-z0-9+/=]*)";\n', text)
    same = all(open(os.path.join(page, n), "rb").read() == open(os.path.join(WEB, n), "rb").read()
               for n in ("index.html", "relight-viewer.js"))
    return found is not None and text.endswith(";\n") and glb_whole(base64.b64decode(found.group(1))) and same


check(page_whole(), "the page written first is whole")
for name in ("scene.js", "index.html", "relight-viewer.js"):
    child = subprocess.Popen([sys.executable, "-c", writer, scene, page, name], stdout=subprocess.PIPE, text=True,
                             env=os.environ)
    stalled = child.stdout.readline().strip() == "stalled"
    child.send_signal(signal.SIGKILL)
    child.wait()
    check(stalled and page_whole(), f"killed half way through {name}: the page there is whole")
left = sorted(n for n in os.listdir(page) if n.endswith(".part"))
check(left, f"the kills left their half-written files beside the page: {left}")
relight.export_viewer(relight.solve(read_polydata(scene), 1.5, 0.375).GetOutput(), page)
left = sorted(n for n in os.listdir(page) if n.endswith(".part"))
check(page_whole() and not left, f"the next export is whole and leaves no .part file ({left})")
finish("TestInterruptedWrites")

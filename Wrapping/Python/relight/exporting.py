"""Solutions out: ``write_gltf`` writes a solved (and optionally relit) scene as binary
glTF with one vertex attribute per light, for relighting outside VTK."""

import warnings

from .errors import ErrorCatcher, own_words
from .vtkRadiosityIO import vtkRadiosityGLTFWriter


def write_gltf(data, path, exposure=0.0):
    """Writes `data` (the solver's or the relight filter's output) as a .glb file:
    geometry, `_RADIOSITY_<LIGHT>` per light, COLOR_0 from `Radiosity` x `exposure` (the
    relight filter's; for the solver's output, every light at its default color), and
    the light names, default colors and exposure in the mesh's extras.relight. Exposure 0:
    the relight filter's (its field array Exposure), else metered as it meters. Raises
    OSError; the writer's warnings (an input without radiosity) come as RuntimeWarnings."""
    writer = vtkRadiosityGLTFWriter()
    writer.SetInputData(data)
    writer.SetFileName(str(path))
    writer.SetExposure(exposure)
    catcher = ErrorCatcher(writer)
    if not writer.Write():
        raise OSError(f"could not write {path!r}: {catcher.first_error()}")
    for message in catcher.warnings:  # as relight.solve passes the filters' warnings on
        warnings.warn(own_words(message), RuntimeWarning, stacklevel=2)


def light_scene_settings(data, path):
    """Each light scene of the light-scenes file `path` as the relight filter resolves it on
    `data`: [(name, [(r, g, b) color times intensity, enabled] per light)], in the file's
    order. Raises ValueError naming the problem where the file cannot be used."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from .vtkRadiosityFilters import vtkRadiosityRelight

    relit = vtkRadiosityRelight()
    relit.SetInputData(data)
    relit.SetLightScenesFileName(str(path))
    catcher = ErrorCatcher(relit)
    relit.Update()
    if catcher.failed():
        raise ValueError(f"cannot use the light scenes of {str(path)!r}: {catcher.first_error()}")
    scenes = []
    for name in [relit.GetLightSceneName(i) for i in range(relit.GetNumberOfLightScenes())]:
        relit.SetLightScene(name)
        relit.Update()
        fields = relit.GetOutput().GetFieldData()
        colors = vtk_to_numpy(fields.GetArray("LightColors"))
        enabled = vtk_to_numpy(fields.GetArray("LightEnabled"))
        scenes.append((name, [([float(c) for c in color], bool(on)) for color, on in zip(colors, enabled)]))
    return scenes


def export_viewer(data, folder, camera=None, size=(640, 480), exposure=0.0, scenes=None):
    """Writes a web page into `folder` that relights `data` in the browser: index.html,
    the bundled viewer (three.js) and scene.js (the .glb as base64, so the page opens
    from file:// without a server). Per light: on/off, color, intensity; exposure (0: as
    write_gltf picks it);
    orbit with the mouse. `camera` = (position, focal point, view-up, view angle) as for
    render_png. `scenes`: a light-scenes file (as the relight filter's LightScenesFileName),
    whose scenes the page offers by name, resolved as the relight filter resolves them. URL
    parameters set controls as a user would: ?intensity.<light>=4, enabled.<light>=0,
    color.<light>=ff8800, scene=<name>, controls=0 (hide the panel).
    Returns the path of index.html."""
    import base64
    import json
    import os
    import shutil
    import tempfile

    web = os.path.join(os.path.dirname(__file__), "web")
    if not os.path.exists(os.path.join(web, "relight-viewer.js")):
        raise RuntimeError("the web viewer was not built (it needs npm at build time: apt-get install npm)")
    os.makedirs(folder, exist_ok=True)
    with tempfile.TemporaryDirectory() as scratch:
        glb = os.path.join(scratch, "scene.glb")
        write_gltf(data, glb, exposure)
        with open(glb, "rb") as f:
            encoded = base64.b64encode(f.read()).decode("ascii")
    view = None
    if camera is not None:
        position, focal, up, angle = camera
        view = {"position": list(position), "focalPoint": list(focal), "up": list(up), "angle": angle}
    resolved = [{"name": name, "lights": [{"color": color, "enabled": on} for color, on in lights]}
                for name, lights in light_scene_settings(data, scenes)] if scenes else []
    text = (f"window.RELIGHT_GLB = \"{encoded}\";\nwindow.RELIGHT_CAMERA = {json.dumps(view)};\n"
            f"window.RELIGHT_SIZE = {json.dumps(list(size))};\nwindow.RELIGHT_SCENES = {json.dumps(resolved)};\n")
    # Each file whole or not at all, as the other writers do: a page that was there keeps
    # working if the export is killed half way (scene.js was left at 0 bytes).
    contents = {"scene.js": text.encode()}
    for name in ("index.html", "relight-viewer.js"):
        with open(os.path.join(web, name), "rb") as f:
            contents[name] = f.read()
    for name, data in contents.items():
        part = os.path.join(folder, name + ".part")
        with open(part, "wb") as f:
            f.write(data)
            f.flush()
            os.fsync(f.fileno())
        os.replace(part, os.path.join(folder, name))
    return os.path.join(folder, "index.html")

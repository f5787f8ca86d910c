"""An independent check of a solved scene: Mitsuba 3 (mitsuba_reference.py) at probe points
on element centroids, drawn by area with a fixed seed, every element sent as its own polygon
so both renderers see the same geometry. Used by house.py --reference."""

import hashlib, json, pathlib, subprocess
import numpy as np
import relight
from vtkmodules.util.numpy_support import vtk_to_numpy

HERE = pathlib.Path(__file__).resolve().parent


def _loops(mesh):
    polys = mesh.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    ids = vtk_to_numpy(polys.GetConnectivityArray())
    return [ids[offsets[c]:offsets[c + 1]] for c in range(len(offsets) - 1)]


def _cell_normals(mesh):
    """Each polygon's own unit normal (VTK's Newell normal, no reorienting)."""
    from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
    normals = vtkPolyDataNormals()
    normals.SetInputData(mesh)
    normals.ComputeCellNormalsOn(), normals.ComputePointNormalsOff(), normals.SplittingOff(), normals.ConsistencyOff()
    normals.Update()
    return relight.cell_array(normals.GetOutput(), "Normals")


def spread(corners, count, rng):
    """`count` points uniform over a planar convex polygon (its fan triangles by area)."""
    a, b, c = corners[0], corners[1:-1], corners[2:]
    area = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    fan = rng.choice(len(area), count, p=area / area.sum())
    u, v = rng.random((2, count))
    flip = u + v > 1  # fold the square's far half back into the triangle
    u[flip], v[flip] = 1 - u[flip], 1 - v[flip]
    return a + u[:, None] * (b[fan] - a) + v[:, None] * (c[fan] - a)


def _cosine(normal, rng):
    """A cosine-distributed direction about a unit normal."""
    u, phi = rng.random(), 2 * np.pi * rng.random()
    t = np.cross(normal, [1.0, 0, 0] if abs(normal[0]) < 0.6 else [0, 1.0, 0])
    t /= np.linalg.norm(t)
    b = np.cross(normal, t)
    r = np.sqrt(u)
    return r * np.cos(phi) * t + r * np.sin(phi) * b + np.sqrt(1 - u) * normal


class _Tracer:
    """Nearest hits on the solved mesh (vtkOBBTree), for probes that do not sit on our
    elements' centroids."""

    def __init__(self, mesh, normals, light):
        from vtkmodules.vtkFiltersGeneral import vtkOBBTree
        self.tree = vtkOBBTree()
        self.tree.SetDataSet(mesh)
        self.tree.BuildLocator()
        self.normals, self.light = normals, light
        self.span = float(np.linalg.norm(np.ptp(np.reshape(mesh.GetBounds(), (3, 2)), axis=1)))

    def front_hit(self, start, direction):
        """(point, cell) of the nearest surface the ray meets on its front, not a lamp;
        None where it meets nothing, a back face or a lamp."""
        from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
        points, cells = vtkPoints(), vtkIdList()
        self.tree.IntersectWithLine(start, start + direction * self.span, points, cells)
        hits = [(np.dot(np.array(points.GetPoint(i)) - start, direction), i) for i in range(points.GetNumberOfPoints())]
        hits = [h for h in hits if h[0] > 1e-6]
        if not hits:
            return None
        d, i = min(hits)
        c = cells.GetId(i)
        if self.light[c] >= 0 or np.dot(self.normals[c], direction) >= 0:
            return None
        return start + direction * d, c


def traced_probes(mesh, normals, light, areas, loops, points, per_light=100, seed=11):
    """Probes drawn independently of our mesh: for each lamp, half where cosine rays from
    the lamp first meet a surface, half one cosine bounce further on. Each is (point,
    cell)."""
    rng = np.random.default_rng(seed)
    tracer = _Tracer(mesh, normals, light)
    out = []
    for k in range(int(light.max()) + 1):
        lamp = np.flatnonzero(light == k)
        got, tries = [], 0
        while len(got) < per_light and tries < 50 * per_light:
            tries += 1
            c = rng.choice(lamp, p=areas[lamp] / areas[lamp].sum())
            start = spread(points[loops[c]], 1, rng)[0] + normals[c] * 1e-4
            first = tracer.front_hit(start, _cosine(normals[c], rng))
            if first is None:
                continue
            got.append(first)
            x, cell = first
            second = tracer.front_hit(x + normals[cell] * 1e-4, _cosine(normals[cell], rng))
            if second is not None and len(got) < per_light:
                got.append(second)
        out += got
    return out


def export(mesh, path, probes=600, seed=7, average=0, traced=False):
    """The solver's output (polygons only) as mitsuba_reference.py's JSON; probes on
    non-emitting elements, by area, at their centroids or, with `average` > 0, spread over
    the element at that many points (Mitsuba then gives the element's mean). Returns the
    probes' cell ids."""
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    loops = _loops(mesh)
    light = np.asarray(relight.cell_array(mesh, "LightId")).astype(int)
    reflectance = np.asarray(relight.cell_array(mesh, "Reflectance"), float).reshape(len(loops), -1)
    reflectance = np.repeat(reflectance, 3 // reflectance.shape[1], axis=1)
    cents, normals, areas = relight.cell_centroids(mesh), _cell_normals(mesh), relight.cell_areas(mesh)
    if traced:
        found = traced_probes(mesh, normals, light, areas, loops, points, per_light=probes // (int(light.max()) + 1))
        spots, pick = [x for x, _ in found], np.array([c for _, c in found])
    else:
        candidates = np.flatnonzero((light < 0) & (areas > 0))
        pick = np.random.default_rng(seed).choice(candidates, min(probes, len(candidates)), replace=False,
                                                  p=areas[candidates] / areas[candidates].sum())
        spots = [cents[c] for c in pick]
    scene = {"lights": int(light.max()) + 1,
             "polygons": [{"points": points[l].tolist(), "reflectance": reflectance[c].tolist(), "light": int(light[c])}
                          for c, l in enumerate(loops)],
             "probes": [{"point": np.asarray(x).tolist(), "normal": normals[c].tolist(), "seen": True, "cell": int(c)}
                        for x, c in zip(spots, pick)]}
    rng = np.random.default_rng(seed + 1)
    for probe in scene["probes"][:len(pick) if average > 0 else 0]:
        probe["points"] = spread(points[loops[probe["cell"]]], average, rng).tolist()
    text = json.dumps(scene)
    if not path.exists() or path.read_text() != text:  # an unchanged scene keeps its reference
        path.write_text(text)
    return [(int(c), np.asarray(x, float)) for x, c in zip(spots, pick)]


PATHS = 8192  # Mitsuba's paths per probe and light in the first reference


def render(scene_path, csv_path, python, spp=PATHS, script="mitsuba_reference.py", seed=0):
    """A reference's radiosity at the probes (Mitsuba's, or with `script`
    radiance_reference.py Radiance's), rendered once per scene, sample count, seed and version
    of the script (a digest of them beside the csv says what it was made from)."""
    script = HERE / script
    made_from = hashlib.sha256(scene_path.read_bytes() + str(spp).encode() + script.read_bytes()
                               + (f" seed {seed}".encode() if seed else b"")).hexdigest()
    key = csv_path.with_suffix(".key")
    if csv_path.exists() and key.exists() and key.read_text() == made_from:
        return
    extra = ["--spp", str(spp)] if script.name == "mitsuba_reference.py" else ["--ad", str(spp)]
    extra += ["--seed", str(seed)]
    subprocess.run([str(python), str(script), str(scene_path), str(csv_path), *extra], check=True)
    key.write_text(made_from)


def references_apart(first_csv, second_csv):
    """Per light, mean |second - first| over the probes over the first's mean: how far two
    references are apart (their noise and their models' differences)."""
    a = np.loadtxt(first_csv, delimiter=",", skiprows=1, ndmin=2)
    b = np.loadtxt(second_csv, delimiter=",", skiprows=1, ndmin=2)
    out = []
    for k in range(int(a[:, 1].max()) + 1):
        x, y = a[a[:, 1] == k], b[b[:, 1] == k]
        x, y = x[np.argsort(x[:, 0])][:, 2:5].mean(axis=1), y[np.argsort(y[:, 0])][:, 2:5].mean(axis=1)
        out.append(float(np.abs(y - x).mean() / x.mean()))
    return out


def _weights(mesh, cell, x):
    """The point ids of `cell` and the weights that interpolate its point values at x (what a
    rendering shows there; at a quad's centroid, the mean of its corners)."""
    from vtkmodules.vtkCommonCore import reference
    polygon = mesh.GetCell(cell)
    closest, sub, dist2 = [0.0] * 3, reference(0), reference(0.0)
    pcoords, w = [0.0] * 3, [0.0] * polygon.GetNumberOfPoints()
    polygon.EvaluatePosition(list(x), closest, sub, pcoords, dist2, w)
    ids = [polygon.GetPointId(i) for i in range(polygon.GetNumberOfPoints())]
    return np.array(ids), np.array(w)


def compare(mesh, cells, csv_path, names, average=False):
    """Per light, the mean |ours - Mitsuba| over the probes over Mitsuba's mean (ours at a
    centroid: the mean of the element's corner values, what a rendering shows there; with
    `average`, the element's own value, the solver's answer for its mean), and over the
    probes Mitsuba finds lit (above a fifth of the mean, all lights on) the median of
    ours / Mitsuba."""
    loops = _loops(mesh)
    weights = [_weights(mesh, c, x) for c, x in cells]
    cells = np.array([c for c, _ in cells])
    table = np.loadtxt(csv_path, delimiter=",", skiprows=1, ndmin=2)
    errors, ours_all, ref_all, rows_out = {}, 0.0, 0.0, []
    for k, name in enumerate(names):
        rows = table[table[:, 1] == k]
        want = np.zeros(len(cells))
        want[rows[:, 0].astype(int)] = rows[:, 2:5].mean(axis=1)
        if average:
            got = np.asarray(relight.cell_array(mesh, f"Radiosity_{name}")).reshape(len(loops), -1)[cells].mean(axis=1)
        else:
            values = relight.point_array(mesh, f"Radiosity_{name}").reshape(mesh.GetNumberOfPoints(), -1)
            got = np.array([values[ids].mean(axis=1) @ w for ids, w in weights])
        errors[name] = float(np.abs(got - want).mean() / want.mean())
        rows_out += [(i, k, g, w) for i, (g, w) in enumerate(zip(got, want))]
        ours_all, ref_all = ours_all + got, ref_all + want
    np.savetxt(csv_path.with_suffix(".ours.csv"), np.array(rows_out), delimiter=",", fmt="%.6g",
               header="probe,light,ours,reference", comments="")  # per probe, for a closer look
    lit = ref_all > 0.2 * ref_all.mean()
    return errors, float(np.median(ours_all[lit] / ref_all[lit])), int(lit.sum())

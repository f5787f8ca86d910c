"""A real third-party building: KIT's FZK-Haus (IFC from Debian's assimp-testmodels, to OBJ by
assimp), 6 ceiling lamps, Hierarchical solve, two pictures from inside. Run:
./relight python Testing/Benchmark/house.py [--element 0.25] [--patch 0.5] [--out out/bench]"""

import argparse, os, pathlib, resource, shutil, subprocess, sys
import numpy as np
import relight
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkIdList, vtkPoints
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkOBBTree
from vtkmodules.vtkIOGeometry import vtkOBJReader

IFC = pathlib.Path("/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc")
UP = 1  # assimp writes OBJ Y-up (checked below: the smallest extent is the height)
DIRS = [np.array(d, float) for d in ((1, 0, 0), (-1, 0, 0), (0, 0, 1), (0, 0, -1))]


def convert(folder):
    """IFC -> OBJ + MTL with assimp, cached in `folder`; both come from Debian packages."""
    if not (IFC.exists() and shutil.which("assimp")):
        if os.geteuid() != 0:
            sys.exit("need Debian's assimp-utils and assimp-testmodels: sudo apt-get install assimp-utils assimp-testmodels")
        subprocess.run(["apt-get", "install", "-y", "-q", "assimp-utils", "assimp-testmodels"], check=True,
                       env=dict(os.environ, DEBIAN_FRONTEND="noninteractive"))
    obj = folder / "fzk.obj"
    if not obj.exists() or obj.stat().st_mtime < IFC.stat().st_mtime:
        folder.mkdir(parents=True, exist_ok=True)
        subprocess.run(["assimp", "export", str(IFC), str(obj)], check=True, stdout=subprocess.DEVNULL)
    return obj


def parse_mtl(path):
    """{material: Kd}. assimp writes one `newmtl` per IFC style and styles may share a
    name; usemtl names only one, so the first wins and differing repeats are reported."""
    kd, name, conflicts = {}, None, set()
    for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
        words = line.split()
        if words[:1] == ["newmtl"]:
            name = line.split(None, 1)[1].strip()
        elif words[:1] == ["Kd"] and name is not None:
            value = tuple(float(w) for w in words[1:4])
            conflicts |= {name} if kd.setdefault(name, value) != value else set()
    return kd, conflicts


def load_house(obj):
    """The OBJ as (list of point arrays in metres, reflectance per polygon)."""
    reader = vtkOBJReader()
    reader.SetFileName(str(obj))
    reader.Update()
    data = reader.GetOutput()  # cell arrays MaterialIds, GroupIds; field array MaterialNames
    names = data.GetFieldData().GetAbstractArray("MaterialNames")
    names = [names.GetValue(i) for i in range(names.GetNumberOfValues())]
    kd, conflicts = parse_mtl(obj.with_suffix(".mtl"))
    print(f"MTL: {len(kd)} material names; first Kd used for {len(conflicts)} defined with several colours: {sorted(conflicts)}")
    rho = np.array([kd.get(n, (0.6, 0.6, 0.6)) for n in names])
    clamped = np.clip(rho, 0.02, 0.9)
    changed = [f"{n} {np.round(a, 3)} -> {np.round(b, 3)}" for n, a, b in zip(names, rho, clamped) if not np.allclose(a, b)]
    print(f"Reflectance clamped to [0.02, 0.9]: {'; '.join(changed) or 'none needed'}")
    extent = np.ptp(np.reshape(data.GetBounds(), (3, 2)), axis=1)
    scale = 0.001 if extent.max() > 200 else 1.0  # a 12 m house in mm would be 12000
    assert np.argmin(extent) == UP, f"expected Y-up, extents {extent}"
    print(f"OBJ: {data.GetNumberOfPolys()} polygons, extent {np.round(extent * scale, 2)} m (scale {scale})")
    pts = vtk_to_numpy(data.GetPoints().GetData()).astype(float) * scale
    offsets = vtk_to_numpy(data.GetPolys().GetOffsetsArray())
    conn = vtk_to_numpy(data.GetPolys().GetConnectivityArray())
    ids = vtk_to_numpy(data.GetCellData().GetArray("MaterialIds"))[data.GetNumberOfVerts() + data.GetNumberOfLines():]
    loops = [pts[conn[a:b]] for a, b in zip(offsets[:-1], offsets[1:])]
    area = [0.5 * np.linalg.norm(np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)) for p in loops]  # Newell
    keep = [c for c, p in enumerate(loops) if len(p) >= 3 and area[c] > 1e-10]  # not zero area nor collinear
    print(f"dropped {len(loops) - len(keep)} degenerate polygons, kept {len(keep)}")
    return [loops[c] for c in keep], [clamped[ids[c]] for c in keep]


class Rays:
    """Ray queries against the house (vtkOBBTree): all hits along a segment, with the
    normal of the hit cell, so floors, ceilings and wall sides can be told apart."""

    def __init__(self, scene):
        self.tree = vtkOBBTree()
        self.tree.SetDataSet(scene)
        self.tree.BuildLocator()
        normals = vtkPolyDataNormals()  # cell normals, each cell keeping its own orientation
        normals.SetInputData(scene)
        normals.ComputeCellNormalsOn(), normals.ComputePointNormalsOff(), normals.SplittingOff(), normals.ConsistencyOff()
        normals.Update()
        self.normals = vtk_to_numpy(normals.GetOutput().GetCellData().GetArray("Normals"))

    def hits(self, start, direction, length):
        """[(distance, normal)] sorted by distance."""
        points, cells = vtkPoints(), vtkIdList()
        self.tree.IntersectWithLine(start, start + direction * length, points, cells)
        out = [(np.dot(np.array(points.GetPoint(i)) - start, direction), self.normals[cells.GetId(i)])
               for i in range(points.GetNumberOfPoints())]
        return sorted(((d, n) for d, n in out if d > 1e-6), key=lambda h: h[0])

    def first(self, start, direction, length=15.0):  # (inf, None) if nothing is hit
        h = self.hits(start, direction, length)
        return h[0] if h else (np.inf, None)

    def indoors(self, p):
        """Every horizontal ray meets the front of a wall: p is inside a closed room."""
        return all(n is not None and np.dot(n, d) < 0 for d in DIRS for _, n in [self.first(p, d)])


def lamp_at(rays, x, z, floor):
    """A lamp position above floor (x, floor, z), or None: the lowest ceiling over the
    0.3 m square must be 2.2-3.2 m up and face down (sloped roofs included), the room
    must be closed and walls at least 0.4 m away (the quad's half width is 0.15 m)."""
    up = np.eye(3)[UP]
    tops = []
    for dx, dz in ((0, 0), (-0.2, -0.2), (0.2, -0.2), (0.2, 0.2), (-0.2, 0.2)):
        d, n = rays.first(np.array([x + dx, floor + 0.5, z + dz]), up)
        if n is None or n[UP] > -0.3:
            return None
        tops.append(floor + 0.5 + d)
    p = np.array([x, min(tops) - 0.02, z])
    if not 2.2 <= p[UP] - floor <= 3.2 or not rays.indoors(np.array([x, floor + 1.2, z])):
        return None
    # Only near-vertical hits count as walls: under a sloped roof a level ray meets the roof.
    walls = [d for d, n in (rays.first(p, v) for v in DIRS) if n is not None and abs(n[UP]) < 0.5]
    return p if min(walls, default=np.inf) >= 0.4 else None


def find_lamps(rays, bounds, count=6, step=0.4):
    """Floors = up-facing hits of vertical rays; keep lamp spots on the two storeys with
    the most spots and spread 3 per storey by farthest-point sampling."""
    spots = {}
    for x in np.arange(bounds[0] + step / 2, bounds[1], step):
        for z in np.arange(bounds[4] + step / 2, bounds[5], step):
            start = np.array([x, bounds[2] - 1, z])
            for d, n in rays.hits(start, np.eye(3)[UP], bounds[3] - bounds[2] + 2):
                p = lamp_at(rays, x, z, start[UP] + d) if n[UP] > 0.9 else None
                if p is not None:
                    spots.setdefault(round(start[UP] + d, 1), []).append(p)
    storeys = sorted(sorted(spots, key=lambda f: -len(spots[f]))[:2])
    lamps = []
    for f in storeys:
        cand = np.array(spots[f])
        chosen = [cand[np.argmin(np.linalg.norm(cand - cand.mean(axis=0), axis=1))]]
        while len(chosen) < count // len(storeys):
            dist = np.min([np.linalg.norm(cand - c, axis=1) for c in chosen], axis=0)
            chosen.append(cand[np.argmax(dist)])
        lamps += [(f, c) for c in chosen]
    return lamps


def lamp_quad(p, half=0.15):
    """A square in the horizontal plane whose right-hand-rule normal points down."""
    x, y, z = p
    quad = np.array([(x - half, y, z - half), (x + half, y, z - half), (x + half, y, z + half), (x - half, y, z + half)])
    assert np.cross(quad[1] - quad[0], quad[2] - quad[0])[UP] < 0
    return quad


def solve(scene, patch, element):
    """Mesh + solve at the solver's default settings (Auto picks Hierarchical at this size);
    keeps warnings and errors."""
    mesher = relight.vtkRadiosityMesher()
    mesher.SetInputData(scene)
    mesher.SetPatchSize(patch), mesher.SetElementSize(element)
    solver = relight.vtkLightTaggedRadiosity()
    solver.SetInputConnection(mesher.GetOutputPort())
    catchers = [relight.ErrorCatcher(mesher), relight.ErrorCatcher(solver)]
    solver.Update()
    if any(c.errors for c in catchers):
        raise RuntimeError([e for c in catchers for e in c.errors][0])
    return solver, [w for c in catchers for w in c.warnings]


def camera(rays, floor, lamp):
    """Stand against the wall behind the lamp, eye 1.5 m up, look at the far wall."""
    eye = np.array([lamp[0], floor + 1.5, lamp[2]])
    dist = [rays.first(eye, d)[0] for d in DIRS]
    ahead = int(np.argmax(dist))
    back = ahead ^ 1  # DIRS come in opposite pairs
    eye = eye - DIRS[ahead] * max(dist[back] - 0.2, 0.0)
    focal = eye + DIRS[ahead] * dist[ahead] - np.eye(3)[UP] * 0.4
    return tuple(eye), tuple(focal), tuple(np.eye(3)[UP]), 80.0


def render(solver, shots, out):
    """All lamps on at unit exitance; exposure puts the 99th percentile of the lit
    surfaces at 0.8 so walls are visible and only the lamps (and walls right by them) clip."""
    relit = relight.vtkRadiosityRelight()
    relit.SetInputConnection(solver.GetOutputPort())  # intensity 1, white: the Emission
    relit.Update()
    b = relight.point_array(relit.GetOutput(), "Radiosity").max(axis=1)
    lit = b[(b > 0) & (b < 0.5)]  # the lamps themselves are at 1
    relit.SetExposure(0.8 / np.percentile(lit, 99))
    relit.Update()
    for i, cam in enumerate(shots, 1):
        relight.render_png(relit.GetOutput(), out / f"house_inside_{i}.png", cam)
    return relit.GetExposure()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--element", type=float, default=0.25, help="ElementSize, m (0.1 gives ~830k elements)")
    parser.add_argument("--patch", type=float, default=0.5, help="PatchSize, m")
    parser.add_argument("--out", default="out/bench")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    polygons, refl = load_house(convert(out / "fzk"))
    house = relight.make_scene(polygons, refl, [-1] * len(polygons))
    rays = Rays(house)
    lamps = find_lamps(rays, house.GetBounds())
    print("\n".join(f"Lamp{i}: {np.round(p, 2)} (floor at {f} m)" for i, (f, p) in enumerate(lamps)))
    k, n = len(lamps), len(polygons)
    scene = relight.make_scene(polygons + [lamp_quad(p) for _, p in lamps], refl + [(0.8,) * 3] * k,
                               [-1] * n + list(range(k)), [f"Lamp{i}" for i in range(k)], [(0, 0, 0)] * n + [(1, 1, 1)] * k)
    solver, warnings = solve(scene, args.patch, args.element)
    result = solver.GetOutput()
    method = result.GetFieldData().GetAbstractArray("SolverMethod").GetValue(0)
    commit = subprocess.run(["git", "describe", "--always", "--dirty"], capture_output=True, text=True).stdout.strip()
    row = dict(commit=commit or "?", polygons=scene.GetNumberOfCells(), elements=result.GetNumberOfCells(),
               patches=len(np.unique(relight.cell_array(result, "PatchId"))), lights=k,
               element=args.element, patch=args.patch, solve_s=round(solver.GetLastSolveSeconds(), 2),
               shots=solver.GetLastShots(), converged=bool(solver.GetLastConverged()),
               peak_mib=round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024),
               warnings=len(warnings))
    exposure = render(solver, [camera(rays, *lamps[0]), camera(rays, *lamps[-1])], out)  # one per storey
    summary = "\n".join([f"{key}: {value}" for key, value in row.items()] + [f"SolverMethod: {method}",
                         f"exposure: {exposure:.4g}"] + [f"warning: {w.strip().splitlines()[-1]}" for w in warnings])
    print(summary)
    (out / "house.txt").write_text(summary + "\n")
    csv = out / "house.csv"
    header = "" if csv.exists() else ",".join(row) + "\n"  # append: one row per run
    with csv.open("a") as f:
        f.write(header + ",".join(str(v) for v in row.values()) + "\n")


if __name__ == "__main__":
    main()

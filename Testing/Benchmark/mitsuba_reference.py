#!/usr/bin/env python3
"""Independent Mitsuba 3 (path tracing) reference for the radiosity benchmark.

Usage:
  out/mitsuba-venv/bin/python Testing/Benchmark/mitsuba_reference.py \
      out/bench/room.json out/bench/room_reference.csv [--spp 4096] [--probes N]
  out/mitsuba-venv/bin/python Testing/Benchmark/mitsuba_reference.py --selftest

For each light k separately (only light k emits; the other lamp quads stay in
the scene as plain reflectors) and for each of the first N probes with
seen == true, the radiosity B = pi * L is measured, where L is the radiance
leaving the probe point towards its normal. CSV columns: probe,light,r,g,b.

Why the setup is equivalent to the radiosity model:
  * Every quad is a mesh with a plain `diffuse` BSDF. Mitsuba's `diffuse` is
    one-sided: it returns 0 when either direction is below the local (front)
    hemisphere, so light reaching a back face is absorbed and back faces look
    black (checked by --selftest). Back faces still occlude.
  * Triangle normals are (v1-v0) x (v2-v0), so a fan (0,1,2),(0,2,3) keeps
    the right-hand-rule front side of the JSON quads.
  * An `area` emitter emits from the front face only; radiance 1/pi gives
    unit exitance (M = pi * L).
  * A `radiancemeter` a hair (1e-4 x (1 + the largest |coordinate|)) above the point, looking along -normal,
    records the radiance leaving the surface there; a diffuse surface has
    B = pi * L. Probes on an emitting quad would include its emission (1).
  * A probe with "points" (samples spread over an element) is the mean of a meter at each,
    the element's average radiosity, which is what a radiosity solution computes.
  * The `path` integrator runs with unlimited depth (Russian roulette keeps it
    unbiased), i.e. all interreflections, like a converged radiosity solution.
"""
import argparse
import math
import sys
import time

import mitsuba as mi

mi.set_variant("scalar_rgb")

EPS = 1e-4  # the self-test's lift; a scene's is EPS x (1 + its largest |coordinate|)
# Mitsuba's rays ignore hits closer than an epsilon that grows with the coordinates: at a
# fixed 1e-4 a scene in millimetres lifted the meter inside it and its ray missed the
# surface below (0 on the Cornell box's blocks); a lift from the diagonal alone failed the
# same box in metres.


def make_mesh(name, loops, reflectance, radiance=None):
    """One mesh of planar convex polygons (each fanned from its first corner, which keeps
    its right-hand-rule front), built directly via mi.Mesh."""
    props = mi.Properties()
    props["bsdf"] = mi.load_dict(
        {"type": "diffuse", "reflectance": {"type": "rgb", "value": list(reflectance)}})
    if radiance is not None:
        props["emitter"] = mi.load_dict(
            {"type": "area", "radiance": {"type": "rgb", "value": [radiance] * 3}})
    positions, faces = [], []
    for pts in loops:
        base = len(positions) // 3
        positions += [float(c) for p in pts for c in p]
        for t in range(1, len(pts) - 1):
            faces += [base, base + t, base + t + 1]
    mesh = mi.Mesh(name, len(positions) // 3, len(faces) // 3, props)
    params = mi.traverse(mesh)
    params["vertex_positions"] = positions
    params["faces"] = faces
    params.update()
    return mesh


def make_scene(polygons, active_light):
    """Scene in which only polygons with light == active_light emit; the others are
    grouped into one mesh per reflectance (a tessellated model has many thousands)."""
    scene = {"type": "scene",
             "integrator": {"type": "path", "max_depth": -1}}
    groups = {}
    for poly in polygons:
        emits = poly["light"] >= 0 and poly["light"] == active_light
        key = (tuple(poly["reflectance"]), emits)
        groups.setdefault(key, []).append(poly["points"])
    for i, ((reflectance, emits), loops) in enumerate(sorted(groups.items())):
        scene["m%d" % i] = make_mesh("m%d" % i, loops, reflectance, 1.0 / math.pi if emits else None)
    return mi.load_dict(scene)


def meter(point, normal, seed, spp, eps=EPS):
    """Radiancemeter `eps` above `point`, looking down at it."""
    n = mi.ScalarVector3f(normal)
    n = n / math.sqrt(n[0] ** 2 + n[1] ** 2 + n[2] ** 2)
    origin = mi.ScalarPoint3f(point) + eps * n
    return mi.load_dict({
        "type": "radiancemeter",
        "origin": list(origin), "direction": list(-n),
        "film": {"type": "hdrfilm", "width": 1, "height": 1,
                 "rfilter": {"type": "box"}, "pixel_format": "rgb"},
        "sampler": {"type": "independent", "sample_count": spp, "seed": seed},
    })


def radiosity(scene, point, normal, spp, seed=0):
    img = mi.render(scene, sensor=meter(point, normal, seed, spp), spp=spp, seed=seed)
    arr = img.array  # 1x1 pixel, RGB
    return [math.pi * float(arr[c]) for c in range(3)]


def lift(polygons):
    """How far above its point each meter sits: EPS x (1 + the largest |coordinate|)."""
    return EPS * (1 + max(abs(x) for poly in polygons for c in poly["points"] for x in c))


def batch_radiosity(scene, probes, spp, seed, eps=EPS):
    """All probes in one render: a `batch` sensor of radiancemeters, one film
    pixel each. mi.render already spreads the film's blocks over all cores, and
    one render per light avoids the per-render overhead (measured ~2x faster
    than one render per probe; results agree within noise)."""
    sensor = {"type": "batch",
              "film": {"type": "hdrfilm", "width": len(probes), "height": 1,
                       "rfilter": {"type": "box"}, "pixel_format": "rgb"},
              "sampler": {"type": "independent", "sample_count": spp}}
    for k, pr in enumerate(probes):
        sensor["m%06d" % k] = meter(pr["point"], pr["normal"], seed, spp, eps)
    arr = mi.render(scene, sensor=mi.load_dict(sensor), spp=spp, seed=seed).array
    return [[math.pi * float(arr[3 * k + c]) for c in range(3)] for k in range(len(probes))]


def meters(probes):
    """Each probe's meter points: its "points" (samples spread over an element, whose mean is
    the element's average radiosity) or its one "point"."""
    return [pr.get("points", [pr["point"]]) for pr in probes]


def probe_radiosity(scene, probes, spp, seed, eps):
    """batch_radiosity over every meter point, averaged per probe; a probe of m points gives
    each spp // m samples, so an element average costs what a point does."""
    spots = meters(probes)
    flat = [{"point": q, "normal": pr["normal"]} for pr, qs in zip(probes, spots) for q in qs]
    per = max(1, spp // max(len(qs) for qs in spots))
    values, out = batch_radiosity(scene, flat, per, seed, eps), []
    for qs in spots:
        chunk, values = values[:len(qs)], values[len(qs):]
        out.append([sum(v[c] for v in chunk) / len(chunk) for c in range(3)])
    return out


def run(args):
    import json
    with open(args.input) as f:
        data = json.load(f)
    polys, probes, K = data["polygons"], data["probes"], data["lights"]
    seen = [i for i, p in enumerate(probes) if p["seen"]]
    if args.probes > 0:
        seen = seen[:args.probes]
    eps = lift(polys)
    t0 = time.time()
    with open(args.output, "w") as f:
        f.write("probe,light,r,g,b\n")
        for k in range(K):
            t = time.time()
            # Distinct seed per light so the lights' estimates are independent.
            res = probe_radiosity(make_scene(polys, k), [probes[i] for i in seen], args.spp,
                                  seed=k + 1000 * args.seed, eps=eps)
            for i, b in zip(seen, res):
                f.write("%d,%d,%.7g,%.7g,%.7g\n" % (i, k, *b))
            print("light %d: %.1f s" % (k, time.time() - t), flush=True)
    dt = time.time() - t0
    print("%d probes x %d lights, spp=%d: %.1f s total, %.2f ms per probe per light "
          "(wall, all cores)" % (len(seen), K, args.spp, dt, 1e3 * dt / (K * len(seen))))


def selftest(spp):
    """Closed-form checks: direct light from a unit-exitance 1x1 square onto a
    parallel 1x1 receiver (reflectance 0.5) at distance 1, plus one-sidedness."""
    def corner(x, y):  # point-to-rectangle form factor, rectangle x*y at distance 1 with a corner above the point
        a, b = math.sqrt(1 + x * x), math.sqrt(1 + y * y)
        return (x / a * math.atan(y / a) + y / b * math.atan(x / b)) / (2 * math.pi)
    F = 4 * corner(0.5, 0.5)
    expect = 0.5 * F
    rx = [[-.5, -.5, 0], [.5, -.5, 0], [.5, .5, 0], [-.5, .5, 0]]           # normal +z
    em_down = [[-.5, -.5, 1], [-.5, .5, 1], [.5, .5, 1], [.5, -.5, 1]]      # normal -z (faces receiver)
    em_up = [p for p in reversed(em_down)]                                  # normal +z (faces away)
    em_below = [[x, y, -1] for x, y, _ in rx]                              # under receiver, normal +z
    black = [0, 0, 0]

    def scene(em):
        return mi.load_dict({"type": "scene",
                             "integrator": {"type": "path", "max_depth": -1},
                             "r": make_mesh("r", [rx], [0.5] * 3),
                             "e": make_mesh("e", [em], black, 1 / math.pi)})
    ok = True

    def check(name, got, want, tol):
        nonlocal ok
        good = abs(got - want) <= tol
        ok &= good
        print("%-55s got %.5f  want %.5f  %s" % (name, got, want, "OK" if good else "FAIL"))
    tol = max(4e-3, 4 * expect / math.sqrt(spp))  # ~4 sigma-ish bound
    b = radiosity(scene(em_down), [0, 0, 0], [0, 0, 1], spp)
    for c in range(3):
        check("receiver centre B, channel %d (0.5*F, F=%.4f)" % (c, F), b[c], expect, tol)
    check("emitter front face: B at emitter centre (=1 exitance)",
          radiosity(scene(em_down), [0, 0, 1], [0, 0, -1], spp)[0], 1.0, 1e-3)
    check("emitter facing away: receiver B", radiosity(scene(em_up), [0, 0, 0], [0, 0, 1], spp)[0], 0.0, 1e-6)
    check("light hitting receiver back, viewed from front",
          radiosity(scene(em_below), [0, 0, 0], [0, 0, 1], spp)[0], 0.0, 1e-6)
    check("receiver back face viewed from below (light above)",
          radiosity(scene(em_down), [0, 0, 0], [0, 0, -1], spp)[0], 0.0, 1e-6)
    # Furnace: closed unit cube, all walls inward-facing, emitting unit exitance,
    # reflectance 0.5 -> B = 1 / (1 - 0.5) = 2. Checks unlimited-depth
    # interreflection (Russian roulette must not bias it).
    walls = {}
    for a in range(3):
        for side in (0, 1):
            u, v = (a + 1) % 3, (a + 2) % 3
            pts = []
            for cu, cv in ((0, 0), (1, 0), (1, 1), (0, 1)):
                p = [0.0] * 3
                p[a], p[u], p[v] = side, cu, cv
                pts.append(p)
            if side == 1:  # (u x v) = +a; flip the far wall so it faces inwards
                pts.reverse()
            walls["w%d%d" % (a, side)] = make_mesh("w%d%d" % (a, side), [pts], [0.5] * 3, 1 / math.pi)
    furnace = mi.load_dict(dict(type="scene", integrator={"type": "path", "max_depth": -1}, **walls))
    check("furnace cube, rho=0.5, all walls emit: B = 2",
          radiosity(furnace, [0.3, 0.6, 0], [0, 0, 1], spp)[0], 2.0, 0.02)
    print("selftest", "PASSED" if ok else "FAILED")
    return ok


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("input", nargs="?")
    ap.add_argument("output", nargs="?")
    ap.add_argument("--spp", type=int, default=4096)
    ap.add_argument("--seed", type=int, default=0,
                    help="another seed gives an independent render of the same probes (to measure its noise)")
    ap.add_argument("--probes", type=int, default=0,
                    help="use only the first N seen probes (0 = all)")
    ap.add_argument("--selftest", action="store_true")
    args = ap.parse_args()
    if args.selftest:
        sys.exit(0 if selftest(max(args.spp, 16384)) else 1)
    if not (args.input and args.output):
        ap.error("input and output are required unless --selftest")
    run(args)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Blender Cycles (bpy from PyPI) baking each light's diffuse lighting to point colors:
the peer of `./relight bench peers`. Runs in its own venv (out/blender-venv), never with
the product.

Usage:
  out/blender-venv/bin/python Testing/Benchmark/blender_bake.py IN.npz OUT.npz \
      [--samples 16,64,256] [--lights 0,1,2] [--threads 2]
  out/blender-venv/bin/python Testing/Benchmark/blender_bake.py --selftest

IN.npz (written by peers_bench.py): `points` (n, 3), `offsets` (m + 1) and
`connectivity` of m polygons (front by the right-hand rule), per polygon `reflectance`
(m, 3) and `light` (-1 or the light's index). OUT.npz: `b_<samples>_<light>` (n, 3), the
radiosity B at every point with only that light emitting, and `bakes` rows of
(samples, light, process CPU seconds, wall seconds), `setup_s` (process CPU seconds /
threads from the start to the first bake) and `peak_rss_mb`.

How Cycles is made to solve the radiosity model (the same choices as
mitsuba_reference.py):
  * Every polygon is one-sided: a Mix Shader switched by Geometry > Backfacing gives back
    faces a black Diffuse BSDF (they absorb and occlude), front faces a Diffuse BSDF
    (Lambert: roughness 0) of the polygon's reflectance plus, on the baked light's
    polygons, an Emission. Cycles' own Diffuse BSDF and Emission are two-sided.
  * Emission strength S is the radiance leaving the surface (Blender: strength 1 makes a
    surface show exactly its color), so unit exitance M = pi L is S = 1/pi.
  * A DIFFUSE bake with pass_filter {DIRECT, INDIRECT} is the diffuse *light* pass,
    reflected radiance divided by the albedo: E / pi for irradiance E. With COLOR as well
    it is the reflected radiance rho E / pi, so the radiosity of a non-emitting surface
    is B = rho E = pi x bake. `--selftest` checks both against closed forms.
  * A vertex bake evaluates every polygon corner at its point (the first triangle of the
    corner's polygon that has it; the noise seeded by the point) and a point-domain
    attribute gets the mean over the point's corners: one path-traced estimate of B at
    the point itself, at the cost of all its corners (up to 4 in a quad mesh).
  * World black, 1,024 bounces of every kind (Cycles' hard maximum; its Russian roulette keeps
    the estimate unbiased), no clamping, no light threshold, no adaptive sampling, no
    denoising (vertex bakes are never denoised anyway), CPU device.
"""
import argparse
import math
import resource
import sys
import time

import bpy
import numpy as np

STRENGTH = 1.0 / math.pi  # unit exitance
BLACK = (0.0, 0.0, 0.0, 1.0)


def reset_scene(threads, samples=16, seed=0):
    """An empty scene set up as a plain unbiased path tracer (see the module docstring)."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads
    cycles = scene.cycles
    cycles.device = "CPU"
    cycles.samples = samples
    cycles.seed = seed
    cycles.use_adaptive_sampling = False
    cycles.use_denoising = False
    cycles.sample_clamp_direct = 0.0  # 0 = no clamping
    cycles.sample_clamp_indirect = 0.0
    cycles.light_sampling_threshold = 0.0  # no probabilistic cut of weak lights
    for bounces in ("max_bounces", "diffuse_bounces", "glossy_bounces", "transmission_bounces",
                    "transparent_max_bounces", "volume_bounces"):
        setattr(cycles, bounces, 1024)
    world = bpy.data.worlds.new("black")
    world.node_tree.nodes["Background"].inputs["Color"].default_value = BLACK
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
    scene.world = world
    scene.render.bake.target = "VERTEX_COLORS"
    return scene


def one_sided_material(name, reflectance):
    """A Lambert material lit only on its front; returns it and its Emission node, whose
    strength the caller sets to STRENGTH while this material's light is baked."""
    material = bpy.data.materials.new(name)
    material.cycles.emission_sampling = "FRONT"  # only the front emits (see the mix below)
    nodes, links = material.node_tree.nodes, material.node_tree.links
    nodes.clear()
    front = nodes.new("ShaderNodeBsdfDiffuse")
    front.inputs["Color"].default_value = (*reflectance, 1.0)
    front.inputs["Roughness"].default_value = 0.0
    emission = nodes.new("ShaderNodeEmission")
    emission.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
    emission.inputs["Strength"].default_value = 0.0
    lit = nodes.new("ShaderNodeAddShader")
    links.new(front.outputs["BSDF"], lit.inputs[0])
    links.new(emission.outputs["Emission"], lit.inputs[1])
    back = nodes.new("ShaderNodeBsdfDiffuse")
    back.inputs["Color"].default_value = BLACK
    side = nodes.new("ShaderNodeNewGeometry")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(side.outputs["Backfacing"], mix.inputs["Fac"])
    links.new(lit.outputs["Shader"], mix.inputs[1])  # Fac 0: front
    links.new(back.outputs["BSDF"], mix.inputs[2])  # Fac 1: back
    output = nodes.new("ShaderNodeOutputMaterial")
    links.new(mix.outputs["Shader"], output.inputs["Surface"])
    return material, emission


def make_object(points, offsets, connectivity, material_of_polygon, materials):
    """One mesh object holding exactly these points and polygons (no welding), with a
    float point-domain color attribute as the active bake target."""
    mesh = bpy.data.meshes.new("scene")
    faces = [connectivity[offsets[i]:offsets[i + 1]].tolist() for i in range(len(offsets) - 1)]
    mesh.from_pydata(np.asarray(points, dtype=float).tolist(), [], faces)
    for material in materials:
        mesh.materials.append(material)
    mesh.polygons.foreach_set("material_index", np.asarray(material_of_polygon, dtype=np.int32))
    mesh.polygons.foreach_set("use_smooth", np.zeros(len(faces), dtype=bool))
    mesh.update()
    target = mesh.color_attributes.new("bake", "FLOAT_COLOR", "POINT")
    mesh.color_attributes.active_color = target
    obj = bpy.data.objects.new("scene", mesh)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    return obj


def bake(obj, samples, seed, with_color=True):
    """One DIFFUSE bake into the point colors; returns (pi x bake as an (n, 3) array,
    process CPU seconds, wall seconds)."""
    scene = bpy.context.scene
    scene.cycles.samples = samples
    scene.cycles.seed = seed
    passes = {"DIRECT", "INDIRECT", "COLOR"} if with_color else {"DIRECT", "INDIRECT"}
    cpu, wall = time.process_time(), time.perf_counter()
    result = bpy.ops.object.bake(type="DIFFUSE", pass_filter=passes, target="VERTEX_COLORS")
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    if "FINISHED" not in result:
        raise RuntimeError(f"Cycles bake returned {result}")
    data = obj.data.color_attributes["bake"].data
    rgba = np.empty(len(data) * 4, dtype=np.float32)
    data.foreach_get("color", rgba)
    return math.pi * rgba.reshape(-1, 4)[:, :3].astype(float), cpu, wall


def peak_rss_mb():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def run(args):
    data = np.load(args.input)
    reset_scene(args.threads)
    reflectance, light = data["reflectance"], data["light"]
    # One material per reflectance for plain polygons, one per light for the lamps (their
    # emission is switched on one light at a time).
    keys = sorted({(tuple(r), int(l)) for r, l in zip(reflectance.tolist(), light)})
    index = {key: i for i, key in enumerate(keys)}
    made = [one_sided_material(f"m{i}", key[0]) for i, key in enumerate(keys)]
    emitters = {key[1]: made[i][1] for i, key in enumerate(keys) if key[1] >= 0}
    polygon_material = [index[(tuple(r), int(l))] for r, l in zip(reflectance.tolist(), light)]
    obj = make_object(data["points"], data["offsets"], data["connectivity"], polygon_material,
                      [m for m, _ in made])
    setup = time.process_time()  # since the start: loading bpy and building the scene
    results, rows = {}, []
    for samples in (int(s) for s in args.samples.split(",")):
        for k in (int(s) for s in args.lights.split(",")):
            for j, emission in emitters.items():
                emission.inputs["Strength"].default_value = STRENGTH if j == k else 0.0
            # A seed per bake, so no two bakes share their noise.
            b, cpu, wall = bake(obj, samples, seed=1000 * k + samples)
            results[f"b_{samples}_{k}"] = b
            rows.append((samples, k, cpu, wall))
            print(f"Cycles: light {k}, {samples} samples: {cpu:.1f} s CPU, {wall:.1f} s wall", flush=True)
    np.savez(args.output, bakes=np.array(rows), setup_s=setup / args.threads, peak_rss_mb=peak_rss_mb(), **results)


def panel(corners):
    """A planar quad (front by the right-hand rule) as 2 x 2 quads around its centre, so
    that a point of the bake sits at the centre (point 4): (points, quads)."""
    a, b, c, d = (np.asarray(p, dtype=float) for p in corners)
    points = [tuple((1 - u) * (1 - v) * a + u * (1 - v) * b + u * v * c + (1 - u) * v * d)
              for v in (0, 0.5, 1) for u in (0, 0.5, 1)]
    return points, [(0, 1, 4, 3), (1, 2, 5, 4), (3, 4, 7, 6), (4, 5, 8, 7)]


def add_object(name, panels, material):
    """One mesh object of several panels with one material and a bake target."""
    points, quads = [], []
    for panel_points, panel_quads in panels:
        quads += [tuple(len(points) + i for i in q) for q in panel_quads]
        points += panel_points
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(points, [], quads)
    mesh.materials.append(material)
    mesh.update()
    mesh.color_attributes.active_color = mesh.color_attributes.new("bake", "FLOAT_COLOR", "POINT")
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def square(side, height, normal_z):
    """A side x side square centred over the origin at `height`, its front along +z or -z."""
    h = side / 2
    corners = [(-h, -h, height), (h, -h, height), (h, h, height), (-h, h, height)]
    return panel(corners if normal_z > 0 else corners[::-1])


def bake_centres(obj, samples, with_color=True):
    """pi x the DIFFUSE bake (channel 0) at the centre of each of the object's panels."""
    for o in bpy.context.scene.objects:
        o.select_set(o is obj)
    bpy.context.view_layer.objects.active = obj
    return bake(obj, samples, seed=7, with_color=with_color)[0][4::9, 0]


def corner_factor(x, y):
    """Form factor from a point to an x * y rectangle at distance 1, parallel to it,
    with one corner straight above the point."""
    a, b = math.sqrt(1 + x * x), math.sqrt(1 + y * y)
    return (x / a * math.atan(y / a) + y / b * math.atan(x / b)) / (2 * math.pi)


def selftest(samples=4096, threads=2):
    """Closed forms: a unit-exitance square (side 2, 1 above) over a small receiver of
    reflectance 0.5 has irradiance E = F (the point-to-square form factor) at the
    receiver's centre, and B = 0.5 F; one-sidedness; and the furnace (closed cube, all
    walls emit unit exitance, rho = 0.5: total B = 2, of which 1 reflected)."""
    ok = True

    def check(name, got, want, tol):
        nonlocal ok
        good = abs(got - want) <= tol
        ok &= good
        print(f"{name:<62} got {got:.5f}  want {want:.5f}  {'OK' if good else 'FAIL'}", flush=True)

    F = 4 * corner_factor(1.0, 1.0)  # side 2 at height 1: four 1 x 1 corners
    tol = max(2e-3, 4 * F / math.sqrt(samples))

    def emitter_over(height, normal_z):
        """The small receiver (side 0.02, rho 0.5, facing up) under or over the emitter."""
        reset_scene(threads)
        receiver = add_object("receiver", [square(0.02, 0.0, +1)], one_sided_material("r", (0.5,) * 3)[0])
        material, emission = one_sided_material("e", (0.0,) * 3)
        emission.inputs["Strength"].default_value = STRENGTH
        add_object("emitter", [square(2.0, height, normal_z)], material)
        return receiver

    receiver = emitter_over(1.0, -1)
    check(f"irradiance E = F = {F:.4f} (pi x bake, color off)", bake_centres(receiver, samples, False)[0], F, tol)
    check("radiosity B = 0.5 F (pi x bake, color on)", bake_centres(receiver, samples)[0], 0.5 * F, tol / 2)
    check("emitter facing away from the receiver: B = 0", bake_centres(emitter_over(1.0, +1), samples)[0], 0.0, 1e-6)
    check("emitter under the receiver, facing up: B = 0", bake_centres(emitter_over(-1.0, +1), samples)[0], 0.0, 1e-6)

    # Furnace: every wall of a closed unit cube faces in and emits unit exitance, rho 0.5:
    # B = 1 / (1 - rho) = 2 everywhere, 1 of it reflected (the bake has no emission).
    reset_scene(threads)
    corner = np.array([(x, y, z) for z in (0, 1) for y in (0, 1) for x in (0, 1)], dtype=float)
    walls = []
    for wall in ((0, 1, 3, 2), (4, 5, 7, 6), (0, 1, 5, 4), (2, 3, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5)):
        p = corner[list(wall)]
        inward = np.dot(np.cross(p[1] - p[0], p[2] - p[0]), 0.5 - p.mean(axis=0)) > 0
        walls.append(panel(p if inward else p[::-1]))
    material, emission = one_sided_material("furnace", (0.5, 0.5, 0.5))
    emission.inputs["Strength"].default_value = STRENGTH
    cube = add_object("furnace", walls, material)
    centres = bake_centres(cube, samples)
    check("furnace, rho = 0.5: reflected B = 1 (mean of the 6 wall centres)", float(centres.mean()), 1.0,
          max(0.01, 4 * centres.std() / math.sqrt(6)))
    print("selftest", "PASSED" if ok else "FAILED")
    return ok


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("input", nargs="?")
    parser.add_argument("output", nargs="?")
    parser.add_argument("--samples", default="16,64,256")
    parser.add_argument("--lights", default="0")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--selftest", action="store_true")
    args = parser.parse_args()
    if args.selftest:
        sys.exit(0 if selftest(threads=args.threads) else 1)
    if not (args.input and args.output):
        parser.error("input and output are required unless --selftest")
    run(args)


if __name__ == "__main__":
    main()

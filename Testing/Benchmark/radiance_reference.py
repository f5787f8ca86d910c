#!/usr/bin/env python3
"""A second independent reference beside Mitsuba 3: Radiance's rtrace (from PyPI's
pyradiance, bench-only, in the same venv) at the probes of a mitsuba_reference.py scene.

Usage:
  out/mitsuba-venv/bin/python Testing/Benchmark/radiance_reference.py \
      out/bench/house_traced_room.json out/bench/house_traced_radiance.csv [--ad 512] [--ab 16]

Same JSON in, same CSV out (probe,light,r,g,b) as mitsuba_reference.py. For each light k
alone, every polygon is a Radiance `polygon` with a `plastic` material of its reflectance
(no specular part), light k a `light` of radiance 1/pi (unit exitance);
rtrace -I gives the irradiance at a hair above each probe towards its normal, and the
probe's radiosity is its reflectance times that. Radiance samples the lamps directly and the
rest by Monte Carlo ambient rays (-aa 0: no interpolation, every probe gathered anew);
-ab bounces (16 by default), where Mitsuba's paths run on under Russian roulette. Radiance's plastic
reflects on both sides where the radiosity model and Mitsuba absorb on a back face: the two
references part where a back face is seen (a lamp's back), which the bench reports as their
agreement.
"""
import argparse
import json
import os
import pathlib
import subprocess
import sys
import tempfile
import time

import numpy as np


def tool(name):
    """A Radiance program shipped inside pyradiance (its bin folder), else one on PATH."""
    import pyradiance
    path = pathlib.Path(pyradiance.__file__).parent / "bin" / name
    return str(path) if path.exists() else name


def write_scene(polygons, light, path):
    """The scene as Radiance text: one plastic per reflectance, light `light` glowing."""
    materials, lines = {}, []
    radiance = 1.0 / np.pi
    lines.append(f"void light lamp 0 0 3 {radiance:.9g} {radiance:.9g} {radiance:.9g}")
    for i, poly in enumerate(polygons):
        if poly["light"] == light:
            name = "lamp"
        else:
            rho = tuple(round(float(c), 6) for c in poly["reflectance"])
            name = materials.get(rho)
            if name is None:
                name = materials[rho] = f"m{len(materials)}"
                lines.append(f"void plastic {name} 0 0 5 {rho[0]} {rho[1]} {rho[2]} 0 0")
        coords = " ".join(f"{x:.9g}" for p in poly["points"] for x in p)
        lines.append(f"{name} polygon p{i} 0 0 {3 * len(poly['points'])} {coords}")
    pathlib.Path(path).write_text("\n".join(lines) + "\n")


def irradiance(octree, probes, args, eps):
    """rtrace -I at each probe, a hair above it along its normal. With a seed, the probes go
    to rtrace in an order shuffled by it (and come back in theirs): Radiance takes no seed,
    but a ray's samples follow its place in the run, so another order is another draw."""
    order = np.random.default_rng(args.seed).permutation(len(probes)) if args.seed else np.arange(len(probes))
    rows = []
    for p in (probes[i] for i in order):
        n = np.asarray(p["normal"], float)
        x = np.asarray(p["point"], float) + eps * n
        rows.append(f"{x[0]:.9g} {x[1]:.9g} {x[2]:.9g} {n[0]:.9g} {n[1]:.9g} {n[2]:.9g}")
    command = [tool("rtrace"), "-h", "-I+", "-ab", str(args.ab), "-ad", str(args.ad), "-as", "0", "-aa", "0",
               "-lw", "1e-7", "-lr", "-" + str(args.ab), "-dj", "0.7", "-ds", "0.05", "-dt", "0", "-dc", "1", "-st", "0", "-n", str(os.cpu_count() or 1),
               octree]
    done = subprocess.run(command, input="\n".join(rows) + "\n", capture_output=True, text=True, check=True)
    traced = np.array([[float(v) for v in line.split()[:3]] for line in done.stdout.splitlines() if line.strip()])
    values = np.empty_like(traced)
    values[order] = traced
    return values


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scene")
    parser.add_argument("csv")
    parser.add_argument("--ab", type=int, default=16, help="ambient bounces")
    parser.add_argument("--ad", type=int, default=512, help="ambient divisions (rays) at the probe")
    parser.add_argument("--seed", type=int, default=0,
                        help="another draw of the same render (the probes traced in an order shuffled by it): "
                             "two seeds' difference is Radiance's noise")
    args = parser.parse_args()
    data = json.loads(pathlib.Path(args.scene).read_text())
    polygons, probes = data["polygons"], [p for p in data["probes"] if p["seen"]]
    span = max(abs(x) for poly in polygons for p in poly["points"] for x in p)
    eps = 1e-4 * (1 + span)
    reflectance = np.array([polygons[p["cell"]]["reflectance"] for p in probes], float)
    with tempfile.TemporaryDirectory() as folder, open(args.csv, "w") as out:
        out.write("probe,light,r,g,b\n")
        for k in range(data["lights"]):
            start = time.perf_counter()
            rad, octree = os.path.join(folder, "scene.rad"), os.path.join(folder, "scene.oct")
            write_scene(polygons, k, rad)
            with open(octree, "wb") as f:
                subprocess.run([tool("oconv"), rad], stdout=f, check=True)
            b = reflectance * irradiance(octree, probes, args, eps)
            for i, row in enumerate(b):
                out.write(f"{i},{k},{row[0]:.9g},{row[1]:.9g},{row[2]:.9g}\n")
            print(f"light {k}: {time.perf_counter() - start:.1f} s", file=sys.stderr)


if __name__ == "__main__":
    main()

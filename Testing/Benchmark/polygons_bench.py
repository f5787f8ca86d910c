"""./relight bench polygons: a room with four tessellated spheres (8 lamps, patch 0.5 m,
element 0.1 m) from 10k triangles up, solved by Auto with face clusters (the mesher's
default) and, where it finishes in reasonable time, without them (ClusterAngle 0, the way
every triangle was its own patch before); at the largest size also k = 1 (all lights in
one solution) against k = 8. One PolygonsBench process per run, so each peak memory is its
own; errors against Mitsuba at 3,000 probe points (--reference, which `./relight bench
polygons` renders once). Writes out/bench/polygons.csv and polygons.png and prints the
ratios measured in this run.
  --sizes 10000,20000,80000  --lamps 8  --plain-up-to 20000  --bin build/bin/PolygonsBench"""

import argparse, csv, io, math, pathlib, subprocess, sys

parser = argparse.ArgumentParser()
parser.add_argument("--out", default="out/bench")
parser.add_argument("--bin", default="build/bin/PolygonsBench")
parser.add_argument("--sizes", default="10000,20000,80000,200000")
parser.add_argument("--lamps", type=int, default=8)
parser.add_argument("--plain-up-to", type=int, default=20000, help="largest size also run without clusters")
parser.add_argument("--spheres", type=int, default=4)
parser.add_argument("--reference", default="", help="Mitsuba's probe,light,r,g,b CSV")
args = parser.parse_args()


def run(triangles, angle, combined=False):
    command = [args.bin, "--triangles", str(triangles), "--spheres", str(args.spheres), "--lamps", str(args.lamps),
               "--cluster-angle", str(angle), "--combined", "1" if combined else "0"]
    if args.reference:
        command += ["--reference", args.reference]
    text = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    row = next(csv.DictReader(io.StringIO(text)))
    row["k"] = 1 if combined else args.lamps
    error = "" if combined or row["error_pct"] == "nan" else f", {float(row['error_pct']):.2f} % from Mitsuba"
    print(f"{int(row['triangles']):>9,} triangles, clusters {'on ' if angle else 'off'}, k = {row['k']}: "
          f"{int(row['elements']):>9,} elements, {int(row['patches']):>7,} patches, {row['method']}, "
          f"{int(row['shots']):>7,} shots, solve {float(row['solve_s']):7.2f} s, total {float(row['total_s']):7.2f} s, "
          f"{float(row['peak_mb']):6.0f} MB{error}", flush=True)
    return row


rows = []
for size in (int(s) for s in args.sizes.split(",")):
    rows.append(run(size, 30))
    if size <= args.plain_up_to:
        rows.append(run(size, 0))
        clustered, plain = rows[-2], rows[-1]
        print(f"  clusters: {float(plain['total_s']) / float(clustered['total_s']):.1f}x faster, "
              f"{float(plain['peak_mb']) / float(clustered['peak_mb']):.1f}x less memory")
largest = rows[-1] if float(rows[-1]["cluster_angle"]) > 0 else rows[-2]
one = run(int(largest["triangles"]) and max(int(s) for s in args.sizes.split(",")), 30, combined=True)
rows.append(one)
print(f"  k = {args.lamps} costs {float(largest['solve_s']) / float(one['solve_s']):.2f}x k = 1 (solve)")
out = pathlib.Path(args.out)
out.mkdir(parents=True, exist_ok=True)
with open(out / "polygons.csv", "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    writer.writeheader()
    writer.writerows(rows)
on = [r for r in rows if float(r["cluster_angle"]) > 0 and r["k"] == args.lamps]
if len(on) >= 2:
    a, b = on[-2], on[-1]
    growth = math.log(float(b["total_s"]) / float(a["total_s"])) / math.log(float(b["triangles"]) / float(a["triangles"]))
    print(f"time grows as N^{growth:.2f} from {int(a['triangles']):,} to {int(b['triangles']):,} triangles")
try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    sys.exit(0)
fig, ax = plt.subplots(figsize=(6, 4))
for angle, label, style in ((30, "face clusters (default)", "o-"), (0, "every triangle a patch", "s--")):
    sel = [r for r in rows if float(r["cluster_angle"]) == angle and r["k"] == args.lamps]
    if sel:
        ax.loglog([int(r["triangles"]) for r in sel], [float(r["total_s"]) for r in sel], style, label=label)
ax.set_xlabel("input triangles (spheres in a 6 x 5 x 3 m room)")
ax.set_ylabel("mesh + prepare + solve (s), 2 cores")
ax.set_title(f"k = {args.lamps} lights, Auto")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(out / "polygons.png", dpi=110)
print(f"wrote {out / 'polygons.csv'} and {out / 'polygons.png'}")

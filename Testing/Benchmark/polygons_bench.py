"""./relight bench polygons: a room with four tessellated spheres (8 lamps, patch 0.5 m,
element 0.1 m) from 10k triangles up, solved by Auto with face clusters (the mesher's
default) and, where it finishes in reasonable time, without them (ClusterAngle 0, the way
every triangle was its own patch before); at the largest size also k = 1 (all lights in
one solution) against k = 8. One PolygonsBench process per run, so each peak memory is its
own; errors against Mitsuba at 3,000 probe points (--reference, which `./relight bench
polygons` renders once). Writes out/bench/polygons.csv and polygons.png and prints the
ratios measured in this run. What accuracy costs in time: each size is also solved by the
clustered method (element-level gathering), which Auto leaves for the faster patch-level
hierarchical method on this room; the second plot puts both on error against time.
  --sizes 10000,20000,80000  --lamps 8  --plain-up-to 20000  --clustered-up-to 200000"""

import argparse, csv, io, math, pathlib, subprocess, sys

parser = argparse.ArgumentParser()
parser.add_argument("--out", default="out/bench")
parser.add_argument("--bin", default="build/bin/PolygonsBench")
parser.add_argument("--sizes", default="10000,20000,80000,200000")
parser.add_argument("--lamps", type=int, default=8)
parser.add_argument("--plain-up-to", type=int, default=20000, help="largest size also run without clusters")
parser.add_argument("--spheres", type=int, default=4)
parser.add_argument("--clustered-up-to", type=int, default=200000, help="largest size also solved by the clustered method")
parser.add_argument("--reference", default="", help="Mitsuba's probe,light,r,g,b CSV")
parser.add_argument("--replot", action="store_true", help="only plot out/bench/polygons.csv again")
args = parser.parse_args()


def run(triangles, angle, combined=False, method="auto"):
    command = [args.bin, "--triangles", str(triangles), "--spheres", str(args.spheres), "--lamps", str(args.lamps),
               "--cluster-angle", str(angle), "--combined", "1" if combined else "0", "--method", method]
    if args.reference:
        command += ["--reference", args.reference]
    text = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    row = next(csv.DictReader(io.StringIO(text)))
    row["k"] = 1 if combined else args.lamps
    row["asked"] = method
    error = "" if combined or row["error_pct"] == "nan" else f", {float(row['error_pct']):.2f} % from Mitsuba"
    print(f"{int(row['triangles']):>9,} triangles, clusters {'on ' if angle else 'off'}, k = {row['k']}: "
          f"{int(row['elements']):>9,} elements, {int(row['patches']):>7,} patches, {row['method']}, "
          f"{int(row['shots']):>7,} shots, solve {float(row['solve_s']):7.2f} s, total {float(row['total_s']):7.2f} s, "
          f"{float(row['peak_mb']):6.0f} MB{error}", flush=True)
    return row


if args.replot:  # plot the csv of the last run again
    with open(pathlib.Path(args.out) / "polygons.csv") as f:
        rows = [dict(r, k=int(r["k"])) for r in csv.DictReader(f)]
else:
    rows = []
    for size in (int(s) for s in args.sizes.split(",")):
        rows.append(run(size, 30))
        if size <= args.clustered_up_to:
            auto, clustered = rows[-1], run(size, 30, method="clustered")
            rows.append(clustered)
            if args.reference:
                print(f"  clustered: {float(clustered['total_s']) / float(auto['total_s']):.1f}x the time, error "
                      f"{float(clustered['error_pct']):.2f} % against {float(auto['error_pct']):.2f} %")
        if size <= args.plain_up_to:
            rows.append(run(size, 0))
            faced, plain = [r for r in rows if r["asked"] == "auto"][-2:]
            print(f"  clusters: {float(plain['total_s']) / float(faced['total_s']):.1f}x faster, "
                  f"{float(plain['peak_mb']) / float(faced['peak_mb']):.1f}x less memory")
    largest = [r for r in rows if r["asked"] == "auto" and float(r["cluster_angle"]) > 0][-1]
    one = run(int(largest["triangles"]) and max(int(s) for s in args.sizes.split(",")), 30, combined=True)
    rows.append(one)
    print(f"  k = {args.lamps} costs {float(largest['solve_s']) / float(one['solve_s']):.2f}x k = 1 (solve)")
out = pathlib.Path(args.out)
out.mkdir(parents=True, exist_ok=True)
with open(out / "polygons.csv", "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
    writer.writeheader()
    writer.writerows(rows)
on = [r for r in rows if float(r["cluster_angle"]) > 0 and r["k"] == args.lamps and r["asked"] == "auto"]
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
fig, (ax, acc) = plt.subplots(1, 2, figsize=(11, 4))
for angle, label, style in ((30, "face clusters (default)", "o-"), (0, "every triangle a patch", "s--")):
    sel = [r for r in rows if float(r["cluster_angle"]) == angle and r["k"] == args.lamps and r["asked"] == "auto"]
    if sel:
        ax.loglog([int(r["triangles"]) for r in sel], [float(r["total_s"]) for r in sel], style, label=label)
sel = [r for r in rows if r["asked"] == "clustered"]
if sel:
    ax.loglog([int(r["triangles"]) for r in sel], [float(r["total_s"]) for r in sel], "^:", label="clustered method")
ax.set_xlabel("input triangles (spheres in a 6 x 5 x 3 m room)")
ax.set_ylabel("mesh + prepare + solve (s), 2 cores")
ax.set_title(f"k = {args.lamps} lights, Auto")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
for asked, label, style, color in (("auto", "Auto (by estimated cost)", "o-", "C0"), ("clustered", "clustered method", "^:", "C2")):
    sel = [r for r in rows if r["asked"] == asked and float(r["cluster_angle"]) > 0 and r["k"] == args.lamps
           and r["error_pct"] not in ("", "nan")]
    if sel:
        acc.semilogx([float(r["total_s"]) for r in sel], [float(r["error_pct"]) for r in sel], style, label=label,
                     color=color)
        for r in sel:
            acc.annotate(f"{int(r['triangles']) // 1000}k", (float(r["total_s"]), float(r["error_pct"])), fontsize=7,
                         textcoords="offset points", xytext=(4, 3))
acc.axhline(2.0, color="grey", lw=0.8, ls="--")
acc.set_xlabel("mesh + prepare + solve (s), 2 cores")
acc.set_ylabel("mean per-light error vs Mitsuba 3 (%)")
acc.set_title("what accuracy costs in time")
acc.grid(True, which="both", alpha=0.3)
acc.legend()
fig.tight_layout()
fig.savefig(out / "polygons.png", dpi=110)
print(f"wrote {out / 'polygons.csv'} and {out / 'polygons.png'}")

"""What the final gather's irradiance cache buys on the furnished room: error against a
Mitsuba 3 reference and solve time, at two mesh sizes, without the gather, gathering at every
point, and sharing the gathers (GatherCache) at 256 and 1,024 rays. Plots error against time.

    /usr/bin/python3 Testing/Benchmark/gather_cache_bench.py --bin build/bin/ScaleBench \\
        --reference out/bench/room_reference_20k.csv --out out/bench

The reference should be a strong one: the 4,096-path room_reference.csv holds about 0.74 % of
noise in this measure (combine_references.py makes a 20,480-path one from a second render)."""
import argparse
import csv
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from bench_plots import error_against_time  # noqa: E402

RUNS = [  # label, ScaleBench flags
    ("no gather", ["--gather", "0"]),
    ("256 rays at every point", ["--gather", "256", "--cache", "0"]),
    ("256 rays, cache 0.15 (defaults)", ["--gather", "256", "--cache", "0.15"]),
    ("1,024 rays, cache 0.15", ["--gather", "1024", "--cache", "0.15"]),
]


def run(binary, size, flags, reference, csv_path):
    subprocess.run([binary, "--sizes", str(size), "--mitsuba", reference, "--csv", csv_path] + flags,
                   check=True, capture_output=True, text=True)
    row = next(r for r in csv.DictReader(open(csv_path)) if r["mode"] == "tagged")
    return int(row["elements"]), float(row["seconds"]), 100 * float(row["mean_error"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--bin", default="build/bin/ScaleBench")
    parser.add_argument("--reference", default="out/bench/room_reference_20k.csv")
    parser.add_argument("--out", default="out/bench")
    parser.add_argument("--sizes", default="40000,320000")
    parser.add_argument("--replot", action="store_true", help="plot the last run's gather_cache.csv again")
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    table = os.path.join(args.out, "gather_cache.csv")
    if args.replot:
        results = [(int(r["elements"]), r["run"], float(r["seconds"]), float(r["error_pct"]))
                   for r in csv.DictReader(open(table))]
    else:
        results = measure(args)
        with open(table, "w", newline="") as f:
            out = csv.writer(f)
            out.writerow(["elements", "run", "seconds", "error_pct"])
            out.writerows(results)
    plot(results, os.path.join(args.out, "gather_cache.png"))


def measure(args):
    results = []
    for size in (int(s) for s in args.sizes.split(",")):
        for label, flags in RUNS:
            elements, seconds, error = run(args.bin, size, flags, args.reference,
                                           os.path.join(args.out, "gather_cache_run.csv"))
            results.append((elements, label, seconds, error))
            print(f"{elements:>9,} elements  {label:<34} {seconds:7.2f} s  {error:5.2f} %", flush=True)
    return results


def plot(results, path):
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for label, _ in RUNS:
        points = [(s, e, n) for n, l, s, e in results if l == label]
        ax.plot([p[0] for p in points], [p[1] for p in points], "o-", label=label)
        for s, e, n in points:
            ax.annotate(f"{n:,}", (s, e), textcoords="offset points", xytext=(4, 4), fontsize=7)
    ax.axhline(0.33, color="grey", linestyle=":", linewidth=1, label="the reference's own noise (20,480 paths)")
    error_against_time(ax, [2, 5, 10, 20, 50], "Furnished room, 8 lights: what sharing the gather buys",
                       "mean error against Mitsuba 3, %")
    ax.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()

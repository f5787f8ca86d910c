"""What accuracy costs in time on the FZK-Haus: mean per-lamp error against Mitsuba 3 over
solve time, one point per ClusterSeparation, from the rows house.py --reference appended to
its CSV (the newest row per separation of the given commit). Run:
for s in 3 4 6 8; do ./relight python Testing/Benchmark/house.py --reference --cluster-separation $s; done
./relight python Testing/Benchmark/plot_house_separation.py out/bench/house.csv docs/images/house_accuracy_time.png [COMMIT]"""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def points(path, commit):
    """{separation: (solve_s, error_pct, peak_mib)} from the newest matching rows."""
    rows = [r for r in csv.DictReader(open(path)) if r.get("mean_error_pct") and r["method"] == "Auto"]
    commit = commit or rows[-1]["commit"]
    found = {}
    for r in rows:
        if r["commit"] == commit:
            found[float(r["separation"])] = (float(r["solve_s"]), float(r["mean_error_pct"]), int(r["peak_mib"]))
    return commit, dict(sorted(found.items()))


def main(path, out, commit=None):
    commit, found = points(path, commit)
    if not found:
        sys.exit(f"no rows with mean_error_pct for commit {commit} in {path}")
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    times = [t for t, _, _ in found.values()]
    errors = [e for _, e, _ in found.values()]
    ax.plot(times, errors, "o-")
    for s, (t, e, peak) in found.items():
        ax.annotate(f"{s:g} ({peak / 1024:.1f} GB)", (t, e), textcoords="offset points", xytext=(6, 4))
    ax.set_xlabel("solve time (s), 2 cores")
    ax.set_ylabel("mean per-lamp error vs Mitsuba 3 (%)")
    ax.set_title(f"FZK-Haus, 6 lamps: ClusterSeparation (peak memory) [{commit}]")
    ax.set_ylim(0, 1.15 * max(errors))
    ax.set_xlim(0.8 * min(times), 1.15 * max(times))
    ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    for s, (t, e, peak) in found.items():
        print(f"| {s:g} | {t:.1f} s | {peak:,} MiB | {e:.1f} % |")
    print(f"wrote {out}")


if __name__ == "__main__":
    main(*sys.argv[1:4])

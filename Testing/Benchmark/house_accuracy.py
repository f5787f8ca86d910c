"""What accuracy costs in time on a real building: the FZK-Haus (house.py) solved at each
level of the one knob (relight.levels), each against Mitsuba 3 at the 600 probes traced
from the lamps. Each level runs in its own process (its peak memory is its own). Writes
out/bench/accuracy_house.csv, .md and .png. Run: ./relight bench accuracy house
[--levels preview,draft,default,fine,reference] [--mitsuba-python PATH]"""

import argparse, csv, pathlib, subprocess, sys

HERE = pathlib.Path(__file__).resolve().parent


def run_level(level, out, mitsuba):
    """house.py at `level`; its row of house.csv (the last one it appended)."""
    subprocess.run([sys.executable, str(HERE / "house.py"), "--reference", "--traced-probes", "--accuracy", level,
                    "--out", str(out), "--mitsuba-python", mitsuba], check=True, stdout=subprocess.DEVNULL)
    with (out / "house.csv").open() as f:
        return list(csv.DictReader(f))[-1]


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from bench_plots import error_against_time
    fig, ax = plt.subplots(figsize=(6.2, 4.4))
    seconds = [float(r["solve_s"]) for r in rows]
    errors = [float(r["mean_error_pct"]) for r in rows]
    ax.plot(seconds, errors, "o-", color="tab:blue")
    for r, x, y in zip(rows, seconds, errors):
        ax.annotate(f"{r['accuracy']}\n{int(r['elements']):,} el", (x, y), textcoords="offset points", xytext=(8, -14),
                    fontsize=8)
    ax.axhline(3.0, color="tab:red", linestyle="--", linewidth=1, label="3 %: the target at the defaults")
    ax.axhline(1.18, color="grey", linestyle=":", linewidth=1,
               label="Radiance vs Mitsuba 3: 1.18 %")
    error_against_time(ax, [5, 10, 20, 30, 60, 120], "FZK-Haus, 6 lamps, 600 probes traced from the lamps",
                       "mean per-lamp error against Mitsuba 3 (%)")
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", default="preview,draft,default,fine,reference")
    parser.add_argument("--out", default="out/bench")
    parser.add_argument("--mitsuba-python", default="out/mitsuba-venv/bin/python")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    rows = []
    for level in args.levels.split(","):
        rows.append(run_level(level, out, args.mitsuba_python))
        r = rows[-1]
        print(f"{level:10s} {int(r['elements']):8,d} elements  solve {float(r['solve_s']):6.1f} s  "
              f"peak {r['peak_mib']} MiB  error {r['mean_error_pct']} %  lit median {r['lit_median_ratio']}", flush=True)
    keys = ["accuracy", "elements", "element", "lamp_grading", "shadow_grading", "gather_rays", "separation", "solve_s", "peak_mib",
            "mean_error_pct", "lit_median_ratio", "commit"]
    with (out / "accuracy_house.csv").open("w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=keys, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)
    lines = ["| level | elements | element (m) | LampGrading | ShadowGrading | GatherRays | separation | solve (s) "
             "| peak (MiB) | error vs Mitsuba 3 | lit median |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    lines += [f"| {r['accuracy']} | {int(r['elements']):,} | {r['element']} | {r['lamp_grading']} "
              f"| {r['shadow_grading']} | {r['gather_rays']} "
              f"| {r['separation']} | {r['solve_s']} | {r['peak_mib']} | {r['mean_error_pct']} % | {r['lit_median_ratio']} |"
              for r in rows]
    (out / "accuracy_house.md").write_text("\n".join(lines) + "\n")
    plot(rows, out / "accuracy_house.png")
    print("\n".join(lines))
    print(f"wrote {out / 'accuracy_house.csv'}, .md, .png")


if __name__ == "__main__":
    main()

"""Log-log plot of `./relight bench scale`'s CSV: solve time against elements per method,
with linear and quadratic guides through the first hierarchical point."""

import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path, out):
    rows = list(csv.DictReader(open(path)))
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for method, mode, style in (("hierarchical", "tagged", "o-"), ("hierarchical", "combined", "s--"),
                                ("progressive", "tagged", "^-")):
        points = sorted((int(r["elements"]), float(r["seconds"])) for r in rows
                        if r["method"] == method and r["mode"] == mode)
        if points:
            lights = "k=8" if mode == "tagged" else "k=1 combined"
            ax.plot(*zip(*points), style, label=f"{method}, {lights}")
    base = sorted((int(r["elements"]), float(r["seconds"])) for r in rows
                  if r["method"] == "hierarchical" and r["mode"] == "tagged")
    if base:
        n0, t0 = base[0]
        xs = [n0, base[-1][0]]
        ax.plot(xs, [t0 * x / n0 for x in xs], ":", color="grey", label="linear")
        ax.plot(xs, [t0 * (x / n0) ** 2 for x in xs], ":", color="black", label="quadratic")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("elements")
    ax.set_ylabel("solve time (s), 2 cores")
    ax.set_title("Furnished room, 8 lights, converged to 1e-3")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    print(f"wrote {out}")


def table(path, out):
    """The CSV as the README's markdown table."""
    lines = ["| method | elements | k | solve | shots | converged | peak memory | links | mean error vs Mitsuba |",
             "|---|---|---|---|---|---|---|---|---|"]
    for r in csv.DictReader(open(path)):
        k = "8" if r["mode"] == "tagged" else "1 (combined)"
        memory = float(r["peak_mb"])
        memory = f"{memory / 1024:.2f} GB" if memory >= 1024 else f"{memory:.0f} MB"
        links = f"{float(r['links_mb']):.0f} MB" if r["method"] == "hierarchical" else "—"
        error = "—" if r["mean_error"] == "nan" else f"{100 * float(r['mean_error']):.2f} %"
        lines.append(f"| {r['method']} | {int(r['elements']):,} | {k} | {float(r['seconds']):.1f} s | "
                     f"{int(r['shots']):,} | {'yes' if r['converged'] == '1' else 'no'} | {memory} | {links} | {error} |")
    open(out, "w").write("\n".join(lines) + "\n")
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
    table(sys.argv[1], sys.argv[2].replace(".png", ".md"))

"""Two independent renders of the same probes (mitsuba_reference.py with different --seed and
--spp): how far apart they are, what that says of each one's noise, and their sample-weighted
mean as a stronger reference.

    combine_references.py A.csv SPP_A B.csv SPP_B OUT.csv

The measure is the benches' error measure (per light, mean |difference| over the mean); a
render's noise in it falls as 1 / sqrt(spp), so two renders apart by d each hold
d * sqrt(w) of it, w = 1 / (1 + spp_this / spp_other)."""
import math
import sys

import numpy as np


def load(path):
    rows = np.loadtxt(path, delimiter=",", skiprows=1, ndmin=2)
    return rows[np.lexsort((rows[:, 0], rows[:, 1]))]


def combine(a_path, a_spp, b_path, b_spp, out_path):
    """Writes the two renders' sample-weighted mean to out_path; returns how far apart they
    are and the noise that implies in A, in B and in their mean (fractions, the benches'
    measure)."""
    a, b = load(a_path), load(b_path)
    if a.shape != b.shape or not np.array_equal(a[:, :2], b[:, :2]):
        raise SystemExit("the two renders are not of the same probes and lights")
    apart = []
    for light in np.unique(a[:, 1]):
        x, y = a[a[:, 1] == light][:, 2:5].mean(axis=1), b[b[:, 1] == light][:, 2:5].mean(axis=1)
        apart.append(float(np.abs(y - x).mean() / x.mean()))
    d = float(np.mean(apart))
    noise_a, noise_b = d * math.sqrt(1 / (1 + a_spp / b_spp)), d * math.sqrt(1 / (1 + b_spp / a_spp))
    mean = a.copy()
    mean[:, 2:5] = (a[:, 2:5] * a_spp + b[:, 2:5] * b_spp) / (a_spp + b_spp)
    np.savetxt(out_path, mean, delimiter=",", header="probe,light,r,g,b", comments="",
               fmt=["%d", "%d", "%.9g", "%.9g", "%.9g"])
    return dict(apart=d, per_light=apart, noise_a=noise_a, noise_b=noise_b,
                noise_mean=noise_a * math.sqrt(a_spp / (a_spp + b_spp)))


def main(a_path, a_spp, b_path, b_spp, out_path):
    r = combine(a_path, a_spp, b_path, b_spp, out_path)
    print(f"apart: {100 * r['apart']:.3f} % (per light {', '.join(f'{100 * v:.2f}' for v in r['per_light'])})")
    print(f"noise of A ({a_spp} spp): about {100 * r['noise_a']:.3f} %")
    print(f"noise of B ({b_spp} spp): about {100 * r['noise_b']:.3f} %")
    print(f"their mean ({a_spp + b_spp} spp): noise about {100 * r['noise_mean']:.3f} %")
    print(f"wrote {out_path}")


if __name__ == "__main__":
    if len(sys.argv) != 6:
        raise SystemExit(__doc__)
    main(sys.argv[1], int(sys.argv[2]), sys.argv[3], int(sys.argv[4]), sys.argv[5])

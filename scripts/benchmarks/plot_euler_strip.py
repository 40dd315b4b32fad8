#!/usr/bin/python3
"""Plot of doc/tutorials/step-10-large-deformation: the clamped strip with a
first-mode imperfection (prm/euler_strip_2d.prm), total Lagrangian against
small strain: the axial force against the end shortening, and against the
mid-span deflection with the imperfect Euler column N = N_1 (1 - w0 / w);
from the histories scripts/benchmarks/euler_strip.sh writes.
usage: plot_euler_strip.py BENCHMARK.csv OUT.png"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    csv_path, out = sys.argv[1:3]
    stem = csv_path[:-len(".csv")]
    large = table(stem + "_history.csv")
    small = table(stem + "_small_strain.csv")
    N_1, w0 = 44.24, 0.01
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for data, style, name in ((large, "o-", "total Lagrangian"),
                              (small, "s--", "small strain")):
        shortening = [0.07 * t for t in data["time"]]
        force = [-r for r in data["reaction_x+_x"]]
        left.plot(shortening, force, style, ms=3, label=name)
    left.axhline(N_1, color="k", lw=0.8, ls=":")
    left.text(0.002, N_1 + 1.5, "N_1 = 44.24 N/mm (Engesser)")
    left.set_xlabel("end shortening [mm]")
    left.set_ylabel("axial force N [N/mm]")
    left.set_ylim(0, 100)
    left.legend(loc="upper left")
    w = [w0 + u for u in large["p0_uy"]]
    force = [-r for r in large["reaction_x+_x"]]
    right.plot(w, force, "o", ms=3, label="amfrac, total Lagrangian")
    curve = [w0 * 1.01 ** k for k in range(0, 500)]
    curve = [x for x in curve if x <= max(w)]
    right.plot(curve, [N_1 * (1 - w0 / x) for x in curve], "k-", lw=0.8,
               label="N_1 (1 - w0 / w)")
    right.set_xscale("log")
    right.set_xlabel("mid-span deflection w [mm] (w0 = 0.01)")
    right.set_ylabel("axial force N [N/mm]")
    right.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


main()

#!/usr/bin/python3
"""Plot of doc/tutorials/step-10-large-deformation: the clamped [90_4] strip
of prm/plastic_strip_2d.prm with Hoffman plasticity against the same strip
with elastic plies: the axial force against the end shortening, and the
plastic work and the yielding points; from the histories
scripts/benchmarks/plastic_strip.sh writes.
usage: plot_plastic_strip.py BENCHMARK.csv OUT.png"""
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
    plastic = table(stem + "_history.csv")
    elastic = table(stem + "_elastic.csv")
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    for data, style, name in ((elastic, "s--", "elastic plies"),
                              (plastic, "o-", "Hoffman plasticity")):
        shortening = [4 * t * t for t in data["time"]]
        force = [-r for r in data["reaction_x+_x"]]
        left.plot(shortening, force, style, ms=3, label=name)
    first = next(k for k, y in enumerate(plastic["yielding_points"]) if y > 0)
    d_yield = 4 * plastic["time"][first] ** 2
    left.axvline(d_yield, color="k", lw=0.8, ls=":")
    left.text(d_yield + 0.05, 0.5, "first yield")
    left.set_xlabel("end shortening [mm]")
    left.set_ylabel("axial force N [N/mm]")
    left.set_ylim(0, 4)
    left.legend(loc="lower right")
    shortening = [4 * t * t for t in plastic["time"]]
    right.plot(shortening, plastic["plastic_work"], "o-", ms=3,
               label="plastic work [N mm/mm]")
    right.plot(shortening, plastic["external_work"], "k-", lw=0.8,
               label="external work [N mm/mm]")
    right.set_xlabel("end shortening [mm]")
    right.set_ylabel("work [N mm/mm]")
    twin = right.twinx()
    twin.plot(shortening, plastic["yielding_points"], "g:",
              label="yielding points")
    twin.set_ylabel("yielding quadrature points", color="g")
    right.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


main()

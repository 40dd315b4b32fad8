#!/usr/bin/python3
"""Plot of doc/tutorials/step-10-large-deformation: the snap-through of the
clamped shallow arch (prm/shallow_arch_2d.prm) traced by arc-length control,
the load against the mid-span rise with the shallow-arch theory's q(c), and
the load parameter against the step number (it falls past the limit point).
usage: plot_shallow_arch.py HISTORY.csv [HISTORY_PSI1.csv] OUT.png"""
import csv
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

H, E, L, Q11, Q_END = 0.5, 0.75, 100.0, 135906.0, 0.016


def theory(c):
    k = 2 * math.pi / L
    EI, EA = Q11 * H ** 3 / 12, Q11 * H
    return k * k / 2 * (EI * k * k * (E - c) + EA * k * k * c * (E * E - c * c) / 16)


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def main():
    paths, out = sys.argv[1:-1], sys.argv[-1]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
    curve = [E - 1.55 * E * i / 400 * 2 for i in range(0, 401)]
    curve = [c for c in curve if c >= -1.05 * E]
    left.plot(curve, [1e3 * theory(c) for c in curve], "k-", lw=0.8,
              label="shallow-arch theory q(c)")
    for path, style, name in zip(paths, ("o", "x"),
                                 ("arc-length, psi = 0", "arc-length, psi = 1")):
        data = table(path)
        rise = [E + u for u in data["p0_uy"]]
        load = [1e3 * Q_END * t for t in data["time"]]
        left.plot(rise, load, style, ms=4, label=name)
        right.plot(range(1, len(load) + 1), load, style + "-", ms=3, label=name)
    left.invert_xaxis()
    left.set_xlabel("mid-span rise c [mm] (e = 0.75)")
    left.set_ylabel("load amplitude q [kPa]")
    left.legend(loc="lower center")
    right.set_xlabel("arc-length step")
    right.set_ylabel("load amplitude q [kPa]")
    right.legend(loc="upper left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


main()

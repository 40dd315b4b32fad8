#!/usr/bin/python3
"""Plot of doc/tutorials/step-10-large-deformation: the delaminated [0_20]
panel (prm/delaminated_panel.prm), total Lagrangian, displacement control
up to the growth of the delamination and opening control through it: the
axial force against the end shortening, against the mid-length
deflections of the sublaminate's top and the base's bottom, and against
the debonded length, with the local buckling load of the linear analysis
of the pre-buckled state (prm/delaminated_panel_2d.prm).
usage: plot_panel.py HISTORY.csv OUT.png"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

LBF_PER_IN = 0.175127  # N/mm per lbf/in


def main():
    path, out = sys.argv[1:3]
    with open(path) as f:
        rows = list(csv.DictReader(f))
    t = [float(r["time"]) for r in rows]
    force = [-float(r["reaction_x+_x"]) for r in rows]
    sub = [float(r["p0_uy"]) for r in rows]
    base = [float(r["p1_uy"]) for r in rows]
    debonded = [float(r["debonded_i15"]) for r in rows]
    fig, (left, right, growth) = plt.subplots(1, 3, figsize=(15, 4))
    left.plot([0] + [0.01 * x for x in t], [0] + force, "o-", ms=3)
    left.axhline(185.4, color="k", ls=":", lw=0.8)
    left.text(0.005, 195, "local, linear buckling: 185.4 N/mm")
    left.set_xlabel("end shortening [mm]")
    left.set_ylabel("axial force N [N/mm]")
    second = left.secondary_yaxis(
        "right", functions=(lambda n: n / LBF_PER_IN, lambda p: p * LBF_PER_IN))
    second.set_ylabel("[lbf/in]")
    right.plot(sub, force, "o-", ms=3, label="sublaminate top, mid-length")
    right.plot(base, force, "s-", ms=3, label="base bottom, mid-length")
    right.axhline(185.4, color="k", ls=":", lw=0.8)
    right.set_xlabel("out-of-plane deflection [mm]")
    right.set_ylabel("axial force N [N/mm]")
    right.legend(loc="lower right")
    growth.plot(debonded, force, "o-", ms=3)
    growth.set_xlabel("debonded length of the interface [mm]")
    growth.set_ylabel("axial force N [N/mm]")
    growth.set_title("the growth (opening control)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


main()

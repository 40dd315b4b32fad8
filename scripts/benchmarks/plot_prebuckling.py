#!/usr/bin/python3
"""Plot of doc/tutorials/step-10-large-deformation: linear buckling of
pre-buckled total Lagrangian states, from the tables
scripts/benchmarks/prebuckling.sh writes. Left: the shallow arch's path
(load parameter against the mid-span deflection, arc-length) and the limit
point predicted from states along it. Right: the delaminated panel's
local buckling load predicted from states at growing loads.
usage: plot_prebuckling.py OUT OUT.png (OUT as given to prebuckling.sh)"""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def table(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def first_maximum(values):
    for k in range(1, len(values) - 1):
        if values[k] >= values[k - 1] and values[k] > values[k + 1]:
            return k
    return len(values) - 1


def arch_panel(axes, stem):
    path = table(stem + "_arch_path.csv")
    states = table(stem + "_arch.csv")
    k = first_maximum(path["time"])
    limit = path["time"][k]
    deflection = [-w for w in path["p0_uy"]]
    axes.plot(deflection, path["time"], "-", color="0.5",
              label="path (arc-length)")
    axes.axhline(limit, color="0.5", ls=":",
                 label=f"limit point t_l = {limit:.4f}")
    # The states on the path: their deflection from the path by t.
    state_w = [min((abs(t - s), w) for t, w in
                   zip(path["time"][:k + 1], deflection[:k + 1]))[1]
               for s in states["t"]]
    axes.plot(state_w, states["t"], "ko", ms=4, label="analysed state")
    axes.plot(state_w, states["t_c"], "rs", ms=4,
              label="predicted t_c (pre-buckled state)")
    for w, t, tc in zip(state_w, states["t"], states["t_c"]):
        axes.plot([w, w], [t, tc], "r-", lw=0.5)
    axes.set_xlabel("mid-span deflection [mm]")
    axes.set_ylabel("load parameter t")
    axes.set_title("shallow arch: limit point")
    axes.set_xlim(0, 1.6)
    axes.set_ylim(0, 0.9)
    axes.legend(fontsize=8, loc="lower right")


def delaminated_panel(axes, stem):
    states = table(stem + "_panel.csv")
    axes.plot(states["N"], states["N_c"], "rs-", ms=4,
              label="predicted local buckling load")
    axes.axhline(184.1, color="0.5", ls=":",
                 label="small-strain analysis (perfect), 184.1")
    axes.axhspan(158, 180, color="0.9",
                 label="deflection passes 10 w0 (path)")
    top = max(states["N_c"]) * 1.05
    axes.plot([0, top], [0, top], "k--", lw=0.5, label="N_c = N")
    axes.set_xlabel("axial force of the analysed state N [N/mm]")
    axes.set_ylabel("critical force N_c [N/mm]")
    axes.set_title("delaminated panel (imperfect): local buckling")
    axes.set_xlim(0, top)
    axes.set_ylim(0, top)
    axes.legend(fontsize=8, loc="lower right")


def main():
    stem, out = sys.argv[1:3]
    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4.2))
    arch_panel(left, stem)
    delaminated_panel(right, stem)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


main()

#!/usr/bin/python3
"""Draws the histories of impact_prism.py (OUT-histories.csv): the energy
dissipated by both interfaces and the centre deflection against time,
wedges against hexahedra and the 0.25 mm hexahedral reference.

usage: plot_impact_prism.py HISTORIES.csv FIGURE.png
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

histories_csv, figure = sys.argv[1:3]
curves = {}
with open(histories_csv) as f:
    for r in csv.DictReader(f):
        curve = curves.setdefault(r["mesh"], ([], [], []))
        curve[0].append(float(r["time"]) * 1e6)
        curve[1].append(float(r["dissipated"]))
        curve[2].append(-float(r["p0_uz"]))

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
for mesh, (t, dissipated, deflection) in curves.items():
    style = "k--" if "reference" in mesh else "-"
    left.plot(t, dissipated, style, label=mesh)
    right.plot(t, deflection, style, label=mesh)
left.set_xlabel("time [us]")
left.set_ylabel("dissipated, both interfaces [N mm]")
right.set_xlabel("time [us]")
right.set_ylabel("centre deflection (bottom face) [mm]")
left.legend(fontsize=8)
left.set_title("quarter plate, 5 kN pulse")
right.set_title("wedges from Gmsh against hexahedra")
fig.tight_layout()
fig.savefig(figure, dpi=110)

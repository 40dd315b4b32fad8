#!/usr/bin/env python3
"""Plot linear buckling on wedges against hexahedra (the CSV of
scripts/benchmarks/buckling_prism.sh): the first load factor of the
[0/90]s plate against the unknowns and against the run time, with
CalculiX's finest C3D20 value (benchmark section 8) as the reference line.

usage: plot_buckling_prism.py BUCKLING_PRISM.csv FIGURE.png
(run with /usr/bin/python3: it needs Debian's matplotlib)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

CALCULIX_FINEST = 55.6735  # C3D20, 196,647 DoF

table, figure = sys.argv[1:3]
rows = list(csv.DictReader(open(table)))
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for shape, label, marker in (("hexahedron", "Q2 hexahedra", "s"),
                             ("prism", "P2 wedges", "^")):
    picked = [r for r in rows if r["shape"] == shape]
    dofs = [int(r["dofs"]) for r in picked]
    wall = [float(r["wall_s"]) for r in picked]
    factor = [float(r["lambda_1"]) for r in picked]
    axes[0].semilogx(dofs, factor, marker=marker, label=label)
    axes[1].semilogx(wall, factor, marker=marker, label=label)
for axis, name in zip(axes, ("unknowns", "wall time [s], one rank")):
    axis.axhline(CALCULIX_FINEST, color="gray", linestyle="--",
                 label="CalculiX C3D20, 196,647 DoF")
    axis.set_xlabel(name)
    axis.set_ylabel("first load factor")
    axis.grid(True, which="both", alpha=0.3)
    axis.legend()
fig.suptitle("[0/90]s plate, linear buckling: wedges and hexahedra")
fig.tight_layout()
fig.savefig(figure, dpi=110)

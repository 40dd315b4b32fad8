"""Load-work error against run time and unknowns of the open-hole plate on
Gmsh prisms and on deal.II's hexahedral plate with a hole
(doc/benchmarks/open_hole_prism.csv, from open_hole_prism.sh).
usage: /usr/bin/python3 plot_open_hole_prism.py CSV PNG"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
families = (("prism", "1", "o", "-", "P1 prisms"),
            ("prism", "2", "s", "-", "P2 prisms (curved hole)"),
            ("hexahedron", "1", "^", "--", "Q1 hexahedra"),
            ("hexahedron", "2", "D", "--", "Q2 hexahedra"))
for shape, degree, marker, line, label in families:
    runs = sorted((r for r in rows if r["shape"] == shape and r["degree"] == degree),
                  key=lambda r: int(r["dofs"]))
    if not runs:
        continue
    for ax, x in zip(axes, ("dofs", "wall_s")):
        ax.loglog([float(r[x]) for r in runs], [float(r["work_error"]) for r in runs],
                  marker=marker, linestyle=line, label=label)
axes[0].set_xlabel("unknowns")
axes[1].set_xlabel("wall time [s] (one rank, meshing included)")
for ax in axes:
    ax.set_ylabel("relative error of the load work")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
fig.suptitle("Open-hole plate: Gmsh prisms and hexahedra against the plane-stress reference")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)

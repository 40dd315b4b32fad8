"""True energy error against unknowns and run time of the open-hole plate
on P1 prisms, uniform refinement against global remeshing
(doc/benchmarks/remesh_open_hole.csv, from remesh_open_hole.sh).
usage: /usr/bin/python3 plot_remesh_open_hole.py CSV PNG"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
fig, axes = plt.subplots(1, 2, figsize=(10, 4))
for kind, marker in (("uniform", "o"), ("remeshed", "s")):
    runs = sorted((r for r in rows if r["kind"] == kind), key=lambda r: int(r["unknowns"]))
    label = "uniform refinement" if kind == "uniform" else "ZZ remeshing (Gmsh)"
    for ax, x in zip(axes, ("unknowns", "wall_s")):
        ax.loglog([float(r[x]) for r in runs], [float(r["energy_error"]) for r in runs],
                  marker=marker, label=label)
axes[0].set_xlabel("unknowns (last mesh)")
axes[1].set_xlabel("wall time [s] (one rank, all cycles, Gmsh included)")
for ax in axes:
    ax.set_ylabel("relative energy error")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
fig.suptitle("Open-hole plate, P1 prisms: global remeshing against uniform refinement")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)

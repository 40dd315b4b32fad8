#!/usr/bin/env python3
"""Plot the prism (wedge) elements of issue 8 against the hexahedra: the
convergence on the manufactured solution (the tables of
tests/app/manufactured_solution.output: L2 and H1 errors against the
number of unknowns for Q1, Q2 and the P1, P2 wedges on the same vertices)
and, given the CSV of scripts/benchmarks/prism_time_error.sh, the run time
against the error of Pagano's centre deflection.

usage: plot_prisms.py FIGURE.png MANUFACTURED.output [TIME_ERROR.csv]
(run with /usr/bin/python3: it needs Debian's matplotlib)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_tables(path):
    """{name: [(dofs, L2, H1)]} from the ConvergenceTable text."""
    tables, name = {}, None
    for line in open(path):
        words = line.split()
        if not words or words[0] == "cells":
            continue
        if not words[0].isdigit():
            name = " ".join(words)
            tables[name] = []
            continue
        numbers = [w for w in words if w != "-"]
        dofs, l2 = int(numbers[1]), float(numbers[2])
        h1 = float(numbers[3] if len(numbers) == 4 else numbers[4])
        tables[name].append((dofs, l2, h1))
    return tables


figure, manufactured = sys.argv[1:3]
timing = sys.argv[3] if len(sys.argv) > 3 else None
tables = read_tables(manufactured)
panels = 2 if timing else 1
fig, axes = plt.subplots(1, panels, figsize=(6.5 * panels, 4.8))
axes = axes if panels > 1 else [axes]
styles = {"Q1": "C0o-", "Q2": "C1o-", "prism P1": "C0s--", "prism P2": "C1s--"}
for name, rows in tables.items():
    dofs = [r[0] for r in rows]
    axes[0].loglog(dofs, [r[1] for r in rows], styles[name], label=name + " L2")
    axes[0].loglog(dofs, [r[2] for r in rows], styles[name], alpha=0.45,
                   label=name + " H1")
axes[0].set_xlabel("unknowns")
axes[0].set_ylabel("error (manufactured solution)")
axes[0].set_title("hexahedra (solid) and prisms (dashed): optimal rates")
axes[0].legend(fontsize=7, ncol=2)
axes[0].grid(True, which="both", alpha=0.3)

if timing:
    rows = list(csv.DictReader(open(timing)))
    for shape, marker in (("hexahedron", "o-"), ("prism", "s--")):
        for degree, colour in (("1", "C0"), ("2", "C1")):
            chosen = [r for r in rows if r["shape"] == shape
                      and r["degree"] == degree and r["solver"] == "direct"]
            axes[1].loglog([float(r["wall_s"]) for r in chosen],
                           [float(r["w_error"]) for r in chosen],
                           colour + marker,
                           label="%s, degree %s" % (shape, degree))
    axes[1].set_xlabel("wall time [s] (one rank, direct solver)")
    axes[1].set_ylabel("relative error of w_bar (Pagano, S = 10)")
    axes[1].set_title("run time against error")
    axes[1].legend(fontsize=8)
    axes[1].grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(figure, dpi=110)

#!/usr/bin/python3
"""Cost of one global remeshing against mesh size (issue 8): the open-hole
plate of prm/open_hole_prism.prm (P1 wedges, the isotropic material of
tests/app/open_hole_isotropic.prm) from starts of 12 x 3, 24 x 6, 48 x 12,
96 x 24 and 192 x 48 elements (around the hole x along the width),
remeshed once with every size halved (Adaptivity/Strategy = uniform, one
cycle). One rank, Release, CG with AMG (the solves are not measured).

Per start, the median over REPEAT runs of the remeshing's two parts as
adaptivity.csv reports them: "remesh" (the size field, Gmsh's in-plane
mesh, the extrusion, the DoF layer and the set-up of the new mesh) and
"transfer" (locating every new node in an old cell, inverting the old
map, interpolating; the setup of the search tree included), and their sum
against N, the new mesh's cells. The exponent a of cost = C N^a log N is
the least-squares slope of log(cost / log N) against log N: 1 for N log N.

Fails if that exponent is 1.3 or more, or if a run did not remesh.

usage: remesh_cost.py AMFRAC OUT.csv [REPEAT]
"""
import csv
import math
import os
import statistics
import subprocess
import sys
import tempfile

amfrac, out_csv = sys.argv[1:3]
repeat = int(sys.argv[3]) if len(sys.argv) > 3 else 3
here = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../..")
work = tempfile.mkdtemp()
with open(os.path.join(here, "prm/open_hole_prism.prm")) as f:
    scene = f.read()
with open(os.path.join(here, "tests/app/open_hole_isotropic.prm")) as f:
    scene += "\n" + f.read()


def remesh_once(around, width):
    prm, out = os.path.join(work, "run.prm"), os.path.join(work, "out")
    with open(prm, "w") as g:
        g.write(scene + f"""
subsection Geometry
  set Elements around hole = {around}
  set Elements along width = {width}
end
subsection Adaptivity
  set Refinement cycles = 1
  set Strategy = uniform
end
subsection Linear solver
  set Solver = cg-amg
end
subsection Output
  set Directory = {out}
  set Field format = none
end
""")
    subprocess.run([amfrac, prm], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "adaptivity.csv")) as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 2, "the run did not remesh once"
    return (int(rows[0]["cells"]), int(rows[1]["cells"]),
            float(rows[1]["remesh_seconds"]),
            float(rows[1]["transfer_seconds"]))


table = []
for around, width in ((12, 3), (24, 6), (48, 12), (96, 24), (192, 48)):
    runs = [remesh_once(around, width) for _ in range(repeat)]
    remesh = statistics.median(r[2] for r in runs)
    transfer = statistics.median(r[3] for r in runs)
    row = {"start": f"{around} x {width}", "old_cells": runs[0][0],
           "new_cells": runs[0][1], "remesh_s": remesh,
           "transfer_s": transfer, "total_s": remesh + transfer}
    row["us_per_cell"] = 1e6 * row["total_s"] / row["new_cells"]
    table.append(row)
    print(row, flush=True)


def slope(xs, ys):
    mx, my = statistics.mean(xs), statistics.mean(ys)
    return (sum((x - mx) * (y - my) for x, y in zip(xs, ys))
            / sum((x - mx) ** 2 for x in xs))


logs_n = [math.log(r["new_cells"]) for r in table]
exponents = {}
for part in ("remesh_s", "transfer_s", "total_s"):
    # cost = C N^a log N: a from the slope of log(cost / log N).
    ys = [math.log(r[part] / math.log(r["new_cells"])) for r in table]
    exponents[part] = slope(logs_n, ys)
with open(out_csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(table[0]))
    writer.writeheader()
    writer.writerows(table)
    f.write("# exponent a in cost = C N^a log N: " + ", ".join(
        f"{k} {v:.2f}" for k, v in exponents.items()) + "\n")
print("exponent a in cost = C N^a log N:", exponents)
if exponents["total_s"] >= 1.3:
    print("FAIL: one remeshing grows faster than N^1.3 log N")
    sys.exit(1)

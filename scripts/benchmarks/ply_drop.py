#!/usr/bin/python3
"""Run time against error of a 3D Geometry/Mesh file: the symmetric
external ply drop of prm/ply_drop.prm (its mesh prm/ply_drop.geo) on four
meshes, the element size along x at the delamination h = 0.4, 0.2 (the
scene), 0.1 and 0.05 mm, with 1, 2, 4 and 8 element layers per ply.

The exact plateau of the delamination's growth is the steady-state energy
balance P = b sqrt(2 E1 G_c / (1/t_s - 1/t)) = 275.26 N (the scene's
header). Per mesh: cells, steps, wall time (median of REPEAT runs, the
whole process), the mean load over the crack areas 0.5 .. 3.5 mm^2 and its
error, the largest deviation from the exact plateau there (the sawtooth of
points debonding one at a time), and the dissipated energy per crack area
(least-squares slope) against G_c. Writes OUT.csv and a figure: the load
against the end displacement of every mesh, and the plateau error
against the wall time.

Fails if the finest mesh's plateau is more than 0.5 % off, or if the
largest deviation does not fall from the coarsest to the finest mesh.

usage: ply_drop.py AMFRAC OUT.csv FIGURE.png [REPEAT]
"""
import csv
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

amfrac, out_csv, figure = sys.argv[1:4]
repeat = int(sys.argv[4]) if len(sys.argv) > 4 else 3
here = os.path.dirname(os.path.abspath(__file__))
prm_dir = os.path.join(here, "../../prm")
work = tempfile.mkdtemp()
E1, G_c, b, t_s, t = 135300, 0.28, 1, 0.5, 1
exact = b * math.sqrt(2 * E1 * G_c / (1 / t_s - 1 / t))
# (h along x under the dropped ply, elements beyond the drop, layers/ply)
MESHES = [(0.4, 6, 1), (0.2, 12, 2), (0.1, 24, 4), (0.05, 48, 8)]


def read(name):
    with open(os.path.join(prm_dir, name)) as f:
        return f.read()


def mesh_text(h, beyond, layers):
    geo = read("ply_drop.geo")
    for old, new in [("Transfinite Curve{1, 3} = 51;",
                      f"Transfinite Curve{{1, 3}} = {round(10 / h) + 1};"),
                     ("Transfinite Curve{5, 7} = 13;",
                      f"Transfinite Curve{{5, 7}} = {beyond + 1};"),
                     ("Layers{2}", f"Layers{{{layers}}}")]:
        assert old in geo, old
        geo = geo.replace(old, new)
    return geo


def slope(xs, ys):
    n, sx, sy = len(xs), sum(xs), sum(ys)
    sxx = sum(x * x for x in xs)
    sxy = sum(x * y for x, y in zip(xs, ys))
    return (n * sxy - sx * sy) / (n * sxx - sx * sx)


def run(h, beyond, layers):
    name = f"h{h}"
    geo = os.path.join(work, name + ".geo")
    with open(geo, "w") as g:
        g.write(mesh_text(h, beyond, layers))
    prm = os.path.join(work, name + ".prm")
    out = os.path.join(work, name)
    with open(prm, "w") as g:
        g.write(read("ply_drop.prm"))
        g.write(f"\nsubsection Geometry\n  set Mesh file = {geo}\nend\n"
                f"subsection Output\n  set Field format = none\n"
                f"  set Directory = {out}\nend\n")
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        log = subprocess.run([amfrac, prm], check=True, capture_output=True,
                             text=True).stdout
        times.append(time.perf_counter() - start)
    with open(os.path.join(out, "history.csv")) as f:
        rows = list(csv.DictReader(f))
    area = [float(r["debonded_i0"]) for r in rows]
    load = [float(r["force_x+"]) for r in rows]
    window = [i for i, a in enumerate(area) if 0.5 <= a <= 3.5]
    mean = statistics.fmean(load[i] for i in window)
    cells = int(re.search(r"(\d+) cells", log).group(1))
    return {
        "h [mm]": h, "layers per ply": layers, "cells": cells,
        "steps": len(rows), "wall [s]": round(statistics.median(times), 2),
        "plateau [N]": round(mean, 2),
        "plateau error": round(mean / exact - 1, 5),
        "largest deviation": round(max(abs(load[i] / exact - 1)
                                       for i in window), 5),
        "dissipated per area / G_c": round(
            slope([area[i] for i in window],
                  [float(rows[i]["dissipated_i0"]) for i in window]) / G_c,
            4),
    }, [float(r["time"]) for r in rows], load


results, curves = [], []
for h, beyond, layers in MESHES:
    row, u, p = run(h, beyond, layers)
    print(row, flush=True)
    results.append(row)
    curves.append((h, u, p))
with open(out_csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(results[0]))
    writer.writeheader()
    writer.writerows(results)

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for h, u, p in curves:
        left.plot(u, p, label=f"h = {h} mm")
    left.axhline(exact, color="k", ls="--", lw=0.8,
                 label=f"steady state {exact:.1f} N")
    left.set_xlabel("end displacement t [mm]")
    left.set_ylabel("load P [N]")
    left.set_title("ply drop: load against end displacement")
    left.legend(fontsize=8)
    right.loglog([r["wall [s]"] for r in results],
                 [abs(r["plateau error"]) for r in results], "o-",
                 label="|mean plateau error|")
    right.loglog([r["wall [s]"] for r in results],
                 [r["largest deviation"] for r in results], "s--",
                 label="largest deviation over the plateau")
    for r in results:
        right.annotate(f"{r['h [mm]']} mm", (r["wall [s]"],
                                             r["largest deviation"]),
                       fontsize=8)
    right.set_xlabel("wall time [s]")
    right.set_ylabel("relative to the steady-state load")
    right.set_title("run time against error")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figure, dpi=110)
except ImportError:
    print("matplotlib not found: no figure")

finest, coarsest = results[-1], results[0]
ok = (abs(finest["plateau error"]) < 0.005
      and finest["largest deviation"] < coarsest["largest deviation"])
print("ok" if ok else "FAILED")
sys.exit(0 if ok else 1)

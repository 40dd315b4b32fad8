#!/usr/bin/python3
"""Global remeshing during a load history: the DCB strip of
prm/dcb_remeshed_prism.prm (wedges remeshed by Gmsh when the relative ZZ
error exceeds 0.05) against the same strip on uniform 0.25 mm wedges
without remeshing (the reference), the same scene remeshed every 5 steps
instead (28 remeshings), the hexahedral strip whose mesh follows the
front by refinement (prm/dcb_adaptive_3d.prm), and the wedges remeshed by
the process-zone rule (prm/dcb_process_zone_prism.prm), all to an opening
of 3 mm without field output.

Per run: wall time (median of REPEAT runs, from the process start), steps,
the largest number of cells and unknowns, the number of mesh changes, the
peak load and its difference to the reference's, the largest difference of
the load-opening curve to the reference's (in units of the reference
peak), the remeshing term of the energy balance over the external work,
and the time in the ZZ estimate (TimerOutput). Writes OUT.csv and a figure
with the load-opening curves and the cells of the remeshed run over the
opening.

Fails if the remeshed scene is not faster than the uniform wedges or its
peak is more than 3 % off theirs.

usage: dcb_remeshed_prism.py AMFRAC OUT.csv FIGURE.png [REPEAT]
"""
import csv
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
work = tempfile.mkdtemp()


def scene_text(name):
    with open(os.path.join(here, "../../prm", name + ".prm")) as f:
        return f.read()


UNIFORM = """
subsection Geometry
  set Elements along length = 400
  set Elements along width  = 8
end
subsection Adaptivity
  set Error threshold = 0
end
"""
EVERY_5 = """
subsection Adaptivity
  set Error threshold = 0
  set Refine every    = 5
end
"""
RUNS = [("uniform 0.25 mm wedges", "dcb_remeshed_prism", UNIFORM),
        ("remeshed (threshold 0.05)", "dcb_remeshed_prism", ""),
        ("remeshed every 5 steps", "dcb_remeshed_prism", EVERY_5),
        ("hexahedra, refined at the front", "dcb_adaptive_3d", ""),
        ("remeshed by the process-zone rule", "dcb_process_zone_prism", "")]


def run(index, label, scene, extra):
    prm = os.path.join(work, f"run{index}.prm")
    out = os.path.join(work, f"run{index}")
    with open(prm, "w") as g:
        g.write(scene_text(scene) + extra)
        g.write(f"\nsubsection Time\n  set End time = 3\nend\n"
                f"subsection Output\n  set Field format = none\n"
                f"  set Directory = {out}\nend\n")
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        log = subprocess.run([amfrac, prm], check=True, capture_output=True,
                             text=True).stdout
        times.append(time.perf_counter() - start)
    steps = int(re.search(r"(\d+) steps, \d+ Newton iterations", log)
                .group(1))
    first = re.search(r"(\d+) cells, (\d+) unknowns", log)
    cells, unknowns = int(first.group(1)), int(first.group(2))
    estimate = re.search(r"\| estimate error\s+\|\s+\d+\s+\|\s+([0-9.]+)s",
                         log)
    rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    changes = os.path.join(out, "adaptivity.csv")
    mesh = []
    if os.path.exists(changes):
        mesh = [(float(r["t"]), int(float(r["cells"])),
                 int(float(r["unknowns"])))
                for r in csv.DictReader(open(changes))]
        cells = max([cells] + [c for _, c, _ in mesh])
        unknowns = max([unknowns] + [u for _, _, u in mesh])
    curve = [(float(r["time"]), float(r["force_x-"])) for r in rows]
    last = rows[-1]
    return {
        "run": label,
        "seconds": statistics.median(times),
        "steps": steps,
        "largest_cells": cells,
        "largest_unknowns": unknowns,
        "mesh_changes": len(mesh),
        "peak_N": max(p for _, p in curve),
        "remeshing_energy_over_work": float(last.get("remeshing_energy", 0))
        / float(last["external_work"]),
        "estimate_seconds": float(estimate.group(1)) if estimate else 0.0,
    }, curve, mesh


def interpolate(curve, t):
    for (t0, p0), (t1, p1) in zip(curve, curve[1:]):
        if t0 <= t <= t1:
            return p0 + (p1 - p0) * (t - t0) / (t1 - t0) if t1 > t0 else p1
    return curve[-1][1]


results = [run(i, *r) for i, r in enumerate(RUNS)]
reference, reference_curve = results[0][0], results[0][1]
end = min(c[-1][0] for _, c, _ in results)
grid = [0.05 + k * (end - 0.05) / 300 for k in range(301)]
for row, curve, _ in results:
    row["peak_difference"] = row["peak_N"] / reference["peak_N"] - 1
    row["largest_curve_difference"] = max(
        abs(interpolate(curve, t) - interpolate(reference_curve, t))
        for t in grid) / reference["peak_N"]
    row["time_ratio"] = row["seconds"] / reference["seconds"]
with open(out_csv, "w") as f:
    writer = csv.DictWriter(f, fieldnames=list(results[0][0].keys()))
    writer.writeheader()
    for row, _, _ in results:
        writer.writerow(row)

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
styles = ["k-", "C0-", "C1--", "C2:", "C3-."]
for (row, curve, _), style in zip(results, styles):
    left.plot([t for t, _ in curve], [p for _, p in curve], style,
              label=f"{row['run']} ({row['seconds']:.0f} s)")
left.set_xlabel("opening [mm]")
left.set_ylabel("load on the 2 mm strip [N]")
left.legend(fontsize=8)
left.grid(alpha=0.3)
for (row, _, mesh), style in zip(results, styles):
    if mesh and row["run"].startswith("remeshed"):
        right.step([t for t, _, _ in mesh], [c for _, c, _ in mesh], style,
                   where="post", marker="o", label=row["run"])
right.axhline(reference["largest_cells"], color="k", lw=1,
              label="uniform 0.25 mm wedges")
right.set_xlabel("opening at the remeshing [mm]")
right.set_ylabel("wedges")
right.set_yscale("log")
right.legend(fontsize=8)
right.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(figure, dpi=110)
print(open(out_csv).read())

# The remeshed scenes must beat the uniform mesh's time and stay within
# 3 % of its peak (measured: 0.50 and 0.63 of the time, -2.0 %), and the
# process-zone rule must beat the ZZ threshold's time.
for remeshed in (results[1][0], results[4][0]):
    if remeshed["time_ratio"] >= 1 or abs(remeshed["peak_difference"]) > 0.03:
        sys.exit(f"{remeshed['run']}: not faster than the uniform wedges or "
                 "its peak is more than 3 % off")
if results[4][0]["seconds"] >= results[1][0]["seconds"]:
    sys.exit("the process-zone rule is not faster than the ZZ threshold")

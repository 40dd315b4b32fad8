#!/usr/bin/python3
"""The DCB with the mesh following the crack front (prm/dcb_adaptive_2d.prm)
against the uniformly fine mesh (prm/dcb_2d.prm), both to the scene's end
(delta = 10 mm, about 41 mm of crack growth), without field output.

Per scene: wall time (median of REPEAT runs, `/usr/bin/time`-like, from
the process start), steps, Newton iterations and factorizations (from the
log), unknowns (largest during the run), the peak load and the load at
delta = 3.88 and 5.82 mm (the beam-theory check points of
../shared/reference/README.md section 1). Writes OUT.csv and a figure with
the two load-opening curves and the unknowns of the adaptive mesh over the
opening.

usage: dcb_adaptive.py AMFRAC OUT.csv FIGURE.png [REPEAT]
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
width = 20.0


def run(name):
    prm = os.path.join(work, name + ".prm")
    out = os.path.join(work, name)
    with open(os.path.join(here, "../../prm", name + ".prm")) as f, \
            open(prm, "w") as g:
        g.write(f.read())
        g.write(f"\nsubsection Output\n  set Field format = none\n"
                f"  set Directory = {out}\nend\n")
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        log = subprocess.run([amfrac, prm], check=True, capture_output=True,
                             text=True).stdout
        times.append(time.perf_counter() - start)
    summary = re.search(r"(\d+) steps, (\d+) Newton iterations, (\d+) "
                        r"factorizations", log)
    rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    unknowns = int(re.search(r"cells, (\d+) unknowns", log).group(1))
    changes = os.path.join(out, "adaptivity.csv")
    mesh = []
    if os.path.exists(changes):
        mesh = [(float(r["t"]), int(float(r["unknowns"])))
                for r in csv.DictReader(open(changes))]
        unknowns = max(u for _, u in mesh)
    curve = [(float(r["time"]), width * float(r["force_x-"])) for r in rows]

    def load_at(delta):
        return [p for t, p in curve if t <= delta][-1]

    return {
        "scene": name,
        "seconds": statistics.median(times),
        "steps": int(summary.group(1)),
        "newton_iterations": int(summary.group(2)),
        "factorizations": int(summary.group(3)),
        "largest_unknowns": unknowns,
        "mesh_changes": len(mesh),
        "peak_N": max(p for _, p in curve),
        "P_3.88_N": load_at(3.88),
        "P_5.82_N": load_at(5.82),
    }, curve, mesh


results = [run("dcb_2d"), run("dcb_adaptive_2d")]
with open(out_csv, "w") as f:
    writer = csv.DictWriter(f, fieldnames=list(results[0][0].keys()))
    writer.writeheader()
    for row, _, _ in results:
        writer.writerow(row)
        print(row)

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
for (row, curve, _), style in zip(results, ["-", "--"]):
    left.plot([t for t, _ in curve], [p for _, p in curve], style,
              label=f"{row['scene']} ({row['largest_unknowns']} unknowns "
                    f"at most, {row['seconds']:.1f} s)")
left.set_xlabel("opening delta [mm]")
left.set_ylabel("load P [N]")
left.legend(fontsize=8)
mesh = results[1][2]
right.step([t for t, _ in mesh], [u for _, u in mesh], where="post",
           label="adaptive")
right.axhline(results[0][0]["largest_unknowns"], color="k", ls=":",
              label="uniform 0.25 mm")
right.set_xlabel("opening delta [mm] at the mesh change")
right.set_ylabel("unknowns")
right.legend(fontsize=8)
fig.tight_layout()
fig.savefig(figure, dpi=120)

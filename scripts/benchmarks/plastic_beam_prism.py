#!/usr/bin/python3
"""Plastic plies on wedges remeshed during the load history
(prm/plastic_beam_prism.prm) against the same beam on uniform wedge
meshes of 11, 22, 44 and 88 squares along the half-span, never remeshed.

Per run: wedges at the end, wall time (median of REPEAT runs for the
remeshed scene, one run for the uniform meshes), the end force
(-reaction_x+_z, per mm of width) and the plastic work, and for the
remeshed run the plastic work of the steps right after a remeshing
against the same steps of the finest uniform mesh: the transfer's
smoothing of the plastic strain shows there as extra plastic flow.

usage: plastic_beam_prism.py AMFRAC OUT.csv [REPEAT]
"""
import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

amfrac, out_csv = os.path.abspath(sys.argv[1]), sys.argv[2]
repeat = int(sys.argv[3]) if len(sys.argv) > 3 else 3
here = os.path.dirname(os.path.abspath(__file__))
scene = open(os.path.join(here, "../../prm/plastic_beam_prism.prm")).read()
work = tempfile.mkdtemp()


def run(text, name, times):
    """Run the scene text; (wall times, history rows, log)."""
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write(text + "\nsubsection Output\n set Directory = " + name +
                "\n set Field format = none\nend\n")
    walls = []
    for _ in range(times):
        start = time.time()
        log = subprocess.run([amfrac, prm], cwd=work, check=True,
                             capture_output=True, text=True).stdout
        walls.append(time.time() - start)
    rows = list(csv.DictReader(open(os.path.join(work, name,
                                                 "history.csv"))))
    return walls, rows, log


def uniform(n):
    text = re.sub(r"set Elements along length = \d+",
                  "set Elements along length = %d" % n, scene)
    return re.sub(r"subsection Adaptivity.*?\nend\n", "", text,
                  flags=re.S)


def summary(label, walls, rows, log):
    cells = re.findall(r"(\d+) cells", log)
    last = rows[-1]
    return {"run": label, "wedges": cells[-1],
            "wall_s": "%.2f" % statistics.median(walls),
            "force": float(last["reaction_x+_z"]) * -1,
            "plastic_work": float(last["plastic_work"])}


results, finest = [], None
for n in (11, 22, 44, 88):
    walls, rows, log = run(uniform(n), "uniform%d" % n, 1)
    results.append(summary("uniform %d" % n, walls, rows, log))
    finest = rows
walls, remeshed, log = run(scene, "remeshed", repeat)
results.append(summary("remeshed", walls, remeshed, log))
with open(out_csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(results[0]))
    writer.writeheader()
    writer.writerows(results)
for r in results:
    print(r)


def increments(rows):
    work_done = [float(r["plastic_work"]) for r in rows]
    return [b - a for a, b in zip([0] + work_done[:-1], work_done)]


# The steps right after a remeshing ("adapted after step k": step k + 1).
after = [int(k) + 1 for k in re.findall(r"adapted after step (\d+)", log)]
mine, reference = increments(remeshed), increments(finest)
for step in after:
    if step <= len(mine):
        print("step %d: plastic work %.5f, uniform 88: %.5f" %
              (step, mine[step - 1], reference[step - 1]))

#!/usr/bin/python3
"""Plastic plies on wedges remeshed during the load history
(prm/plastic_beam_prism.prm) against the same beam on uniform wedge
meshes of 11, 22, 44 and 88 squares along the half-span, never remeshed.

The remeshed scene runs with both ways of carrying the plastic strain
(Adaptivity/Plastic history transfer = nearest point, the default, and
projection, the seed's tau_1) and with a remeshing every 2, 4 (the
scene) and 8 steps; then the whole comparison again with Kinematics =
total Lagrangian (uniform meshes and the scene's remeshing).

Per run: wedges at the end, remeshings, wall time (median of REPEAT runs
for the scene itself, one run otherwise), the end force (-reaction_x+_z,
per mm of width), the plastic work and the largest equivalent plastic
strain.

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


def uniform(n, kinematics):
    text = re.sub(r"set Elements along length = \d+",
                  "set Elements along length = %d" % n, scene)
    text = re.sub(r"subsection Adaptivity.*?\nend\n", "", text, flags=re.S)
    return text + "\nset Kinematics = %s\n" % kinematics


def remeshed(every, transfer, kinematics):
    text = re.sub(r"set Refine every = \d+", "set Refine every = %d" % every,
                  scene)
    return text + ("\nset Kinematics = %s\nsubsection Adaptivity\n"
                   " set Plastic history transfer = %s\nend\n" %
                   (kinematics, transfer))


def summary(label, kinematics, walls, rows, log):
    cells = re.findall(r"(\d+) cells", log)
    last = rows[-1]
    return {"kinematics": kinematics, "run": label, "wedges": cells[-1],
            "remeshings": len(re.findall(r"adapted after step", log)),
            "wall_s": "%.2f" % statistics.median(walls),
            "force": float(last["reaction_x+_z"]) * -1,
            "plastic_work": float(last["plastic_work"]),
            "max_kappa": float(last["max_equivalent_plastic_strain"])}


results = []
for kinematics in ("small strain", "total Lagrangian"):
    for n in (11, 22, 44, 88):
        walls, rows, log = run(uniform(n, kinematics), "uniform%d" % n, 1)
        results.append(summary("uniform %d" % n, kinematics, walls, rows,
                               log))
        print(results[-1], flush=True)
    cases = [(4, "nearest point"), (4, "projection")]
    if kinematics == "small strain":
        cases += [(2, "nearest point"), (2, "projection"),
                  (8, "nearest point"), (8, "projection")]
    for every, transfer in cases:
        times = repeat if (every, transfer) == (4, "nearest point") else 1
        walls, rows, log = run(remeshed(every, transfer, kinematics),
                               "remeshed", times)
        results.append(summary("remeshed every %d, %s" % (every, transfer),
                               kinematics, walls, rows, log))
        print(results[-1], flush=True)
with open(out_csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(results[0]))
    writer.writeheader()
    writer.writerows(results)

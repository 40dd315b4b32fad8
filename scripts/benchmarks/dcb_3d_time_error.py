#!/usr/bin/python3
"""Run time against error for the 3D DCB (prm/dcb_3d.prm) over meshes, on
2 ranks (mpirun -np 2), Release, without field output.

The meshes: the process-zone rule with 1, 2, 3 (the scene) and 6 elements
across l_cz = 0.68 mm (front cells of 0.5, 0.25, 0.125 and 0.0625 mm along
x), with 4 elements across the width, and the scene's rule with 8 across
the width. Per mesh: wall time (median of REPEAT runs, from the process
start), steps, Newton iterations and factorizations (from the log), the
largest number of unknowns, and the errors of the peak load and of the
load at delta = 3.88 and 5.82 mm against corrected beam theory (reference
section 1: onset 63.03 N, envelope P = sqrt(2 (G b)^1.5 (E I)^0.5 /
(3 delta))); a mesh on which Newton stops is recorded with the opening
where it stopped. Writes OUT.csv and a figure of run time against the peak
error, with the 2D DCB's meshes (doc/benchmarks/dcb_time_error.csv) if
TWO_D.csv is given (signed errors: beam theory is about 1 % above the
converged cohesive answer at the peak).

Fails if the scene's mesh takes more than 300 s (the issue's target for
the 3D DCB on 2 cores) or misses the onset or the envelope by more than
3 %.

usage: dcb_3d_time_error.py AMFRAC OUT.csv FIGURE.png [REPEAT] [TWO_D.csv]
(REPEAT = 0 only draws the figure from an existing OUT.csv)
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
two_d = sys.argv[5] if len(sys.argv) > 5 else None
here = os.path.dirname(os.path.abspath(__file__))
scene = os.path.join(here, "../../prm/dcb_3d.prm")
work = tempfile.mkdtemp()
onset, G, E, h = 63.03, 0.28, 135300.0, 1.5
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def envelope(delta, width):
    inertia = width * h**3 / 12
    return math.sqrt(2 * (G * width)**1.5 * math.sqrt(E * inertia)
                     / (3 * delta))


def run(zone_elements, across):
    name = f"pz{zone_elements}_w{across}"
    prm, out = os.path.join(work, name + ".prm"), os.path.join(work, name)
    with open(scene) as f, open(prm, "w") as g:
        g.write(f.read())
        g.write(f"\nsubsection Geometry\n  set Elements along width = "
                f"{across}\nend\nsubsection Adaptivity\n  set Process zone "
                f"elements = {zone_elements}\nend\nsubsection Output\n"
                f"  set Field format = none\n  set Directory = {out}\nend\n")
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        process = subprocess.run(["mpirun", "-np", "2", "--oversubscribe",
                                  amfrac, prm], capture_output=True,
                                 text=True, env=environment)
        times.append(time.perf_counter() - start)
    log = process.stdout
    summary = re.search(r"(\d+) steps, (\d+) Newton iterations, (\d+) "
                        r"factorizations", log)
    rows = list(csv.DictReader(open(os.path.join(out, "history.csv"))))
    changes = list(csv.DictReader(open(os.path.join(out, "adaptivity.csv"))))
    curve = [(float(r["time"]), float(r["force_x-"])) for r in rows]
    peak = max(range(len(curve)), key=lambda k: curve[k][1])
    width = 20.0

    def error_at(delta):
        if curve[-1][0] < delta:
            return math.nan
        k = min(range(peak, len(curve)),
                key=lambda k: abs(curve[k][0] - delta))
        return 100 * (curve[k][1] / envelope(curve[k][0], width) - 1)

    # A mesh on which Newton stops (the process zone under-resolved) is
    # recorded with the opening where it stopped.
    stopped = "" if process.returncode == 0 else curve[-1][0]
    iterations = [int(float(r["newton_iterations"])) for r in rows]

    return {
        "zone_elements": zone_elements,
        "elements_across_width": across,
        "front_cell_mm": 2.0 / 2**math.ceil(math.log2(
            2.0 / (0.88 * 9000 * G / 57**2 / zone_elements))),
        "largest_unknowns": max(int(float(r["unknowns"])) for r in changes),
        "steps": len(rows),
        "newton_iterations": sum(iterations),
        "factorizations": int(summary.group(3)) if summary else "",
        "seconds": round(statistics.median(times), 2),
        "peak_N": round(curve[peak][1], 3),
        "peak_error_pct": round(100 * (curve[peak][1] / onset - 1), 2),
        "P388_error_pct": round(error_at(3.88), 2),
        "P582_error_pct": round(error_at(5.82), 2),
        "stopped_at": stopped,
    }


def plot(results):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # Signed errors: beam theory is not the converged cohesive answer
    # (about 1 % above it at the peak), so |error| would reward a mesh
    # whose error cancels that difference.
    fig, axis = plt.subplots(figsize=(6.4, 4.2))
    axis.axhline(0, color="k", lw=0.8)
    for across, marker in ((4, "o"), (8, "s")):
        rows = [r for r in results if int(r["elements_across_width"]) == across
                and not r["stopped_at"]]
        axis.plot([float(r["seconds"]) for r in rows],
                  [float(r["peak_error_pct"]) for r in rows], marker,
                  label=f"3D, {across} elements across the width, 2 ranks")
        for r in rows:
            axis.annotate(f" {float(r['front_cell_mm'])} mm",
                          (float(r["seconds"]), float(r["peak_error_pct"])),
                          fontsize=7)
    if two_d:
        rows = [r for r in csv.DictReader(open(two_d)) if not r["stopped_at"]]
        axis.plot([float(r["seconds"]) for r in rows],
                  [float(r["peak_error_pct"]) for r in rows], "^",
                  label="2D (Q2, uniform), 1 rank")
        for r in rows:
            axis.annotate(f" {100 / int(r['elements'])} mm",
                          (float(r["seconds"]), float(r["peak_error_pct"])),
                          fontsize=7)
    axis.set_xscale("log")
    axis.set_xlabel("wall time [s]")
    axis.set_ylabel("peak load against beam theory [%]")
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(figure, dpi=120)


if repeat == 0:  # only draw the figure from OUT.csv
    plot(list(csv.DictReader(open(out_csv))))
    sys.exit(0)
results = [run(n, 4) for n in (1, 2, 3, 6)] + [run(3, 8)]
with open(out_csv, "w") as f:
    writer = csv.DictWriter(f, fieldnames=list(results[0].keys()))
    writer.writeheader()
    for row in results:
        writer.writerow(row)
        print(row)
plot(results)

scene_row = results[2]
# not (x <= 3): a NaN (the opening never reached) fails too
failed = (scene_row["stopped_at"] != "" or scene_row["seconds"] > 300
          or not abs(scene_row["peak_error_pct"]) <= 3
          or not abs(scene_row["P388_error_pct"]) <= 3
          or not abs(scene_row["P582_error_pct"]) <= 3)
print("scene mesh:", scene_row, "FAILED" if failed else "within targets")
sys.exit(1 if failed else 0)

#!/usr/bin/python3
"""Run time against error for the seed's impact (prm/impact_plate.prm,
100 microseconds) on uniform meshes and on meshes that adapt during the
run (prm/impact_plate_adaptive.prm), on 2 ranks (mpirun -np 2), Release,
without field output.

The meshes (in-plane cell size; one element per ply through the
thickness):
- uniform 1, 0.5 (the scene) and 0.25 mm (the reference);
- adaptive: the initial in-plane mesh refined along the plies within 6 mm
  of the centre (Geometry/Refinement region) and wherever an interface
  front has cells larger than l_cz / N (Adaptivity/Process zone elements
  N), coarsened behind the fronts but never below the initial mesh:
  2 mm -> 0.5 mm (N = 1), 1 mm -> 0.5 mm (N = 1) and 1 mm -> 0.25 mm
  (N = 2, the scene prm/impact_plate_adaptive.prm).
Per mesh: wall time (median of REPEAT runs, from the process start), the
largest number of cells, and against the reference run: the total
dissipated energy and debonded area of the two interfaces at 100 us, and
the largest difference of the centre deflection over the run (relative to
its largest value). The reference is the finest uniform mesh that this
machine runs in minutes, not a converged answer: the adaptive mesh of the
same finest size measures what adapting costs in accuracy.
Writes OUT.csv, a figure of the errors against run time, the histories of
the last repetition (total dissipated energy, debonded area and centre
deflection per output step) as OUT-histories.csv, and with HISTORY.png
a figure of them.

Fails if the adaptive scene is not at least 2x faster than the uniform
0.25 mm mesh or misses its dissipation by more than 3 % or its debonded
area by more than 5 %.

usage: impact_adaptive.py AMFRAC OUT.csv FIGURE.png [REPEAT] [HISTORY.png]
(REPEAT = 0 computes the errors again from OUT-histories.csv and draws
the figures, without running)
"""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

amfrac, out_csv, figure = sys.argv[1:4]
repeat = int(sys.argv[4]) if len(sys.argv) > 4 else 3
history_figure = sys.argv[5] if len(sys.argv) > 5 else None
histories_csv = out_csv.replace(".csv", "-histories.csv")
here = os.path.dirname(os.path.abspath(__file__))
uniform_scene = os.path.join(here, "../../prm/impact_plate.prm")
adaptive_scene = os.path.join(here, "../../prm/impact_plate_adaptive.prm")
work = tempfile.mkdtemp()
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")

# name, scene, in-plane cells per side, region refinements, process-zone
# elements, maximum level (the adaptive scene's own values last).
meshes = [("uniform 1 mm", uniform_scene, 30, None, None, None),
          ("uniform 0.5 mm", uniform_scene, 60, None, None, None),
          ("uniform 0.25 mm", uniform_scene, 120, None, None, None),
          ("adaptive 2 -> 0.5 mm", adaptive_scene, 15, 2, 1, 2),
          ("adaptive 1 -> 0.5 mm", adaptive_scene, 30, 1, 1, 1),
          ("adaptive 1 -> 0.25 mm", adaptive_scene, 30, 2, 2, 2)]
reference = "uniform 0.25 mm"


def run(name, scene, cells, region, zone, level):
    tag = name.replace(" ", "_").replace(">", "").replace(".", "p")
    prm, out = os.path.join(work, tag + ".prm"), os.path.join(work, tag)
    with open(scene) as f, open(prm, "w") as g:
        g.write(f.read())
        g.write(f"\nsubsection Geometry\n  set Elements along length = "
                f"{cells}\n  set Elements along width = {cells}\n")
        if region is not None:
            g.write(f"  set Region refinements = {region}\n")
        g.write("end\n")
        if zone is not None:
            g.write(f"subsection Adaptivity\n  set Process zone elements = "
                    f"{zone}\n  set Maximum refinement level = {level}\n"
                    f"end\n")
        g.write(f"subsection Output\n  set Directory = {out}\n"
                f"  set Field format = none\nend\n")
    started = time.perf_counter()
    subprocess.run(["mpirun", "-np", "2", amfrac, prm], check=True,
                   stdout=subprocess.DEVNULL, env=environment)
    seconds = time.perf_counter() - started
    with open(os.path.join(out, "history.csv")) as f:
        history = list(csv.DictReader(f))
    largest = cells * cells * 8  # uniform: cells per ply x 8 plies
    changes = os.path.join(out, "adaptivity.csv")
    if os.path.exists(changes):
        with open(changes) as f:
            largest = max([largest]
                          + [int(r["cells"]) for r in csv.DictReader(f)])
    return seconds, largest, history


def total(row, what):
    return float(row[what + "_i1"]) + float(row[what + "_i5"])


def compare(rows, histories):
    """The errors of every row's history against the reference's: the
    totals at 100 us, and the centre deflection at the reference's output
    times (the adaptive scenes write every 0.5 us, the uniform ones every
    2 us)."""
    ref = histories[reference]
    peak = max(abs(float(r["p0_uz"])) for r in ref)
    for row in rows:
        h = histories[row["mesh"]]
        last, ref_last = h[-1], ref[-1]
        at = {round(float(r["time"]) * 1e9): float(r["p0_uz"]) for r in h}
        row["dissipated"] = total(last, "dissipated")
        row["debonded"] = total(last, "debonded")
        row["dissipated_error"] = (row["dissipated"]
                                   / total(ref_last, "dissipated") - 1)
        row["debonded_error"] = (row["debonded"]
                                 / total(ref_last, "debonded") - 1)
        row["deflection_error"] = max(
            abs(at[round(float(b["time"]) * 1e9)] - float(b["p0_uz"]))
            for b in ref) / peak
        row["remeshing_energy"] = float(last.get("remeshing_energy", 0))
        row["external_work"] = float(last["external_work"])


def read_histories():
    """The histories of OUT-histories.csv, with the totals as columns of
    both interfaces (total() reads them back)."""
    histories = {}
    with open(histories_csv) as f:
        for r in csv.DictReader(f):
            histories.setdefault(r["mesh"], []).append(
                {"time": r["time"], "p0_uz": r["p0_uz"],
                 "dissipated_i1": r["dissipated"], "dissipated_i5": 0,
                 "debonded_i1": r["debonded"], "debonded_i5": 0,
                 "external_work": "nan"})
    return histories


def measure():
    rows, histories = [], {}
    for name, scene, cells, region, zone, level in meshes:
        times = []
        for _ in range(repeat):
            seconds, largest, history = run(name, scene, cells, region,
                                            zone, level)
            times.append(seconds)
        histories[name] = history
        rows.append({"mesh": name, "seconds": statistics.median(times),
                     "cells": largest})
        print(f"{name}: {statistics.median(times):.1f} s, {largest} cells",
              flush=True)
    compare(rows, histories)
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
    with open(histories_csv, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["mesh", "time", "dissipated", "debonded", "p0_uz"])
        for name, h in histories.items():
            for r in h:
                writer.writerow([name, r["time"], total(r, "dissipated"),
                                 total(r, "debonded"), r["p0_uz"]])
    return rows


def draw_histories():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    with open(histories_csv) as f:
        rows = list(csv.DictReader(f))
    figure_, axes = plt.subplots(1, 2, figsize=(10, 4))
    for name, _, _, _, _, _ in meshes:
        mine = [r for r in rows if r["mesh"] == name]
        t = [1e6 * float(r["time"]) for r in mine]
        style = "k-" if name == reference else (
            "--" if name.startswith("uniform") else "-")
        axes[0].plot(t, [float(r["dissipated"]) for r in mine], style,
                     label=name)
        axes[1].plot(t, [-float(r["p0_uz"]) for r in mine], style,
                     label=name)
    axes[0].set_ylabel("dissipated energy, both interfaces [N mm]")
    axes[1].set_ylabel("centre deflection [mm]")
    for ax in axes:
        ax.set_xlabel("t [us]")
        ax.grid(True, alpha=0.3)
    axes[0].legend(fontsize=8)
    figure_.tight_layout()
    figure_.savefig(history_figure, dpi=120)


def draw(rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure_, axes = plt.subplots(1, 2, figsize=(10, 4))
    for ax, column, label in [
            (axes[0], "dissipated_error", "dissipated energy at 100 us"),
            (axes[1], "deflection_error", "centre deflection over the run")]:
        for marker, kind in [("o", "uniform"), ("s", "adaptive")]:
            chosen = [r for r in rows if r["mesh"].startswith(kind)
                      and r["mesh"] != reference]
            ax.loglog([float(r["seconds"]) for r in chosen],
                      [max(abs(float(r[column])), 1e-4) for r in chosen],
                      marker + "-", label=kind)
            for r in chosen:
                ax.annotate(r["mesh"].split(" ", 1)[1],
                            (float(r["seconds"]),
                             max(abs(float(r[column])), 1e-4)),
                            fontsize=7)
        reference_seconds = [float(r["seconds"]) for r in rows
                             if r["mesh"] == reference][0]
        ax.axvline(reference_seconds, color="k", linestyle=":",
                   label=reference + " (the reference)")
        ax.set_xlabel("wall time on 2 ranks [s]")
        ax.set_ylabel("|relative difference| to uniform 0.25 mm")
        ax.set_title(label)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    figure_.tight_layout()
    figure_.savefig(figure, dpi=120)


if repeat > 0:
    rows = measure()
else:
    # Only the errors again, from the stored histories (the run times and
    # cells, the remeshing energy and the work stay those measured).
    with open(out_csv) as f:
        rows = list(csv.DictReader(f))
    kept = {r["mesh"]: (r["remeshing_energy"], r["external_work"])
            for r in rows}
    compare(rows, read_histories())
    for r in rows:
        r["remeshing_energy"], r["external_work"] = kept[r["mesh"]]
    with open(out_csv, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)
draw(rows)
if history_figure:
    draw_histories()
if repeat > 0:
    by_name = {r["mesh"]: r for r in rows}
    scene = by_name["adaptive 1 -> 0.25 mm"]
    speedup = by_name[reference]["seconds"] / scene["seconds"]
    print(f"adaptive scene: {speedup:.1f}x faster than uniform 0.25 mm, "
          f"dissipation {100 * scene['dissipated_error']:+.2f} %, debonded "
          f"{100 * scene['debonded_error']:+.2f} %")
    # Round-off, amplified by the contact chatter, moves the debonded area
    # by about 1.5 % (two orders of the same sums: +2.3 and +3.7 %).
    if (speedup < 2 or abs(scene["dissipated_error"]) > 0.03
            or abs(scene["debonded_error"]) > 0.05):
        sys.exit(1)

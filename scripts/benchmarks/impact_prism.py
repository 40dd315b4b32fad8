#!/usr/bin/python3
"""The seed's impact on prisms (prm/impact_plate_prism.prm) against
hexahedra (prm/impact_plate.prm): run time against error, 100
microseconds, on 2 ranks (mpirun -np 2), Release, without field output.

Meshes (one element per ply through the thickness):
- hexahedra, uniform 0.5 mm (the scene of step 6);
- wedges from Gmsh, 0.5 mm within 10 mm of the impact, growing to 2.5 mm
  (the scene), and the same with 0.25 mm within 10 mm;
- the scene's wedges remeshed by Gmsh whenever the ZZ error exceeds its
  threshold (prm/impact_plate_prism_remeshed.prm; its cells: the most
  any of its meshes had).
Per mesh: wall time (median of REPEAT runs, from the process start), the
number of cells, and against the reference, the uniform 0.25 mm
hexahedral mesh (its history from REFERENCE, the histories file that
impact_adaptive.py writes, so that it is not run again: 6 minutes): the
total dissipated energy and debonded area of the two interfaces at 100 us,
and the largest difference of the centre deflection over the run
(relative to its largest value). Also the contact columns (friction_i1 +
friction_i5: with mu = 0, what chattering contact gains or loses).

Writes OUT.csv and OUT-histories.csv (the last repetition's total
dissipation, debonded area and centre deflection per output step, and the
reference's), which plot_impact_prism.py draws.

Fails if the wedge scene is not faster than the 0.5 mm hexahedra or not
closer to the reference in dissipation and debonded area, or if the
remeshed run does not remesh or its ledger (with the remeshing term) does
not close to 1 % of the external work.

usage: impact_prism.py AMFRAC REFERENCE-histories.csv OUT.csv [REPEAT]
                       [MESHES]
MESHES: a comma-separated list of the meshes' labels to run (default all);
the failure criteria need their meshes.
"""
import csv
import os
import statistics
import subprocess
import sys
import tempfile
import time

amfrac, reference_csv, out_csv = sys.argv[1:4]
repeat = int(sys.argv[4]) if len(sys.argv) > 4 else 3
chosen = sys.argv[5].split(",") if len(sys.argv) > 5 else None
here = os.path.dirname(os.path.abspath(__file__))
prm_dir = os.path.join(here, "../../prm")
work = tempfile.mkdtemp()
environment = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
                   OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def scene_files(folder, name, fine_size):
    """The text of the scene NAME, and in FOLDER a copy of its .geo (if it
    has one) with the wedges' fine size changed to FINE_SIZE."""
    with open(os.path.join(prm_dir, name + ".prm")) as f:
        text = f.read()
    named = [line.split("=")[1].strip() for line in text.splitlines()
             if line.strip().startswith("set Mesh file")]
    geo_file = os.path.join(prm_dir, named[0] if named else name + ".geo")
    if os.path.exists(geo_file):
        with open(geo_file) as f:
            geo = f.read()
        if fine_size is not None:
            geo = geo.replace("SizeMin = 0.5;", f"SizeMin = {fine_size};")
            assert f"SizeMin = {fine_size};" in geo
        with open(os.path.join(folder, os.path.basename(geo_file)),
                  "w") as g:
            g.write(geo)
    return text


def run(label, name, fine_size):
    folder = os.path.join(work, label.replace(" ", "_"))
    os.makedirs(folder, exist_ok=True)
    text = scene_files(folder, name, fine_size)
    prm, out = os.path.join(folder, name + ".prm"), os.path.join(folder, "out")
    with open(prm, "w") as g:
        g.write(text)
        g.write(f"\nsubsection Output\n  set Directory = {out}\n"
                f"  set Field format = none\n  set Damage maps = false\nend\n")
    started = time.perf_counter()
    log = subprocess.run(["mpirun", "-np", "2", amfrac, prm], check=True,
                         capture_output=True, text=True, env=environment)
    seconds = time.perf_counter() - started
    cells = int(log.stdout.split(" cells,")[0].split()[-1])
    changes = os.path.join(out, "adaptivity.csv")
    remeshings = 0
    if os.path.exists(changes):
        with open(changes) as f:
            rows = list(csv.DictReader(f))
        remeshings = len(rows)
        cells = max([cells] + [int(r["cells"]) for r in rows])
    with open(os.path.join(out, "history.csv")) as f:
        return seconds, cells, list(csv.DictReader(f)), remeshings


def total(row, what):
    return float(row[what + "_i1"]) + float(row[what + "_i5"])


def reference_history():
    with open(reference_csv) as f:
        rows = [r for r in csv.DictReader(f) if r["mesh"] == "uniform 0.25 mm"]
    assert len(rows) > 10, "no uniform 0.25 mm history in " + reference_csv
    return rows


meshes = [("hexahedra 0.5 mm", "impact_plate", None),
          ("wedges 0.5 mm zone", "impact_plate_prism", None),
          ("wedges 0.25 mm zone", "impact_plate_prism", 0.25),
          ("wedges remeshed", "impact_plate_prism_remeshed", None)]
if chosen:
    meshes = [m for m in meshes if m[0] in chosen]
    assert len(meshes) == len(chosen), "unknown mesh in " + sys.argv[5]
ref = reference_history()
peak = max(abs(float(r["p0_uz"])) for r in ref)
ref_dissipated = float(ref[-1]["dissipated"])
ref_debonded = float(ref[-1]["debonded"])
rows, histories = [], [("hexahedra 0.25 mm (reference)", r) for r in ref]
for label, name, fine in meshes:
    runs = [run(label, name, fine) for _ in range(repeat)]
    seconds = statistics.median(r[0] for r in runs)
    _, cells, history, remeshings = runs[-1]
    last = history[-1]
    at = {round(float(r["time"]) * 1e9): float(r["p0_uz"]) for r in history}
    row = {"mesh": label, "seconds": seconds, "cells": cells,
           "dissipated": total(last, "dissipated"),
           "debonded": total(last, "debonded"),
           "contact": total(last, "friction"),
           "external_work": float(last["external_work"]),
           "remeshings": remeshings,
           "remeshing_energy": float(last.get("remeshing_energy", 0)),
           "balance_error": max(abs(float(r["balance_error"]))
                                for r in history)}
    row["dissipated_error"] = row["dissipated"] / ref_dissipated - 1
    row["debonded_error"] = row["debonded"] / ref_debonded - 1
    row["deflection_error"] = max(
        abs(at[round(float(b["time"]) * 1e9)] - float(b["p0_uz"]))
        for b in ref) / peak
    rows.append(row)
    histories += [(label, {"time": r["time"],
                           "dissipated": total(r, "dissipated"),
                           "debonded": total(r, "debonded"),
                           "p0_uz": r["p0_uz"]}) for r in history]
    print(", ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}"
                    for k, v in row.items()), flush=True)

with open(out_csv, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)

with open(out_csv.replace(".csv", "-histories.csv"), "w",
          newline="") as f:
    writer = csv.writer(f)
    writer.writerow(["mesh", "time", "dissipated", "debonded", "p0_uz"])
    for label, r in histories:
        writer.writerow([label, r["time"], r["dissipated"], r["debonded"],
                         r["p0_uz"]])

by_label = {r["mesh"]: r for r in rows}
failures = []
hexahedra = by_label.get("hexahedra 0.5 mm")
wedges = by_label.get("wedges 0.5 mm zone")
if hexahedra and wedges:
    if not wedges["seconds"] < hexahedra["seconds"]:
        failures.append("the wedge scene is not faster than the hexahedra")
    for what in ("dissipated_error", "debonded_error"):
        if not abs(wedges[what]) < abs(hexahedra[what]):
            failures.append(f"the wedge scene's {what} is not smaller")
remeshed = by_label.get("wedges remeshed")
if remeshed:
    if remeshed["remeshings"] < 1:
        failures.append("the remeshed scene did not remesh")
    if not remeshed["balance_error"] < 0.01 * remeshed["external_work"]:
        failures.append("the remeshed scene's ledger does not close")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)

#!/usr/bin/env python3
"""Plot the history of one or more impactor runs (prm/impact_plate_sphere.prm
or variants): the contact force on the plate (the mean over each output
interval), the sphere's velocity, the centre deflection, and the energies
(sphere, plate kinetic and strain, the balance error).

usage: impactor_history.py FIGURE.png LABEL=history.csv [LABEL=history.csv ...]
(run with /usr/bin/python3: it needs Debian's matplotlib)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

figure = sys.argv[1]
runs = [a.split("=", 1) for a in sys.argv[2:]]
fig, axes = plt.subplots(1, 3, figsize=(13, 4))
for label, path in runs:
    with open(path) as f:
        rows = list(csv.DictReader(f))
    t = [1e6 * float(r["time"]) for r in rows]
    column = lambda name: [float(r[name]) for r in rows]
    axes[0].plot(t, column("mean_contact_force"), label=label)
    axes[1].plot(t, [-v / 1000 for v in column("impactor_velocity")],
                 label=label + ": sphere (down +)")
    axes[1].plot(t, [-u for u in column("p0_uz")], "--",
                 label=label + ": plate centre deflection [mm]")
    if label == runs[0][0]:
        axes[2].plot(t, column("impactor_kinetic"), label="sphere kinetic")
        axes[2].plot(t, column("strain_energy"), label="plate strain")
        axes[2].plot(t, column("kinetic_energy"), label="plate kinetic")
        axes[2].plot(t, [100 * b for b in column("balance_error")],
                     label="balance error x 100")
axes[0].set_ylabel("contact force on the plate [N] (quarter model)")
axes[1].set_ylabel("sphere velocity [m/s]; deflection [mm]")
axes[2].set_ylabel("energy [N mm] (" + runs[0][0] + ")")
for ax in axes:
    ax.set_xlabel("t [us]")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(figure, dpi=120)

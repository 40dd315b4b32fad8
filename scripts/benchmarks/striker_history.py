#!/usr/bin/env python3
"""Plot a run of prm/impact_plate_striker.prm (a striker at a prescribed
speed): the contact force on the plate (at the output step and its mean
over each output interval) against the striker's travel, and the energies
against time (the striker's work, the plate's strain and kinetic energy,
the interfaces' dissipation, the balance error).

usage: striker_history.py FIGURE.png history.csv
(run with /usr/bin/python3: it needs Debian's matplotlib)
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

figure, path = sys.argv[1], sys.argv[2]
with open(path) as f:
    rows = list(csv.DictReader(f))
column = lambda name: [float(r[name]) for r in rows]
start = column("impactor_position")[0]
travel = [start - z for z in column("impactor_position")]
t = [1e6 * v for v in column("time")]
fig, axes = plt.subplots(1, 2, figsize=(11, 4))
axes[0].plot(travel, column("contact_force"), ".", ms=3,
             label="at the output step")
axes[0].plot(travel, column("mean_contact_force"),
             label="mean over the output interval")
axes[0].plot(travel, [-100 * u for u in column("p0_uz")], "--",
             label="plate centre deflection x 100 [mm]")
axes[0].set_xlabel("striker travel [mm]")
axes[0].set_ylabel("contact force on the plate [N] (quarter model)")
axes[1].plot(t, column("external_work"), label="striker's work")
axes[1].plot(t, column("strain_energy"), label="plate strain")
axes[1].plot(t, column("kinetic_energy"), label="plate kinetic")
dissipated = [a + b for a, b in zip(column("dissipated_i1"),
                                    column("dissipated_i5"))]
axes[1].plot(t, dissipated, label="interfaces dissipated")
axes[1].plot(t, [1e3 * b for b in column("balance_error")],
             label="balance error x 1000")
axes[1].set_xlabel("t [us]")
axes[1].set_ylabel("energy [N mm] (quarter model)")
for ax in axes:
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(figure, dpi=120)

#!/usr/bin/python3
"""Figure of the impact scene (prm/impact_plate.prm): the damage maps of
both interfaces, mirrored from the quarter model to the whole plate, and
the energy ledger over time.
usage: plot_impact.py OUTPUT_DIR FIGURE.png"""
import csv
import glob
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg
import matplotlib.pyplot as plt
import numpy as np

out, figure = sys.argv[1], sys.argv[2]
rows = list(csv.DictReader(open(out + "/history.csv")))
col = lambda k: np.array([float(r[k]) for r in rows])
t = col("time") * 1e6

fig, axes = plt.subplots(1, 3, figsize=(14, 4.4))
for ax, k, name in zip(axes[:2], ("1", "5"), ("0/90 (z = 0.5 mm)",
                                              "90/0 (z = 1.5 mm)")):
    quarter = mpimg.imread(sorted(glob.glob(
        f"{out}/damage-interface-{k}-*.png"))[-1])
    # the quarter's lower left corner is the plate's center
    top = np.hstack([np.fliplr(quarter), quarter])
    whole = np.vstack([top, np.flipud(top)])
    ax.imshow(whole, extent=[-30, 30, -30, 30])
    ax.set_title(f"interface {k}, {name}: "
                 f"{4 * col('debonded_i' + k)[-1]:.0f} mm$^2$ debonded")
    ax.set_xlabel("x [mm] (0$^\\circ$ fibres of the outer plies)")
    ax.set_ylabel("y [mm]")
ax = axes[2]
for k, label in (("external_work", "external work"),
                 ("kinetic_energy", "kinetic"),
                 ("strain_energy", "strain"),
                 ("dissipated_i1", "dissipated, interface 1"),
                 ("dissipated_i5", "dissipated, interface 5"),
                 ("friction_i1", "contact 'friction', interface 1"),
                 ("balance_error", "balance error")):
    ax.plot(t, 4 * col(k), label=label)
ax.set_xlabel("t [$\\mu$s]")
ax.set_ylabel("energy, whole plate [N mm]")
ax.legend(fontsize=8)
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(figure, dpi=110)

#!/usr/bin/python3
"""Load-opening curves of 2D DCB runs against beam theory.

usage: /usr/bin/python3 plot_dcb.py OUT.png LABEL=history.csv [LABEL=...]
The curves are P = 20 force_x- (N, width 20 mm) against the opening t (mm);
the reference lines are the corrected-beam-theory loading line up to the
onset (63.03 N at 1.940 mm) and the propagation envelope
P = sqrt(2 (G b)^1.5 (E I)^0.5 / (3 delta)) of ../shared/reference/README.md.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

b, h, E, G = 20.0, 1.5, 135300.0, 0.28
EI = E * b * h**3 / 12


def envelope(delta):
    return math.sqrt(2 * (G * b) ** 1.5 * EI**0.5 / (3 * delta))


fig, ax = plt.subplots(figsize=(6.4, 4.2))
onset_P, onset_d = 63.03, 1.940
ax.plot([0, onset_d], [0, onset_P], "k--", lw=1, label="corrected beam theory")
ds = [onset_d + 0.05 * i for i in range(200)]
ax.plot(ds, [envelope(d) for d in ds], "k--", lw=1)
for item in sys.argv[2:]:
    label, path = item.split("=", 1)
    rows = list(csv.DictReader(open(path)))
    ax.plot([float(r["time"]) for r in rows],
            [b * float(r["force_x-"]) for r in rows], lw=1.2, label=label)
ax.set_xlabel("opening $\\delta$ [mm]")
ax.set_ylabel("load P [N]")
ax.set_xlim(0, 10)
ax.set_ylim(0, 75)
ax.grid(alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)

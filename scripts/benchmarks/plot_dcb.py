#!/usr/bin/python3
"""Load-opening curves of 2D and 3D DCB runs against beam theory.

usage: /usr/bin/python3 plot_dcb.py [--data mi|as4peek] OUT.png LABEL=history.csv [...]
The curves are P = b force_x- (N; force_x- itself in 3D runs, whose
history has z reactions) against the opening t (mm); the reference
lines are the corrected-beam-theory loading line up to the onset and the
propagation envelope P = sqrt(2 (G b)^1.5 (E I)^0.5 / (3 delta)) of
../shared/reference/README.md section 1 (mi: Mi et al. / Alfano & Crisfield
Table I, the default; as4peek: Camanho, Davila & de Moura 2003).
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

DATA = {
    # b, h, E11, G_Ic, CBT onset (P, delta), plot limits (delta, P)
    "mi": (20.0, 1.5, 135300.0, 0.28, (63.03, 1.940), (10, 75)),
    "as4peek": (25.4, 1.56, 122700.0, 0.969, (138.51, 4.213), (13, 160)),
}
args = sys.argv[1:]
name = "mi"
if args[0] == "--data":
    name, args = args[1], args[2:]
b, h, E, G, (onset_P, onset_d), (xmax, ymax) = DATA[name]
EI = E * b * h**3 / 12


def envelope(delta):
    return math.sqrt(2 * (G * b) ** 1.5 * EI**0.5 / (3 * delta))


fig, ax = plt.subplots(figsize=(6.4, 4.2))
ax.plot([0, onset_d], [0, onset_P], "k--", lw=1, label="corrected beam theory")
ds = [onset_d + 0.05 * i for i in range(int((xmax - onset_d) / 0.05) + 1)]
ax.plot(ds, [envelope(d) for d in ds], "k--", lw=1)
for item in args[1:]:
    label, path = item.split("=", 1)
    rows = list(csv.DictReader(open(path)))
    # 2D: per unit width; 3D: the whole width
    scale = 1 if any(c.endswith("_z") for c in rows[0]) else b
    ax.plot([float(r["time"]) for r in rows],
            [scale * float(r["force_x-"]) for r in rows], lw=1.2,
            label=label)
ax.set_xlabel("opening $\\delta$ [mm]")
ax.set_ylabel("load P [N]")
ax.set_xlim(0, xmax)
ax.set_ylim(0, ymax)
ax.grid(alpha=0.3)
ax.legend()
fig.tight_layout()
fig.savefig(args[0], dpi=110)

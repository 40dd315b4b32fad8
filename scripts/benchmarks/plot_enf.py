#!/usr/bin/python3
"""Load-deflection curves of 2D ENF runs against beam theory.

usage: /usr/bin/python3 plot_enf.py OUT.png LABEL=history.csv [LABEL=...]
The curves are P = 25.4 force_y+ (N) against the load-point deflection t
(mm) of prm/enf_2d.prm. Reference (../shared/reference/README.md section 2):
the loading line C(a0) P with C = (3a^3 + 2L^3)/(8 E b h^3) + 3L/(10 b h G13)
and the LEFM propagation branch (P_c(a), C(a) P_c(a)) for a0 <= a <= L, once
with the simple beam theory and once with the crack-tip correction
a + 0.42 chi h (Wang & Williams 1992) and the Timoshenko shear term of G_II.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

b, h, L, a0, E, E22, G13, G = 25.4, 1.56, 51.0, 35.7, 122700.0, 10100.0, 5500.0, 1.719
Gamma = 1.18 * math.sqrt(E * E22) / G13
chi = math.sqrt(E / (11 * G13) * (3 - 2 * (Gamma / (1 + Gamma)) ** 2))


def compliance(a):
    return (3 * a**3 + 2 * L**3) / (8 * E * b * h**3) + 3 * L / (10 * b * h * G13)


def onset(a, shear):
    factor = 1 + 0.2 * (E / G13) * (h / a) ** 2 if shear else 1
    return math.sqrt(16 * b * b * E * h**3 * G / (9 * a * a * factor))


fig, ax = plt.subplots(figsize=(6.4, 4.2))
for shift, shear, style, label in [(0, False, "k:", "simple beam theory"),
                                   (0.42 * chi * h, True, "k--",
                                    "corrected beam theory, shear term")]:
    a_list = [a0 + (L - a0) * i / 100 for i in range(101)]
    P = [onset(a + shift, shear) for a in a_list]
    d = [compliance(a + shift) * p for a, p in zip(a_list, P)]
    ax.plot([0] + d, [0] + P, style, lw=1, label=label)
for item in sys.argv[2:]:
    label, path = item.split("=", 1)
    rows = list(csv.DictReader(open(path)))
    ax.plot([float(r["time"]) for r in rows],
            [b * float(r["force_y+"]) for r in rows], lw=1.2, label=label)
ax.set_xlabel("load-point deflection $\\delta$ [mm]")
ax.set_ylabel("load P [N]")
ax.set_xlim(0, 5)
ax.set_ylim(0, 950)
ax.grid(alpha=0.3)
ax.legend(loc="lower right")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)

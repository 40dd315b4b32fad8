#!/usr/bin/python3
"""Load-deflection curve of the 2D MMB run against beam theory.

usage: /usr/bin/python3 plot_mmb.py OUT.png LABEL:history.csv [LABEL:...]
The curves are the lever load P = 25.4 force_lever (N) against the
load-point deflection t (mm) of prm/mmb_2d.prm. Reference: Reeder & Crews
(1990) with the ASTM D6671 corrections (see tests/app/mmb_2d.cc): the
loading line C(a0) P and the propagation envelope (P_c(a), C(a) P_c(a)) for
a0 <= a < L, where P_c solves G_I + G_II = G_c(B) (Benzeggagh-Kenane); once
with the simple beam theory and once with the corrections.
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

b, h, L, c, a0 = 25.4, 1.56, 51.0, 43.0, 34.0
E, E22, G13 = 122700.0, 10100.0, 5500.0
G_Ic, G_IIc, eta = 0.969, 1.719, 2.284
Gamma = 1.18 * math.sqrt(E * E22) / G13
chi = math.sqrt(E / (11 * G13) * (3 - 2 * (Gamma / (1 + Gamma)) ** 2))
f_I, f_II = (3 * c - L) / (4 * L), (c + L) / L


def lengths(a, corrected):
    if not corrected:
        return a, a, 1.0
    a_II = a + 0.42 * chi * h
    return a + chi * h, a_II, 1 + 0.2 * (E / G13) * (h / a_II) ** 2


def onset(a, corrected):
    a_I, a_II, shear = lengths(a, corrected)
    G_I = 12 * f_I**2 * a_I**2 / (b * b * h**3 * E)
    G_II = 9 * f_II**2 * a_II**2 / (16 * b * b * h**3 * E) * shear
    B = G_II / (G_I + G_II)
    return math.sqrt((G_Ic + (G_IIc - G_Ic) * B**eta) / (G_I + G_II))


def compliance(a, corrected):
    a_I, a_II, _ = lengths(a, corrected)
    dcb = 8 * a_I**3 / (E * b * h**3)
    enf = (3 * a_II**3 + 2 * L**3) / (8 * E * b * h**3)
    if corrected:
        enf += 3 * L / (10 * b * h * G13)
    return f_I**2 * dcb + f_II**2 * enf


fig, ax = plt.subplots(figsize=(6.4, 4.2))
for corrected, style, label in [(False, "k:", "simple beam theory"),
                                (True, "k--", "corrected beam theory")]:
    a_list = [a0 + (L - 1 - a0) * i / 100 for i in range(101)]
    P = [onset(a, corrected) for a in a_list]
    d = [compliance(a, corrected) * p for a, p in zip(a_list, P)]
    ax.plot([0] + d, [0] + P, style, lw=1, label=label)
for item in sys.argv[2:]:
    label, path = item.split(":", 1)
    rows = list(csv.DictReader(open(path)))
    ax.plot([float(r["time"]) for r in rows],
            [b * float(r["force_lever"]) for r in rows], lw=1.2, label=label)
ax.set_xlabel("lever load-point deflection $\\delta$ [mm]")
ax.set_ylabel("lever load P [N]")
ax.set_xlim(0, 8)
ax.set_ylim(0, 320)
ax.grid(alpha=0.3)
ax.legend(loc="lower right")
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)

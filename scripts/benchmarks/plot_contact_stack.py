"""Tip deflection of two unbonded plies in frictionless contact (a
cantilever under a pressure q, prm/contact_stack_2d.prm), against a single
ply under q / 2, the bonded pair, and Euler-Bernoulli's lines for both.
usage: /usr/bin/python3 plot_contact_stack.py STACK.csv SINGLE.csv BONDED.csv
OUT.png (the history.csv files of the three runs; see doc/tutorials/
step-14-contact)."""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

q, length, modulus = 0.01, 20.0, 70000.0


def column(path, name):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [float(r["time"]) for r in rows], [-float(r[name]) for r in rows]


def beam(thickness, load):
    inertia = thickness**3 / 12
    return load * length**4 / (8 * modulus * inertia)


stack, single, bonded, out = sys.argv[1:5]
fig, ax = plt.subplots(figsize=(6, 4))
t, w = column(stack, "p0_uy")
ax.plot([q * x for x in t], w, "o-", label="two unbonded plies, contact (top tip)")
t, w = column(stack, "p1_uy")
ax.plot([q * x for x in t], w, "x", label="two unbonded plies, contact (bottom tip)")
t, w = column(single, "p0_uy")
ax.plot([q * x for x in t], w, "s--", mfc="none", label="one ply under q / 2")
t, w = column(bonded, "p0_uy")
ax.plot([q * x for x in t], w, "^-", label="bonded pair")
loads = [0, q]
ax.plot(loads, [beam(1, x / 2) for x in loads], "k:", label="beam theory, one ply under q / 2")
ax.plot(loads, [beam(2, x) for x in loads], "k-.", label="beam theory, bonded pair")
ax.set_xlabel("pressure q [MPa]")
ax.set_ylabel("tip deflection [mm]")
ax.legend(fontsize=8)
ax.grid(alpha=0.3)
fig.tight_layout()
fig.savefig(out, dpi=120)

#!/usr/bin/python3
"""The clamped strip's buckling modes (prm/buckling_strip_2d.prm) against
the clamped-clamped beam's: runs amfrac with 101 points along the mid-line
and plots u_y of each mode (run with Debian's /usr/bin/python3).
usage: plot_buckling_strip.py AMFRAC OUT.png"""
import csv
import math
import os
import subprocess
import sys
import tempfile
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

amfrac, png = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
here = os.path.dirname(os.path.abspath(__file__))
scene = open(os.path.join(here, "../../prm/buckling_strip_2d.prm")).read()
L, n = 100.0, 101
xs = [L * i / (n - 1) for i in range(n)]
with tempfile.TemporaryDirectory() as work:
    points = "; ".join(f"{x:g}, 0.5" for x in xs)
    with open(f"{work}/strip.prm", "w") as f:
        f.write(scene + "\nsubsection Output\n  set Field format = none\n"
                f"  set Directory = {work}/out\n  set Point values = {points}\nend\n")
    subprocess.run([amfrac, f"{work}/strip.prm"], check=True,
                   stdout=subprocess.DEVNULL)
    modes = list(csv.DictReader(open(f"{work}/out/buckling.csv")))


def beam_mode(kL, symmetric):
    """Clamped-clamped: w = 1 - cos kx (symmetric) or
    (1 - cos kx) + B (kx - sin kx) with w(L) = 0 (antisymmetric)."""
    k = kL / L
    if symmetric:
        w = [1 - math.cos(k * x) for x in xs]
    else:
        B = -(1 - math.cos(kL)) / (kL - math.sin(kL))
        w = [1 - math.cos(k * x) + B * (k * x - math.sin(k * x)) for x in xs]
    scale = max(w, key=abs)
    return [v / scale for v in w]


fig, ax = plt.subplots(figsize=(7, 4))
for m, (kL, sym) in enumerate(((2 * math.pi, True), (8.98681892, False),
                               (4 * math.pi, True))):
    u = [float(modes[m][f"p{i}_uy"]) for i in range(n)]
    ref = beam_mode(kL, sym)
    # Same sign as amfrac's (largest displacement positive).
    if sum(a * b for a, b in zip(u, ref)) < 0:
        ref = [-v for v in ref]
    line, = ax.plot(xs, u, "o", ms=3,
                    label=f"amfrac mode {m + 1}, lambda = {float(modes[m]['load_factor']):.4g}")
    ax.plot(xs, ref, "-", color=line.get_color(), lw=1,
            label=f"beam, kL = {kL:.4g}")
ax.set_xlabel("x [mm]")
ax.set_ylabel("u_y (largest 1)")
ax.set_title("Clamped [0_4] strip: buckling modes")
ax.grid(True, alpha=0.3)
ax.legend(fontsize=7, ncol=2)
fig.tight_layout()
fig.savefig(png, dpi=110)

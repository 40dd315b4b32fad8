"""Step 17's figure of the cylindrical loading nose: the coupon's force
against its mid-span deflection (prm/three_point_bending_3d.prm) with beam
theory, and the stiffness on the meshes of three_point_bending.sh.
usage: /usr/bin/python3 plot_three_point_bending.py HISTORY.csv BENCH.csv
       OUT.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

BEAM = 42.65  # N/mm, narrow beam with Timoshenko's shear (the .prm)
PLATE = 42.93  # E1 / (1 - nu12 nu21) for E1: a wide plate

history = list(csv.DictReader(open(sys.argv[1])))
bench = list(csv.DictReader(open(sys.argv[2])))
w = [0] + [-float(r["p0_uz"]) for r in history]
P = [0] + [4 * float(r["contact_force"]) for r in history]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot(w, P, "o", label="amfrac, Q2, 200 cells")
left.plot([0, max(w)], [0, BEAM * max(w)], "k-", lw=0.8,
          label="narrow beam, 42.65 N/mm")
left.set_xlabel("mid-span deflection of the bottom face w [mm]")
left.set_ylabel("nose force P [N]")
left.legend()
left.set_title("three-point bending under a cylindrical nose")

n = [int(r["unknowns"]) for r in bench]
k = [float(r["stiffness_N_per_mm"]) for r in bench]
right.semilogx(n, k, "o-", label="amfrac P / w")
right.axhline(BEAM, color="k", lw=0.8, label="narrow beam (E1)")
right.axhline(PLATE, color="k", ls="--", lw=0.8,
              label="wide plate (E1 / (1 - nu12 nu21))")
right.set_xlabel("unknowns")
right.set_ylabel("stiffness P / w [N/mm]")
right.set_ylim(42.5, 43.0)
right.legend()
right.set_title("mesh refinement")
fig.tight_layout()
fig.savefig(sys.argv[3], dpi=100)

"""Figure of tutorial step 14's section on a body touching itself.

usage: /usr/bin/python3 scripts/benchmarks/plot_hairpin.py OUTPUT_DIR OUT.png
  OUTPUT_DIR: output of prm/self_contact_hairpin_2d.prm (Field format =
              vtu; step 5 is the pressed state, t = 1)
Writes OUT.png: the folded strip pressed (displacements to scale, the
stress across the arms in colour) and the stress along the lower arm's
inner face against the three springs in series of the scene's header.
"""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_plasticity import vtu_arrays  # noqa: E402

MODULUS, PENALTY, THICKNESS, D = 70000.0, 5e5, 1.0, 0.6
GAP0 = 2 * (2.4 / math.pi - THICKNESS / 2)
PRESSURE = (D - GAP0) / (2 * THICKNESS / MODULUS + 1 / PENALTY)


def cells_and_values(vtu, field):
    arrays = vtu_arrays(vtu)
    points = arrays["Float32"][1]
    u = arrays["displacement"][1]
    value = arrays[field][1]
    connectivity = arrays["connectivity"][1] if "connectivity" in arrays else arrays["Int32"][1]
    n = len(points) // 3
    reference = [(points[3 * i], points[3 * i + 1]) for i in range(n)]
    moved = [(points[3 * i] + u[3 * i], points[3 * i + 1] + u[3 * i + 1]) for i in range(n)]
    cells = [[connectivity[4 * c + k] for k in (0, 1, 2, 3)]
             for c in range(len(connectivity) // 4)]
    return reference, moved, value, cells


def main(output_dir, out):
    vtu = os.path.join(output_dir, "solution-00005.0000.vtu")
    reference, moved, stress, cells = cells_and_values(vtu, "stress_yy")
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.2))
    left.add_collection(PolyCollection([[reference[i] for i in c] for c in cells],
                                       facecolors="none", edgecolors="0.75",
                                       linewidths=0.3))
    pressed = PolyCollection([[moved[i] for i in c] for c in cells],
                             array=[sum(stress[i] for i in c) / 4 for c in cells],
                             cmap="viridis", edgecolors="k", linewidths=0.15)
    pressed.set_clim(-1.5 * PRESSURE, 0)
    left.add_collection(pressed)
    left.set_xlim(-0.5, 11.5)
    left.set_ylim(-1.6, 1.6)
    left.set_aspect("equal")
    left.set_xlabel("x [mm]")
    left.set_ylabel("y [mm]")
    left.set_title("pressed by d = 0.6 mm (grey: unloaded, gap 0.528 mm)")
    plt.colorbar(pressed, ax=left, label="stress_yy [MPa]", orientation="horizontal",
                 pad=0.22)
    # The lower arm's inner face: y = -g0 / 2 in the unloaded U, x <= 10.
    face = sorted({(reference[i][0], stress[i]) for c in cells for i in c
                   if abs(reference[i][1] + GAP0 / 2) < 1e-4 and reference[i][0] <= 10 + 1e-6})
    right.plot([x for x, _ in face], [-s for _, s in face], "o", ms=3,
               label="amfrac, lower arm's inner face (each cell's value)")
    right.axhline(PRESSURE, color="k", ls="--",
                  label="springs in series: (d - g0) / (2h/E + 1/Penalty)")
    right.set_xlabel("x [mm] (bend beyond x = 10)")
    right.set_ylabel("contact pressure -stress_yy [MPa]")
    right.set_ylim(0, 1.3 * PRESSURE)
    right.legend(fontsize=8, loc="lower left")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])

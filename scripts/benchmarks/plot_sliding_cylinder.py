"""The sliding cylinder of prm/sliding_cylinder_2d.prm (issue 10): its
friction force over mu times the normal force and the share of the contact
nodes that slide against the drag, with Cattaneo-Mindlin's for the
half-space: 2 (a - c) / h nodes, c = a sqrt(1 - F_x / (mu N)), a Hertz's
half-width for the force N, h the cell (as app/impactor_friction_slide);
and the dissipation against the drag work of F_x. Prints the table of
step 17.
usage: /usr/bin/python3 plot_sliding_cylinder.py history.csv FIGURE.png"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

MU, PRESS = 0.3, 0.03
E_STAR, RADIUS, CELL = 70000 / (1 - 0.3**2), 5.0, 5.0 / 256

rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(sys.argv[1]))]
drag = [r["time"] - PRESS for r in rows if r["time"] > PRESS + 1e-12]
dragged = [r for r in rows if r["time"] > PRESS + 1e-12]
ratio = [r["contact_force_x"] / (MU * r["contact_force"]) for r in dragged]
share = [r["sliding_nodes"] / r["contact_nodes"] for r in dragged]
# The nodes Mindlin's slip zones span, 2 (a - c) / h.
mindlin = [2 * math.sqrt(4 * r["contact_force"] * RADIUS / (math.pi * E_STAR))
           * (1 - math.sqrt(max(0.0, 1 - q))) / CELL for r, q in zip(dragged, ratio)]
dissipated = [r["impactor_friction_dissipation"] for r in dragged]
# The drag work of F_x by the trapezoidal rule from the end of the pressing.
work, last_x, last_f = [], 0.0, 0.0
total = 0.0
for x, r in zip(drag, dragged):
    total += 0.5 * (last_f + r["contact_force_x"]) * (x - last_x)
    work.append(total)
    last_x, last_f = x, r["contact_force_x"]

print("| drag [um] | F_x / (mu N) | sliding nodes | Mindlin | dissipated [N mm] | work of F_x [N mm] |")
print("|---|---|---|---|---|---|")
for x, r, q, m, d, w in zip(drag, dragged, ratio, mindlin, dissipated, work):
    partial = r["sliding_nodes"] < r["contact_nodes"]
    expected = f"{m:.1f}" if partial else "-"
    print(f"| {1000 * x:.1f} | {q:.4f} | {int(r['sliding_nodes'])} of {int(r['contact_nodes'])}"
          f" | {expected} | {d:.4f} | {w:.4f} |")

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
left.plot([1000 * x for x in drag], ratio, "o-", label="F_x / (mu N)")
left.plot([1000 * x for x in drag], share, "s-", label="sliding nodes / contact nodes")
partial = [i for i, r in enumerate(dragged) if r["sliding_nodes"] < r["contact_nodes"]]
left.plot([1000 * drag[i] for i in partial],
          [mindlin[i] / dragged[i]["contact_nodes"] for i in partial], "k--",
          label="Mindlin: 2 (a - c) / h over the contact nodes")
left.set_xlabel("drag [um]")
left.set_ylim(0, 1.1)
left.legend(fontsize=8, loc="lower right")
left.set_title("partial slip, then sliding")
right.plot([1000 * x for x in drag], dissipated, "o-", label="friction dissipation")
right.plot([1000 * x for x in drag], work, "k--", label="work of F_x over the drag")
right.set_xlabel("drag [um]")
right.set_ylabel("N mm (per mm of width)")
right.legend(fontsize=8)
right.set_title("the drag's work goes into friction")
fig.suptitle("A cylinder (R = 5 mm) pressed 30 um into aluminium and dragged, mu = 0.3")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=110)

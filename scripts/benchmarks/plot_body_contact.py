#!/usr/bin/env python3
"""Plot the two contact scenes of issue 10: the collision of two bars
(prm/bar_collision.prm: contact force, far-end displacements against 1D
wave theory, momentum and energies) and the block sliding on a block
(prm/contact_blocks.prm: normal and friction force, mu N, the top block's
displacement and the friction dissipation), and, given the CSV of
scripts/benchmarks/contact_search.sh, the search cost against the number
of surface faces.

usage: plot_body_contact.py FIGURE.png COLLISION.csv SLIDING.csv [SEARCH.csv]
(run with /usr/bin/python3: it needs Debian's matplotlib)
"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return lambda name: [float(r[name]) for r in rows]


figure, collision, sliding = sys.argv[1:4]
search = sys.argv[4] if len(sys.argv) > 4 else None
fig, axes = plt.subplots(1, 4 if search else 3, figsize=(18 if search else 14, 4))

c = read(collision)
t = [1e6 * x for x in c("time")]
speed, length, wave = 1000.0, 10.0, math.sqrt(70000 / 2.7e-9)
ax = axes[0]
ax.plot(t, c("body_contact_normal_force"), label="contact force [N]")
stress = 2.7e-9 * wave * speed / 2  # the impact stress rho c v / 2, area 1
ax.axhline(stress, color="gray", ls=":", label="1D theory rho c v / 2")
ax.axvline(1e6 * 2 * length / wave, color="k", ls="--", lw=0.8,
           label="2 L / c")
ax.set_xlabel("t [us]")
ax.set_ylabel("force [N]")
ax.set_title("two bars: the contact")
ax.legend(fontsize=8)

ax = axes[1]
ax.plot(t, [1000 * u for u in c("p0_uz")], label="bottom bar, far end")
ax.plot(t, [1000 * u for u in c("p1_uz")], label="top bar, far end")
tt = [x * 1e-6 for x in t]
ax.plot(t, [1000 * speed * min(x, length / wave) for x in tt], "k:",
        lw=0.8, label="1D theory")
ax.plot(t, [1000 * speed * max(x - length / wave, 0) for x in tt], "k:",
        lw=0.8)
ax.set_xlabel("t [us]")
ax.set_ylabel("displacement [um]")
ax.set_title("two bars: far ends")
ax.legend(fontsize=8)

s = read(sliding)
t = [1e6 * x for x in s("time")]
ax = axes[2]
ax.plot(t, s("body_contact_normal_force"), label="normal force N [N]")
ax.plot(t, s("body_contact_friction_force"), label="friction force [N]")
ax.plot(t, [0.3 * n for n in s("body_contact_normal_force")], "k:",
        label="mu N")
ax.plot(t, [1000 * u for u in s("p0_ux")], label="top block u_x [um]")
ax.plot(t, [1000 * d for d in s("friction_dissipation")],
        label="friction dissipation [uJ]")
ax.set_xlabel("t [us]")
ax.set_title("block sliding on a block (mu = 0.3)")
ax.legend(fontsize=8)

if search:
    b = read(search)
    faces = b("faces")
    ax = axes[3]
    ax.loglog(faces, b("search_us"), "o-", label="search per evaluation")
    ax.loglog(faces, b("contact_us"), "s-", label="all contact per evaluation")
    internal = [1e6 * f / e for f, e in zip(b("internal_forces_s"), b("evaluations"))]
    ax.loglog(faces, internal, "^-", label="internal forces per step")
    ax.loglog(faces, [b("search_us")[0] * f / faces[0] for f in faces], "k:",
              label="linear")
    ax.set_xlabel("surface faces")
    ax.set_ylabel("us")
    ax.set_title("contact search cost (impact plate)")
    ax.legend(fontsize=8)

fig.tight_layout()
fig.savefig(figure, dpi=110)

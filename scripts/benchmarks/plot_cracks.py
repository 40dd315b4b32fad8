"""Figures of tutorial step 11 (crack insertion).

usage: /usr/bin/python3 scripts/benchmarks/plot_cracks.py BAR_DIR BEAM_DIR OUT_DIR [PLATE_DIR]
  BAR_DIR:   output of prm/cracked_bar_2d.prm
  BEAM_DIR:  output of prm/cracked_beam_2d.prm (may be '-': skipped)
  PLATE_DIR: output of prm/fragmenting_plate.prm (optional)
Writes OUT_DIR/splitting.png (the node-splitting rule), bar.png, beam.png
and fragmentation.png.
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def splitting(out):
    """2 x 2 cells around a node: which released faces split it."""
    cases = [
        ("one face from the edge:\nedge node splits, tip node does not",
         [((1, 0), (1, 1))], {(1, 0): 2, (1, 1): 1}),
        ("two faces in line, a cut through:\nevery node on it splits",
         [((1, 0), (1, 1)), ((1, 1), (1, 2))], {(1, 0): 2, (1, 1): 2, (1, 2): 2}),
        ("four faces meeting:\nthe centre node becomes four",
         [((1, 0), (1, 1)), ((1, 1), (1, 2)), ((0, 1), (1, 1)), ((1, 1), (2, 1))],
         {(1, 1): 4, (1, 0): 2, (1, 2): 2, (0, 1): 2, (2, 1): 2}),
    ]
    fig, axes = plt.subplots(1, 3, figsize=(11, 3.8))
    for ax, (title, faces, copies) in zip(axes, cases):
        for i in range(3):
            ax.plot([0, 2], [i, i], color="0.6", lw=1)
            ax.plot([i, i], [0, 2], color="0.6", lw=1)
        for a, b in faces:
            ax.plot([a[0], b[0]], [a[1], b[1]], color="tab:red", lw=4)
        for x in range(3):
            for y in range(3):
                n = copies.get((x, y), 1)
                ax.scatter([x], [y], s=60 + 50 * (n - 1),
                           color="tab:red" if n > 1 else "k", zorder=3)
                if n > 1:
                    ax.annotate(f"{n}", (x, y), textcoords="offset points",
                                xytext=(7, 5), color="tab:red")
        ax.set_title(title, fontsize=9)
        ax.set_aspect("equal")
        ax.axis("off")
    fig.suptitle("released faces (red) and the number of unknowns each node "
                 "becomes: the connected parts of its cell star")
    fig.tight_layout()
    fig.savefig(f"{out}/splitting.png", dpi=110)


def bar(directory, out):
    h = read(f"{directory}/history.csv")
    u = [0.07 * t for t in h["time"]]
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(u, h["reaction_x+_x"], "o-", ms=3, label="force (N per mm width)")
    ax.axhline(45, color="0.5", ls=":", label="0.9 Yt x area (onset)")
    ax.set_xlabel("end displacement u (mm)")
    ax.set_ylabel("force (N/mm)")
    ax2 = ax.twinx()
    ax2.plot(u, h["dissipated_cracks"], "s-", ms=3, color="tab:red",
             label="dissipated by the crack (N mm/mm)")
    ax2.axhline(1.0, color="tab:red", ls=":", label="Gc x area")
    ax2.set_ylabel("energy (N mm per mm width)")
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], fontsize=8,
              loc="center right")
    ax.set_title("cracked_bar_2d: break at the weak section, Gc dissipated")
    fig.tight_layout()
    fig.savefig(f"{out}/bar.png", dpi=110)


def beam(directory, out):
    h = read(f"{directory}/history.csv")
    d = [1.5 * t for t in h["time"]]  # Displacement = -1.5*t
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(d, [-f for f in h["reaction_y+_y"]], "o-", ms=3,
            label="load (N per mm width)")
    ax.set_xlabel("mid-span deflection (mm)")
    ax.set_ylabel("load (N/mm)")
    ax2 = ax.twinx()
    ax2.plot(d, h["crack_faces"], "s-", ms=3, color="tab:red",
             label="crack faces")
    ax2.plot(d, [1e3 * a for a in h["damaged_i1"]], "^-", ms=3,
             color="tab:green", label="damaged interface 1 (um)")
    ax2.set_ylabel("count / length")
    lines = ax.get_legend_handles_labels()
    lines2 = ax2.get_legend_handles_labels()
    ax.legend(lines[0] + lines2[0], lines[1] + lines2[1], fontsize=8,
              loc="upper left")
    ax.set_title("cracked_beam_2d: transverse cracks, then delamination")
    fig.tight_layout()
    fig.savefig(f"{out}/beam.png", dpi=110)


def fragmentation(directory, out):
    """Crack faces, fragments and the energies of the explicit plate."""
    h = read(directory + "/history.csv")
    events = read(directory + "/cracks.csv")
    t = [1e6 * x for x in h["time"]]
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 3.8))
    a.plot(t, h["crack_faces"], label="crack faces")
    a.bar([1e6 * x for x in events["time"]], events["faces"], width=0.02,
          color="tab:gray", label="faces inserted per event")
    a.set_xlabel("t [us]")
    a.set_ylabel("faces")
    a2 = a.twinx()
    a2.step(t, h["fragments"], where="post", color="tab:red")
    a2.set_ylabel("fragments", color="tab:red")
    a.legend(loc="center right", fontsize=8)
    a.set_title("insertion and fragments")
    for name, label in [("kinetic_energy", "kinetic"),
                        ("strain_energy", "strain"),
                        ("dissipated_cracks", "dissipated by cracks"),
                        ("interface_stored", "held by crack faces")]:
        b.plot(t, h[name], label=label)
    b.plot(t, [abs(x) for x in h["balance_error"]], "k--",
           label="|balance error|")
    b.set_yscale("symlog", linthresh=1e-2)
    b.set_xlabel("t [us]")
    b.set_ylabel("N mm")
    b.legend(fontsize=8)
    b.set_title("energy ledger")
    fig.tight_layout()
    fig.savefig(out + "/fragmentation.png", dpi=120)


if __name__ == "__main__":
    bar_dir, beam_dir, out = sys.argv[1:4]
    splitting(out)
    bar(bar_dir, out)
    if beam_dir != "-":
        beam(beam_dir, out)
    if len(sys.argv) > 4:
        fragmentation(sys.argv[4], out)

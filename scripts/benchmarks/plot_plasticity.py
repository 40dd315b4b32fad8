"""Figures of tutorial step 16 (Hoffman plasticity of the plies).

usage: /usr/bin/python3 scripts/benchmarks/plot_plasticity.py \
           BEAM_DIR UNIFORM_DIR CYCLE_DIR BENCHMARK_CSV OUT_DIR
  BEAM_DIR:      output of prm/plastic_beam_2d.prm (history.csv and the
                 VTU of the last step)
  UNIFORM_DIR:   output of the same scene on the uniform 384 x 8 mesh
                 (Adaptivity/Refine every = 0)
  CYCLE_DIR:     output of app/plasticity_cycle (the 90-degree cube loaded,
                 unloaded and reloaded)
  BENCHMARK_CSV: scripts/benchmarks/plastic_plies.sh's table
Writes OUT_DIR/beam.png (force against deflection, plastic work, the
equivalent plastic strain on the adapted mesh), cycle.png and
time_error.png.
"""
import base64
import csv
import glob
import re
import struct
import sys
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection


def read(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: [float(r[k]) for r in rows] for k in rows[0]}


def vtu_arrays(path):
    """The DataArrays of a deal.II VTU (inline binary, zlib): name ->
    (components, values)."""
    text = open(path).read()
    arrays = {}
    pattern = re.compile(
        r'<DataArray type="(\w+)"(?: Name="(\w+)")?'
        r'(?: NumberOfComponents="(\d+)")? format="binary">\s*(\S+)\s*</DataArray>'
    )
    for kind, name, components, data in pattern.findall(text):
        # A header of 32-bit words (blocks, block size, last block size,
        # compressed sizes), then the compressed blocks.
        blocks = struct.unpack("<I", base64.b64decode(data[:8])[:4])[0]
        header_length = ((3 + blocks) * 4 + 2) // 3 * 4
        raw = zlib.decompress(base64.b64decode(data[header_length:]))
        fmt = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B"}[kind]
        values = struct.unpack("<%d%s" % (len(raw) // struct.calcsize(fmt), fmt), raw)
        arrays[name or kind] = (int(components or 1), values)
    # Points and connectivity come without Name in deal.II's writer.
    return arrays


def plastic_zone(ax, vtu):
    arrays = vtu_arrays(vtu)
    points = arrays["Float32"][1]  # the first unnamed Float32: Points
    connectivity = arrays["connectivity"][1] if "connectivity" in arrays else arrays["Int32"][1]
    # deal.II writes cell data as point data of each patch's vertices.
    vertex_kappa = arrays["equivalent_plastic_strain"][1]
    xy = [(points[3 * i], points[3 * i + 1]) for i in range(len(points) // 3)]
    n_cells = len(connectivity) // 4
    cells = [[xy[connectivity[4 * c + k]] for k in (0, 1, 2, 3)]
             for c in range(n_cells)]
    kappa = [vertex_kappa[connectivity[4 * c]] for c in range(n_cells)]
    collection = PolyCollection(cells, array=kappa, cmap="magma_r",
                                edgecolors="0.6", linewidths=0.1)
    ax.add_collection(collection)
    ax.set_xlim(6, 18)
    ax.set_ylim(-0.05, 1.05)
    ax.set_aspect(2.5)
    ax.set_xlabel("x [mm]")
    ax.set_ylabel("y [mm] (2.5 x)")
    plt.colorbar(collection, ax=ax, label="equivalent plastic strain kappa",
                 orientation="horizontal", pad=0.25)


def beam(beam_dir, uniform_dir, out):
    adaptive = read(beam_dir + "/history.csv")
    uniform = read(uniform_dir + "/history.csv")
    fig = plt.figure(figsize=(11, 7.5))
    top_left = fig.add_subplot(2, 2, 1)
    top_right = fig.add_subplot(2, 2, 2)
    bottom = fig.add_subplot(2, 1, 2)
    for h, label, style in ((uniform, "uniform 384 x 8 per ply (24,576 cells)", "k-"),
                            (adaptive, "adaptive (ZZ every 4 steps, up to 5,976 cells)", "o")):
        deflection = [1.5 * t for t in h["time"]]
        top_left.plot(deflection, h["force_y+"], style, ms=4, label=label)
        top_right.plot(deflection, h["plastic_work"], style, ms=4, label=label)
    elastic = [adaptive["force_y+"][0] / adaptive["time"][0] * t for t in adaptive["time"]]
    top_left.plot([1.5 * t for t in adaptive["time"]], elastic, ":", color="0.5",
                  label="elastic (first step extended)")
    top_left.set_xlabel("deflection at mid-span [mm]")
    top_left.set_ylabel("force [N per mm of width]")
    top_left.legend(fontsize=8)
    top_right.set_xlabel("deflection at mid-span [mm]")
    top_right.set_ylabel("plastic work [N mm per mm]")
    top_right.legend(fontsize=8)
    steps = sorted(glob.glob(beam_dir + "/solution-*.0000.vtu"))
    plastic_zone(bottom, steps[-1])
    bottom.set_title("equivalent plastic strain at 1.5 mm (the middle half of the beam)")
    fig.tight_layout()
    fig.savefig(out + "/beam.png", dpi=110)


def cycle(cycle_dir, out):
    h = read(cycle_dir + "/history.csv")
    strain = [0.01 * (t if t <= 1 else (2 - t if t <= 2 else t - 2)) for t in h["time"]]
    fig, ax = plt.subplots(figsize=(5.5, 4))
    ax.plot([0] + strain, [0] + h["reaction_x+_x"], "o-", ms=4)
    ax.axhline(50, color="0.6", ls=":", label="Yt = 50 MPa")
    ax.set_xlabel("strain across the fibres")
    ax.set_ylabel("stress [MPa]")
    ax.set_title("load, unload, reload (hardening 1)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out + "/cycle.png", dpi=110)


def time_error(table, out):
    rows = list(csv.DictReader(open(table)))
    beams = [r for r in rows if r["case"] == "beam"]
    reference = 19.51
    fig, ax = plt.subplots(figsize=(5.5, 4))
    uniform = [r for r in beams if r["setting"].startswith("uniform")]
    ax.loglog([float(r["wall_s"]) for r in uniform],
              [abs(float(r["force"]) / reference - 1) for r in uniform], "s-",
              label="uniform refinement")
    for r in beams:
        if r["setting"] == "adaptive":
            ax.loglog([float(r["wall_s"])], [abs(float(r["force"]) / reference - 1)],
                      "o", ms=9, label="adaptive (tau_1 transfer)")
    ax.set_xlabel("wall time [s], one rank")
    ax.set_ylabel("relative error of the final force")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out + "/time_error.png", dpi=110)


if __name__ == "__main__":
    beam_dir, uniform_dir, cycle_dir, table, out = sys.argv[1:6]
    beam(beam_dir, uniform_dir, out)
    cycle(cycle_dir, out)
    time_error(table, out)

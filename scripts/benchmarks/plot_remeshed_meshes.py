#!/usr/bin/python3
"""The in-plane mesh of a prism laminate before and after a global
remeshing: the bottom triangles of the wedges of two VTU files that amfrac
wrote (deal.II's zlib-compressed binary VTU, one piece each), one above
the other.

usage: plot_remeshed_meshes.py BEFORE.vtu AFTER.vtu FIGURE.png [XMAX YMAX]
(XMAX, YMAX: the corner of the region drawn, from the origin)
"""
import base64
import re
import struct
import sys
import zlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def decode(text, kind):
    """A zlib-compressed binary DataArray: a base64 header (number of
    blocks, block size, last block size, compressed sizes; UInt32), then
    the base64 of the compressed blocks."""
    text = text.strip()
    blocks = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_chars = 4 * ((12 + 4 * blocks + 2) // 3)
    header = struct.unpack(f"<{3 + blocks}I",
                           base64.b64decode(text[:header_chars]))
    data = base64.b64decode(text[header_chars:])
    raw, start = b"", 0
    for size in header[3:]:
        raw += zlib.decompress(data[start:start + size])
        start += size
    code = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B",
            "Int64": "q", "UInt32": "I"}[kind]
    return struct.unpack(f"<{len(raw) // struct.calcsize(code)}{code}", raw)


def arrays(path):
    with open(path) as f:
        xml = f.read()
    found = {}
    for match in re.finditer(
            r'<DataArray type="(\w+)"(?: Name="(\w+)")?[^>]*>([^<]*)'
            r'</DataArray>', xml):
        kind, name, text = match.groups()
        found.setdefault(name or "points", decode(text, kind))
    return found


def bottom_edges(path):
    """The edges of the wedges' bottom triangles in the lowest layer."""
    a = arrays(path)
    points, connectivity = a["points"], a["connectivity"]
    offsets, types = a["offsets"], a["types"]
    z = [points[3 * i + 2] for i in range(len(points) // 3)]
    bottom = min(z)
    edges, start = [], 0
    for end, kind in zip(offsets, types):
        cell = connectivity[start:end]
        start = end
        if kind != 13 or max(z[v] for v in cell[:3]) > bottom + 1e-9:
            continue
        xy = [(points[3 * v], points[3 * v + 1]) for v in cell[:3]]
        edges += [(xy[i], xy[(i + 1) % 3]) for i in range(3)]
    return edges, len(edges) // 3


before, after, figure = sys.argv[1:4]
limits = [float(v) for v in sys.argv[4:6]] if len(sys.argv) > 5 else None
fig, axes = plt.subplots(2, 1, figsize=(8, 8))
for ax, path, title in zip(axes, (before, after), ("before", "after")):
    edges, triangles = bottom_edges(path)
    ax.add_collection(LineCollection(edges, linewidths=0.3, colors="k"))
    ax.set_aspect("equal")
    ax.autoscale()
    if limits:
        ax.set_xlim(0, limits[0])
        ax.set_ylim(0, limits[1])
    ax.set_title(f"{title}: {triangles} triangles per layer")
fig.tight_layout()
fig.savefig(figure, dpi=130)

#!/usr/bin/env python3
"""Grade the in-plane mesh of a deck from the CalculiX peer's gen_plate.py
the way amfrac's Geometry/Edge grading grades its box: nx elements per
side whose lengths shrink geometrically from the middle to both edges, the
longest RATIO times the shortest. Vertices move to the graded positions and
mid-side nodes to the middle of their graded element, so the elements stay
straight-sided and the node sets (chosen by lattice index) are unchanged.
usage: grade_calculix_deck.py NX RATIO SIDE < deck.inp > graded.inp"""
import sys


def graded_vertices(n, length, ratio):
    half = (n + 1) // 2
    growth = ratio ** (1.0 / (half - 1)) if half > 1 else 1.0
    steps = [growth ** min(i, n - 1 - i) for i in range(n)]
    scale = length / sum(steps)
    vertices = [0.0]
    for step in steps:
        vertices.append(vertices[-1] + step * scale)
    return vertices


def remap(x, vertices, length):
    n = len(vertices) - 1
    position = x / length * n
    i = min(int(position), n - 1)
    f = position - i
    return vertices[i] + f * (vertices[i + 1] - vertices[i])


def main():
    n, ratio, side = int(sys.argv[1]), float(sys.argv[2]), float(sys.argv[3])
    vertices = graded_vertices(n, side, ratio)
    in_nodes = False
    for line in sys.stdin:
        if line.startswith('*'):
            in_nodes = line.split(',')[0].strip().upper() == '*NODE'
            sys.stdout.write(line)
            continue
        if in_nodes:
            fields = line.split(',')
            x, y = float(fields[1]), float(fields[2])
            fields[1] = ' %.10g' % remap(x, vertices, side)
            fields[2] = ' %.10g' % remap(y, vertices, side)
            sys.stdout.write(','.join(fields))
        else:
            sys.stdout.write(line)


main()

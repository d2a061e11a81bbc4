#!/usr/bin/env python3
"""Writes docs/gallery/fibres.vtk: 60 helical strands around a bent axis (120 points each), a
legacy VTK polydata of LINES, the input of the README's "fibres as lit lines" image."""
import math
import sys

points, lines = [], []
for k in range(60):
    radius = 0.25 * math.sqrt((k + 0.5) / 60)
    phase = k * 2.399963  # the golden angle: strands spread evenly over the bundle's section
    ids = []
    for i in range(120):
        s = i / 119
        a = phase + 6 * s
        th = -1.0 + 2.0 * s  # along an arc of radius 2 in the XZ plane
        cx, cz = 2 * math.sin(th), 2 * math.cos(th) - 2
        tx, tz = math.cos(th), -math.sin(th)
        ox, oy = radius * math.cos(a), radius * math.sin(a)
        ids.append(len(points))
        points.append((cx - ox * tz, oy, cz + ox * tx))
    lines.append(ids)
out = sys.argv[1] if len(sys.argv) > 1 else "docs/gallery/fibres.vtk"
with open(out, "w") as f:
    f.write("# vtk DataFile Version 3.0\nfibres\nASCII\nDATASET POLYDATA\n")
    f.write("POINTS %d float\n" % len(points))
    for p in points:
        f.write("%.5g %.5g %.5g\n" % p)
    f.write("LINES %d %d\n" % (len(lines), sum(len(l) + 1 for l in lines)))
    for l in lines:
        f.write("%d %s\n" % (len(l), " ".join(map(str, l))))

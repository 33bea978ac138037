#!/usr/bin/env python3
"""Writes an open cap: a sphere of radius 0.49 cut at 0.375 along its axis (the
shape of CGAL's half.xyz), 15,888 points on a Fibonacci lattice with outward
normals, dense enough (about 0.3 h at h = 0.0436) to be its own exact shape when
cap_drag.json drags it (docs/real-data.md).

    make_cap.py [OUT] [--axis {z,y}]

OUT: cap.xyz next to this script by default. The cap opens towards +axis: +z
for cap_drag.json; +y for the editor's GUI test (tests/editor_gui_test.py),
whose default view looks along -z, so that pulling the bottom pole down is a
drag in the screen's plane."""
import argparse
import math
import os
import sys

SPHERE_POINTS = 18000
RADIUS = 0.49
CUT = 0.375


def cap_points(axis="z"):
    """(x, y, z, nx, ny, nz) of every point of the cap, opening towards +axis."""
    golden = math.pi * (3.0 - math.sqrt(5.0))
    out = []
    for i in range(SPHERE_POINTS):
        z = 1.0 - 2.0 * (i + 0.5) / SPHERE_POINTS
        r = math.sqrt(1.0 - z * z)
        a = golden * i
        if RADIUS * z > CUT:
            continue
        x, y = r * math.cos(a), r * math.sin(a)
        n = (x, y, z) if axis == "z" else (y, z, x)  # a turn taking +z to +y
        out.append(tuple(RADIUS * c for c in n) + n)
    return out


def main():
    parser = argparse.ArgumentParser(description="Writes the open cap's points with normals (.xyz).")
    parser.add_argument("out", nargs="?", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "cap.xyz"))
    parser.add_argument("--axis", choices=("z", "y"), default="z", help="the direction the cap opens towards")
    options = parser.parse_args()
    with open(options.out, "w") as out:
        for p in cap_points(options.axis):
            out.write("%.10f %.10f %.10f %.10f %.10f %.10f\n" % p)
    print(options.out)


if __name__ == "__main__":
    main()

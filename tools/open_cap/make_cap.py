#!/usr/bin/env python3
"""Writes cap.xyz next to this script: a sphere of radius 0.49 cut at z = 0.375
(an open cap, the shape of CGAL's half.xyz), 15,888 points on a Fibonacci
lattice with outward normals, dense enough (about 0.3 h at h = 0.0436) to be
its own exact shape when cap_drag.json drags it (docs/real-data.md)."""
import math
import os

SPHERE_POINTS = 18000
RADIUS = 0.49
CUT = 0.375

golden = math.pi * (3.0 - math.sqrt(5.0))
path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "cap.xyz")
with open(path, "w") as out:
    for i in range(SPHERE_POINTS):
        z = 1.0 - 2.0 * (i + 0.5) / SPHERE_POINTS
        r = math.sqrt(1.0 - z * z)
        a = golden * i
        if RADIUS * z > CUT:
            continue
        x, y = r * math.cos(a), r * math.sin(a)
        out.write(f"{RADIUS * x:.10f} {RADIUS * y:.10f} {RADIUS * z:.10f} {x:.10f} {y:.10f} {z:.10f}\n")
print(path)

#!/usr/bin/env python3
"""Writes the region-drag scene of docs/editor.md's picture: the unit sphere at h = 0.05, its south cap
(y < -0.6) a pinned region, its north cap (y > 0.7) a region lifted by 0.35 and tilted by 0.6 rad about
the z axis in 20 steps (+y is up in `amls render`'s pictures) - what a lasso, P and a drag of the marker (then Ctrl+drag) do in the editor.

    python3 tools/region_drag/make_scene.py [OUT=/tmp/region_drag.json]

The members are points of a Fibonacci sphere 0.7 h apart, finer than the reach (h), so that every point of
the caps lies within reach of one."""
import json
import math
import sys


def fibonacci_sphere(count):
    golden = math.pi * (3 - math.sqrt(5))
    for i in range(count):
        z = 1 - 2 * (i + 0.5) / count
        r = math.sqrt(1 - z * z)
        yield [round(r * math.cos(golden * i), 6), round(r * math.sin(golden * i), 6), round(z, 6)]


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "/tmp/region_drag.json"
    h = 0.05
    spacing = 0.7 * h
    count = round(4 * math.pi / (spacing * spacing * math.sqrt(3) / 2))
    points = list(fibonacci_sphere(count))
    scene = {
        "dimension": 3,
        "name": "region drag",
        "description": "A pinned south cap and a north cap lifted and tilted as one piece (docs/editor.md)",
        "shape": {"type": "sphere", "radius": 1},
        "grid": {"spacing": h},
        "regions": [{"points": [p for p in points if p[1] < -0.6]}, {"points": [p for p in points if p[1] > 0.7]}],
        "stages": [{"handles": [], "regions": [{"region": 0, "pinned": True}, {"region": 1}],
                    "targets": [{"steps": 20, "handles": [],
                                 "regions": [{}, {"translation": [0, 0.35, 0], "rotation": [0, 0, 0.6]}]}]}],
    }
    with open(out, "w") as f:
        json.dump(scene, f)
    print("wrote %s: %d + %d members" % (out, len(scene["regions"][0]["points"]), len(scene["regions"][1]["points"])))


if __name__ == "__main__":
    main()

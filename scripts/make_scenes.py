#!/usr/bin/env python3
"""Writes the scenes in assets/scenes/ (clover2d.json, clover3d.json, torus_tentacles.json).

The handles are designed here, in a few lines each, so that the scenes can be
changed and remade: python3 scripts/make_scenes.py. Where a new stage adds a
handle on the already deformed shape, its start is found by carrying the
initial point through the previous stages with the same 2D rigid MLS map as
core/deform/mls_deformation.cpp (Schaefer et al. 2006, alpha = 1).
"""
import json
import math
import os
import re

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "..", "assets", "scenes")


def polar(r, degrees):
    a = math.radians(degrees)
    return [r * math.cos(a), r * math.sin(a)]


def rounded(points, digits=6):
    return [[round(x, digits) for x in p] for p in points]


def rigid_mls_2d(p, q, v):
    """f(v) for handles p -> q (rigid, alpha = 1)."""
    w = []
    for pi in p:
        d2 = (pi[0] - v[0]) ** 2 + (pi[1] - v[1]) ** 2
        if d2 == 0.0:
            return list(q[p.index(pi)])
        w.append(1.0 / d2)
    total = sum(w)
    ps = [sum(wi * pi[k] for wi, pi in zip(w, p)) / total for k in range(2)]
    qs = [sum(wi * qi[k] for wi, qi in zip(w, q)) / total for k in range(2)]
    a = b = 0.0
    for wi, pi, qi in zip(w, p, q):
        ph = (pi[0] - ps[0], pi[1] - ps[1])
        qh = (qi[0] - qs[0], qi[1] - qs[1])
        a += wi * (ph[0] * qh[0] + ph[1] * qh[1])
        b += wi * (ph[0] * qh[1] - ph[1] * qh[0])
    r = math.hypot(a, b)
    c, s = (a / r, b / r) if r > 0 else (1.0, 0.0)
    d = (v[0] - ps[0], v[1] - ps[1])
    return [c * d[0] - s * d[1] + qs[0], s * d[0] + c * d[1] + qs[1]]


def carry_2d(stage, v):
    """Carries v through every step of a 2D stage, as `amls deform` does."""
    previous = stage["handles"]
    for target in stage["targets"]:
        n = target["steps"]
        for k in range(n):
            t0, t1 = k / n, (k + 1) / n
            a = [[(1 - t0) * x + t0 * y for x, y in zip(h0, h1)] for h0, h1 in zip(previous, target["handles"])]
            b = [[(1 - t1) * x + t1 * y for x, y in zip(h0, h1)] for h0, h1 in zip(previous, target["handles"])]
            v = rigid_mls_2d(a, b, v)
        previous = target["handles"]
    return v


# Leaf tips in their final directions: the bottom two are turned 10 degrees
# apart, which opens the bottom notch for the stem.
LEAF_TIPS = (45, 135, 215, 325)
MATERIAL_TIPS = (45, 135, 225, 315)
# Each leaf is a circle of radius 0.55 centred 0.95 from the origin; its
# handles sit on it at these angles from the tip (seen from the leaf's centre),
# and started on the unit circle at these angles from the tip's start.
LEAF_ANGLES = (0, -75, 75)
MATERIAL_OFFSETS = (0, -20, 20)


def lerp(a, b, t):
    return [(1 - t) * x + t * y for x, y in zip(a, b)]


def clover_start():
    handles = [polar(1.0, tip + offset) for tip in MATERIAL_TIPS for offset in MATERIAL_OFFSETS]
    handles += [polar(1.0, notch) for notch in (0, 90, 180, 270)]
    return rounded(handles)


def clover_final():
    handles = []
    for tip in LEAF_TIPS:
        u, v = polar(1.0, tip), polar(1.0, tip + 90)
        for angle in LEAF_ANGLES:
            c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
            handles.append([0.95 * u[k] + 0.55 * (c * u[k] + s * v[k]) for k in range(2)])
    handles += [polar(0.3, notch) for notch in (0, 90, 180)] + [polar(0.45, 270)]
    return rounded(handles)


def clover2d():
    # Stage 1 (40 steps): a stem grows out of the bottom of the circle. Handles
    # at 270 -+ 3 degrees pull its end down, handles at 270 -+ 9 degrees narrow
    # its base to 0.16, handles at 270 -+ 20 and at 0, 45, 90, 135, 180 degrees
    # hold the rest of the circle where it is.
    anchors = [polar(1.0, a) for a in (0, 45, 90, 135, 180, 250, 290)]
    stem_start = [polar(1.0, a) for a in (261, 279, 267, 273)]
    half = 0.08

    def stem(top, length):
        return [[-half, top], [half, top], [-half, top - length], [half, top - length]]

    stage1 = {
        "handles": rounded(anchors + stem_start),
        "targets": [
            {"steps": 20, "handles": rounded(anchors + stem(-1.0, 0.7))},
            {"steps": 20, "handles": rounded(anchors + stem(-1.0, 1.4))},
        ],
    }
    # Stage 2 (80 steps): the anchors are removed and the leaves' handles added
    # (a new stage): three per leaf, at the points that started at the leaf's
    # tip and 20 degrees either side, move onto a circle of radius 0.55 centred
    # 0.95 from the origin; the notches at 0, 90 and 180 degrees are pulled in
    # to 0.3, and the stem moves up with the bottom notch to 0.45. The first
    # target has the leaves 60 % of the way out and the rest 35 % of the way.
    leaf_start = rounded([carry_2d(stage1, p) for p in clover_start()[:12]])
    notch_start = [polar(1.0, a) for a in (0, 90, 180)]
    start = leaf_start + notch_start + rounded(stem(-1.0, 1.4))
    final = clover_final()[:15] + stem(-0.45, 1.4)
    halfway = [lerp(a, b, 0.6 if i < 12 else 0.35) for i, (a, b) in enumerate(zip(start, final))]
    stage2 = {
        "handles": start,
        "targets": [{"steps": 40, "handles": rounded(halfway)}, {"steps": 40, "handles": rounded(final)}],
    }
    return scene(2, "clover2d", "A unit circle of 250 points becomes a four-leaf clover with a stem in 120 resampling steps "
        "(the paper's Fig. 2): stage 1 pulls a stem out of the circle's bottom, stage 2 swaps the anchors for "
        "leaf handles and grows four leaves.",
                 {"type": "circle", "center": [0.0, 0.0], "radius": 1.0, "points": 250}, 0.024, [stage1, stage2])


def spherical(r, azimuth, latitude):
    a, b = math.radians(azimuth), math.radians(latitude)
    return [r * math.cos(b) * math.cos(a), r * math.cos(b) * math.sin(a), r * math.sin(b)]


def on_equator(points2d, z=0.0):
    return [[p[0], p[1], z] for p in points2d]


def clover3d():
    """The 2D clover's handles on the equator of a unit sphere, with handles
    off the equator that flatten the leaves to slabs 0.6 thick and make the
    stem round. One stage, three targets: the stem first (40 steps), then the
    leaves (two targets of 40 steps)."""
    start, final = [], []
    # Equator: leaf tips and shoulders, and notches at 0, 90, 180 degrees.
    start += on_equator(clover_start()[:15])
    final += on_equator(clover_final()[:15])
    # Off the equator: above and below each leaf's centre, each notch, and the poles.
    for material, tip in zip(MATERIAL_TIPS, LEAF_TIPS):
        for lat in (-40, 40):
            start.append(spherical(1.0, material, lat))
            final.append(spherical(0.95, tip, 0)[:2] + [0.3 if lat > 0 else -0.3])
    for notch in (0, 90, 180):
        for lat in (-45, 45):
            start.append(spherical(1.0, notch, lat))
            final.append(spherical(0.25, notch, 0)[:2] + [0.3 if lat > 0 else -0.3])
    start += [[0.0, 0.0, 1.0], [0.0, 0.0, -1.0]]
    final += [[0.0, 0.0, 0.35], [0.0, 0.0, -0.35]]
    # The stem: rings of four handles at 9 degrees (its base) and 3 degrees (its
    # end) around the bottom point (0, -1, 0); its flanks at 20 degrees.
    radius = 0.12

    def ring(y, r):
        return [[-r, y, 0.0], [r, y, 0.0], [0.0, y, -r], [0.0, y, r]]

    def material_ring(degrees):
        s, c = math.sin(math.radians(degrees)), math.cos(math.radians(degrees))
        return [[-s, -c, 0.0], [s, -c, 0.0], [0.0, -c, -s], [0.0, -c, s]]

    flanks = material_ring(20)
    stem_material = material_ring(9) + material_ring(3)
    fixed = len(start)
    start += flanks + stem_material
    out_stem = ring(-1.0, radius) + ring(-2.4, radius)
    final_stem = ring(-0.45, radius) + ring(-1.85, radius)
    final_flanks = [[-0.3, -0.55, 0.0], [0.3, -0.55, 0.0], [0.0, -0.5, -0.28], [0.0, -0.5, 0.28]]
    target1 = start[:fixed] + flanks + out_stem
    target3 = final + final_flanks + final_stem
    target2 = [lerp(a, b, 0.5) for a, b in zip(target1, target3)]
    targets = [{"steps": 40, "handles": rounded(t)} for t in (target1, target2, target3)]
    return scene(3, "clover3d", "A unit sphere of 10,000 points becomes a four-leaf clover with a round stem in 120 "
        "resampling steps (the paper's Fig. 3, top): the 2D clover's handles on the equator, handles above and "
        "below the leaves and notches that flatten it, and rings of handles that pull out the stem.",
                 {"type": "sphere", "center": [0.0, 0.0, 0.0], "radius": 1.0, "points": 10000}, 0.035, [{"handles": rounded(start), "targets": targets}])


def torus_tentacles():
    """A torus (major radius 1, minor 0.35) grows four tentacles out of its
    outer equator: first straight out to 1.2 beyond it, thinning to a radius
    of 0.1, then curling up and further out."""
    big, small = 1.0, 0.35
    outer = big + small

    def tube(azimuth, v):
        """The torus point at azimuth and tube angle v (0: outer equator)."""
        a, b = math.radians(azimuth), math.radians(v)
        rr = big + small * math.cos(b)
        return [rr * math.cos(a), rr * math.sin(a), small * math.sin(b)]

    start, target1, target2 = [], [], []
    for k in range(4):
        phi = 90 * k + 20
        u = [math.cos(math.radians(phi)), math.sin(math.radians(phi)), 0.0]
        t = [-u[1], u[0], 0.0]
        # Base: held where it is.
        base = [tube(phi - 14, 0), tube(phi + 14, 0), tube(phi, -45), tube(phi, 45)]
        start += base
        target1 += base
        target2 += base
        # End: four handles close around the outer equator's point, pulled out.
        end = [tube(phi - 4, 0), tube(phi + 4, 0), tube(phi, -12), tube(phi, 12)]
        start += end
        for length, lift, goal in ((1.2, 0.0, target1), (1.6, 0.9, target2)):
            centre = [outer * u[i] + length * u[i] for i in range(2)] + [lift]
            r = 0.1
            goal += [[centre[0] - r * t[0], centre[1] - r * t[1], centre[2]],
                     [centre[0] + r * t[0], centre[1] + r * t[1], centre[2]],
                     [centre[0], centre[1], centre[2] - r], [centre[0], centre[1], centre[2] + r]]
        # The hole side and the top and bottom between tentacles: held.
        anchors = [tube(phi + 45, 180), tube(phi + 45, 90), tube(phi + 45, -90), tube(phi + 45, 0)]
        start += anchors
        target1 += anchors
        target2 += anchors
    targets = [{"steps": 60, "handles": rounded(target1)}, {"steps": 60, "handles": rounded(target2)}]
    return scene(3, "torus_tentacles", "A torus grows four long, thin tentacles (radius 0.1, about 3 h) out of its outer equator "
        "in 60 steps, then curls them up and further out in 60 more.",
                 {"type": "torus", "center": [0.0, 0.0, 0.0], "major_radius": big, "minor_radius": small}, 0.035, [{"handles": rounded(start), "targets": targets}])


def drag_sphere():
    """amls bench's drag (core/run/drag_bench.cpp) at 20,000 points: h from the same 0.83 points per area / h^2."""
    centre, r, points = [0.5, 0.5, 0.5], 0.3, 20000
    h = round(math.sqrt(0.83 * 4.0 * math.pi * r * r / points), 5)
    start = [[0.5, 0.5, 0.5 - r], [0.5 + r, 0.5, 0.5], [0.5, 0.5 + r, 0.5], [0.5, 0.5, 0.5 + r]]
    pulled = [list(p) for p in start]
    pulled[3][2] += 40 * 0.5 * h
    return scene(3, "drag_sphere", "The drag of amls bench (drag 200k, drag 1M) at 20,000 points: a sphere with three "
                 "fixed handles (the bottom and two on the equator) and one at the top pulled outwards by h/2 per step "
                 "for 40 steps.", {"type": "sphere", "center": centre, "radius": r, "points": points}, h,
                 [{"handles": rounded(start), "targets": [{"steps": 40, "handles": rounded(pulled)}]}])


def scene(dimension, name, description, shape, h, stages):
    """A scene with the settings every scene here shares: Delta = 3h, exact resampling, rigid MLS, alpha = 1."""
    return {
        "dimension": dimension,
        "name": name,
        "description": description + " Made by scripts/make_scenes.py.",
        "shape": shape,
        "grid": {"spacing": h},
        "radius_factor": 3.0,
        "variant": "exact",
        "deformation": {"kind": "rigid", "alpha": 1.0},
        "stages": stages,
    }


def main():
    os.makedirs(OUT, exist_ok=True)
    for name, scene in (("clover2d", clover2d()), ("clover3d", clover3d()), ("torus_tentacles", torus_tentacles()),
                         ("drag_sphere", drag_sphere())):
        path = os.path.join(OUT, name + ".json")
        text = json.dumps(scene, indent=2)
        # One line per point: [x, y] rather than a number per line.
        text = re.sub(r"\[\s*(-?[0-9.e+-]+(?:,\s*-?[0-9.e+-]+)*)\s*\]",
                      lambda m: "[" + ", ".join(x.strip() for x in m.group(1).split(",")) + "]", text)
        with open(path, "w") as f:
            f.write(text + "\n")
        print("wrote", os.path.relpath(path))


if __name__ == "__main__":
    main()

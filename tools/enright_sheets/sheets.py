#!/usr/bin/env python3
"""Where Enright's point set departs from the exact shape, frame by frame.

    sheets.py GRID FRAME.ply...   (frames of frames.cpp, named fKKK.ply: step KKK, t = 3 KKK / 300)

For each frame: the points; the sign changes of the exact shape's indicator
on the GRID^3 lattice around them (inside where a vertex carried back to
t = 0 by RK4 lies in the starting sphere), about twice the points that a
resampling of the exact shape on that grid would give; and the points
grouped by how far the nearest point of the sheet's other side (a normal
more than 120 degrees off) is, each group's share of points on the material
surface (carried back to t = 0, within 0.01 of the starting sphere, that is
h/1.56 at 64^3) and off it outward or inward, and the mean of F/h at the
group's own points (F of the frame's surface, as the next resample sees it,
by the amls module of build/python: negative where F's zero set lies outside
the points, where that resample moves them outward).
The flow runs backward after t = 1.5, so the shape at t is the one at 3 - t.
"""
import sys

import amls
import numpy as np

CENTER = np.array([0.35, 0.35, 0.35])
RADIUS = 0.15
ON_SURFACE = 0.01


def read_ply(path):
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().split("\n")
    count = int(next(line for line in header if line.startswith("element vertex")).split()[2])
    properties = [line.split() for line in header if line.startswith("property")]
    if any(p[1] != "double" for p in properties):
        sys.exit(f"{path}: expected double properties (frames.cpp writes them)")
    values = np.frombuffer(data[end:end + 8 * len(properties) * count], dtype="<f8").reshape(count, len(properties))
    return values[:, :3].copy(), values[:, 3:6].copy()


def velocity(x, t):
    amplitude = np.cos(np.pi * t / 3.0)
    s = np.sin(np.pi * x)
    s2 = np.sin(2.0 * np.pi * x)
    return amplitude * np.stack([2 * s[:, 0] ** 2 * s2[:, 1] * s2[:, 2],
                                 -s2[:, 0] * s[:, 1] ** 2 * s2[:, 2],
                                 -s2[:, 0] * s2[:, 1] * s[:, 2] ** 2], 1)


def carried_back(x, t, dt=0.0025):
    """x at time t carried back to t = 0 (RK4)."""
    t = min(t, 3.0 - t)
    steps = max(1, int(round(t / dt)))
    dt = t / steps
    for _ in range(steps):
        k1 = velocity(x, t)
        k2 = velocity(x - 0.5 * dt * k1, t - 0.5 * dt)
        k3 = velocity(x - 0.5 * dt * k2, t - 0.5 * dt)
        k4 = velocity(x - dt * k3, t - dt)
        x = x - dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)
        t -= dt
    return x


def offset_at_start(x, t):
    return np.linalg.norm(carried_back(x, t) - CENTER, axis=1) - RADIUS


def other_side_distance(points, normals, h, chunk=2000):
    out = np.empty(len(points))
    for s in range(0, len(points), chunk):
        d2 = ((points[s:s + chunk, None, :] - points[None]) ** 2).sum(-1)
        d2[(normals[s:s + chunk] @ normals.T) >= -0.5] = np.inf
        out[s:s + chunk] = np.sqrt(d2.min(1))
    return out / h


def exact_sign_changes(points, t, h):
    offsets = np.array([[i, j, k] for i in range(-3, 5) for j in range(-3, 5) for k in range(-3, 5)])
    vertices = np.unique((np.floor(points / h).astype(int)[:, None, :] + offsets[None]).reshape(-1, 3), axis=0)
    inside = dict(zip(map(tuple, vertices), offset_at_start(vertices * h, t) < 0.0))
    changes = 0
    for v, sign in inside.items():
        for axis in range(3):
            w = list(v)
            w[axis] += 1
            other = inside.get(tuple(w))
            changes += other is not None and other != sign
    return changes


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    h = 1.0 / int(sys.argv[1])
    for path in sys.argv[2:]:
        step = int(path[-7:-4])
        t = 3.0 * step / 300
        points, normals = read_ply(path)
        offset = offset_at_start(points, t)
        other = other_side_distance(points, normals, h)
        residual = np.asarray(amls.Surface(points, normals, h=h, threads=2).F(points)) / h
        print(f"t = {t:.2f}: {len(points)} points, {exact_sign_changes(points, t, h)} sign changes of the exact shape")
        for low, high in [(0, 1.5), (1.5, 2), (2, 3), (3, np.inf)]:
            group = (other >= low) & (other < high)
            if group.any():
                print(f"  other side in [{low}, {high}) h: {group.sum():5d} points, on the surface "
                      f"{np.mean(abs(offset[group]) < ON_SURFACE):.2f}, outward {np.mean(offset[group] >= ON_SURFACE):.2f}, "
                      f"inward {np.mean(offset[group] <= -ON_SURFACE):.2f}, F/h {np.nanmean(residual[group]):+.4f}")


if __name__ == "__main__":
    main()

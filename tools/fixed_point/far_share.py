#!/usr/bin/env python3
"""The share of the points of B farther than `factor` h from every point of A.

    far_share.py A.ply B.ply H [FACTOR]     (FACTOR: 0.75 by default)

A and B are amls outputs (binary little-endian PLY, double x y z first). Prints
the share as a percentage. Pure Python, no NumPy: a hash of cells as wide as
the distance asked for, so each point of B looks at 27 cells.
"""
import struct
import sys


def read_positions(path):
    with open(path, "rb") as f:
        count = 0
        properties = []
        while True:
            line = f.readline().decode("ascii", "replace").strip()
            if line.startswith("format") and "binary_little_endian" not in line:
                sys.exit(f"{path}: expected a binary little-endian PLY written by amls")
            if line.startswith("element vertex"):
                count = int(line.split()[2])
            elif line.startswith("property"):
                if line.split()[1] != "double":
                    sys.exit(f"{path}: expected double properties, got '{line}'")
                properties.append(line.split()[2])
            elif line == "end_header":
                break
            elif not line and f.tell() > 1 << 16:
                sys.exit(f"{path}: no end_header")
        if properties[:3] != ["x", "y", "z"]:
            sys.exit(f"{path}: expected x y z first, got {properties[:3]}")
        stride = 8 * len(properties)
        data = f.read(stride * count)
    if len(data) != stride * count:
        sys.exit(f"{path}: truncated")
    unpack = struct.Struct("<3d").unpack_from
    return [unpack(data, k * stride) for k in range(count)]


def far_share(a, b, distance):
    cells = {}
    for p in a:
        key = (int(p[0] // distance), int(p[1] // distance), int(p[2] // distance))
        cells.setdefault(key, []).append(p)
    limit2 = distance * distance
    far = 0
    for q in b:
        cx, cy, cz = int(q[0] // distance), int(q[1] // distance), int(q[2] // distance)
        near = False
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for p in cells.get((cx + dx, cy + dy, cz + dz), ()):
                        if (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2 <= limit2:
                            near = True
                            break
                    if near:
                        break
                if near:
                    break
            if near:
                break
        far += 0 if near else 1
    return 100.0 * far / max(len(b), 1)


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    h = float(sys.argv[3])
    factor = float(sys.argv[4]) if len(sys.argv) == 5 else 0.75
    print(f"{far_share(read_positions(sys.argv[1]), read_positions(sys.argv[2]), factor * h):.2f}")


if __name__ == "__main__":
    main()

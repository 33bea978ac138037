#!/usr/bin/env python3
"""The share of the points of B farther than `factor` h from every point of A.

    far_share.py A.ply B.ply H [FACTOR]     (FACTOR: 0.75 by default)

A and B are amls outputs (binary little-endian PLY, double x y z first; other
scalar properties, such as the rim mark, are skipped). Prints
the share as a percentage. Pure Python, no NumPy: a hash of cells as wide as
the distance asked for, so each point of B looks at 27 cells.
"""
import struct
import sys

# The bytes of each PLY scalar type (amls writes doubles, and a uchar rim mark).
SIZES = {"char": 1, "uchar": 1, "int8": 1, "uint8": 1, "short": 2, "ushort": 2, "int16": 2, "uint16": 2,
         "int": 4, "uint": 4, "int32": 4, "uint32": 4, "float": 4, "float32": 4, "double": 8, "float64": 8}


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
                kind, name = line.split()[1:3]
                if kind not in SIZES:
                    sys.exit(f"{path}: expected scalar properties, got '{line}'")
                properties.append((name, SIZES[kind]))
            elif line == "end_header":
                break
            elif not line and f.tell() > 1 << 16:
                sys.exit(f"{path}: no end_header")
        if properties[:3] != [("x", 8), ("y", 8), ("z", 8)]:
            sys.exit(f"{path}: expected double x y z first, got {properties[:3]}")
        stride = sum(size for _, size in properties)
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

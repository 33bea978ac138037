#!/usr/bin/env python3
"""off_to_obj.py IN.off OUT.obj: a triangle mesh from OFF (Geomview, CGAL) to OBJ.

Reads the header (OFF, optionally with the counts on the same line), the
vertices and the faces (polygons, written as they are: the OBJ reader
fan-triangulates them); '#' starts a comment. For the real-data tests, which
use CGAL's OFF meshes through a format the reader of the code under test knows.
"""
import sys


def tokens(path):
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0]
            yield from line.split()


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: off_to_obj.py IN.off OUT.obj")
    words = tokens(sys.argv[1])
    header = next(words)
    if header != "OFF":
        sys.exit(f"{sys.argv[1]}: expected an OFF header, got {header!r}")
    nv, nf = int(next(words)), int(next(words))
    next(words)  # edge count, unused
    with open(sys.argv[2], "w") as out:
        for _ in range(nv):
            out.write("v {} {} {}\n".format(next(words), next(words), next(words)))
        for _ in range(nf):
            n = int(next(words))
            corners = [int(next(words)) + 1 for _ in range(n)]
            out.write("f " + " ".join(map(str, corners)) + "\n")


if __name__ == "__main__":
    main()

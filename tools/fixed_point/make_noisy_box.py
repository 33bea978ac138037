#!/usr/bin/env python3
"""Writes a noisy open box: the bottom and four sides of a unit cube (no lid),
sampled on a jittered lattice of spacing 0.02 with outward normals, each point
moved along its normal by Gaussian noise. An open scan with sharp edges and a
rim, for tools/fixed_point/run.sh.

    make_noisy_box.py OUT.xyz [--noise SIGMA]   (SIGMA: 0.002 by default, a tenth of the spacing)
"""
import argparse
import random

STEP = 0.02


def box_points(noise, seed=1):
    rng = random.Random(seed)
    count = round(1.0 / STEP)
    faces = [  # (origin, u, v, outward normal): the bottom and the four sides
        ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, -1)),
        ((0, 0, 0), (1, 0, 0), (0, 0, 1), (0, -1, 0)),
        ((0, 1, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0)),
        ((1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 0, 0)),
    ]
    out = []
    for origin, u, v, n in faces:
        for i in range(count):
            for j in range(count):
                a = (i + 0.5 + rng.uniform(-0.3, 0.3)) * STEP
                b = (j + 0.5 + rng.uniform(-0.3, 0.3)) * STEP
                d = rng.gauss(0.0, noise)
                out.append(tuple(origin[k] + a * u[k] + b * v[k] + d * n[k] for k in range(3)) + n)
    return out


def main():
    parser = argparse.ArgumentParser(description="Writes a noisy open box with normals (.xyz).")
    parser.add_argument("out")
    parser.add_argument("--noise", type=float, default=0.1 * STEP, help="standard deviation along the normal")
    options = parser.parse_args()
    with open(options.out, "w") as f:
        for p in box_points(options.noise):
            f.write("%.10f %.10f %.10f %g %g %g\n" % p)


if __name__ == "__main__":
    main()

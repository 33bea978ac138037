#!/usr/bin/env python3
"""resample_check.py AMLS INPUT WORK_DIR [--scaled]: the real-data bars of `amls resample`.

Runs `amls resample INPUT --out ... --json ...` with no spacing option and fails
(exit 1, saying why) unless it exits 0, covers at least 99.5 % of the input,
puts at least 98 % of its output on the input and writes at most 10 points per
point (a mesh: vertex) of the file. Prints the report's figures for the log.

--scaled: also resamples a copy of the point set (XYZ) in other units and
elsewhere (x 1000, shifted by 10^4 on every axis) and fails unless the output is
the same up to that scale and shift: h x 1000, the same number of points and
the same coverage counts, and every point (but one in a thousand, moved to a
neighbouring edge by rounding) within 10^-6 h of the original's.
"""
import json
import os
import subprocess
import sys
import time

SCALE = 1000.0
SHIFT = 1.0e4


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def resample(amls, path, out, report):
    start = time.monotonic()
    run = subprocess.run([amls, "resample", path, "--out", out, "--json", report, "--threads", "2"],
                         capture_output=True, text=True)
    seconds = time.monotonic() - start
    print(run.stdout + run.stderr, end="")
    if run.returncode != 0:
        fail(f"amls resample {path} exited with {run.returncode}")
    with open(report) as f:
        r = json.load(f)
    cov = r["coverage"]
    print(f"{os.path.basename(path)}: {r['file_points']} points in the file, {r['points_out']} out, "
          f"h = {r['h']:.6g}, input covered {100 * cov['input_covered']:.2f} %, output on the input "
          f"{100 * cov['output_on_input']:.2f} %, {seconds:.1f} s, peak {r['peak_memory_mib']:.0f} MiB")
    return r


def check_bars(r):
    cov = r["coverage"]
    if cov["input_covered"] < 0.995:
        fail(f"only {100 * cov['input_covered']:.2f} % of the input covered (bar: 99.5 %)")
    if cov["output_on_input"] < 0.98:
        fail(f"only {100 * cov['output_on_input']:.2f} % of the output on the input (bar: 98 %)")
    if r["points_out"] > 10 * r["file_points"]:
        fail(f"{r['points_out']} points out for {r['file_points']} in (bar: at most 10 x)")


def read_xyz(path):
    points = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                points.append(tuple(float(v) for v in line[:3]))
    return points


def nearest_distances(points, others, cell):
    """Each point's distance to the nearest of `others` (searched within 2 cells; farther counts as infinite)."""
    buckets = {}
    for q in others:
        buckets.setdefault(tuple(int(v // cell) for v in q), []).append(q)
    out = []
    for p in points:
        c = tuple(int(v // cell) for v in p)
        best = float("inf")
        for dx in range(-2, 3):
            for dy in range(-2, 3):
                for dz in range(-2, 3):
                    for q in buckets.get((c[0] + dx, c[1] + dy, c[2] + dz), ()):
                        best = min(best, sum((x - y) ** 2 for x, y in zip(p, q)) ** 0.5)
        out.append(best)
    return out


def check_scaled(amls, path, work, original):
    scaled = os.path.join(work, "scaled.xyz")
    with open(path) as f, open(scaled, "w") as out:
        for line in f:
            values = line.split()
            if not values or values[0].startswith("#"):
                continue
            position = [repr(SCALE * float(v) + SHIFT) for v in values[:3]]
            out.write(" ".join(position + values[3:6]) + "\n")
    r = resample(amls, scaled, os.path.join(work, "scaled_out.xyz"), os.path.join(work, "scaled.json"))
    if abs(r["h"] / (SCALE * original["h"]) - 1.0) > 1e-9:
        fail(f"h in the scaled copy is {r['h']}, expected {SCALE} x {original['h']}")
    for key in ("points_out",):
        if r[key] != original[key]:
            fail(f"{key}: {r[key]} in the scaled copy, {original[key]} in the original")
    for key in ("input_uncovered_points", "output_off_points"):
        if r["coverage"][key] != original["coverage"][key]:
            fail(f"coverage {key}: {r['coverage'][key]} in the scaled copy, {original['coverage'][key]} in the original")
    h = original["h"]
    a = read_xyz(os.path.join(work, "out.xyz"))
    b = [tuple((v - SHIFT) / SCALE for v in p) for p in read_xyz(os.path.join(work, "scaled_out.xyz"))]
    distances = nearest_distances(b, a, h)
    moved = [d for d in distances if d > 1e-6 * h]
    # Rounding may flip F's sign at a vertex where F is within rounding of 0, moving a
    # point to a neighbouring edge: allow that for one point in a thousand, by less than 2 h.
    if len(moved) > len(b) // 1000 or (moved and max(moved) > 2 * h):
        fail(f"{len(moved)} of the scaled copy's {len(b)} points, mapped back, are more than 1e-6 h from the "
             f"original's (the farthest by {max(moved) / h:.3g} h)")
    print(f"scaled x{SCALE:g} and shifted by {SHIFT:g}: the same output; {len(b) - len(moved)} of {len(b)} points "
          f"within 1e-6 h of the original's, {len(moved)} moved to a neighbouring edge")


def main():
    args = [a for a in sys.argv[1:] if a != "--scaled"]
    if len(args) != 3:
        sys.exit(__doc__)
    amls, path, work = args
    os.makedirs(work, exist_ok=True)
    r = resample(amls, path, os.path.join(work, "out.xyz"), os.path.join(work, "report.json"))
    check_bars(r)
    if "--scaled" in sys.argv:
        check_scaled(amls, path, work, r)
    print("PASS")


if __name__ == "__main__":
    main()

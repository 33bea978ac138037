#!/usr/bin/env python3
"""resample_command_test.py AMLS WORK_DIR: `amls resample`'s choices and refusals, end to end.

On small generated 2D point sets (a circle of points with normals):
- with no spacing option, h is the rule's and is printed with its reason, the
  coverage is printed and in the JSON, and the command exits 0;
- a far part 12 x sparser is closed by the widened supports, with a second
  pass at h (one with --one-pass, and on the dense circle alone); with
  --uniform-support it is lost at the dense part's h, exits 1 naming the
  loss, and --accept-loss exits 0 with a warning, writing the same file;
- an h whose output would pass the point limit is refused before any work,
  naming a spacing that fits, and that spacing then runs;
- an open arc keeps its ends, and --rims off extends them past the input's.
"""
import json
import math
import os
import re
import subprocess
import sys


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def circle(cx, cy, r, n):
    lines = []
    for i in range(n):
        a = 2 * math.pi * i / n
        lines.append(f"{cx + r * math.cos(a)!r} {cy + r * math.sin(a)!r} 0 {math.cos(a)!r} {math.sin(a)!r} 0")
    return lines


def run(amls, *args):
    r = subprocess.run([amls, "resample", *args], capture_output=True, text=True)
    return r.returncode, r.stdout, r.stderr


def main():
    amls, work = sys.argv[1:3]
    os.makedirs(work, exist_ok=True)
    dense = os.path.join(work, "dense.xyz")
    with open(dense, "w") as f:
        f.write("\n".join(circle(3.0, 3.0, 1.0, 400)) + "\n")
    report = os.path.join(work, "dense.json")
    code, out, err = run(amls, dense, "--dim", "2", "--out", os.path.join(work, "dense_out.xyz"), "--json", report)
    if code != 0:
        fail(f"the dense circle exited {code}:\n{out}{err}")
    step = 2 * math.pi / 400
    m = re.search(r"^h = ([0-9.e+-]+) \(the median distance from each of the 400 points to its 4th nearest neighbour",
                  out, re.M)
    if not m or abs(float(m.group(1)) / step - 1) > 1e-3:
        fail(f"expected h = the circle's step {step} with the rule's reason, got:\n{out}")
    if "coverage: 100.00 % of the 400 input points covered" not in out:
        fail(f"expected the coverage line, got:\n{out}")
    with open(report) as f:
        r = json.load(f)
    if r["coverage"]["input_covered"] != 1.0 or r["coverage"]["clear_loss"]:
        fail(f"the JSON's coverage: {r['coverage']}")

    both = os.path.join(work, "both.xyz")
    with open(both, "w") as f:
        f.write("\n".join(circle(3.0, 3.0, 1.0, 400) + circle(9.0, 3.0, 0.3, 10)) + "\n")
    lost = os.path.join(work, "both_out.xyz")
    # The small circle is 12 x sparser than the large one: its points' supports
    # are widened (4 Delta) and close it.
    code, out, err = run(amls, both, "--dim", "2", "--out", lost)
    if (code != 0 or "widened at 10 of 410 points" not in out
            or "coverage: 100.00 % of the 410 input points covered" not in out):
        fail(f"a sparse part: expected widened supports to close it, got {code}:\n{out}{err}")
    # 10 of 410 points widened (over 1 %): a second pass at h, which --one-pass leaves out; the
    # first pass is the same either way, and the dense circle alone makes one.
    if r["passes"] != 1 or r["first_pass_points"] != r["points_out"]:
        fail(f"the dense circle: expected one pass, got {r['passes']} ({r['first_pass_points']} first)")
    passes = {}
    for extra in ([], ["--one-pass"]):
        json_path = os.path.join(work, f"both{len(extra)}.json")
        code, out, err = run(amls, both, "--dim", "2", "--out", lost, "--json", json_path, *extra)
        if code != 0 or ("second pass: the first pass's" in out) == bool(extra):
            fail(f"passes with {extra}: expected exit 0 and the second pass's line only without --one-pass, "
                 f"got {code}:\n{out}{err}")
        with open(json_path) as f:
            passes[bool(extra)] = json.load(f)
    if passes[False]["passes"] != 2 or passes[True]["passes"] != 1:
        fail(f"passes: expected 2 by default and 1 with --one-pass, got {passes[False]['passes']}, "
             f"{passes[True]['passes']}")
    if passes[False]["first_pass_points"] != passes[True]["points_out"]:
        fail(f"the first pass's points ({passes[False]['first_pass_points']}) are not --one-pass's output "
             f"({passes[True]['points_out']})")
    # With one Delta for all it is lost.
    code, out, err = run(amls, both, "--dim", "2", "--out", lost, "--uniform-support")
    if code != 1 or "the output misses part of the input: 10 of 410 input points" not in err:
        fail(f"a lost part: expected exit 1 naming 10 of 410 points, got {code}:\n{out}{err}")
    if not os.path.exists(lost):
        fail("a lost part: the output was not kept for inspection")
    code, out, err = run(amls, both, "--dim", "2", "--out", lost, "--uniform-support", "--accept-loss")
    if code != 0 or "(accepted: --accept-loss)" not in err:
        fail(f"--accept-loss: expected exit 0 with a warning, got {code}:\n{out}{err}")

    code, out, err = run(amls, dense, "--dim", "2", "--out", os.path.join(work, "x.xyz"), "--spacing", "1e-9")
    m = re.search(r"more than the limit of .*; --spacing ([0-9.e+-]+) or larger would fit", err)
    if code != 1 or not m:
        fail(f"a tiny --spacing: expected a refusal naming a spacing, got {code}:\n{out}{err}")
    code, out, err = run(amls, dense, "--dim", "2", "--out", os.path.join(work, "x.xyz"), "--spacing", m.group(1))
    if "more than the limit" in err:
        fail(f"the named --spacing {m.group(1)} is refused too:\n{err}")

    # An open arc (half the circle) keeps its ends; --rims off extends them, as the paper's resampler does.
    arc = os.path.join(work, "arc.xyz")
    with open(arc, "w") as f:
        f.write("\n".join(circle(3.0, 3.0, 1.0, 400)[:201]) + "\n")
    reach = {}
    for rims in ("on", "off"):
        kept = os.path.join(work, f"arc_{rims}.xyz")
        code, out, err = run(amls, arc, "--dim", "2", "--out", kept, "--rims", rims)
        if code != 0 or (rims == "on") != ("rim: " in out):
            fail(f"--rims {rims}: expected exit 0 and the rim line only with rims kept, got {code}:\n{out}{err}")
        with open(kept) as f:
            points = [(float(x) - 3.0, float(y) - 3.0) for x, y, *_ in (l.split() for l in f if not l.startswith("#"))]
        # The angle from the arc's middle (straight up), less the arc's half: past its ends, in h (h = step).
        reach[rims] = max(abs(math.atan2(x, y)) - 0.5 * math.pi for x, y in points) / step
    if not (reach["on"] < 0.5 and reach["off"] > 1.0):
        fail(f"the arc's ends past the input's, in h: expected under 0.5 with rims, over 1 without, got {reach}")
    code, out, err = run(amls, arc, "--dim", "2", "--out", os.path.join(work, "x.xyz"), "--rims", "maybe")
    if code == 0 or "--rims" not in out + err:
        fail(f"--rims maybe: expected a refusal naming the option, got {code}:\n{out}{err}")

    # A circle whose normals point outward on one half and inward on the other (unoriented): with
    # --normals estimated the file's normals are set aside, and the output is that of the bare points.
    halves, bare = os.path.join(work, "halves.xyz"), os.path.join(work, "bare.xyz")
    rows = [line.split() for line in circle(3.0, 3.0, 1.0, 400)]
    with open(halves, "w") as f:
        for x, y, _, nx, ny, _ in rows:
            sign = 1.0 if float(x) >= 3.0 else -1.0
            f.write(f"{x} {y} {sign * float(nx)!r} {sign * float(ny)!r}\n")
    with open(bare, "w") as f:
        f.write("".join(f"{x} {y}\n" for x, y, *_ in rows))
    outputs = {}
    for name, source, extra in (("set_aside", halves, ["--normals", "estimated"]), ("bare", bare, [])):
        outputs[name] = os.path.join(work, f"{name}_out.xyz")
        code, out, err = run(amls, source, "--dim", "2", "--out", outputs[name], *extra)
        if code != 0:
            fail(f"{name}: expected exit 0, got {code}:\n{out}{err}")
        if name == "set_aside" and "with normals, set aside" not in out:
            fail(f"--normals estimated: expected the source line to say the normals were set aside:\n{out}")
    with open(outputs["set_aside"]) as a, open(outputs["bare"]) as b:
        if a.read() != b.read():
            fail("--normals estimated: expected the output of the same points without normals")
    code, out, err = run(amls, halves, "--dim", "2", "--out", os.path.join(work, "x.xyz"), "--normals", "flipped")
    if code == 0 or "--normals" not in out + err:
        fail(f"--normals flipped: expected a refusal naming the option, got {code}:\n{out}{err}")
    print("PASS")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Ctrl+C ends every long command promptly and cleanly.

    interrupt_test.py AMLS SCENE3D WORK_DIR

Each case starts a command that runs for many seconds, waits until it is at
work, sends SIGINT and checks that the process ends within a second with exit
status 130, says it was interrupted, and leaves none of its output files (nor
a DIR.partial). Prints one line per case; exits 1 on the first failure.
"""
import os
import shutil
import signal
import subprocess
import sys
import time

# The time a case is given to get to its main work before the signal (unless
# it says otherwise), and the time it then has to end.
START_SECONDS = 2.0
STOP_SECONDS = 1.0


def sphere_xyz(path, count):
    """A sphere of radius 0.3 at (0.5, 0.5, 0.5) with outward normals (Fibonacci lattice)."""
    import math
    golden = math.pi * (3.0 - math.sqrt(5.0))
    with open(path, "w") as out:
        for i in range(count):
            z = 1.0 - 2.0 * (i + 0.5) / count
            r = math.sqrt(1.0 - z * z)
            x, y = r * math.cos(golden * i), r * math.sin(golden * i)
            out.write(f"{0.5 + 0.3 * x:.9f} {0.5 + 0.3 * y:.9f} {0.5 + 0.3 * z:.9f} {x:.9f} {y:.9f} {z:.9f}\n")


def run_case(name, command, outputs, work, start_seconds):
    log_path = os.path.join(work, name + ".log")
    with open(log_path, "w") as log:
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT)
        time.sleep(start_seconds)
        if process.poll() is not None:
            return f"ended before the signal (status {process.returncode}); the case is too short:\n" + open(log_path).read()
        sent = time.monotonic()
        process.send_signal(signal.SIGINT)
        try:
            status = process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()
            return "still running 30 s after SIGINT"
        elapsed = time.monotonic() - sent
    text = open(log_path).read()
    problems = []
    if status != 130:
        problems.append(f"exit status {status}, expected 130")
    if "amls: interrupted" not in text:
        problems.append("no 'amls: interrupted' message")
    if elapsed > STOP_SECONDS:
        problems.append(f"took {elapsed:.2f} s to stop, more than {STOP_SECONDS} s")
    for path in outputs:
        for leftover in (path, path + ".partial"):
            if os.path.exists(leftover):
                problems.append(f"left {leftover}")
    if problems:
        return "; ".join(problems) + "\noutput:\n" + text
    print(f"{name}: stopped {elapsed:.2f} s after SIGINT, status 130, no output")
    return None


def main():
    amls, scene3d, work = sys.argv[1:4]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    sphere = os.path.join(work, "sphere.xyz")
    sphere_xyz(sphere, 20000)
    out = lambda name: os.path.join(work, name)
    cases = [
        ("vortex", ["vortex", "--grid", "2048", "--out", out("vortex.ply"), "--json", out("vortex.json")],
         [out("vortex.ply"), out("vortex.json")]),
        ("enright", ["enright", "--grid", "128", "--out", out("enright.ply"), "--json", out("enright.json")],
         [out("enright.ply"), out("enright.json")]),
        ("deform", ["deform", scene3d, "--out-dir", out("frames"), "--json", out("deform.json")],
         [out("frames"), out("deform.json")]),
        # A scan resampled densely with a very wide support: about 4 s on a quiet machine, most of it in
        # the resampler's polled loops, after a serial set-up (reading, hashing, clearing the vertex
        # values) that takes up to about a second; the signal comes 2.5 s in.
        ("resample", ["resample", sphere, "--grid", "512", "--radius-factor", "32", "--out", out("resampled.ply")],
         [out("resampled.ply")], 2.5),
        ("bench", ["bench", "--only", "Enright", "--json", out("bench.json")], [out("bench.json")]),
        ("render", ["render", scene3d, "--step", "last", "--out", out("render.png")], [out("render.png")]),
    ]
    for name, arguments, outputs, *start in cases:
        problem = run_case(name, [amls] + arguments, outputs, work, start[0] if start else START_SECONDS)
        if problem:
            print(f"{name}: {problem}")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

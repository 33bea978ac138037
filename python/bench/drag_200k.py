#!/usr/bin/env python3
"""The Python drag loop against `amls deform` on the same scene: 40 drag steps on a 200k-point sphere.

    /usr/bin/python3 python/bench/drag_200k.py [--amls build/app/amls] [--threads 1] [--points 200000]
                                               [--steps 40] [--repeats 1] [--work DIR]

The scene is the drag of `amls bench` ("drag 200k"): a sphere of radius 0.3 sampled so that h =
sqrt(0.83 * 4 pi r^2 / N) gives about N points, four handles (three fixed, the top one pulled out
by h/2 a step), rigid MLS maps, resampled every step (`--resample always`). Its shape is a file of
N Fibonacci-lattice points with normals, which both sides open the same way.

Measured, each side in its own process on the same input:
- amls deform SCENE --tracers 1 --json: the whole process, and the report's surface work
  (timings_s.total: the loop's phases, without the tracers, spacing measures and distances);
- Python: Surface(...) then `steps` calls of surface.step(deformation, targets) and a final
  surface.resample(), the scene's final frame: the whole script part, and the loop alone.
Prints both and their ratios, and whether the final points are the same. Not a test: timings on a
shared machine vary; it asserts nothing about them.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE_DIR = os.path.abspath(os.path.join(HERE, "..", ".."))
HANDLES = [[0.5, 0.5, 0.2], [0.8, 0.5, 0.5], [0.5, 0.8, 0.5], [0.5, 0.5, 0.8]]


def sphere(count, radius=0.3):
    i = np.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    r = np.sqrt(1.0 - z * z)
    phi = math.pi * (3.0 - math.sqrt(5.0)) * np.arange(count)
    normals = np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)
    return 0.5 + radius * normals, normals


def targets(h, step, steps):
    """The handles after `step` of `steps`: the top one pulled out by h/2 a step, computed as the
    scene computes them, (1 - t) start + t end, so that both sides map by the same doubles."""
    start = np.array(HANDLES)
    end = start.copy()
    end[3, 2] += 0.5 * h * steps
    t = step / steps
    return (1.0 - t) * start + t * end


PYTHON_SIDE = r"""
import json, sys, time
import numpy as np
import amls
sys.path.insert(0, {here!r})
from drag_200k import targets
args = json.loads(sys.argv[1])
start = time.perf_counter()
points, normals = amls.read(args["shape"])
surface = amls.Surface(points, normals, h=args["h"], uniform_support=True, threads=args["threads"])
deformation = amls.MlsDeformation(np.array(args["handles"]), kind="rigid")
loop_start = time.perf_counter()
surface_seconds = 0.0
for step in range(1, args["steps"] + 1):
    surface_seconds += surface.step(deformation, targets(args["h"], step, args["steps"]))["timings_s"]["total"]
surface_seconds += surface.resample()["timings_s"]["total"]
end = time.perf_counter()
amls.write(args["out"], surface.points, surface.normals)
print(json.dumps({{"whole": end - start, "loop": end - loop_start, "surface": surface_seconds,
                  "points": len(surface.points)}}))
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amls", default=os.path.join(SOURCE_DIR, "build", "app", "amls"))
    parser.add_argument("--threads", type=int, default=1)
    parser.add_argument("--points", type=int, default=200000)
    parser.add_argument("--steps", type=int, default=40)
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--work", default=None)
    args = parser.parse_args()
    work = args.work or tempfile.mkdtemp(prefix="amls_drag_")
    os.makedirs(work, exist_ok=True)
    env = dict(os.environ)
    env["PYTHONPATH"] = os.path.join(SOURCE_DIR, "build", "python") + os.pathsep + env.get("PYTHONPATH", "")
    sys.path.insert(0, env["PYTHONPATH"].split(os.pathsep)[0])
    import amls

    h = math.sqrt(0.83 * 4.0 * math.pi * 0.3 * 0.3 / args.points)
    shape = os.path.join(work, "sphere.ply")
    amls.write(shape, *sphere(args.points))
    scene_path = os.path.join(work, "drag.json")
    with open(scene_path, "w") as f:
        json.dump({"dimension": 3, "name": "drag_python_bench",
                   "shape": {"type": "file", "path": "sphere.ply"}, "grid": {"spacing": h},
                   "radius_factor": 3.0, "variant": "exact", "deformation": {"kind": "rigid", "alpha": 1.0},
                   "stages": [{"handles": HANDLES,
                               "targets": [{"steps": args.steps, "handles": targets(h, args.steps, args.steps).tolist()}]}]}, f)

    print(f"{args.points} points on the sphere, h = {h:.6g}, {args.steps} steps, {args.threads} thread(s)")
    rows = []
    for repeat in range(args.repeats):
        report_path = os.path.join(work, "report.json")
        start = time.perf_counter()
        subprocess.run([args.amls, "deform", scene_path, "--tracers", "1", "--threads", str(args.threads),
                        "--json", report_path, "--out-dir", os.path.join(work, f"frames{repeat}"),
                        "--frames-every", str(args.steps)], check=True, stdout=subprocess.DEVNULL)
        cli_whole = time.perf_counter() - start
        with open(report_path) as f:
            report = json.load(f)
        cli_surface = report["timings_s"]["total"]
        side = {"shape": shape, "h": h, "threads": args.threads, "steps": args.steps, "handles": HANDLES,
                "out": os.path.join(work, "python_final.ply")}
        out = subprocess.run([sys.executable, "-c", PYTHON_SIDE.format(here=HERE), json.dumps(side)], check=True,
                             env=env, capture_output=True, text=True)
        py = json.loads(out.stdout.strip().splitlines()[-1])
        frames = sorted(os.listdir(os.path.join(work, f"frames{repeat}")))
        last = [n for n in frames if n.startswith("frame_")][-1]
        cli_points = amls.read(os.path.join(work, f"frames{repeat}", last))[0]
        same = np.array_equal(cli_points, amls.read(side["out"])[0])
        rows.append((cli_whole, cli_surface, py["whole"], py["loop"], py["surface"]))
        print(f"run {repeat + 1}: amls deform {cli_whole:.2f} s in all, {cli_surface:.2f} s surface work "
              f"({report['points_final']} points); Python {py['whole']:.2f} s in all, loop {py['loop']:.2f} s, "
              f"surface work {py['surface']:.2f} s ({py['points']} points); final points the same: {same}")
    cli_whole, cli_surface, py_whole, py_loop, py_surface = (min(column) for column in zip(*rows))
    print(f"best of {len(rows)}: Python loop / amls deform's surface work = {py_loop / cli_surface:.3f}; "
          f"Python loop / its own surface work = {py_loop / py_surface:.3f}; "
          f"Python script / amls deform process = {py_whole / cli_whole:.3f}")


if __name__ == "__main__":
    main()

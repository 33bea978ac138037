#!/usr/bin/env python3
"""Every mesh `amls resample --mesh` writes for CGAL's demo data, checked by Open3D.

    /usr/bin/python3 python/checks/cgal_watertight.py [--amls build/app/amls] [--data DIR]
        [--work DIR] [--threads 2] [--only TEXT ...] [--timeout 600]

For each file of DIR/points_3 and DIR/meshes (CGAL's demo data; the test fixture unpacks it into
build/cgal_data/data): `amls resample FILE --out ... --mesh m.ply --accept-loss`, then, where amls
says the mesh is closed, Open3D's verdict on it: is_watertight() (edge- and vertex-manifold, no
self-intersection; the last run cell by cell, open3d_watertight.py) and the number of crossing
triangle pairs. Prints one line per file and a summary; exits 1 when a mesh amls calls closed is
not watertight to Open3D. Files amls refuses (no h, too many points) or that take longer than
--timeout are listed, not counted.
"""
import argparse
import os
import re
import subprocess
import sys
import time

import open3d as o3d

from open3d_watertight import crossing_pairs

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amls", default=os.path.join(SOURCE_DIR, "build", "app", "amls"))
    parser.add_argument("--data", default=os.path.join(SOURCE_DIR, "build", "cgal_data", "data"))
    parser.add_argument("--work", default="/tmp/amls_cgal_watertight")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", nargs="*", default=[])
    parser.add_argument("--timeout", type=float, default=600.0)
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    files = [os.path.join(folder, name) for folder in ("points_3", "meshes")
             for name in sorted(os.listdir(os.path.join(args.data, folder)))]
    if args.only:
        files = [f for f in files if any(text in f for text in args.only)]
    closed = watertight = 0
    failures, skipped = [], []
    for relative in files:
        name = relative.replace("/", "_")
        out, mesh_path = os.path.join(args.work, name + ".out.ply"), os.path.join(args.work, name + ".mesh.ply")
        start = time.monotonic()
        try:
            run = subprocess.run([args.amls, "resample", os.path.join(args.data, relative), "--out", out, "--mesh",
                                  mesh_path, "--accept-loss", "--threads", str(args.threads)],
                                 capture_output=True, text=True, timeout=args.timeout)
        except subprocess.TimeoutExpired:
            skipped.append(f"{relative}: amls took longer than {args.timeout:.0f} s")
            print(f"{relative}: skipped (timeout)", flush=True)
            continue
        if run.returncode != 0:
            reason = (run.stderr.strip().splitlines() or ["?"])[-1]
            skipped.append(f"{relative}: {reason}")
            print(f"{relative}: amls refused: {reason}", flush=True)
            continue
        summary = re.search(r"^mesh: (.*), wrote", run.stdout, re.MULTILINE)
        summary = summary.group(1) if summary else "?"
        if not summary.endswith("closed"):
            print(f"{relative}: {summary} (not closed: not checked)", flush=True)
            continue
        closed += 1
        mesh = o3d.io.read_triangle_mesh(mesh_path)
        crossing = len(crossing_pairs(mesh))
        ok = mesh.is_edge_manifold(allow_boundary_edges=False) and mesh.is_vertex_manifold() and crossing == 0
        watertight += ok
        if not ok:
            failures.append(relative)
        print(f"{relative}: {summary}; Open3D: {'watertight' if ok else 'NOT watertight'}, {crossing} crossing "
              f"pairs, edge-manifold {mesh.is_edge_manifold(allow_boundary_edges=False)}, vertex-manifold "
              f"{mesh.is_vertex_manifold()} ({time.monotonic() - start:.1f} s)", flush=True)
    print(f"\n{closed} closed meshes, {watertight} watertight to Open3D; {len(skipped)} files skipped")
    for line in skipped:
        print("  skipped: " + line)
    for relative in failures:
        print("  NOT watertight: " + relative)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

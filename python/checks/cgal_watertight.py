#!/usr/bin/env python3
"""Every mesh `amls resample --mesh` writes for CGAL's demo data, checked by Open3D.

    /usr/bin/python3 python/checks/cgal_watertight.py [--amls build/app/amls] [--data DIR]
        [--work DIR] [--threads 2] [--only TEXT ...] [--timeout 120]

For each file of DIR/points_3 and DIR/meshes (CGAL's demo data; the test fixture unpacks it into
build/cgal_data/data): `amls resample FILE --out ... --mesh m.ply --accept-loss`, then, where amls
says the mesh is closed, Open3D's verdict on it: is_watertight() (edge- and vertex-manifold, no
self-intersection; the last run cell by cell, open3d_watertight.py), the number of crossing
triangle pairs (and how many of them exact arithmetic proves apart:
open3d_watertight.apart_exactly), the Euler characteristic and, for an input mesh Open3D finds watertight, the
enclosed volume against the input's. Prints one line per file (with amls's and the check's
seconds) and a summary that names every file not checked and why: amls refused it, took longer
than --timeout, or wrote an open mesh (an open scan's). Exits 1 when a mesh amls calls closed is
not watertight to Open3D.
"""
import argparse
import os
import re
import subprocess
import sys
import time

import numpy as np
import open3d as o3d

from open3d_watertight import apart_exactly, crossing_pairs

SOURCE_DIR = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
MESH_EXTENSIONS = (".off", ".obj", ".stl")


def enclosed_volume(mesh):
    """The signed volume a closed, outward-oriented triangle mesh encloses (divergence theorem)."""
    corners = np.asarray(mesh.vertices)[np.asarray(mesh.triangles)]
    return float(np.einsum("ij,ij->i", corners[:, 0], np.cross(corners[:, 1], corners[:, 2])).sum()) / 6.0


def input_volume(path):
    """The input mesh's enclosed volume where Open3D reads it as a watertight mesh, else None."""
    if not path.endswith(MESH_EXTENSIONS):
        return None
    mesh = o3d.io.read_triangle_mesh(path)
    if len(mesh.triangles) == 0 or not mesh.is_edge_manifold(allow_boundary_edges=False):
        return None
    return abs(enclosed_volume(mesh))


def check(path, mesh_path):
    """Open3D's verdict on one closed mesh, as (watertight, line)."""
    mesh = o3d.io.read_triangle_mesh(mesh_path)
    pairs = crossing_pairs(mesh)
    crossing = len(pairs)
    edge_manifold = mesh.is_edge_manifold(allow_boundary_edges=False)
    vertex_manifold = mesh.is_vertex_manifold()
    ok = edge_manifold and vertex_manifold and crossing == 0
    apart = f" ({sum(apart_exactly(mesh, pair) for pair in pairs)} of them apart in exact arithmetic)" if pairs else ""
    line = (f"Open3D: {'watertight' if ok else 'NOT watertight'}, {crossing} crossing pairs{apart}, edge-manifold "
            f"{edge_manifold}, vertex-manifold {vertex_manifold}, Euler {mesh.euler_poincare_characteristic()}")
    reference = input_volume(path)
    if reference:
        line += f", volume {100.0 * (enclosed_volume(mesh) / reference - 1.0):+.3f} % of the input's"
    return ok, line


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--amls", default=os.path.join(SOURCE_DIR, "build", "app", "amls"))
    parser.add_argument("--data", default=os.path.join(SOURCE_DIR, "build", "cgal_data", "data"))
    parser.add_argument("--work", default="/tmp/amls_cgal_watertight")
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--only", nargs="*", default=[])
    parser.add_argument("--timeout", type=float, default=120.0, help="seconds amls may take on one file")
    args = parser.parse_args()
    os.makedirs(args.work, exist_ok=True)
    files = [os.path.join(folder, name) for folder in ("points_3", "meshes")
             for name in sorted(os.listdir(os.path.join(args.data, folder)))]
    if args.only:
        files = [f for f in files if any(text in f for text in args.only)]
    closed = watertight = 0
    failures, refused, timed_out, open_meshes = [], [], [], []
    sweep_start = time.monotonic()
    for relative in files:
        name = relative.replace("/", "_")
        path = os.path.join(args.data, relative)
        out, mesh_path = os.path.join(args.work, name + ".out.ply"), os.path.join(args.work, name + ".mesh.ply")
        start = time.monotonic()
        try:
            run = subprocess.run([args.amls, "resample", path, "--out", out, "--mesh", mesh_path, "--accept-loss",
                                  "--threads", str(args.threads)], capture_output=True, text=True,
                                 timeout=args.timeout)
        except subprocess.TimeoutExpired:
            timed_out.append(relative)
            print(f"{relative}: TIMEOUT (amls took longer than {args.timeout:.0f} s)", flush=True)
            continue
        amls_seconds = time.monotonic() - start
        if run.returncode != 0:
            reason = (run.stderr.strip().splitlines() or ["?"])[-1]
            refused.append(f"{relative}: {reason}")
            print(f"{relative}: amls refused: {reason}", flush=True)
            continue
        summary = re.search(r"^mesh: (.*), wrote", run.stdout, re.MULTILINE)
        summary = summary.group(1) if summary else "?"
        if not summary.endswith("closed"):
            open_meshes.append(f"{relative}: {summary}")
            print(f"{relative}: {summary} (not closed: not checked; amls {amls_seconds:.1f} s)", flush=True)
            continue
        closed += 1
        ok, line = check(path, mesh_path)
        watertight += ok
        if not ok:
            failures.append(relative)
        print(f"{relative}: {summary}; {line} (amls {amls_seconds:.1f} s, check "
              f"{time.monotonic() - start - amls_seconds:.1f} s)", flush=True)
    print(f"\n{len(files)} files in {time.monotonic() - sweep_start:.0f} s: {closed} closed meshes, {watertight} "
          f"watertight to Open3D; {len(open_meshes)} open meshes (not checked), {len(refused)} refused by amls, "
          f"{len(timed_out)} over the {args.timeout:.0f} s limit")
    for relative in timed_out:
        print("  timeout: " + relative)
    for line in refused:
        print("  refused: " + line)
    for line in open_meshes:
        print("  open: " + line)
    for relative in failures:
        print("  NOT watertight: " + relative)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

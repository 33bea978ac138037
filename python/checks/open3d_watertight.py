"""Open3D's watertightness test, made fast enough for meshes of 10^5 triangles and more.

Open3D's TriangleMesh.is_watertight() is is_edge_manifold(False) and is_vertex_manifold() and not
is_self_intersecting(); the last compares every pair of triangles, O(n^2): 7 minutes for the
kitten's 141,808 triangles here. Two triangles can only cross where their bounding boxes overlap,
so the same Open3D pair test, run on the triangles of each cell of a coarse grid (every triangle in
each cell its box touches, the vertex array shared, so pairs are judged exactly as on the whole
mesh), finds the same crossing pairs in seconds. tests/test_open3d_interop.py checks that the two
agree on a mesh small enough for the whole test.
"""
from fractions import Fraction

import numpy as np
import open3d as o3d


def crossing_pairs(mesh, triangles_per_cell=400):
    """The pairs (i, j), i < j, of triangles that Open3D finds crossing, as a sorted list."""
    vertices = np.asarray(mesh.vertices)
    triangles = np.asarray(mesh.triangles)
    if len(triangles) < 2:
        return []
    corners = vertices[triangles]
    lo, hi = corners.min(axis=1), corners.max(axis=1)
    extent = hi - lo
    # Cells at least as wide as any triangle's box, so that a box touches at most 2 cells a side.
    typical = float(np.median(extent.max(axis=1)))
    cell = max(float(extent.max()) * 1.0001, typical * np.sqrt(triangles_per_cell / 2.0), 1e-300)
    origin = lo.min(axis=0)
    first = np.floor((lo - origin) / cell).astype(np.int64)
    last = np.floor((hi - origin) / cell).astype(np.int64)
    keys, owners = [], []
    for offset in np.ndindex(2, 2, 2):
        offset = np.array(offset)
        touches = np.all(first + offset <= last, axis=1)
        cells = first[touches] + offset
        keys.append((cells[:, 0] * 1_000_003 + cells[:, 1]) * 1_000_003 + cells[:, 2])
        owners.append(np.nonzero(touches)[0])
    keys, owners = np.concatenate(keys), np.concatenate(owners)
    order = np.lexsort((owners, keys))
    keys, owners = keys[order], owners[order]
    bounds = np.flatnonzero(np.diff(keys)) + 1
    shared = o3d.utility.Vector3dVector(vertices)
    found = set()
    for group in np.split(owners, bounds):
        if len(group) < 2:
            continue
        part = o3d.geometry.TriangleMesh(shared, o3d.utility.Vector3iVector(triangles[group]))
        for a, b in np.asarray(part.get_self_intersecting_triangles()):
            i, j = int(group[a]), int(group[b])
            found.add((min(i, j), max(i, j)))
    return sorted(found)


def is_watertight(mesh):
    """Open3D's is_watertight(), with the self-intersection test done cell by cell."""
    return mesh.is_edge_manifold(allow_boundary_edges=False) and mesh.is_vertex_manifold() and not crossing_pairs(mesh)


def _orientation(a, b, c, d):
    """The sign of det(b - a, c - a, d - a), exactly (the doubles as fractions)."""
    a, b, c, d = ([Fraction(float(x)) for x in point] for point in (a, b, c, d))
    u, v, w = ([q[i] - a[i] for i in range(3)] for q in (b, c, d))
    det = (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
           + u[2] * (v[0] * w[1] - v[1] * w[0]))
    return (det > 0) - (det < 0)


def apart_exactly(mesh, pair):
    """Whether exact arithmetic proves a pair of triangles apart: one lies strictly on one side of the
    other's plane. Open3D's test has a tolerance of 1e-6 on scaled distances, so nearly coplanar
    triangles (a flat face) can be reported crossing when they are not."""
    vertices, triangles = np.asarray(mesh.vertices), np.asarray(mesh.triangles)
    first, second = vertices[triangles[pair[0]]], vertices[triangles[pair[1]]]
    for plane, other in ((first, second), (second, first)):
        sides = {_orientation(*plane, point) for point in other}
        if sides in ({1}, {-1}):
            return True
    return False

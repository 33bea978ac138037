"""A real client: Open3D reads every point-set format amls writes, and every mesh amls exports is
watertight to it (edge- and vertex-manifold, and no two triangles crossing)."""
import os

import numpy as np
import pytest

from conftest import cgal_file, run_cli, sphere

o3d = pytest.importorskip("open3d")
from open3d_watertight import apart_exactly, crossing_pairs, is_watertight  # noqa: E402 (after the import check)


@pytest.mark.parametrize("extension", [".ply", ".xyz"])
def test_open3d_reads_the_points_and_normals_amls_writes(amls, tmp_path, extension):
    points, normals = sphere(1234)
    path = str(tmp_path / ("s" + extension))
    amls.write(path, points, normals, spacing=0.01)
    # Open3D reads .xyz as positions only; .xyzn is the same columns with normals.
    if extension == ".xyz":
        os.rename(path, path + "n")
        path += "n"
    cloud = o3d.io.read_point_cloud(path)
    assert len(cloud.points) == 1234
    assert cloud.has_normals()
    assert np.allclose(np.asarray(cloud.points), points, rtol=0, atol=1e-12)
    assert np.allclose(np.asarray(cloud.normals), normals, rtol=0, atol=1e-12)


def test_open3d_reads_the_points_the_command_line_writes(amls, tmp_path):
    points, normals = sphere(3000)
    amls.write(str(tmp_path / "in.ply"), points, normals)
    run_cli("resample", tmp_path / "in.ply", "--grid", 64, "--out", tmp_path / "out.ply", "--accept-loss")
    mine, my_normals = amls.read(str(tmp_path / "out.ply"))
    cloud = o3d.io.read_point_cloud(str(tmp_path / "out.ply"))
    assert len(cloud.points) == len(mine)
    assert np.array_equal(np.asarray(cloud.points), mine) and np.array_equal(np.asarray(cloud.normals), my_normals)


def test_open3d_reads_an_open_surface_with_its_rim_marks(amls, tmp_path):
    # An open cap's output marks its rim (a uchar property after the normals): Open3D skips it.
    points, normals = sphere(3000)
    cap = points[:, 2] > 0.6
    amls.write(str(tmp_path / "cap.ply"), points[cap], normals[cap])
    run_cli("resample", tmp_path / "cap.ply", "--grid", 64, "--out", tmp_path / "out.ply", "--accept-loss")
    with open(tmp_path / "out.ply", "rb") as f:
        assert b"property uchar rim\n" in f.read(400)
    mine, my_normals = amls.read(str(tmp_path / "out.ply"))
    cloud = o3d.io.read_point_cloud(str(tmp_path / "out.ply"))
    assert len(cloud.points) == len(mine) > 100
    assert np.array_equal(np.asarray(cloud.points), mine) and np.array_equal(np.asarray(cloud.normals), my_normals)


def watertight(path):
    mesh = o3d.io.read_triangle_mesh(str(path))
    assert len(mesh.triangles) > 0, path
    return mesh


@pytest.mark.parametrize("extension", [".ply", ".obj"])
def test_a_resampled_spheres_mesh_is_watertight_in_both_formats(amls, tmp_path, extension):
    points, normals = sphere(6000)
    new_points, new_normals, report = amls.resample(points, normals, grid=64)
    path = tmp_path / ("m" + extension)
    vertices, faces = amls.mesh(new_points, new_normals, spacing=report["h"], out=str(path))
    mesh = watertight(path)
    assert len(mesh.vertices) == len(vertices) and len(mesh.triangles) == len(faces)
    assert mesh.is_watertight() and mesh.is_orientable()  # Open3D's own test, on the whole mesh
    assert mesh.euler_poincare_characteristic() == 2


def test_a_resampled_spheres_stl_is_watertight_once_open3d_merges_its_corners(amls, tmp_path):
    # STL gives every triangle its own corners: Open3D reads them so, and merges them on request.
    points, normals = sphere(6000)
    new_points, new_normals, report = amls.resample(points, normals, grid=64)
    vertices, faces = amls.mesh(new_points, new_normals, spacing=report["h"], out=str(tmp_path / "m.stl"))
    mesh = watertight(tmp_path / "m.stl")
    assert len(mesh.triangles) == len(faces)
    mesh.remove_duplicated_vertices()
    assert len(mesh.vertices) == len(vertices)
    assert mesh.is_watertight() and mesh.is_orientable()
    assert mesh.euler_poincare_characteristic() == 2
    # And amls reads it back as the same closed mesh, to float precision.
    back_vertices, back_faces = amls.read_mesh(str(tmp_path / "m.stl"))
    assert len(back_vertices) == len(vertices) and len(back_faces) == len(faces)
    assert np.allclose(back_vertices[back_faces], vertices[faces], rtol=0, atol=1e-6)


def test_the_cell_by_cell_check_finds_what_open3d_finds(tmp_path):
    # Two spheres' meshes, one pushed into the other: crossing triangles along a circle.
    points, normals = sphere(1500)
    vertices, faces = [], []
    for shift in (0.0, 0.05):
        v, f = __import__("amls").mesh(points + shift, normals, spacing=1 / 24)
        faces.append(f + sum(len(x) for x in vertices))
        vertices.append(v)
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(np.concatenate(vertices)),
                                     o3d.utility.Vector3iVector(np.concatenate(faces)))
    whole = sorted(tuple(sorted(map(int, p))) for p in np.asarray(mesh.get_self_intersecting_triangles()))
    assert len(whole) > 0
    assert crossing_pairs(mesh, triangles_per_cell=50) == whole
    assert not any(apart_exactly(mesh, pair) for pair in whole)  # they do cross
    assert not is_watertight(mesh)
    single = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(vertices[0]), o3d.utility.Vector3iVector(faces[0]))
    assert is_watertight(single) == single.is_watertight() == True  # noqa: E712


@pytest.mark.parametrize("relative", ["points_3/kitten.xyz", "meshes/fandisk.off", "meshes/3torus.off"])
def test_real_scans_and_meshes_give_watertight_meshes(tmp_path, relative):
    # kitten.xyz once gave 39 pairs of crossing slivers where F is nearly zero at a grid vertex, and
    # 3torus.off a needle lying nearly in the plane of a triangle 0.04 h away.
    # Open3D's whole-mesh test takes minutes at this size; is_watertight() here runs it cell by cell.
    run_cli("resample", cgal_file(relative), "--out", tmp_path / "k.ply", "--mesh", tmp_path / "m.ply")
    mesh = watertight(tmp_path / "m.ply")
    assert mesh.is_edge_manifold(allow_boundary_edges=False) and mesh.is_vertex_manifold()
    assert crossing_pairs(mesh) == []


def test_exact_arithmetic_tells_nearly_coplanar_triangles_apart():
    # A triangle 1e-12 above or below another's plane, over it: apart, though only exactly so; tilted
    # through that plane, it crosses the first.
    first = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]
    for lift in (1e-12, -1e-12):
        second = [[0.2, 0.2, lift], [0.6, 0.2, lift], [0.2, 0.6, lift]]
        mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(np.array(first + second)),
                                         o3d.utility.Vector3iVector(np.array([[0, 1, 2], [3, 4, 5]])))
        assert apart_exactly(mesh, (0, 1))
    through = [[0.2, 0.2, -0.1], [0.6, 0.2, 0.1], [0.2, 0.6, 0.1]]
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(np.array(first + through)),
                                     o3d.utility.Vector3iVector(np.array([[0, 1, 2], [3, 4, 5]])))
    assert not apart_exactly(mesh, (0, 1))

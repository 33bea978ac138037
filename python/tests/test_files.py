"""read and write: the core's formats round trip bit for bit; bad input raises, never crashes."""
import os
import re

import numpy as np
import pytest

from conftest import circle, sphere


@pytest.mark.parametrize("extension", [".ply", ".xyz"])
def test_a_3d_set_round_trips_bit_for_bit(amls, tmp_path, extension):
    points, normals = sphere(500)
    path = str(tmp_path / ("s" + extension))
    amls.write(path, points, normals)
    read_points, read_normals = amls.read(path)
    assert read_points.dtype == np.float64 and read_points.shape == (500, 3)
    assert np.array_equal(read_points, points)
    assert np.array_equal(read_normals, normals)


def test_a_2d_set_stays_2d_and_a_set_without_normals_reads_none(amls, tmp_path):
    points, normals = circle(100)
    amls.write(str(tmp_path / "c.ply"), points, normals)
    read_points, read_normals = amls.read(str(tmp_path / "c.ply"))
    assert read_points.shape == (100, 2) and np.array_equal(read_normals, normals)
    amls.write(str(tmp_path / "bare.xyz"), points)
    assert amls.read(str(tmp_path / "bare.xyz"))[1] is None


def test_the_recorded_spacing_chooses_h_again(amls, tmp_path):
    points, normals = sphere(2000)
    amls.write(str(tmp_path / "s.ply"), points, normals, spacing=0.02)
    _, _, report = amls.resample(str(tmp_path / "s.ply"), accept_loss=True)
    assert report["h"] == 0.02


def test_paths_may_be_path_objects_as_everywhere_else(amls, tmp_path):
    points, normals = sphere(300)
    amls.write(tmp_path / "p.ply", points, normals)
    read_points, read_normals = amls.read(tmp_path / "p.ply")
    assert np.array_equal(read_points, points) and np.array_equal(read_normals, normals)
    mesh = tmp_path / "t.off"
    mesh.write_text("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n")
    vertices, faces = amls.read_mesh(mesh)
    assert vertices.shape == (3, 3) and faces.tolist() == [[0, 1, 2]]


def test_a_mesh_reads_with_its_faces(amls, tmp_path):
    path = tmp_path / "t.obj"
    path.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
    vertices, faces = amls.read_mesh(str(path))
    assert vertices.shape == (4, 3) and faces.shape == (4, 3) and faces.dtype == np.int64
    assert faces.min() == 0 and faces.max() == 3


def test_missing_and_broken_files_raise_os_errors_naming_them(amls, tmp_path):
    missing = str(tmp_path / "missing.ply")
    with pytest.raises(FileNotFoundError, match="missing.ply"):
        amls.read(missing)
    with pytest.raises(FileNotFoundError, match="missing.ply"):
        amls.resample(missing)
    broken = tmp_path / "broken.xyz"
    broken.write_text("0 0 0\n1 2 x\n")
    with pytest.raises(OSError, match="broken.xyz"):
        amls.read(str(broken))
    with pytest.raises(OSError):
        amls.write(str(tmp_path / "no_such_dir" / "s.ply"), *sphere(10))


@pytest.mark.parametrize(
    "points, normals, message",
    [
        (np.zeros((0, 3)), None, "no rows"),
        (np.zeros((5, 4)), None, r"\(n, 2\) or \(n, 3\)"),
        (np.zeros(5), None, r"\(n, 2\) or \(n, 3\)"),
        (np.array([[0.0, 0.0, np.nan]]), None, "non-finite"),
        (np.array([["a", "b", "c"]]), None, "numbers"),
        (None, None, "None"),
        (np.zeros((4, 3)), np.ones((3, 3)), "3 rows for 4 points"),
        (np.zeros((4, 3)), np.ones((4, 2)), r"\(n, 3\)"),
    ],
)
def test_bad_arrays_raise_value_errors(amls, tmp_path, points, normals, message):
    with pytest.raises(ValueError, match=message):
        amls.write(str(tmp_path / "s.ply"), points, normals)
    if points is not None and np.asarray(points).ndim == 2 and np.asarray(points).shape[1:] == (3,):
        with pytest.raises(ValueError, match=message):
            amls.resample(points, normals)


def test_an_unknown_extension_raises_a_value_error(amls, tmp_path):
    with pytest.raises(ValueError, match="extension|.stl"):
        amls.write(str(tmp_path / "s.stl"), *sphere(10))
    assert not os.path.exists(tmp_path / "s.stl")


def test_an_open_surfaces_rim_marks_go_into_a_ply_file_and_come_back(amls, tmp_path):
    points, normals = sphere(3000)
    cap = points[:, 2] > 0.6
    surface = amls.Surface(points[cap], normals[cap], grid=64)
    assert not surface.rim.any()  # a scan's points: no rim known yet
    surface.resample()
    marks = surface.rim
    assert marks.dtype == np.bool_ and marks.shape == (len(surface.points),) and 20 < marks.sum() < len(marks) / 4
    path = str(tmp_path / "cap.ply")
    amls.write(path, surface.points, surface.normals, spacing=surface.h, rim=marks)
    with open(path, "rb") as f:
        assert b"property uchar rim\n" in f.read(400)
    again = amls.Surface(path)
    order = np.lexsort(surface.points.T)  # the surface keeps its points in its own order
    order_again = np.lexsort(again.points.T)
    assert np.array_equal(again.points[order_again], surface.points[order])
    assert np.array_equal(again.rim[order_again], marks[order])
    # None writes no marks; .xyz has no room for them.
    amls.write(path, surface.points, surface.normals)
    assert not amls.Surface(path).rim.any()


@pytest.mark.parametrize("rim, message", [
    (np.ones(5), "rim: expected 4 values, one per point, got shape (5,)"),
    (np.array([0, 1, 2, 0]), "rim: values must be 0 or 1 (or False and True), got 2.0 at 2"),
])
def test_bad_rim_marks_raise_value_errors(amls, tmp_path, rim, message):
    points, normals = sphere(4)
    with pytest.raises(ValueError, match=re.escape(message)):
        amls.write(str(tmp_path / "s.ply"), points, normals, rim=rim)

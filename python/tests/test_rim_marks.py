"""An open scan's rim marks through read and resample, as the command line carries them in .ply files."""
import re

import numpy as np
import pytest

from conftest import run_cli, sphere

GRID = 64  # h = 1/64
SPARSE_GRID = 128  # h at which the cap is sparser than h everywhere


def open_cap():
    """The top of a sphere: a resample finds its rim, carries it and marks it."""
    points, normals = sphere(3000)
    cap = points[:, 2] > 0.6
    return points[cap], normals[cap]


# Two patches of a plane 3 h apart (at h = 1/GRID), a gap narrower than the rim test's bridge, which F
# spans: unmarked, a resample fills it; with the facing columns marked as rim, it stays open.
GAP = (0.5, 0.5 + 3 / GRID)
SIDE = (0.15, 0.85)  # the square the patches fill, in x and y


def gapped_plane():
    """Points 0.7 h apart with +z normals, and the facing columns' marks."""
    step = 0.7 / GRID
    y = SIDE[0] + step * np.arange(int((SIDE[1] - SIDE[0]) / step) + 1)
    x = y[(y <= GAP[0]) | (y >= GAP[1])]
    xs, ys = np.meshgrid(x, y, indexing="ij")
    points = np.stack([xs.ravel(), ys.ravel(), np.full(xs.size, 0.503)], axis=1)
    normals = np.tile([0.0, 0.0, 1.0], (len(points), 1))
    facing = (points[:, 0] > GAP[0] - step) & (points[:, 0] < GAP[1] + step)
    return points, normals, facing


def in_the_gap(points):
    """Points more than h/2 into the gap and 2 h or more from its open ends."""
    h = 1 / GRID
    x, y = points[:, 0], points[:, 1]
    return np.count_nonzero((x > GAP[0] + h / 2) & (x < GAP[1] - h / 2) & (y > SIDE[0] + 2 * h) & (y < SIDE[1] - 2 * h))


def resample_and_write(amls, path, *arrays, **options):
    """resample(..., with_rim=True) written as `amls resample --out` writes it; the arrays and report."""
    points, normals, rim, report = amls.resample(*arrays, with_rim=True, **options)
    amls.write(path, points, normals, spacing=report["h"], rim=rim)
    return points, normals, rim, report


def test_marks_round_trip_through_read_with_rim(amls, tmp_path):
    points, normals = sphere(500)
    marks = np.arange(500) % 7 == 0
    path = str(tmp_path / "marked.ply")
    amls.write(path, points, normals, rim=marks)
    read_points, read_normals, read_marks = amls.read(path, with_rim=True)
    assert np.array_equal(read_points, points) and np.array_equal(read_normals, normals)
    assert read_marks.dtype == np.bool_ and np.array_equal(read_marks, marks)
    assert len(amls.read(path)) == 2  # without with_rim, as before
    # No marks in the file: all False, one per point.
    amls.write(path, points, normals)
    assert np.array_equal(amls.read(path, with_rim=True)[2], np.zeros(500, dtype=bool))


def test_a_resampled_caps_marks_resample_as_the_command_line_resamples_its_file(amls, tmp_path):
    first = tmp_path / "first.ply"
    points, normals, rim, report = resample_and_write(amls, first, *open_cap(), grid=GRID)
    assert rim.dtype == np.bool_ and rim.shape == (len(points),) and 20 < rim.sum() < len(points) / 4
    assert np.array_equal(amls.read(first, with_rim=True)[2], rim)
    run_cli("resample", first, "--out", tmp_path / "cli.ply")
    # The arrays with their marks, at the h the file records.
    again = resample_and_write(amls, tmp_path / "arrays.ply", points, normals, rim=rim, spacing=report["h"])
    assert again[2].any()
    assert (tmp_path / "arrays.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()


def test_marks_keep_a_gap_open_from_a_file_and_from_arrays_alike(amls, tmp_path):
    points, normals, facing = gapped_plane()
    assert in_the_gap(amls.resample(points, normals, grid=GRID)[0]) > 20  # unmarked: filled
    amls.write(tmp_path / "gap.ply", points, normals, rim=facing)
    run_cli("resample", tmp_path / "gap.ply", "--grid", GRID, "--out", tmp_path / "cli.ply")
    marked = resample_and_write(amls, tmp_path / "arrays.ply", points, normals, rim=facing, grid=GRID)
    assert in_the_gap(marked[0]) == 0
    assert (tmp_path / "arrays.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    # The file's path: its marks go into the resample, as on the command line.
    from_file = amls.resample(tmp_path / "gap.ply", grid=GRID, with_rim=True)
    assert all(np.array_equal(a, b) for a, b in zip(from_file[:3], marked[:3]))


def test_one_pass_is_the_command_lines_one_pass(amls, tmp_path):
    points, normals = open_cap()
    amls.write(tmp_path / "cap.ply", points, normals)
    run_cli("resample", tmp_path / "cap.ply", "--grid", SPARSE_GRID, "--one-pass", "--out", tmp_path / "cli.ply")
    *_, report = resample_and_write(amls, tmp_path / "py.ply", points, normals, grid=SPARSE_GRID, one_pass=True)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    assert report["passes"] == 1 and report["first_pass_points"] == report["points_out"]
    # Sparser than h: by default a second pass follows.
    assert amls.resample(points, normals, grid=SPARSE_GRID)[2]["passes"] == 2


def test_rims_off_is_the_command_lines_rims_off(amls, tmp_path):
    points, normals = open_cap()
    amls.write(tmp_path / "cap.ply", points, normals)
    run_cli("resample", tmp_path / "cap.ply", "--grid", GRID, "--rims", "off", "--out", tmp_path / "cli.ply")
    amls.write(tmp_path / "py.ply", *amls.resample(points, normals, grid=GRID, rims=False)[:2], spacing=1 / GRID)
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    # The paper's resampler runs the cap past its rim: more points, no marks.
    kept, _, marks, _ = amls.resample(points, normals, grid=GRID, with_rim=True)
    extended, _, no_marks, _ = amls.resample(points, normals, grid=GRID, rims=False, with_rim=True)
    assert len(extended) > len(kept) and marks.any() and not no_marks.any()


@pytest.mark.parametrize("rim, message", [
    (np.ones(5), "rim: expected 4 values, one per point, got shape (5,)"),
    (np.zeros((4, 1)), "rim: expected 4 values, one per point, got shape (4, 1)"),
    (np.array([0, 1, 2, 0]), "rim: values must be 0 or 1 (or False and True), got 2.0 at 2"),
    (["a", "b", "c", "d"], "rim: expected an array of numbers"),
])
def test_bad_rim_arrays_raise_value_errors(amls, rim, message):
    with pytest.raises(ValueError, match=re.escape(message)):
        amls.resample(*sphere(4), rim=rim)


def test_a_file_path_brings_its_own_marks(amls, tmp_path):
    points, normals = sphere(100)
    amls.write(tmp_path / "s.ply", points, normals)
    with pytest.raises(ValueError, match=re.escape("rim: only for arrays; a file's own marks")):
        amls.resample(tmp_path / "s.ply", rim=np.zeros(100))

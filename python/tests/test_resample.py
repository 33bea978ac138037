"""resample: the command line's defaults, checks and report; the kitten scan to the same bytes."""
import json
import os
import re

import numpy as np
import pytest

from conftest import CLI, cgal_file, circle, run_cli, sphere


def test_the_kitten_scan_resamples_to_the_command_lines_bytes(amls, tmp_path):
    kitten = cgal_file("points_3/kitten.xyz")
    cli_out, cli_report = tmp_path / "cli.ply", tmp_path / "cli.json"
    run_cli("resample", kitten, "--out", cli_out, "--json", cli_report)
    points, normals = amls.read(kitten)
    assert points.shape == (5210, 3) and normals.shape == (5210, 3)
    new_points, new_normals, report = amls.resample(points, normals)
    amls.write(str(tmp_path / "py.ply"), new_points, new_normals, spacing=report["h"])
    assert (tmp_path / "py.ply").read_bytes() == cli_out.read_bytes()
    # The same from the path, and the same report keys and counts as --json.
    from_path = amls.resample(kitten)
    assert np.array_equal(from_path[0], new_points) and np.array_equal(from_path[1], new_normals)
    cli = json.loads(cli_report.read_text())
    assert set(report) == set(cli)
    for key in ("h", "points_in", "points_out", "file_points", "spacing_h", "coverage", "rim", "support"):
        assert report[key] == cli[key], key
    assert from_path[2]["input"] == kitten and report["input"] == "" and report["output"] == ""


def test_a_closed_thin_slab_meshes_closed_to_the_command_lines_bytes(amls, tmp_path):
    # Thinner than Delta: without the input mesh's inside, its mesh was open past the slab's edges.
    # Corner i at (x, y, z) chosen by its bits 0, 1, 2; each face two triangles, counter-clockwise from outside.
    corners = [((0.25, 0.75)[i & 1], (0.25, 0.75)[i >> 1 & 1], (0.48, 0.52)[i >> 2 & 1]) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    faces = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    slab = tmp_path / "slab.off"
    slab.write_text("OFF\n8 12 0\n" + "".join("%g %g %g\n" % p for p in corners) +
                    "".join("3 %d %d %d\n" % f for f in faces))
    output = run_cli("resample", slab, "--out", tmp_path / "cli.ply", "--mesh", tmp_path / "cli_mesh.ply",
                     "--spacing", "0.02", "--accept-loss")
    assert "triangles, closed, wrote" in output
    amls.resample(str(slab), spacing=0.02, accept_loss=True, mesh=str(tmp_path / "py_mesh.ply"))
    assert (tmp_path / "py_mesh.ply").read_bytes() == (tmp_path / "cli_mesh.ply").read_bytes()


def test_results_do_not_depend_on_threads(amls):
    points, normals = sphere(3000)
    one = amls.resample(points, normals, grid=64, threads=1)
    two = amls.resample(points, normals, grid=64, threads=2)
    assert np.array_equal(one[0], two[0]) and np.array_equal(one[1], two[1])
    mesh_one = amls.mesh(one[0], one[1], spacing=1 / 64, threads=1)
    mesh_two = amls.mesh(one[0], one[1], spacing=1 / 64, threads=3)
    assert all(np.array_equal(a, b) for a, b in zip(mesh_one, mesh_two))


def test_a_curve_resamples_in_2d_and_meshes_to_a_closed_polyline(amls):
    points, normals = circle(400)
    new_points, new_normals, report = amls.resample(points, normals, grid=128)
    assert new_points.shape[1] == 2 and report["dimension"] == 2
    assert np.allclose(np.linalg.norm(new_points - 0.5, axis=1), 0.3, atol=0.01 / 128)
    vertices, segments = amls.mesh(new_points, new_normals, spacing=1 / 128)
    assert segments.shape[1] == 2 and len(segments) == len(vertices)  # closed: one segment per vertex


def test_normals_are_estimated_when_missing(amls):
    points, normals = sphere(4000)
    new_points, new_normals, report = amls.resample(points, grid=64)
    radial = (new_points - 0.5) / np.linalg.norm(new_points - 0.5, axis=1)[:, None]
    assert np.min(np.sum(radial * new_normals, axis=1)) > 0.9  # oriented outwards, as given ones would be


@pytest.mark.parametrize(
    "arguments, error, message",
    [
        ({"spacing": 0.0}, ValueError, r"spacing: must be within \[1e-09, 1e\+09\] \(grid spacing h\), got 0"),
        ({"spacing": float("nan")}, ValueError, "spacing: must be within"),
        ({"grid": 0}, ValueError, r"grid: must be within \[1, 65536\]"),
        ({"grid": 10, "spacing": 0.1}, ValueError, "not both"),
        ({"radius_factor": 1.0}, ValueError, r"radius_factor: must be within \[1.5, 32\]"),
        ({"threads": 0}, ValueError, r"threads: must be within \[1, 256\]"),
        ({"variant": "fast"}, ValueError, "exact"),
        ({"spacing": 1e-6}, ValueError, "points: h = 1e-06 would give about .* --spacing .* or larger would fit"),
        ({"mesh": "m.3mf"}, ValueError, "m.3mf"),
    ],
)
def test_out_of_range_arguments_raise_with_the_command_lines_messages(amls, arguments, error, message):
    points, normals = sphere(500)
    with pytest.raises(error, match=message):
        amls.resample(points, normals, **arguments)


def test_a_clear_loss_raises_unless_accepted(amls):
    # A sphere dense above its equator and 20 times sparser below, resampled with one support Delta
    # for all: holes open in the sparse half, and the coverage check says so.
    points, normals = sphere(20000)
    keep = (points[:, 2] > 0.5) | (np.arange(len(points)) % 20 == 0)
    arguments = dict(grid=128, uniform_support=True)
    with pytest.raises(RuntimeError, match=r"points: the output misses part of the input: .*accept_loss=True"):
        amls.resample(points[keep], normals[keep], **arguments)
    with pytest.warns(UserWarning, match="accepted"):
        _, _, report = amls.resample(points[keep], normals[keep], accept_loss=True, **arguments)
    assert report["coverage"]["clear_loss"] is True
    # Widened supports (the default) close the sparse half.
    assert amls.resample(points[keep], normals[keep], grid=128)[2]["coverage"]["clear_loss"] is False


def test_help_reads_like_the_command_lines(amls):
    text = amls.resample.__doc__
    for phrase in ("the median distance from a point", "50 million", "radius_factor", "accept_loss", "threads",
                   "one_pass", "--one-pass", "with_rim"):
        assert phrase in text
    assert os.path.exists(os.path.join(os.path.dirname(amls.__file__), "amls.pyi"))


def test_broken_normals_are_mended_as_the_command_line_mends_them(amls, tmp_path):
    # A sphere with every 50th normal turned inward and every 50th (offset) tipped across the surface.
    points, normals = sphere(4000)
    broken = normals.copy()
    broken[::50] *= -1
    tangent = np.cross(normals[25::50], [0.0, 0.0, 1.0])
    broken[25::50] = tangent / np.linalg.norm(tangent, axis=1)[:, None]
    with pytest.warns(UserWarning, match=r"80 normals pointed against .* turned over, and 80 normals lay more than "
                                         r"60 degrees off theirs and were replaced"):
        mended = amls.resample(points, broken, grid=32)
    # The mended resample is the command line's on the same file, to the byte.
    amls.write(str(tmp_path / "broken.ply"), points, broken)
    run_cli("resample", tmp_path / "broken.ply", "--grid", "32", "--out", tmp_path / "cli.ply")
    amls.write(str(tmp_path / "py.ply"), mended[0], mended[1], spacing=mended[2]["h"])
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    # And near what the good normals give: every output normal within 10 degrees of the radial direction.
    radial = mended[0] - 0.5
    radial /= np.linalg.norm(radial, axis=1)[:, None]
    assert np.min(np.sum(radial * mended[1], axis=1)) > np.cos(np.radians(10.0))


def test_a_files_normals_set_aside_as_the_command_line_sets_them_aside(amls, tmp_path):
    # Every normal inward: consistent, so the file's own stay inward unless set aside.
    points, normals = sphere(4000)
    amls.write(str(tmp_path / "inward.ply"), points, -normals)
    given = amls.resample(str(tmp_path / "inward.ply"), grid=32)
    radial = (given[0] - 0.5) / np.linalg.norm(given[0] - 0.5, axis=1)[:, None]
    assert np.max(np.sum(radial * given[1], axis=1)) < -0.9
    estimated = amls.resample(str(tmp_path / "inward.ply"), "estimated", grid=32)
    run_cli("resample", tmp_path / "inward.ply", "--grid", "32", "--normals", "estimated", "--out", tmp_path / "cli.ply")
    amls.write(str(tmp_path / "py.ply"), estimated[0], estimated[1], spacing=estimated[2]["h"])
    assert (tmp_path / "py.ply").read_bytes() == (tmp_path / "cli.ply").read_bytes()
    radial = (estimated[0] - 0.5) / np.linalg.norm(estimated[0] - 0.5, axis=1)[:, None]
    assert np.min(np.sum(radial * estimated[1], axis=1)) > 0.9
    # On arrays "estimated" is None; a Surface and a mesh take it too.
    from_arrays = amls.resample(points, "estimated", grid=32)
    without = amls.resample(points, grid=32)
    assert np.array_equal(from_arrays[0], without[0]) and np.array_equal(from_arrays[1], without[1])
    surface = amls.Surface(str(tmp_path / "inward.ply"), "estimated", grid=32)
    assert np.min(np.sum((surface.points - 0.5) * surface.normals, axis=1)) > 0
    assert len(amls.mesh(str(tmp_path / "inward.ply"), "estimated", grid=32)[1]) > 0


@pytest.mark.parametrize(
    "normals, message",
    [
        ("guessed", 'normals: expected None, an array of unit normals or "estimated", got "guessed"'),
        ("array", 'normals: only for arrays; a file brings its own (None), or "estimated" sets them aside'),
    ],
)
def test_normals_that_a_file_cannot_take_raise(amls, tmp_path, normals, message):
    points, good = sphere(500)
    amls.write(str(tmp_path / "s.ply"), points, good)
    with pytest.raises(ValueError, match=re.escape(message)):
        amls.resample(str(tmp_path / "s.ply"), good if normals == "array" else normals)

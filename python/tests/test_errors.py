"""Every way the module refuses input: the Python exception a caller expects (ValueError for a value
out of range, an OSError subclass for a file the system refused, OSError for a file it cannot
parse), with the command line's message word for word."""
import json
import os
import subprocess

import numpy as np
import pytest

from conftest import CLI, sphere


def cli_error(*args):
    """The command line's message for a command that fails: its `amls: error: ` line, unprefixed."""
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 1, result.stdout + result.stderr
    line = result.stderr.strip().splitlines()[-1]
    assert line.startswith("amls: error: "), line
    return line[len("amls: error: "):]


def raised(error_type, call):
    with pytest.raises(error_type) as caught:
        call()
    return caught


@pytest.fixture
def files(tmp_path, monkeypatch):
    """A folder with a broken, an empty and a too-small point file and a folder named like a file;
    paths are relative, as a user gives them, so that messages compare as they are."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "broken.xyz").write_text("0 0 0\n1 2 x\n")
    (tmp_path / "empty.xyz").write_text("")
    (tmp_path / "two.xyz").write_text("0 0 0\n1 0 0\n")
    (tmp_path / "folder.xyz").mkdir()
    (tmp_path / "folder").mkdir()
    return tmp_path


# What each unreadable input raises from every reader that takes a path.
READ_CASES = [
    ("missing.xyz", FileNotFoundError),
    ("folder.xyz", IsADirectoryError),
    ("folder", IsADirectoryError),  # a directory is named as one before its extension is judged
    ("broken.xyz", OSError),
    ("empty.xyz", OSError),
    ("points.3mf", ValueError),
]


@pytest.mark.parametrize("path, error_type", READ_CASES)
def test_unreadable_files_raise_the_command_lines_message_as_the_matching_error(amls, files, path, error_type):
    message = cli_error("resample", path, "--out", "out.ply")
    readers = {
        "read": lambda: amls.read(path),
        "resample": lambda: amls.resample(path),
        "mesh": lambda: amls.mesh(path),
        "Surface": lambda: amls.Surface(path),
    }
    for name, call in readers.items():
        caught = raised(error_type, call)
        assert str(caught.value) == message, name
        if error_type is OSError:  # a parse error, not one the system gave: no subclass claims it
            assert type(caught.value) is OSError, name


def test_read_mesh_names_missing_files_directories_and_extensions(amls, files):
    assert isinstance(raised(FileNotFoundError, lambda: amls.read_mesh("missing.off")).value, OSError)
    assert "is a directory" in str(raised(IsADirectoryError, lambda: amls.read_mesh("folder")).value)
    raised(ValueError, lambda: amls.read_mesh("points.xyz"))


def test_writes_the_system_refuses_raise_the_matching_os_error(amls, files):
    points, normals = sphere(2000)
    amls.write("sphere.ply", points, normals)
    message = cli_error("resample", "sphere.ply", "--out", "nowhere/out.ply")
    assert str(raised(FileNotFoundError, lambda: amls.write("nowhere/out.ply", points, normals)).value) == message
    os.mkdir("taken.ply")
    raised(IsADirectoryError, lambda: amls.write("taken.ply", points, normals))
    for call in (lambda: amls.resample(points, normals, grid=24, mesh="nowhere/m.ply"),
                 lambda: amls.mesh(points, normals, grid=24, out="nowhere/m.ply"),
                 lambda: amls.Surface(points, normals, grid=24).mesh("nowhere/m.ply")):
        assert "nowhere/m.ply: cannot create a temporary file in nowhere" in str(raised(FileNotFoundError, call).value)
    assert not os.path.exists("nowhere")


def test_a_resample_past_the_cost_limit_is_a_value_error_with_the_command_lines_message(amls, files):
    points, normals = sphere(2000)
    amls.write("sphere.ply", points, normals)
    message = cli_error("resample", "sphere.ply", "--spacing", 1e-6, "--out", "out.ply")
    assert "would give about" in message and "or larger would fit" in message
    assert str(raised(ValueError, lambda: amls.resample("sphere.ply", spacing=1e-6)).value) == message
    # Arrays are named "points" where the command line names the file.
    from_arrays = str(raised(ValueError, lambda: amls.resample(points, normals, spacing=1e-6)).value)
    assert from_arrays == message.replace("sphere.ply:", "points:", 1)
    raised(ValueError, lambda: amls.mesh(points, normals, spacing=1e-6))
    raised(ValueError, lambda: amls.Surface(points, normals, h=1e-6))


def test_too_few_points_to_choose_h_is_a_value_error(amls, files):
    message = cli_error("resample", "two.xyz", "--out", "out.ply")
    assert "cannot choose h" in message
    assert str(raised(ValueError, lambda: amls.resample("two.xyz")).value) == message
    raised(ValueError, lambda: amls.resample(np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]])))


@pytest.mark.parametrize(
    "points, message",
    [
        (np.ones((4, 3)) * 1j, "points: expected real numbers, got complex ones"),
        (np.array([["a", "b", "c"]]), "points: expected an array of numbers"),
        (np.array([[0.0, 1.0, None]], dtype=object), "points: row 0 has a non-finite value"),
        (np.array([[0.0, np.inf, 0.0]]), "points: row 0 has a non-finite value"),
        (np.zeros((0, 3)), "points: the array has no rows"),
        (np.zeros((3, 3, 3)), r"points: expected an (n, 2) or (n, 3) array, got shape (3, 3, 3)"),
    ],
)
def test_arrays_of_the_wrong_kind_raise_value_errors_everywhere(amls, tmp_path, points, message):
    for call in (lambda: amls.write(str(tmp_path / "s.ply"), points),
                 lambda: amls.resample(points),
                 lambda: amls.mesh(points, spacing=0.1),
                 lambda: amls.Surface(points, h=0.1)):
        assert str(raised(ValueError, call).value) == message


def test_bad_options_raise_value_errors(amls, files):
    points, normals = sphere(500)
    raised(ValueError, lambda: amls.resample(points, normals, dim=5))
    raised(ValueError, lambda: amls.read("any.xyz", dim=1))
    raised(ValueError, lambda: amls.write("s.ply", points, normals, spacing=-1.0))
    surface = amls.Surface(points, normals, h=0.05, uniform_support=True)
    assert str(raised(ValueError, lambda: surface.F(np.zeros((2, 4)))).value) == \
        "x: expected an (n, 3) array, got shape (2, 4)"
    raised(ValueError, lambda: surface.project([np.nan, 0.0, 0.0]))
    raised(ValueError, lambda: surface.mesh("m.3mf"))


def test_run_scene_tells_files_from_their_contents(amls, files):
    scene = {"dimension": 3, "grid": {"cells": 0}}
    (files / "bad.json").write_text(json.dumps(scene))
    (files / "broken.json").write_text("{not json")
    os.mkdir("scenes")
    for path, error_type in (("missing.json", FileNotFoundError), ("scenes", IsADirectoryError),
                             ("bad.json", ValueError), ("broken.json", ValueError)):
        message = cli_error("deform", path)
        assert str(raised(error_type, lambda: amls.run_scene(path)).value) == message, path


def test_run_scene_raises_os_errors_for_a_shape_file_that_is_not_there(amls, files):
    os.mkdir("shape.ply")
    for shape_path, error_type, words in (("gone.ply", FileNotFoundError, "shape.path: no such file: "),
                                          ("shape.ply", IsADirectoryError, "shape.path: is a directory, not a shape file: ")):
        scene = {"dimension": 3, "shape": {"type": "file", "path": shape_path}, "stages": []}
        (files / "uses.json").write_text(json.dumps(scene))
        message = cli_error("deform", "uses.json")
        assert words in message
        assert str(raised(error_type, lambda: amls.run_scene("uses.json")).value) == message, shape_path

"""An open scan's rim marks through read, as the command line keeps them in .ply files."""
import numpy as np

from conftest import sphere


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

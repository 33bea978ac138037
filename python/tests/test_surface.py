"""Surface, MlsDeformation and run_scene: a Python loop of drag steps is the scene's run."""
import json

import numpy as np
import pytest

from conftest import circle, sphere

H = 1.0 / 48
HANDLES = [[0.5, 0.5, 0.2], [0.8, 0.5, 0.5], [0.5, 0.8, 0.5], [0.5, 0.5, 0.8]]
STEPS = 4


def drag_targets(step):
    """The scene's top handle pulled up by h/2 a step, the others fixed: the handles after `step` of
    STEPS steps, computed as the scene computes them, (1 - t) start + t end (so bit for bit the same)."""
    start = np.array(HANDLES)
    end = start.copy()
    end[3, 2] += 0.5 * H * STEPS
    t = step / STEPS
    return (1.0 - t) * start + t * end


def write_scene(amls, path, points, normals, widen_support=False):
    """The drag as a scene whose shape is the file of these points."""
    amls.write(str(path.with_suffix(".ply")), points, normals)
    scene = {
        "dimension": 3,
        "shape": {"type": "file", "path": path.with_suffix(".ply").name},
        "grid": {"spacing": H},
        "radius_factor": 3.0,
        "variant": "exact",
        "widen_support": widen_support,
        "deformation": {"kind": "rigid", "alpha": 1.0},
        "stages": [{"handles": HANDLES, "targets": [{"steps": STEPS, "handles": drag_targets(STEPS).tolist()}]}],
    }
    path.write_text(json.dumps(scene))


def test_F_is_zero_on_the_surface_and_project_lands_there(amls):
    points, normals = sphere(4000)
    surface = amls.Surface(points, normals, h=1 / 64, uniform_support=True)
    assert surface.h == 1 / 64 and surface.dimension == 3
    assert abs(surface.F(points[0])) < 0.05 / 64
    outside = np.array([[0.5, 0.5, 0.5 + 0.3 + 0.02], [0.5 + 0.3 - 0.02, 0.5, 0.5]])
    values = surface.F(outside)
    assert values[0] > 0 > values[1]
    projected = surface.project(outside)
    assert np.all(np.abs(surface.F(projected)) < 1e-6 / 64)
    assert np.allclose(np.linalg.norm(projected - 0.5, axis=1), 0.3, atol=0.05 / 64)
    assert np.isnan(surface.F(np.array([5.0, 5.0, 5.0])))
    assert np.all(np.isnan(surface.project(np.array([5.0, 5.0, 5.0]))))


def test_a_python_drag_loop_gives_the_scenes_points(amls, tmp_path):
    points, normals = sphere(3000)
    scene = tmp_path / "drag.json"
    write_scene(amls, scene, points, normals)
    # The scene's warnings come as Python's: a file shape has no denser sampling for its tracers.
    with pytest.warns(UserWarning, match="cannot be sampled more densely"):
        scene_points, scene_normals, report = amls.run_scene(str(scene), tracers=1, threads=2)
    assert report["steps"] == STEPS and report["status"] == "ok"
    surface = amls.Surface(points, normals, h=H, uniform_support=True)
    deformation = amls.MlsDeformation(HANDLES, kind="rigid")
    for step in range(1, STEPS + 1):
        stats = surface.step(deformation, drag_targets(step))
        assert stats["points_after"] > 0
    assert np.array_equal(deformation.handles, drag_targets(STEPS))
    surface.resample()  # the scene's final frame is a resample
    assert np.array_equal(surface.points, scene_points)
    assert np.array_equal(surface.normals, scene_normals)


def test_a_sparse_shapes_python_loop_starts_as_the_scene_does(amls, tmp_path):
    # The lower half 15 x sparser than h: the start's resample makes a second pass, in the scene and here.
    dense, dense_normals = sphere(3000)
    sparse, sparse_normals = sphere(200)
    upper, lower = dense[:, 2] > 0.5, sparse[:, 2] <= 0.5
    points = np.concatenate([dense[upper], sparse[lower]])
    normals = np.concatenate([dense_normals[upper], sparse_normals[lower]])
    scene = tmp_path / "sparse.json"
    write_scene(amls, scene, points, normals, widen_support=True)
    with pytest.warns(UserWarning, match="cannot be sampled more densely"):
        scene_points, _, report = amls.run_scene(str(scene), tracers=1, threads=2)
    assert report["start_passes"] == 2 and report["status"] == "ok"
    surface = amls.Surface(points, normals, h=H)
    deformation = amls.MlsDeformation(HANDLES, kind="rigid")
    for step in range(1, STEPS + 1):
        surface.step(deformation, drag_targets(step))
    surface.resample()
    assert np.array_equal(surface.points, scene_points)


def test_a_curve_deforms_in_2d(amls):
    points, normals = circle(300)
    surface = amls.Surface(points, normals, grid=128, uniform_support=True)
    deformation = amls.MlsDeformation([[0.2, 0.5], [0.8, 0.5]], kind="similarity")
    surface.step(deformation, [[0.2, 0.5], [0.85, 0.5]])
    assert surface.points.shape[1] == 2 and surface.points[:, 0].max() > 0.8 + 0.03
    vertices, segments = surface.mesh()
    assert segments.shape[1] == 2


def test_steps_do_not_depend_on_threads(amls):
    points, normals = sphere(3000)
    results = []
    for threads in (1, 2):
        surface = amls.Surface(points, normals, h=H, uniform_support=True, threads=threads)
        deformation = amls.MlsDeformation(HANDLES)
        surface.step(deformation, drag_targets(1))
        results.append(surface.points)
    assert np.array_equal(results[0], results[1])


def test_bad_deformations_and_scenes_raise(amls, tmp_path):
    points, normals = sphere(1000)
    surface = amls.Surface(points, normals, h=H, uniform_support=True)
    with pytest.raises(ValueError, match="kind"):
        amls.MlsDeformation(HANDLES, kind="bendy")
    with pytest.raises(ValueError, match=r"alpha: must be within \[0.1, 10\]"):
        amls.MlsDeformation(HANDLES, alpha=0.0)
    with pytest.raises(ValueError, match="non-finite"):
        amls.MlsDeformation([[0.0, np.inf, 0.0]])
    deformation = amls.MlsDeformation(HANDLES)
    with pytest.raises(ValueError, match="3 rows for 4 handles"):
        surface.step(deformation, HANDLES[:3])
    with pytest.raises(ValueError, match="2D handles for a 3D surface"):
        surface.step(amls.MlsDeformation([[0.0, 0.0]]), [[0.0, 0.1]])
    with pytest.raises(TypeError):
        surface.step("not a deformation", HANDLES)
    with pytest.raises(FileNotFoundError):
        amls.run_scene(str(tmp_path / "missing.json"))
    bad = tmp_path / "bad.json"
    bad.write_text('{"dimension": 3, "grid": {"cells": 0}}')
    with pytest.raises(ValueError, match="bad.json"):
        amls.run_scene(str(bad))
    with pytest.raises(ValueError, match="resample"):
        amls.run_scene(str(bad), resample="sometimes")

"""Shared fixtures: the module under test, the command line beside it, CGAL's demo data, small shapes.

ctest (python/CMakeLists.txt) sets PYTHONPATH to the build's module, AMLS_CLI to the `amls` it
built and AMLS_CGAL_DATA to the unpacked demo data; run by hand, the defaults are ./build's.
"""
import math
import os
import subprocess

import sys

import numpy as np
import pytest

SOURCE_DIR = os.environ.get("AMLS_SOURCE_DIR", os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..")))
CLI = os.environ.get("AMLS_CLI", os.path.join(SOURCE_DIR, "build", "app", "amls"))
CGAL_DATA = os.environ.get("AMLS_CGAL_DATA", os.path.join(SOURCE_DIR, "build", "cgal_data", "data"))
# The Open3D watertightness check the tests share with python/checks/cgal_watertight.py.
sys.path.insert(0, os.path.join(SOURCE_DIR, "python", "checks"))


def sphere(count, radius=0.3, center=(0.5, 0.5, 0.5)):
    """A sphere sampled by a Fibonacci lattice: points and outward unit normals, (count, 3) each."""
    i = np.arange(count) + 0.5
    z = 1.0 - 2.0 * i / count
    r = np.sqrt(1.0 - z * z)
    phi = math.pi * (3.0 - math.sqrt(5.0)) * np.arange(count)
    normals = np.stack([r * np.cos(phi), r * np.sin(phi), z], axis=1)
    return np.asarray(center) + radius * normals, normals


def circle(count, radius=0.3, center=(0.5, 0.5)):
    """A circle: points and outward unit normals, (count, 2) each."""
    t = 2.0 * math.pi * np.arange(count) / count
    normals = np.stack([np.cos(t), np.sin(t)], axis=1)
    return np.asarray(center) + radius * normals, normals


def run_cli(*args):
    """Runs the command line; fails the test with its output unless it exits 0."""
    result = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, f"amls {' '.join(map(str, args))}: {result.stdout}{result.stderr}"
    return result.stdout


def cgal_file(relative):
    path = os.path.join(CGAL_DATA, relative)
    assert os.path.exists(path), f"{path}: CGAL's demo data is missing (ctest's cgal_data fixture unpacks it)"
    return path


@pytest.fixture(scope="module")
def amls():
    import amls as module
    return module

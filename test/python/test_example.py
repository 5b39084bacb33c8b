# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The Python examples run: segment_depth_png.py on a depth PNG prints its planes;
open3d_planes.py (with Open3D) prints them with their boxes and writes the coloured cloud."""

import os
import pathlib
import re
import subprocess
import sys

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene, write_png

EXAMPLE = pathlib.Path(os.environ["FLOODPLANE_SOURCE_DIR"], "examples/python/segment_depth_png.py")


def run(*arguments):
    return subprocess.run([sys.executable, str(EXAMPLE), *map(str, arguments)], capture_output=True, text=True,
                          timeout=120)


def test_prints_the_planes_of_a_depth_png_and_writes_its_labels(tmp_path):
    depth = np.round(two_plane_scene()[..., 2] * 5000)
    depth[np.isnan(depth)] = 0
    png = tmp_path / "frame.png"
    floodplane.write_depth_png(str(png), depth.astype(np.uint16))
    labels = tmp_path / "frame.labels.pcd"
    completed = run(png, "--intrinsics", "131.25,131.25,79.5,59.5", "--depth-scale", "5000", "--labels", labels)
    assert completed.returncode == 0, completed.stderr
    lines = completed.stdout.splitlines()
    assert lines[0].startswith(f"{png}: 160x120, 2 planes, ")
    zero = r"[+-]0\.000"
    assert re.match(rf"  plane 1: \d+ pixels, normal \({zero}, {zero}, -1\.000\), d \+2\.000 m, centroid", lines[1])
    assert re.match(rf"  plane 2: \d+ pixels, normal \({zero}, -1\.000, {zero}\), d \+0\.500 m, centroid", lines[2])
    assert len(lines) == 3
    assert floodplane.read_labels_pcd(str(labels)).max() == 2


def test_reports_a_bad_file_in_one_line(tmp_path):
    completed = run(tmp_path / "missing.png", "--intrinsics", "525,525,319.5,239.5")
    assert completed.returncode == 1
    assert completed.stderr.startswith("segment_depth_png: error: read_depth_png: path")
    assert completed.stderr.count("\n") == 1
    assert run(tmp_path / "x.png", "--intrinsics", "525,525").returncode == 2


OPEN3D_EXAMPLE = EXAMPLE.with_name("open3d_planes.py")


def run_open3d_example(*arguments):
    return subprocess.run([sys.executable, str(OPEN3D_EXAMPLE), *map(str, arguments)], capture_output=True,
                          text=True, timeout=120)


@pytest.mark.parametrize("with_color", [False, True])
def test_the_open3d_example_prints_the_planes_and_writes_the_coloured_cloud(tmp_path, with_color):
    open3d = pytest.importorskip("open3d", reason="Open3D's Python module is not installed (Debian: python3-open3d)")
    depth = np.nan_to_num(np.round(two_plane_scene()[..., 2] * 5000)).astype(np.uint16)
    png = tmp_path / "frame.png"
    floodplane.write_depth_png(str(png), depth)
    arguments = [png, "--intrinsics", "131.25,131.25,79.5,59.5", "--depth-scale", "5000", "-o", tmp_path / "p.ply"]
    if with_color:
        color = tmp_path / "rgb.png"
        write_png(color, np.full(depth.shape + (3,), 128, np.uint8), color_type=2, bit_depth=8)
        arguments += ["--color", color]
    completed = run_open3d_example(*arguments)
    assert completed.returncode == 0, completed.stderr
    lines = completed.stdout.splitlines()
    assert lines[0].startswith(f"{png}: 160x120, 2 planes, ")
    assert re.match(r"  plane 1: \d+ pixels, normal \([+-]0\.000, [+-]0\.000, -1\.000\), d \+2\.000 m, box ", lines[1])
    assert re.match(r"  plane 2: \d+ pixels, normal \([+-]0\.000, -1\.000, [+-]0\.000\), d \+0\.500 m, box ", lines[2])
    cloud = open3d.io.read_point_cloud(str(tmp_path / "p.ply"))
    assert len(cloud.points) == np.count_nonzero(depth) and cloud.has_colors()
    assert sorted(p.name for p in tmp_path.iterdir() if p.name.startswith(".")) == [], "no temporary left behind"


def test_the_open3d_example_reports_a_bad_file_in_one_line(tmp_path):
    pytest.importorskip("open3d", reason="Open3D's Python module is not installed (Debian: python3-open3d)")
    completed = run_open3d_example(tmp_path / "missing.png", "--intrinsics", "525,525,319.5,239.5")
    assert completed.returncode == 1
    assert completed.stderr == f"open3d_planes: error: cannot read the image '{tmp_path / 'missing.png'}'\n"

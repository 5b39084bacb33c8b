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


PLANES_AND_OBJECTS = EXAMPLE.with_name("planes_and_objects.py")


def room_with_a_box(width=320, height=240):
    """The two-plane scene (a wall at z = 2 m, a floor 0.5 m below a level camera) with a
    30 cm box standing on the floor 1.5 m ahead: its front face at z = 1.5, x in [-0.15, 0.15],
    y in [0.2, 0.5]."""
    focal = 525.0 * width / 640.0
    v, u = np.mgrid[0:height, 0:width].astype(np.float64)
    rx, ry = (u - (width - 1) / 2.0) / focal, (v - (height - 1) / 2.0) / focal
    t = np.full((height, width), 2.0)
    floor = ry > 0
    t[floor] = np.minimum(2.0, 0.5 / ry[floor])
    front = (np.abs(1.5 * rx) <= 0.15) & (1.5 * ry >= 0.2) & (1.5 * ry <= 0.5)
    t[front] = 1.5
    return np.stack([t * rx, t * ry, t], axis=-1).astype(np.float32)


def test_the_planes_and_objects_example_classes_the_planes_and_finds_the_box(tmp_path):
    cloud = tmp_path / "room.pcd"
    points = room_with_a_box()
    floodplane.write_labels_pcd(str(cloud), points, np.zeros(points.shape[:2], np.uint32))
    completed = subprocess.run([sys.executable, str(PLANES_AND_OBJECTS), str(cloud)], capture_output=True, text=True,
                               timeout=120)
    assert completed.returncode == 0, completed.stderr
    lines = completed.stdout.splitlines()
    assert lines[0] == f"{cloud}: 3 planes, 1 objects", completed.stdout
    classes = {line.split(":")[1].split(",")[0].strip() for line in lines[1:4]}
    assert classes == {"floor", "wall"}, completed.stdout
    assert re.match(r"  plane \d: floor, \d+ pixels, normal \([+-]0\.000, -1\.000, [+-]0\.000\), d \+0\.500 m, "
                    r"\+0\.00 m above the floor", next(line for line in lines if ": floor," in line))
    assert re.match(r"  object 1: \d+ pixels at \([+-]0\.\d\d, \+0\.3\d, \+1\.5\d\) m, on plane \d", lines[4]), lines[4]


def test_the_planes_and_objects_example_reports_a_bad_file_in_one_line(tmp_path):
    completed = subprocess.run([sys.executable, str(PLANES_AND_OBJECTS), str(tmp_path / "missing.pcd")],
                               capture_output=True, text=True, timeout=120)
    assert completed.returncode == 1
    assert completed.stderr.startswith("planes_and_objects: error: ") and completed.stderr.count("\n") == 1

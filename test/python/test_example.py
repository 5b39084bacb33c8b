# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""examples/python/segment_depth_png.py runs on a depth PNG and prints its planes."""

import os
import pathlib
import re
import subprocess
import sys

import numpy as np

import floodplane
from conftest import two_plane_scene

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

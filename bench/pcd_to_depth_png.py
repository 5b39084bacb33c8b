#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Converts a rendered scene (pcd_synth's <scene>.<sensor>.pcd and .planes.json) into the
depth image a camera would have given: a 16-bit PNG of z in units of 1/depth_scale metres
(0 = no return), and the scene camera's intrinsics. Prints "fx,fy,cx,cy" for --intrinsics.

    /usr/bin/python3 bench/pcd_to_depth_png.py scene.kinect.pcd scene.kinect.png [--depth-scale 5000]
"""

import argparse
import json
import pathlib
import sys

import numpy as np

from bench_common import ROOT, use_build_tree


def scene_intrinsics(pcd_path):
    """fx, fy, cx, cy of the camera that rendered `pcd_path` (its .planes.json)."""
    planes_json = pathlib.Path(str(pcd_path)[:-len(".pcd")] + ".planes.json")
    camera = json.loads(planes_json.read_text())["camera"]
    return camera["fx"], camera["fy"], camera["cx"], camera["cy"]


def depth_units(points, depth_scale):
    """z of every point in units (rounded), 0 where there is no return or z is out of range.
    Returns the uint16 image and the number of points that did not fit."""
    z = points[..., 2].astype(np.float64)
    units = np.round(np.nan_to_num(z, nan=0.0) * depth_scale)
    too_far = units > 65535
    units[too_far | (units < 0)] = 0
    return units.astype(np.uint16), int(too_far.sum())


def convert(floodplane, pcd_path, png_path, depth_scale):
    """Writes the depth PNG of `pcd_path`; returns (intrinsics, points that did not fit)."""
    points = floodplane.read_pcd(str(pcd_path))
    depth, lost = depth_units(points, depth_scale)
    floodplane.write_depth_png(str(png_path), depth)
    return scene_intrinsics(pcd_path), lost


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pcd", type=pathlib.Path)
    parser.add_argument("png", type=pathlib.Path)
    parser.add_argument("--depth-scale", type=float, default=5000.0, help="units per metre (TUM: 5000)")
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    arguments = parser.parse_args()
    use_build_tree(arguments.build)
    import floodplane

    intrinsics, lost = convert(floodplane, arguments.pcd, arguments.png, arguments.depth_scale)
    if lost:
        print(f"pcd_to_depth_png: {lost} points beyond {65535 / arguments.depth_scale:.1f} m left out", file=sys.stderr)
    print(",".join(f"{value:g}" for value in intrinsics))
    return 0


if __name__ == "__main__":
    sys.exit(main())

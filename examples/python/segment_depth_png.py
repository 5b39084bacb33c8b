#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Segments a 16-bit depth PNG (a Kinect's, a RealSense's, the TUM RGB-D benchmark's) into
planes and prints them; optionally writes the labelled points as a PCD file.

    segment_depth_png.py depth.png --intrinsics 525,525,319.5,239.5 --depth-scale 5000
"""

import argparse
import sys

import floodplane


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("depth", help="16-bit greyscale PNG, 0 = no return")
    parser.add_argument("--intrinsics", required=True, help="fx,fy,cx,cy of the depth camera [pixels]")
    parser.add_argument("--depth-scale", type=float, default=1000.0,
                        help="units per metre (1000: millimetres, the default; 5000: TUM)")
    parser.add_argument("--labels", help="also write the points and their plane labels to this .pcd file")
    arguments = parser.parse_args()
    try:
        arguments.intrinsics = [float(value) for value in arguments.intrinsics.split(",")]
    except ValueError:
        parser.error(f"--intrinsics: not four numbers: {arguments.intrinsics}")
    if len(arguments.intrinsics) != 4:
        parser.error(f"--intrinsics needs fx,fy,cx,cy, got {len(arguments.intrinsics)} values")
    return arguments


def main():
    arguments = parse_arguments()
    fx, fy, cx, cy = arguments.intrinsics
    try:
        depth = floodplane.read_depth_png(arguments.depth)
        points = floodplane.depth_to_points(depth, fx, fy, cx, cy, depth_scale=arguments.depth_scale)
        result = floodplane.segment(points)
        if arguments.labels:
            floodplane.write_labels_pcd(arguments.labels, points, result.labels)
    except (OSError, ValueError) as error:
        print(f"segment_depth_png: error: {error}", file=sys.stderr)
        return 1

    height, width = depth.shape
    print(f"{arguments.depth}: {width}x{height}, {len(result.planes)} planes, {result.ms:.1f} ms")
    for plane in result.planes:
        nx, ny, nz = plane.normal
        x, y, z = plane.centroid
        print(f"  plane {plane.label}: {plane.inliers} pixels, normal ({nx:+.3f}, {ny:+.3f}, {nz:+.3f}), "
              f"d {plane.d:+.3f} m, centroid ({x:+.2f}, {y:+.2f}, {z:+.2f}) m")
    return 0


if __name__ == "__main__":
    sys.exit(main())

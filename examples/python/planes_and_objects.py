#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Segments an organized PCD file into planes, says what each plane is (floor, wall, table top,
...) given the up direction, and lists the objects standing on the planes.

    planes_and_objects.py frame.pcd [--up 0,-1,0]
"""

import argparse
import sys

import floodplane


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cloud", help="an organized PCD file (x y z; NaN = no return)")
    parser.add_argument("--up", default="0,-1,0",
                        help="the up direction in the cloud's frame (default 0,-1,0: a level camera, y down)")
    arguments = parser.parse_args()
    try:
        arguments.up = [float(value) for value in arguments.up.split(",")]
    except ValueError:
        parser.error(f"--up: not three numbers: {arguments.up}")
    if len(arguments.up) != 3:
        parser.error(f"--up needs x,y,z, got {len(arguments.up)} values")
    return arguments


def main():
    arguments = parse_arguments()
    path, up = arguments.cloud, arguments.up
    try:
        points = floodplane.read_pcd(path)                 # float32 (H, W, 3), NaN = no return
        result = floodplane.segment(points, objects=True)  # keywords: the parameters (docs/parameters.md)
        classes = floodplane.describe_planes(result, up=up)
    except (OSError, ValueError) as error:
        print(f"planes_and_objects: error: {error}", file=sys.stderr)
        return 1
    print(f"{path}: {len(result.planes)} planes, {len(result.objects)} objects")
    for plane, what in zip(result.planes, classes):  # largest first; result.labels: 0 no plane, 1..K
        nx, ny, nz = plane.normal
        print(f"  plane {plane.label}: {what.plane_class}, {plane.inliers} pixels, normal ({nx:+.3f}, {ny:+.3f}, "
              f"{nz:+.3f}), d {plane.d:+.3f} m, {what.height_above_floor:+.2f} m above the floor")
    for obj in result.objects:  # result.object_labels: 0 no object, 1..K
        x, y, z = obj.centroid
        print(f"  object {obj.id}: {obj.pixels} pixels at ({x:+.2f}, {y:+.2f}, {z:+.2f}) m, on plane {obj.support}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

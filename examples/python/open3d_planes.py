#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Segments a depth image read with Open3D into planes and gives them back as Open3D geometry:
prints each plane and its box, writes the points coloured by plane as a PLY file, and shows
the cloud with the boxes on request.

    open3d_planes.py depth.png --intrinsics 525,525,319.5,239.5 --depth-scale 5000 -o planes.ply
    open3d_planes.py depth.png --color rgb.png --intrinsics 525,525,319.5,239.5 --show

With --color, depth and colour become an Open3D RGBDImage (segment_rgbd_image); without, the
depth becomes a PointCloud on its image grid (segment_point_cloud).
"""

import argparse
import os
import sys
import tempfile

import numpy as np
import open3d as o3d

import floodplane.open3d


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("depth", help="16-bit greyscale PNG, 0 = no return")
    parser.add_argument("--color", help="the colour image of the same size (RGBDImage path)")
    parser.add_argument("--intrinsics", required=True, help="fx,fy,cx,cy of the depth camera [pixels]")
    parser.add_argument("--depth-scale", type=float, default=1000.0,
                        help="units per metre (1000: millimetres, the default; 5000: TUM)")
    parser.add_argument("--depth-trunc", type=float, default=100.0,
                        help="depths beyond this [m] are no return (Open3D's truncation; default 100)")
    parser.add_argument("-o", "--output", help="write the points coloured by plane to this .ply file")
    parser.add_argument("--show", action="store_true", help="open a window with the cloud and the boxes")
    arguments = parser.parse_args()
    try:
        arguments.intrinsics = [float(value) for value in arguments.intrinsics.split(",")]
    except ValueError:
        parser.error(f"--intrinsics: not four numbers: {arguments.intrinsics}")
    if len(arguments.intrinsics) != 4:
        parser.error(f"--intrinsics needs fx,fy,cx,cy, got {len(arguments.intrinsics)} values")
    return arguments


def read_image(path):
    """Open3D's image of `path`; OSError when it cannot read it (Open3D only warns)."""
    image = o3d.io.read_image(path)
    if image.is_empty():
        raise OSError(f"cannot read the image '{path}'")
    return image


def segment(arguments):
    depth = read_image(arguments.depth)
    height, width = np.asarray(depth).shape[:2]
    intrinsic = o3d.camera.PinholeCameraIntrinsic(width, height, *arguments.intrinsics)
    if arguments.color:
        rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(
            read_image(arguments.color), depth, depth_scale=arguments.depth_scale, depth_trunc=arguments.depth_trunc,
            convert_rgb_to_intensity=False)
        return floodplane.open3d.segment_rgbd_image(rgbd, intrinsic)
    cloud = o3d.geometry.PointCloud.create_from_depth_image(
        depth, intrinsic, depth_scale=arguments.depth_scale, depth_trunc=arguments.depth_trunc,
        project_valid_depth_only=False)
    return floodplane.open3d.segment_point_cloud(cloud, intrinsic)


def write_cloud(path, cloud):
    """Writes `cloud` to `path` whole or not at all: to a temporary next to it, then renamed."""
    folder, name = os.path.split(os.path.abspath(path))
    descriptor, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=".ply", dir=folder)
    os.close(descriptor)
    try:
        if not o3d.io.write_point_cloud(temporary, cloud):
            raise OSError(f"cannot write '{path}'")
        os.replace(temporary, path)
    finally:
        if os.path.exists(temporary):
            os.remove(temporary)


def main():
    arguments = parse_arguments()
    o3d.utility.set_verbosity_level(o3d.utility.VerbosityLevel.Error)  # a failed read is ours to report
    try:
        planes = segment(arguments)
        if arguments.output:
            write_cloud(arguments.output, planes.cloud)
    except (OSError, ValueError, TypeError) as error:
        print(f"open3d_planes: error: {error}", file=sys.stderr)
        return 1

    result = planes.segmentation
    print(f"{arguments.depth}: {result.width}x{result.height}, {len(result.planes)} planes, {result.ms:.1f} ms")
    for plane, box in zip(result.planes, planes.boxes):
        nx, ny, nz = plane.normal
        length, width, thickness = box.extent
        print(f"  plane {plane.label}: {plane.inliers} pixels, normal ({nx:+.3f}, {ny:+.3f}, {nz:+.3f}), "
              f"d {plane.d:+.3f} m, box {length:.2f} x {width:.2f} x {thickness:.3f} m")
    if arguments.show:
        o3d.visualization.draw_geometries([planes.cloud, *planes.boxes], window_name="floodplane")
    return 0


if __name__ == "__main__":
    sys.exit(main())

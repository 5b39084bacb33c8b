# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Open3D in, Open3D out: segments an Open3D point cloud made from a depth image, or an
RGBDImage with its intrinsics, and gives the planes back as Open3D geometry, in the form of
Open3D's own PointCloud.detect_planar_patches (one coloured OrientedBoundingBox per plane,
its third axis the plane's normal) and a point cloud coloured by plane.

    import open3d as o3d
    import floodplane.open3d

    rgbd = o3d.geometry.RGBDImage.create_from_color_and_depth(color, depth)   # metres
    planes = floodplane.open3d.segment_rgbd_image(rgbd, intrinsic)  # a PinholeCameraIntrinsic
    o3d.visualization.draw_geometries([planes.cloud, *planes.boxes])
    planes.segmentation.planes[0].normal                           # the floodplane result

Needs Open3D (Debian: python3-open3d; pip: open3d); `import floodplane` alone does not
import it. floodplane needs the image grid a cloud came from: a PointCloud made with
create_from_depth_image(..., project_valid_depth_only=False) and the camera's frame (no
extrinsic), together with its height and width.
"""

from typing import List, NamedTuple

import numpy as np

try:
    import open3d as _open3d
except ImportError as error:
    raise ImportError("floodplane.open3d needs Open3D's Python module: apt install python3-open3d (Debian) or "
                      "pip install open3d") from error

from . import Segmentation, depth_to_points, label_colors, segment

__all__ = ["PlaneGeometry", "geometry", "segment_point_cloud", "segment_rgbd_image"]


class PlaneGeometry(NamedTuple):
    """The planes of one frame, as floodplane found them and as Open3D draws them."""

    segmentation: Segmentation
    """The floodplane result: labels (H, W), planes (largest first), noise, stats."""
    cloud: "_open3d.geometry.PointCloud"
    """The frame's points with a depth, each in its plane's colour (label_colors: the colours
    of pcd_segment's PNG files; near-black for no plane)."""
    boxes: List["_open3d.geometry.OrientedBoundingBox"]
    """boxes[k] for segmentation.planes[k], in its colour: axes R[:, 0] and R[:, 1] in the
    plane (the longer first), R[:, 2] its normal (towards the camera); extent the inliers'
    spread along them (the third: their thickness); tight around the inliers."""
    point_labels: np.ndarray
    """uint32 (N,): the plane label of each point of cloud (0: none)."""
    pixels: np.ndarray
    """int64 (N,): the pixel (row * W + column) each point of cloud comes from."""


def geometry(segmentation, points):
    """The Open3D geometry of `segmentation`, the result of segmenting `points` (H, W, 3)."""
    points = np.asarray(points, dtype=np.float64)
    labels = segmentation.labels
    if points.shape != labels.shape + (3,):
        raise ValueError(f"geometry: points must have shape {labels.shape + (3,)} (the segmentation's grid), "
                         f"got {points.shape}")
    flat_points = points.reshape(-1, 3)
    flat_labels = labels.reshape(-1)
    pixels = np.flatnonzero(np.isfinite(flat_points).all(axis=1) & ~(flat_points == 0).all(axis=1))
    point_labels = flat_labels[pixels]
    cloud = _open3d.geometry.PointCloud(_open3d.utility.Vector3dVector(flat_points[pixels]))
    cloud.colors = _open3d.utility.Vector3dVector(label_colors(point_labels) / 255.0)

    # The inliers of every plane at once: pixels sorted by label, cut where the label changes.
    inliers = np.flatnonzero(flat_labels)
    inliers = inliers[np.argsort(flat_labels[inliers], kind="stable")]
    ends = np.cumsum(np.bincount(flat_labels[inliers], minlength=len(segmentation.planes) + 1)[1:])
    colors = label_colors(np.arange(1, len(segmentation.planes) + 1)) / 255.0
    boxes = []
    for plane, plane_pixels, color in zip(segmentation.planes, np.split(inliers, ends[:-1]), colors):
        boxes.append(_plane_box(plane, flat_points[plane_pixels], color))
    return PlaneGeometry(segmentation, cloud, boxes, point_labels, pixels)


def _plane_box(plane, inliers, color):
    """The box around a plane's inliers in the plane's own axes."""
    inliers = inliers[np.isfinite(inliers).all(axis=1)]
    normal = np.asarray(plane.normal, dtype=np.float64)
    _, vectors = np.linalg.eigh(plane.covariance)
    major = vectors[:, 2] - (vectors[:, 2] @ normal) * normal
    if np.linalg.norm(major) < 1e-9:  # no spread in the plane (never with min_inliers >= 3)
        major = np.cross(normal, [1.0, 0.0, 0.0] if abs(normal[0]) < 0.9 else [0.0, 1.0, 0.0])
    major /= np.linalg.norm(major)
    rotation = np.column_stack([major, np.cross(normal, major), normal])  # right-handed
    local = (inliers - plane.centroid) @ rotation
    low, high = local.min(axis=0), local.max(axis=0)
    box = _open3d.geometry.OrientedBoundingBox(plane.centroid + rotation @ ((low + high) / 2), rotation, high - low)
    box.color = color
    return box


def _grid_shape(shape, function):
    """(H, W) from a pair or from an object with height and width (a PinholeCameraIntrinsic)."""
    if hasattr(shape, "height") and hasattr(shape, "width"):
        height, width = shape.height, shape.width
    else:
        try:
            height, width = shape
        except (TypeError, ValueError):
            raise TypeError(f"{function}: shape must be (height, width) or an object with height and width "
                            f"(a PinholeCameraIntrinsic), got {type(shape).__name__}") from None
    if not all(isinstance(n, (int, np.integer)) and not isinstance(n, bool) and n > 0 for n in (height, width)):
        raise ValueError(f"{function}: the grid's height and width must be integers > 0, got {height!r}, {width!r}")
    return int(height), int(width)


def segment_point_cloud(cloud, shape, *, zero_is_hole=True, **params):
    """Segments an open3d.geometry.PointCloud whose points are an image grid of `shape`,
    (height, width) or the PinholeCameraIntrinsic it was made with, in row order, in the
    camera's frame (metres, the camera at the origin): what
    PointCloud.create_from_depth_image(depth, intrinsic, project_valid_depth_only=False)
    gives. NaN points and, unless zero_is_hole=False, points at (0, 0, 0) are holes.
    `params` are floodplane.Segmenter's. Returns a PlaneGeometry."""
    if not isinstance(cloud, _open3d.geometry.PointCloud):
        raise TypeError(f"segment_point_cloud: cloud must be an open3d.geometry.PointCloud, got {type(cloud).__name__}")
    height, width = _grid_shape(shape, "segment_point_cloud")
    points = np.asarray(cloud.points)
    if len(points) != height * width:
        raise ValueError(f"segment_point_cloud: the cloud has {len(points)} points, not the {height} x {width} = "
                         f"{height * width} of its grid (make it with project_valid_depth_only=False, which keeps "
                         "a point for every pixel)")
    points = points.reshape(height, width, 3)
    return geometry(segment(points, zero_is_hole=zero_is_hole, **params), points)


def segment_rgbd_image(rgbd, intrinsic, *, depth_scale=1.0, **params):
    """Segments the depth of an open3d.geometry.RGBDImage seen through `intrinsic` (an Open3D
    PinholeCameraIntrinsic, a 3 x 3 K or (fx, fy, cx, cy)). An RGBDImage holds metres
    (create_from_color_and_depth divides by its depth_scale and sets depths beyond its
    depth_trunc, 3 m by default, to 0), hence depth_scale=1; 0 is no return. `params` are
    floodplane.Segmenter's. Returns a PlaneGeometry."""
    if not isinstance(rgbd, _open3d.geometry.RGBDImage):
        raise TypeError(f"segment_rgbd_image: rgbd must be an open3d.geometry.RGBDImage, got {type(rgbd).__name__}")
    points = depth_to_points(np.asarray(rgbd.depth), intrinsic, depth_scale=depth_scale)
    return geometry(segment(points, **params), points)

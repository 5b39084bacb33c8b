# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Plane segmentation of organized point clouds by seeded flood fill.

    import floodplane
    points = floodplane.read_pcd("frame.pcd")            # float32 (H, W, 3), NaN = no return
    result = floodplane.segment(points)                  # or Segmenter(**params).segment(points)
    result.labels                                        # uint32 (H, W): 0 no plane, 1..K by size
    for plane in result.planes:
        print(plane.label, plane.normal, plane.d, plane.inliers)

The keyword parameters are the fields of the C++ floodplane::Params (PARAMETER_NAMES); the
lengths default to None, which derives them from each frame's measured noise. Depth images:
segment_depth(), depth_to_points(), read_depth_png(). Many files on a cluster:
floodplane.distributed.segment_files(). A stream of frames: Tracker().update(result) gives
each plane an id that persists from frame to frame.
"""

from ._floodplane import (
    PARAMETER_NAMES,
    NoiseModel,
    PhaseTimes,
    Plane,
    Segmentation,
    SegmentationStats,
    Segmenter,
    Track,
    Tracker,
    __version__,
    depth_to_points,
    read_depth_png,
    read_labels_pcd,
    read_pcd,
    write_depth_png,
    write_labels_pcd,
)

__all__ = [
    "PARAMETER_NAMES",
    "NoiseModel",
    "PhaseTimes",
    "Plane",
    "Segmentation",
    "SegmentationStats",
    "Segmenter",
    "Track",
    "Tracker",
    "__version__",
    "depth_to_points",
    "read_depth_png",
    "read_labels_pcd",
    "read_pcd",
    "segment",
    "segment_depth",
    "segment_file",
    "write_depth_png",
    "write_labels_pcd",
]


def segment(points, **params):
    """Segments points, an (H, W, 3) float32 or float64 array in metres (camera at the origin,
    NaN = no return), with a new Segmenter(**params). Returns a Segmentation. To segment a
    sequence of frames, keep one Segmenter: it reuses its buffers."""
    return Segmenter(**params).segment(points)


def segment_depth(depth, fx, fy, cx, cy, depth_scale=1000.0, **params):
    """Segments a depth image: depth (H, W) of integer units, depth_scale units per metre
    (1000: millimetres; 5000: the TUM RGB-D benchmark), 0 = no return, seen by a pinhole
    camera fx, fy, cx, cy [pixels]. The same as segment(depth_to_points(...), **params)."""
    return segment(depth_to_points(depth, fx, fy, cx, cy, depth_scale), **params)


def segment_file(input, output, *, intrinsics=None, depth_scale=1000.0, **params):
    """Segments the file `input` and writes its labelled cloud to `output`, as pcd_segment
    does (the same bytes): a PCD file, or a 16-bit depth PNG with intrinsics=(fx, fy, cx, cy).
    Returns {'width', 'height', 'planes', 'ms'}."""
    return Segmenter(**params).segment_file(input, output, intrinsics=intrinsics, depth_scale=depth_scale)

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
lengths default to None, which derives them from each frame's measured noise. Points at
exactly (0, 0, 0), the "no depth" of Open3D, RealSense and many ROS drivers, are holes like
NaN ones (zero_is_hole=False segments them as points). Depth images, integer units or float
metres, (H, W) or (H, W, 1): segment_depth(), depth_to_points(), read_depth_png(); their
intrinsics as fx, fy, cx, cy, a 3 x 3 K or Open3D's PinholeCameraIntrinsic. A frame with
no finite point (all NaN, all zero, a depth image of zeros) gives a result with no planes,
not an error. Results pickle.
Many files on a cluster: floodplane.distributed.segment_files(). A stream of frames:
Tracker().update(result) gives each plane an id that persists from frame to frame. What the
planes are (floor, walls, tables), given the up direction: describe_planes(result, up).
Open3D in and out: floodplane.open3d (imported on its own; it needs Open3D).
"""

import os as _os

import numpy as _numpy

from ._floodplane import (
    PARAMETER_NAMES,
    NoiseModel,
    Object,
    PhaseTimes,
    Plane,
    PlaneDescription,
    Segmentation,
    SegmentationStats,
    Segmenter,
    Track,
    Tracker,
    __version__,
    _label_color_table,
    depth_to_points,
    describe_planes,
    read_depth_png,
    read_labels_pcd,
    read_pcd,
    write_depth_png,
    write_labels_pcd,
)

__all__ = [
    "PARAMETER_NAMES",
    "NoiseModel",
    "Object",
    "PhaseTimes",
    "Plane",
    "PlaneDescription",
    "Segmentation",
    "SegmentationStats",
    "Segmenter",
    "Track",
    "Tracker",
    "__version__",
    "depth_to_points",
    "describe_planes",
    "json_name",
    "label_colors",
    "read_depth_png",
    "read_labels_pcd",
    "read_pcd",
    "segment",
    "segment_depth",
    "segment_file",
    "write_depth_png",
    "write_labels_pcd",
]


def segment(points, *, zero_is_hole=True, objects=False, **params):
    """Segments points, (H, W, 3) x y z in metres (camera at the origin, NaN = no return), with a
    new Segmenter(**params). points is anything numpy.asarray makes an array of real numbers of:
    float32 is read in place, other floats, integers and nested lists or tuples of numbers are
    converted. Points at exactly (0, 0, 0) are no return too unless zero_is_hole=False.
    Returns a Segmentation. A frame with no finite point (all NaN, all zero) or fewer than
    three is valid: its Segmentation has no planes and labels all 0 (not an error). To segment
    a sequence of frames, keep one Segmenter: it reuses its buffers. objects=True also finds the
    objects standing on the planes (the result's object_labels and objects; None without)."""
    return Segmenter(**params).segment(points, zero_is_hole=zero_is_hole, objects=objects)


def segment_depth(depth, intrinsics, fy=None, cx=None, cy=None, depth_scale=None, *, objects=False, **params):
    """Segments a depth image: segment_depth(depth, fx, fy, cx, cy) or segment_depth(depth, K).
    depth is (H, W) or (H, W, 1), any array or nested list numpy.asarray makes one of: integer
    units (millimetres: Kinect, RealSense, ROS 16UC1; a list of ints is int64, so units too)
    or float (metres: Open3D, ROS 32FC1); depth_scale is units per metre (default 1000 for
    integers, 1 for floats; 5000 for the TUM RGB-D benchmark's PNG files); 0, NaN and
    infinity are no return. intrinsics: fx, fy, cx, cy [pixels], a 3 x 3 matrix K or an Open3D
    PinholeCameraIntrinsic. The same as segment(depth_to_points(...), objects=objects, **params)."""
    return segment(depth_to_points(depth, intrinsics, fy, cx, cy, depth_scale), objects=objects, **params)


def segment_file(input, output, *, intrinsics=None, depth_scale=1000.0, objects_output=None, **params):
    """Segments the file `input` and writes its labelled cloud to `output`, as pcd_segment
    does (the same bytes): a PCD file, or a 16-bit depth PNG with intrinsics ((fx, fy, cx, cy),
    a 3 x 3 K or an Open3D PinholeCameraIntrinsic). With objects_output, also writes the objects
    standing on the planes there, as pcd_segment --objects does (x y z label: object ids 1..K,
    0 none). Returns {'width', 'height', 'planes', 'ms'} and, with objects_output, 'objects'
    (how many)."""
    return Segmenter(**params).segment_file(
        input, output, intrinsics=intrinsics, depth_scale=depth_scale, objects_output=objects_output
    )


def json_name(path):
    """The file name `path` (str, bytes or os.PathLike) as pcd_segment's and pcd_compare's JSON
    reports write it: its bytes (os.fsencode) as UTF-8, each ill-formed sequence replaced with
    U+FFFD, their writers' rule for a name that is not UTF-8. To find a file in their reports,
    and for the JSON a script writes about files: json.dumps of a name that os.fsdecode made of
    such bytes writes lone surrogates ("\\udce9"), which strict JSON readers refuse."""
    return _os.fsencode(path).decode("utf-8", "replace")


def label_colors(labels):
    """The colour of each label as pcd_segment's PNG files show it: uint8 (..., 3), R G B, for
    an integer array of labels (0, no plane, near-black). For pictures of result.labels, or of
    Tracker.relabel's track ids."""
    labels = _numpy.asarray(labels)
    if labels.dtype.kind not in "ui":
        raise TypeError(f"label_colors: labels must be an integer array, got dtype {labels.dtype}")
    if labels.size and (labels.min() < 0 or labels.max() > 0xFFFFFFFF):
        raise ValueError("label_colors: labels must be in [0, 4294967295], got values in "
                         f"[{labels.min()}, {labels.max()}]")
    values, inverse = _numpy.unique(labels, return_inverse=True)
    return _label_color_table(values.astype(_numpy.uint32))[inverse].reshape(labels.shape + (3,))

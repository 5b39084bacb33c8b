# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Points at (0, 0, 0), the "no depth" of Open3D, RealSense and many ROS drivers, are holes
as NaN points are, unless zero_is_hole=False; the caller's array is never changed."""

import numpy as np
import pytest

import floodplane
from conftest import real_frames, two_plane_scene


def noisy_scene_with_dropouts(hole_value):
    """The two-plane scene at 320 x 240 with 0.3 % range noise and 5 % of its pixels dropped
    (set to `hole_value`) at random, as a depth camera drops them."""
    rng = np.random.default_rng(7)
    points = two_plane_scene(320, 240).astype(np.float64)
    points *= 1 + rng.normal(0, 0.003, points.shape[:2])[..., None]
    points = points.astype(np.float32)
    points[rng.random(points.shape[:2]) < 0.05] = hole_value
    return points


def test_zero_points_are_holes_like_nan_points():
    with_nan = floodplane.segment(noisy_scene_with_dropouts(np.nan))
    zeros = noisy_scene_with_dropouts(0.0)
    before = zeros.copy()
    with_zeros = floodplane.segment(zeros)
    assert len(with_nan.planes) == 2
    np.testing.assert_array_equal(with_zeros.labels, with_nan.labels)
    assert with_zeros.noise.patches == with_nan.noise.patches
    # Segmenter.segment does the same, and -0.0 is a zero too.
    np.testing.assert_array_equal(floodplane.Segmenter().segment(zeros).labels, with_nan.labels)
    np.testing.assert_array_equal(floodplane.segment(np.where(zeros == 0, np.float32(-0.0), zeros)).labels,
                                  with_nan.labels)
    # The caller's array keeps its zeros.
    np.testing.assert_array_equal(zeros, before)
    assert (zeros == 0).all(axis=-1).sum() > 3000


def test_zero_is_hole_false_segments_zeros_as_points():
    with_nan = floodplane.segment(noisy_scene_with_dropouts(np.nan))
    zeros = noisy_scene_with_dropouts(0.0)
    as_points = floodplane.segment(zeros, zero_is_hole=False)
    assert (as_points.labels != with_nan.labels).any()
    np.testing.assert_array_equal(floodplane.Segmenter().segment(zeros, zero_is_hole=False).labels, as_points.labels)


@pytest.mark.parametrize("layout", ["float32", "float64", "Fortran order", "x y z of an (H, W, 4) array"])
def test_every_layout_has_its_zeros_made_holes(layout):
    zeros = noisy_scene_with_dropouts(0.0)
    expected = floodplane.segment(noisy_scene_with_dropouts(np.nan)).labels
    if layout == "float64":
        points = zeros.astype(np.float64)
    elif layout == "Fortran order":
        points = np.asfortranarray(zeros)
    elif layout == "x y z of an (H, W, 4) array":
        wide = np.ones(zeros.shape[:2] + (4,), np.float32)
        wide[..., :3] = zeros
        points = wide[..., :3]
    else:
        points = zeros
    before = points.copy()
    np.testing.assert_array_equal(floodplane.segment(points).labels, expected)
    np.testing.assert_array_equal(points, before)


def test_a_point_with_one_zero_coordinate_is_a_point():
    # Points on the plane x = 0 (the image's middle column, here) are real points.
    points = two_plane_scene(161, 120)
    assert (points[:, 80, 0] == 0).all()
    result = floodplane.segment(points)
    assert (result.labels[:, 80][np.isfinite(points[:, 80, 2])] > 0).all()


def test_a_real_frame_with_zeros_for_nan_gives_the_same_planes():
    frames = [frame for frame in real_frames() if frame.name == "office1.pcd"]
    if not frames:
        pytest.skip("no real data (FLOODPLANE_REAL_DATA_DIR)")
    points = floodplane.read_pcd(str(frames[0]))
    with_nan = floodplane.segment(points)
    zeros = np.nan_to_num(points, nan=0.0)
    np.testing.assert_array_equal(floodplane.segment(zeros).labels, with_nan.labels)
    # office1 is where it showed: one more plane when the zeros are taken for points.
    assert len(floodplane.segment(zeros, zero_is_hole=False).planes) != len(with_nan.planes)

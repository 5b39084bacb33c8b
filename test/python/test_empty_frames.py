# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The rule for empty frames, the same in Python, pcd_segment, pcd_compare and the ROS node: a
frame with no finite point (all NaN; all (0, 0, 0) where zero means no depth) or too few to
hold a plane is a valid frame with no planes, an empty result and not an error. Malformed
input (not an image grid, a wrong shape or dtype) stays an error (test_errors.py)."""

import pickle

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene

FACTORS = [1, 2, 4, 8]


def with_finite_points(height, width, count):
    """A flat frame at 2 m of which only the first `count` points are finite."""
    v, u = np.mgrid[0:height, 0:width]
    z = np.full((height, width), 2.0)
    points = np.stack([(u - width / 2) * z / 500, (v - height / 2) * z / 500, z], -1)
    points.reshape(-1, 3)[count:] = np.nan
    return points


EMPTY = {
    "all NaN": np.full((30, 40, 3), np.nan, np.float32),
    "all zero (no depth)": np.zeros((30, 40, 3), np.float32),
    "NaN and zeros": np.where(np.arange(1200).reshape(30, 40, 1) % 2, np.nan, np.zeros((30, 40, 3))),
    "2 x 2, all NaN": np.full((2, 2, 3), np.nan),
    "2 x 1, all NaN": np.full((2, 1, 3), np.nan),
    "two finite points": with_finite_points(30, 40, 2),
    "2 x 2 with two finite points": with_finite_points(2, 2, 2),
    "a column of two finite points": with_finite_points(2, 1, 2),
}


def assert_no_planes(result, height, width):
    assert result.planes == []
    assert result.labels.shape == (height, width) and result.labels.dtype == np.uint32
    assert not result.labels.any()
    assert (result.width, result.height) == (width, height)


@pytest.mark.parametrize("factor", FACTORS)
@pytest.mark.parametrize("name", list(EMPTY))
def test_a_frame_without_a_plane_to_hold_is_an_empty_result(name, factor):
    points = EMPTY[name]
    assert_no_planes(floodplane.segment(points, subsampling=factor), *points.shape[:2])
    assert_no_planes(floodplane.Segmenter(subsampling=factor).segment(points, refine=False), *points.shape[:2])


@pytest.mark.parametrize("factor", FACTORS)
def test_depth_images_of_no_return_are_empty_results(factor):
    for depth in (np.zeros((30, 40), np.uint16), np.zeros((2, 2), np.uint16), np.full((30, 40), np.nan),
                  np.full((30, 40, 1), np.inf, np.float32), [[0, 0], [0, 0]]):
        shape = np.shape(depth)[:2]
        assert_no_planes(floodplane.segment_depth(depth, 500.0, 500.0, 20.0, 15.0, subsampling=factor), *shape)


@pytest.mark.parametrize("factor", FACTORS)
@pytest.mark.parametrize("shape", [(2, 2), (2, 1), (9, 1), (2, 3), (3, 3)])
def test_tiny_frames_are_segmented_without_an_error(shape, factor):
    # A flat 2 x 2 frame is one plane of 4 points at s = 1 (min_inliers, W H / 1000 by default,
    # rounds to 0 there): tiny frames are segmented as any other, never refused.
    points = with_finite_points(*shape, count=shape[0] * shape[1])
    result = floodplane.segment(points, subsampling=factor)
    assert result.labels.shape == shape
    assert sum(plane.inliers for plane in result.planes) == np.count_nonzero(result.labels)


def test_an_empty_frame_in_a_stream_leaves_the_next_frame_as_it_was():
    scene = two_plane_scene()
    segmenter, tracker = floodplane.Segmenter(), floodplane.Tracker()
    before = segmenter.segment(scene)
    ids = tracker.update(before)
    empty = segmenter.segment(np.full_like(scene, np.nan), head_start=True)
    assert_no_planes(empty, *scene.shape[:2])
    assert tracker.update(empty) == []
    assert not tracker.relabel(empty.labels).any()
    after = segmenter.segment(scene, head_start=True)
    np.testing.assert_array_equal(after.labels, before.labels)
    assert tracker.update(after) == ids, "the planes keep their tracks across the empty frame"


def test_an_empty_result_pickles_and_its_noise_is_a_model():
    result = floodplane.segment(EMPTY["all NaN"])
    again = pickle.loads(pickle.dumps(result))
    assert_no_planes(again, 30, 40)
    assert result.noise is not None


def test_an_empty_file_frame_is_written_with_no_planes(tmp_path):
    floodplane.write_labels_pcd(str(tmp_path / "nan.pcd"), EMPTY["all NaN"], np.zeros((30, 40), np.uint32))
    summary = floodplane.segment_file(str(tmp_path / "nan.pcd"), str(tmp_path / "out.pcd"))
    assert summary["planes"] == 0 and (summary["width"], summary["height"]) == (40, 30)
    assert not floodplane.read_labels_pcd(str(tmp_path / "out.pcd")).any()

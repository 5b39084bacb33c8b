# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Results pickle (so that Dask and multiprocessing can move them): a Segmentation, its
planes, noise model, phase times and stats, a Track and a Segmenter come back equal, and a
state that does not fit together is refused with ValueError, not read out of bounds."""

import copy
import pickle

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene

PROTOCOLS = range(2, pickle.HIGHEST_PROTOCOL + 1)


def round_trip(value, protocol=pickle.HIGHEST_PROTOCOL):
    return pickle.loads(pickle.dumps(value, protocol=protocol))


def assert_same_plane(copied, plane):
    assert type(copied) is floodplane.Plane
    assert (copied.label, copied.inliers, copied.first_pixel) == (plane.label, plane.inliers, plane.first_pixel)
    for name in ("normal", "centroid", "covariance", "eigenvalues"):
        np.testing.assert_array_equal(getattr(copied, name), getattr(plane, name), err_msg=name)
    for name in ("d", "mean_squared_error", "curvature"):
        assert getattr(copied, name) == getattr(plane, name), name


def assert_same_fields(copied, original, names):
    assert type(copied) is type(original)
    for name in names:
        assert getattr(copied, name) == getattr(original, name), name


NOISE_FIELDS = ("sigma_constant", "sigma_quadratic", "step_constant", "step_quadratic", "patches", "estimated")
PHASE_FIELDS = ("preparation", "seed_selection", "flood_fill", "relabelling", "merging", "region_output",
                "pcl_conversion", "total")
STATS_FIELDS = ("seed_candidates", "seeds", "pixels_taken_over", "segments", "merges", "head_start")


def assert_same_segmentation(copied, result):
    assert type(copied) is floodplane.Segmentation
    assert (copied.width, copied.height, copied.ms) == (result.width, result.height, result.ms)
    np.testing.assert_array_equal(copied.labels, result.labels)
    assert copied.labels.dtype == np.uint32 and not copied.labels.flags.writeable
    assert len(copied.planes) == len(result.planes)
    for index, (a, b) in enumerate(zip(copied.planes, result.planes)):
        assert_same_plane(a, b)
        np.testing.assert_array_equal(copied.boundary(index), result.boundary(index))
    assert_same_fields(copied.noise, result.noise, NOISE_FIELDS)
    assert_same_fields(copied.phases, result.phases, PHASE_FIELDS)
    assert_same_fields(copied.stats, result.stats, STATS_FIELDS)
    assert repr(copied) == repr(result)


@pytest.mark.parametrize("protocol", PROTOCOLS)
def test_a_segmentation_comes_back_equal(protocol):
    result = floodplane.Segmenter().segment(two_plane_scene(), measure_phases=True)
    assert result.phases.total > 0 and len(result.planes) == 2
    assert_same_segmentation(round_trip(result, protocol), result)


def test_copies_are_deep_and_independent():
    result = floodplane.segment(two_plane_scene())
    assert_same_segmentation(copy.deepcopy(result), result)
    assert_same_segmentation(copy.copy(result), result)


def test_a_segmentation_without_planes_comes_back():
    result = floodplane.segment(np.full((6, 8, 3), np.nan, np.float32))
    copied = round_trip(result)
    assert copied.planes == [] and copied.labels.shape == (6, 8) and not copied.labels.any()


def test_its_parts_pickle_alone():
    result = floodplane.segment(two_plane_scene(), depth_noise_coefficient=0.0015)
    for plane in result.planes:
        assert_same_plane(round_trip(plane), plane)
    assert_same_fields(round_trip(result.noise), result.noise, NOISE_FIELDS)
    assert_same_fields(round_trip(result.phases), result.phases, PHASE_FIELDS)
    assert_same_fields(round_trip(result.stats), result.stats, STATS_FIELDS)
    # The noise model's methods work on the copy.
    assert round_trip(result.noise).sigma(2.0) == result.noise.sigma(2.0)


def test_a_tracker_takes_unpickled_results_as_the_originals():
    frames = []
    for shift in (0.0, 0.01, 0.02):
        points = two_plane_scene()
        points[..., 2] += shift
        frames.append(floodplane.segment(points))
    original, unpickled = floodplane.Tracker(), floodplane.Tracker()
    for frame in frames:
        assert unpickled.update(round_trip(frame)) == original.update(frame)
    np.testing.assert_array_equal(unpickled.relabel(frames[-1].labels), original.relabel(frames[-1].labels))
    track_fields = ("id", "first_frame", "last_frame", "frames_seen", "plane", "inliers", "offset",
                    "smoothed_offset", "best_inliers", "best_offset")
    for track in original.tracks:
        copied = round_trip(track)
        assert_same_fields(copied, track, track_fields)
        for name in ("normal", "centroid", "smoothed_normal", "best_normal", "best_centroid"):
            np.testing.assert_array_equal(getattr(copied, name), getattr(track, name), err_msg=name)


def test_a_segmenter_pickles_as_its_parameters():
    segmenter = floodplane.Segmenter(min_inliers=50, distance_threshold=0.02, subsampling=2)
    segmenter.segment(two_plane_scene())
    copied = round_trip(segmenter)
    assert copied.params == segmenter.params
    np.testing.assert_array_equal(copied.segment(two_plane_scene()).labels,
                                  segmenter.segment(two_plane_scene()).labels)


def test_a_tracker_does_not_pickle():
    with pytest.raises(TypeError, match="pickle"):
        pickle.dumps(floodplane.Tracker())


def unpickled(cls, state):
    """What pickle does with `state`: a bare object, then __setstate__."""
    value = cls.__new__(cls)
    value.__setstate__(state)
    return value


def test_refuses_states_that_do_not_fit_together():
    result = floodplane.segment(two_plane_scene())
    state = result.__getstate__()
    assert unpickled(floodplane.Segmentation, state).labels.shape == (120, 160)

    def changed(index, value):
        fields = list(state)
        fields[index] = value
        return tuple(fields)

    bad = {
        "another format": ((99,) + state[1:], "not a state of format 1"),
        "a field missing": (state[:-1], "not a state of format 1"),
        "labels of another size": (changed(3, np.zeros((10, 10), np.uint32)), r"labels must have shape \(120, 160\)"),
        "a label without a plane": (changed(3, np.full((120, 160), 3, np.uint32)), r"values in \[0, 2\]"),
        "a negative size": (changed(1, -1), "width and height >= 0"),
        "a plane whose first pixel is outside": (
            changed(4, [state[4][0][:2] + (10**9,), state[4][1]]), "plane 1's first pixel does not carry its label"),
        "a plane that is not a tuple": (changed(4, [1, 2]), "a plane's state must be a tuple"),
        "a field of the wrong type": (changed(8, "fast"), "field 8 has the wrong type"),
    }
    for name, (broken, message) in bad.items():
        with pytest.raises(ValueError, match=message):
            unpickled(floodplane.Segmentation, broken)
    with pytest.raises(ValueError, match="a vector of 3 numbers"):
        plane_state = result.planes[0].__getstate__()
        fit = list(plane_state[1])
        fit[0] = (1.0, 2.0)
        unpickled(floodplane.Plane, (plane_state[0], tuple(fit)) + plane_state[2:])

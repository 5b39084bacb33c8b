# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Points and depth images are taken as numpy.asarray takes them: nested lists and tuples of
numbers (a list of integers is int64), arrays of any float or integer dtype, each giving what
the float32 (points) or uint16 (depth) array of the same values gives. What numpy cannot make
an array of numbers of is refused with the argument's name: a ragged list, text, bool."""

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene

FX = FY = 525.0 * 160 / 640
CX, CY = 79.5, 59.5


def integer_scene():
    """The two-plane scene in whole centimetres, holes as (0, 0, 0): integers numpy can hold in
    any integer dtype, and in float32 exactly."""
    scene = np.nan_to_num(np.round(two_plane_scene() * 100.0))
    return scene.astype(np.int64)


def millimetres():
    return np.nan_to_num(np.round(two_plane_scene()[..., 2] * 1000)).astype(np.uint16)


def test_a_nested_list_of_integers_gives_the_planes_of_its_float_array():
    points = integer_scene()
    expected = floodplane.segment(points.astype(np.float32))
    assert len(expected.planes) == 2
    for name, given in {"list of lists of ints": points.tolist(),
                        "tuples": tuple(tuple(tuple(p) for p in row) for row in points.tolist()),
                        "int64 array": points}.items():
        result = floodplane.segment(given)
        np.testing.assert_array_equal(result.labels, expected.labels, err_msg=name)
        assert [p.inliers for p in result.planes] == [p.inliers for p in expected.planes], name


@pytest.mark.parametrize("dtype", [np.int16, np.int32, np.uint16, np.uint64, np.float16,
                                   np.longdouble])
def test_every_integer_and_float_dtype_is_converted_as_numpy_converts_it(dtype):
    points = integer_scene()
    points = np.clip(points, np.iinfo(dtype).min, np.iinfo(dtype).max) if np.dtype(dtype).kind in "iu" else points
    given = points.astype(dtype)
    expected = floodplane.segment(given.astype(np.float32)).labels
    np.testing.assert_array_equal(floodplane.Segmenter().segment(given).labels, expected)


def test_a_list_of_integer_millimetres_is_depth_in_sensor_units():
    depth = millimetres()
    expected = floodplane.depth_to_points(depth, FX, FY, CX, CY)
    for name, given in {"list of lists": depth.tolist(), "tuples": tuple(map(tuple, depth.tolist())),
                        "int64 array": depth.astype(np.int64), "(H, W, 1) list": depth[..., None].tolist()}.items():
        np.testing.assert_array_equal(floodplane.depth_to_points(given, FX, FY, CX, CY), expected, err_msg=name)
    result = floodplane.segment_depth(depth.tolist(), FX, FY, CX, CY)
    np.testing.assert_array_equal(result.labels, floodplane.segment_depth(depth, FX, FY, CX, CY).labels)
    assert len(result.planes) == 2


def test_an_int64_array_takes_the_depth_scale_given():
    depth = millimetres().astype(np.int64) * 5  # TUM's 5000 units a metre
    expected = floodplane.depth_to_points(millimetres(), FX, FY, CX, CY)
    np.testing.assert_allclose(floodplane.depth_to_points(depth, FX, FY, CX, CY, depth_scale=5000.0), expected,
                               rtol=1e-6)
    assert np.nanmax(floodplane.depth_to_points(depth, FX, FY, CX, CY)[..., 2]) > 9.0, "default: millimetres"


def test_a_list_of_floats_is_depth_in_metres():
    metres = two_plane_scene()[..., 2].astype(np.float64)
    np.testing.assert_array_equal(floodplane.depth_to_points(metres.tolist(), FX, FY, CX, CY),
                                  floodplane.depth_to_points(metres, FX, FY, CX, CY))


def test_files_take_lists_too(tmp_path):
    depth = millimetres()
    floodplane.write_depth_png(str(tmp_path / "depth.png"), depth.tolist())
    np.testing.assert_array_equal(floodplane.read_depth_png(str(tmp_path / "depth.png")), depth)
    points = integer_scene()
    labels = np.arange(points.shape[0] * points.shape[1], dtype=np.int64).reshape(points.shape[:2]) % 7
    floodplane.write_labels_pcd(str(tmp_path / "labels.pcd"), points.tolist(), labels.tolist())
    np.testing.assert_array_equal(floodplane.read_labels_pcd(str(tmp_path / "labels.pcd")), labels)
    np.testing.assert_array_equal(floodplane.read_pcd(str(tmp_path / "labels.pcd")), points.astype(np.float32))


RAGGED = [[[0, 0, 1], [1, 0, 1]], [[0, 1, 1]]]


@pytest.mark.parametrize("call", [
    lambda: floodplane.segment(RAGGED),
    lambda: floodplane.Segmenter().segment(RAGGED),
])
def test_a_ragged_list_of_points_is_a_value_error_with_numpys_reason(call):
    with pytest.raises(ValueError, match=r"points must be an array of shape \(H, W, 3\); numpy cannot make an "
                                         r"array of this list: .*inhomogeneous"):
        call()


def test_a_ragged_depth_list_is_a_value_error_with_numpys_reason(tmp_path):
    ragged = [[1000, 1000], [1000]]
    with pytest.raises(ValueError, match=r"depth_to_points: depth must be .*numpy cannot make an array of this list"):
        floodplane.depth_to_points(ragged, FX, FY, CX, CY)
    with pytest.raises(ValueError, match=r"write_depth_png: depth must be .*numpy cannot make an array of this list"):
        floodplane.write_depth_png(str(tmp_path / "d.png"), ragged)
    assert not (tmp_path / "d.png").exists()


@pytest.mark.parametrize("points, error, message", [
    ([[["0", "0", "1"]] * 2] * 2, TypeError, "points must hold real numbers .*got dtype <U1"),
    ([[[True, False, True]] * 2] * 2, TypeError, "got dtype bool"),
    ([[[1j, 0, 1]] * 2] * 2, TypeError, "got dtype complex128"),
    ([[[None, 0, 1]] * 2] * 2, TypeError, "got dtype object"),
    ([[0, 0, 1], [0, 0, 1]], ValueError, r"points must have shape \(H, W, 3\), got \(2, 3\)"),
    ([[[[0, 0, 1]]] * 2] * 2, ValueError, r"got \(2, 2, 1, 3\)"),
    ([[[0, 0, 1, 1]] * 2] * 2, ValueError, r"got \(2, 2, 4\)"),
])
def test_lists_numpy_cannot_make_points_of_are_refused(points, error, message):
    with pytest.raises(error, match=message):
        floodplane.segment(points)


@pytest.mark.parametrize("depth, error, message", [
    ([["1000", "1000"]] * 2, TypeError, "depth must be an integer or floating-point array, got dtype <U4"),
    ([[True, False]] * 2, TypeError, "got dtype bool"),
    ([1000, 1000, 1000], ValueError, r"depth must have shape \(H, W\) or \(H, W, 1\), got \(3,\)"),
    ([[[1000, 1000]]] * 2, ValueError, r"got \(2, 1, 2\)"),
    ([[1000, -1]] * 2, ValueError, "depth must not be negative, got -1 at row 0, column 1"),
])
def test_lists_numpy_cannot_make_depth_of_are_refused(depth, error, message):
    with pytest.raises(error, match=message):
        floodplane.depth_to_points(depth, FX, FY, CX, CY)

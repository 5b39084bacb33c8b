# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Depth images as Open3D, ROS and RealSense users hold them: float metres as well as integer
units, (H, W) and (H, W, 1), and intrinsics as four numbers, a 3 x 3 K or an object with
intrinsic_matrix (Open3D's PinholeCameraIntrinsic, imitated here so that these tests need no
Open3D)."""

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene

FX = FY = 525.0 * 160 / 640
CX, CY = 79.5, 59.5
K = [[FX, 0.0, CX], [0.0, FY, CY], [0.0, 0.0, 1.0]]


class PinholeIntrinsic:
    """What floodplane reads of Open3D's PinholeCameraIntrinsic."""

    def __init__(self, width, height, matrix=K):
        self.width, self.height = width, height
        self.intrinsic_matrix = np.array(matrix)


def millimetres():
    """The two-plane scene's depth in millimetres, 0 in its hole."""
    return np.nan_to_num(np.round(two_plane_scene()[..., 2] * 1000)).astype(np.uint16)


def test_float_metres_give_the_points_of_integer_millimetres():
    depth = millimetres()
    expected = floodplane.depth_to_points(depth, FX, FY, CX, CY)  # 1000 units a metre
    # depth / 1000 in float64 is the division the integer path does: the same bits.
    np.testing.assert_array_equal(floodplane.depth_to_points(depth / 1000.0, FX, FY, CX, CY), expected)
    metres32 = (depth / 1000.0).astype(np.float32)
    np.testing.assert_allclose(floodplane.depth_to_points(metres32, FX, FY, CX, CY), expected, rtol=1e-6)
    # An explicit depth_scale holds for floats too (float millimetres).
    np.testing.assert_array_equal(
        floodplane.depth_to_points(depth.astype(np.float64), FX, FY, CX, CY, depth_scale=1000.0), expected)
    # And for integers it still divides (TUM's 5000 a metre).
    tum = floodplane.depth_to_points(depth, FX, FY, CX, CY, depth_scale=5000.0)
    np.testing.assert_allclose(tum[..., 2][depth > 0], depth[depth > 0] / 5000.0, rtol=1e-6)
    # Other float widths are read as float64.
    np.testing.assert_allclose(floodplane.depth_to_points(metres32.astype(np.float16), FX, FY, CX, CY)[..., 2],
                               expected[..., 2], rtol=1e-3)


def test_segment_depth_takes_float_metres_as_open3d_and_ros_give_them():
    depth = millimetres()
    from_integers = floodplane.segment_depth(depth, FX, FY, CX, CY)
    from_metres = floodplane.segment_depth((depth / 1000.0).astype(np.float32), FX, FY, CX, CY, depth_scale=1.0)
    assert len(from_metres.planes) == 2
    np.testing.assert_array_equal(from_metres.labels, from_integers.labels)


def test_zero_nan_and_infinity_are_no_return_in_float_depth():
    depth = np.full((4, 5), 1.5, np.float32)
    depth[0, 0], depth[1, 1], depth[2, 2], depth[3, 3] = 0.0, np.nan, np.inf, -np.inf
    points = floodplane.depth_to_points(depth, 500.0, 500.0, 2.0, 1.5)
    holes = np.isnan(points).all(axis=-1)
    assert holes.sum() == 4 and holes[0, 0] and holes[1, 1] and holes[2, 2] and holes[3, 3]
    assert np.isfinite(points[~holes]).all()
    np.testing.assert_allclose(points[~holes][:, 2], 1.5)


@pytest.mark.parametrize("dtype", [np.uint16, np.int32, np.float32, np.float64])
def test_an_h_w_1_image_is_its_h_w_image(dtype):
    depth = millimetres().astype(dtype)
    flat = floodplane.depth_to_points(depth, FX, FY, CX, CY, depth_scale=1000.0)
    np.testing.assert_array_equal(floodplane.depth_to_points(depth[..., None], FX, FY, CX, CY, depth_scale=1000.0),
                                  flat)
    # A view with strides of its own (every other column) is read as it is.
    np.testing.assert_array_equal(
        floodplane.depth_to_points(depth[:, ::2, None], FX / 2, FY, CX / 2, CY, depth_scale=1000.0)[..., 2],
        flat[:, ::2, 2])
    np.testing.assert_array_equal(floodplane.segment_depth(depth[..., None], K, depth_scale=1000.0).labels,
                                  floodplane.segment_depth(depth, K, depth_scale=1000.0).labels)


@pytest.mark.parametrize("name, arguments", [
    ("four numbers", (FX, FY, CX, CY)),
    ("a tuple", ((FX, FY, CX, CY),)),
    ("a list", ([FX, FY, CX, CY],)),
    ("an array of four", (np.array([FX, FY, CX, CY], np.float32),)),
    ("K as nested lists", (K,)),
    ("K as an array", (np.array(K),)),
    ("K as a float32 array", (np.array(K, np.float32),)),
    ("K's nine values, as ROS's CameraInfo.k", (tuple(np.ravel(K)),)),
    ("an Open3D intrinsic of the image's size", (PinholeIntrinsic(160, 120),)),
    ("an Open3D intrinsic without a size", (PinholeIntrinsic(-1, -1),)),
])
def test_every_form_of_intrinsics_gives_the_same_points(name, arguments):
    depth = millimetres()
    expected = floodplane.depth_to_points(depth, FX, FY, CX, CY)
    np.testing.assert_allclose(floodplane.depth_to_points(depth, *arguments), expected, rtol=1e-6, err_msg=name)
    np.testing.assert_array_equal(floodplane.segment_depth(depth, *arguments).labels,
                                  floodplane.segment_depth(depth, FX, FY, CX, CY).labels, err_msg=name)


def test_the_loose_numbers_may_be_named():
    depth = millimetres()
    np.testing.assert_array_equal(floodplane.depth_to_points(depth, FX, fy=FY, cx=CX, cy=CY, depth_scale=1000),
                                  floodplane.depth_to_points(depth, FX, FY, CX, CY))


@pytest.mark.parametrize("arguments, error, message", [
    ((FX,), TypeError, "got the single number"),
    ((FX, FY), TypeError, r"give the intrinsics as fx, fy, cx, cy \(all four\)"),
    ((None,), TypeError, "intrinsics must be fx, fy, cx, cy .* got NoneType"),
    (("525,525,79.5,59.5",), TypeError, "got str"),
    (([["a", "b"]],), TypeError, "must hold real numbers"),
    (((FX, FY, CX),), ValueError, r"intrinsics must be \(fx, fy, cx, cy\) or the 9 values of K, got 3 values"),
    ((np.ravel([[FX, 1, CX], [0, FY, CY], [0, 0, 1]]),), ValueError, r"pinhole camera matrix"),
    ((np.eye(2),), ValueError, r"must be \(fx, fy, cx, cy\) or a 3 x 3 matrix K, got shape \(2, 2\)"),
    (([[FX, 0.5, CX], [0, FY, CY], [0, 0, 1]],), ValueError,
     r"pinhole camera matrix .*\(no skew\), got \[\[131\.25, 0\.5, 79\.5\]"),
    (([[FX, 0, CX], [0, FY, CY], [0, 0, 2]],), ValueError, "pinhole camera matrix"),
    (([[0, 0, CX], [0, FY, CY], [0, 0, 1]],), ValueError, "fx must be a finite number of pixels > 0"),
    (([[FX, 0, np.nan], [0, FY, CY], [0, 0, 1]],), ValueError, "cx must be a finite number"),
    ((PinholeIntrinsic(640, 480),), ValueError,
     r"the intrinsics are for a 640 x 480 image, the depth image is 160 x 120 \(width x height\)"),
    ((PinholeIntrinsic(160, 120, np.eye(4)),), ValueError, r"intrinsic_matrix must have shape \(3, 3\)"),
])
def test_refuses_intrinsics_it_cannot_use(arguments, error, message):
    depth = millimetres()
    with pytest.raises(error, match=message):
        floodplane.depth_to_points(depth, *arguments)
    with pytest.raises(error, match=message):
        floodplane.segment_depth(depth, *arguments)


def test_refuses_a_depth_scale_that_is_no_number():
    with pytest.raises(TypeError, match="depth_to_points: depth_scale must be a number, got str"):
        floodplane.depth_to_points(millimetres(), K, depth_scale="1000")
    with pytest.raises(ValueError, match="depth_scale must be a finite number of units per metre > 0"):
        floodplane.depth_to_points(millimetres(), K, depth_scale=0.0)


def test_segment_file_takes_every_form_of_intrinsics(tmp_path):
    png = tmp_path / "depth.png"
    floodplane.write_depth_png(str(png), millimetres())
    segmenter = floodplane.Segmenter()
    outputs = []
    for index, intrinsics in enumerate([(FX, FY, CX, CY), K, PinholeIntrinsic(160, 120)]):
        output = tmp_path / f"out_{index}.pcd"
        assert segmenter.segment_file(str(png), str(output), intrinsics=intrinsics)["planes"] == 2
        outputs.append(output.read_bytes())
    assert outputs[0] == outputs[1] == outputs[2]
    with pytest.raises(OSError, match="the depth image is 160 x 120, the intrinsics are for 640 x 480"):
        segmenter.segment_file(str(png), str(tmp_path / "wrong.pcd"), intrinsics=PinholeIntrinsic(640, 480))
    assert not (tmp_path / "wrong.pcd").exists()

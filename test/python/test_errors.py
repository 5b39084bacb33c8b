# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Every kind of bad input raises the Python exception that fits, with a message naming the
argument: TypeError for a wrong type or dtype, ValueError for a wrong shape or value, OSError
(FileNotFoundError) for a file that cannot be read or written. Never a crash."""

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene, write_png

# ---- points ------------------------------------------------------------------------------


@pytest.mark.parametrize("points, message", [
    (np.zeros((4, 5), np.float32), r"points must have shape \(H, W, 3\), got \(4, 5\)"),
    (np.zeros((4, 5, 4), np.float32), r"points must have shape \(H, W, 3\), got \(4, 5, 4\)"),
    (np.zeros((2, 4, 5, 3), np.float32), r"points must have shape \(H, W, 3\)"),
    (np.zeros((1, 50, 3), np.float32), r"points must be an image grid of H >= 2 rows"),
    (np.zeros((5, 0, 3), np.float32), r"points must be an image grid"),
    (np.zeros((0, 5, 3), np.float32), r"points must be an image grid"),
    (np.float32(1.0), r"points must have shape"),
])
def test_refuses_points_of_the_wrong_shape(points, message):
    with pytest.raises(ValueError, match=message):
        floodplane.segment(points)


@pytest.mark.parametrize("points, message", [
    (np.zeros((4, 5, 3), np.complex64), "points must hold real numbers \\(floats or integers\\), got dtype complex64"),
    (np.zeros((4, 5, 3), bool), "got dtype bool"),
    (np.array([["a"] * 3] * 2), "got dtype <U1"),
    (None, "points must be an array of shape \\(H, W, 3\\), got NoneType"),
    ("frame.pcd", "got str"),
    (object(), "got dtype object"),
])
def test_refuses_points_of_the_wrong_type(points, message):
    with pytest.raises(TypeError, match=message):
        floodplane.Segmenter().segment(points)


def test_refuses_a_ragged_list():
    with pytest.raises(ValueError, match="numpy cannot make an array of this list"):
        floodplane.segment([[[0, 0, 1]], [[0, 0, 1], [1, 1, 1]]])


# ---- parameters --------------------------------------------------------------------------


@pytest.mark.parametrize("params, message", [
    (dict(distance_threshold=-0.01), "distance_threshold must be a finite number of metres > 0"),
    (dict(distance_threshold=float("nan")), "distance_threshold must be"),
    (dict(seed_size=0.0), "seed_size must be"),
    (dict(angular_threshold=2.0), "angular_threshold"),
    (dict(merge_distance=float("inf")), "merge_distance must be"),
    (dict(maximum_curvature=-1.0), "maximum_curvature must be"),
    (dict(subsampling=3), "subsampling"),
    (dict(subsampling=0), "subsampling"),
    (dict(min_inliers=-1), r"min_inliers must be an integer in \[0, 4294967295\], got -1"),
    (dict(min_inliers=2**32), "min_inliers must be an integer in"),
    (dict(subsampling=2**40), "subsampling must be an integer in"),
    (dict(depth_noise_coefficient=-0.1), "depth_noise_coefficient must be"),
    (dict(depth_noise_constant=float("nan")), "depth_noise_constant must be"),
])
def test_refuses_parameter_values_the_method_cannot_use(params, message):
    with pytest.raises(ValueError, match=message):
        floodplane.Segmenter(**params)
    with pytest.raises(ValueError, match=message):
        floodplane.segment(two_plane_scene(), **params)


@pytest.mark.parametrize("params, message", [
    (dict(distance_threshold="0.01"), "distance_threshold must be a number, got str"),
    (dict(distance_threshold=True), "distance_threshold must be a number, got bool"),
    (dict(angular_threshold=None), "angular_threshold must be a number, got NoneType"),
    (dict(maximum_curvature=[0.1]), "maximum_curvature must be a number, got list"),
    (dict(min_inliers=10.5), "min_inliers must be an integer, got float"),
    (dict(subsampling="2"), "subsampling must be an integer, got str"),
    (dict(subsampling=None), "subsampling must be an integer, got NoneType"),
    (dict(distance_treshold=0.01), "unexpected keyword argument 'distance_treshold'.*distance_threshold"),
])
def test_refuses_parameters_of_the_wrong_type_or_name(params, message):
    with pytest.raises(TypeError, match=message):
        floodplane.Segmenter(**params)


def test_refuses_positional_parameters():
    with pytest.raises(TypeError):
        floodplane.Segmenter(0.01)


def test_none_restores_a_derived_length():
    assert floodplane.Segmenter(distance_threshold=None, min_inliers=None).params["distance_threshold"] is None


# ---- depth images ------------------------------------------------------------------------


@pytest.mark.parametrize("depth, error, message", [
    (np.zeros((4, 5), bool), TypeError, "depth must be an integer or floating-point array, got dtype bool"),
    (np.zeros((4, 5), np.complex64), TypeError, "got dtype complex64"),
    (np.zeros((4, 5, 2), np.uint16), ValueError,
     r"depth must have shape \(H, W\) or \(H, W, 1\), got \(4, 5, 2\)"),
    (np.zeros((4,), np.uint16), ValueError, r"got \(4,\)"),
    (np.array([[1, 2], [3, -4]], np.int16), ValueError, "depth must not be negative, got -4 at row 1, column 1"),
    (np.array([[1, 2], [-0.25, 4]], np.float32), ValueError,
     "depth must not be negative, got -0.25 at row 1, column 0"),
    (None, TypeError, "got NoneType"),
])
def test_refuses_bad_depth_images(depth, error, message):
    with pytest.raises(error, match=message):
        floodplane.depth_to_points(depth, 500.0, 500.0, 2.0, 2.0)
    with pytest.raises(error, match=message):
        floodplane.segment_depth(depth, 500.0, 500.0, 2.0, 2.0)


@pytest.mark.parametrize("intrinsics, message", [
    ((0.0, 500.0, 2.0, 2.0, 1000.0), "fx must be a finite number of pixels > 0, got 0"),
    ((500.0, -1.0, 2.0, 2.0, 1000.0), "fy must be"),
    ((500.0, 500.0, float("nan"), 2.0, 1000.0), "cx must be a finite number"),
    ((500.0, 500.0, 2.0, float("inf"), 1000.0), "cy must be a finite number"),
    ((500.0, 500.0, 2.0, 2.0, 0.0), "depth_scale must be a finite number of units per metre > 0"),
])
def test_refuses_bad_intrinsics(intrinsics, message):
    depth = np.full((4, 5), 1000, np.uint16)
    with pytest.raises(ValueError, match=message):
        floodplane.depth_to_points(depth, *intrinsics)


def test_a_one_row_depth_image_is_no_image_grid():
    with pytest.raises(ValueError, match="image grid"):
        floodplane.segment_depth(np.full((1, 5), 1000, np.uint16), 500.0, 500.0, 2.0, 0.0)


# ---- files -------------------------------------------------------------------------------


def test_a_missing_file_is_file_not_found(tmp_path):
    missing = tmp_path / "missing.pcd"
    for read in (floodplane.read_pcd, floodplane.read_labels_pcd, floodplane.read_depth_png):
        with pytest.raises(FileNotFoundError, match=f"{read.__name__}: path '{missing}': cannot read file"):
            read(str(missing))


@pytest.mark.parametrize("content, message", [
    (b"", "empty file"),
    (b"hello, world\n", "not a PCD file"),
    (b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 2\n"
     b"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 8\nDATA binary\n" + b"\0" * 40, "truncated"),
    (b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 4\nHEIGHT 1\n"
     b"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n", "unorganized"),
    (b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 10000\nHEIGHT 10000\n"
     b"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 100000000\nDATA binary_compressed\n" + b"\0" * 64, "announces"),
    (b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 100000\nHEIGHT 100000\n"
     b"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 10000000000\nDATA binary_compressed\n" + b"\0" * 64, "is not a count"),
])
def test_a_broken_pcd_file_is_an_os_error_naming_it(tmp_path, content, message):
    path = tmp_path / "broken.pcd"
    path.write_bytes(content)
    with pytest.raises(OSError, match=f"read_pcd: path '{path}': .*{message}") as caught:
        floodplane.read_pcd(str(path))
    assert not isinstance(caught.value, FileNotFoundError)


def test_a_pcd_without_labels_has_no_labels_to_read(tmp_path):
    path = tmp_path / "points.pcd"
    path.write_bytes(b"VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH 2\nHEIGHT 2\n"
                     b"VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 4\nDATA ascii\n1 2 3\n1 2 3\n1 2 3\n1 2 3\n")
    assert floodplane.read_pcd(str(path)).shape == (2, 2, 3)
    with pytest.raises(OSError, match="no uint32 label field"):
        floodplane.read_labels_pcd(str(path))


@pytest.mark.parametrize("pixels, color_type, bit_depth, message", [
    (np.zeros((3, 4)), 0, 8, "not a depth image: 8 bits per pixel"),
    (np.zeros((3, 4, 3)), 2, 8, "not a depth image: a colour PNG"),
    (np.zeros((3, 4, 3)), 2, 16, "not a depth image: a colour PNG"),
    (np.zeros((3, 4, 2)), 4, 16, "not a depth image: a PNG with an alpha channel"),
])
def test_a_png_that_is_not_a_depth_image_is_an_os_error(tmp_path, pixels, color_type, bit_depth, message):
    path = tmp_path / "image.png"
    write_png(path, pixels, color_type, bit_depth)
    with pytest.raises(OSError, match=f"read_depth_png: path '{path}': {message}"):
        floodplane.read_depth_png(str(path))


def test_a_broken_png_is_an_os_error(tmp_path):
    good = tmp_path / "good.png"
    floodplane.write_depth_png(str(good), np.arange(600, dtype=np.uint16).reshape(20, 30))
    content = good.read_bytes()
    for name, broken in {"truncated": content[:len(content) // 2], "not a png": b"P5\n30 20\n65535\n",
                         "empty": b""}.items():
        path = tmp_path / f"{name}.png"
        path.write_bytes(broken)
        with pytest.raises(OSError, match="PNG"):
            floodplane.read_depth_png(str(path))


def test_writes_refuse_bad_arrays_and_unwritable_paths(tmp_path):
    points = two_plane_scene(8, 6)
    labels = np.zeros((6, 8), np.uint32)
    with pytest.raises(ValueError, match=r"write_labels_pcd: labels must have shape \(6, 8\), got \(8, 6\)"):
        floodplane.write_labels_pcd(str(tmp_path / "a.pcd"), points, labels.T)
    with pytest.raises(TypeError, match="write_labels_pcd: labels must be an integer array, got dtype float64"):
        floodplane.write_labels_pcd(str(tmp_path / "a.pcd"), points, labels.astype(float))
    with pytest.raises(ValueError, match=r"labels must hold values in \[0, 4294967295\], got -1 at row 0, column 0"):
        floodplane.write_labels_pcd(str(tmp_path / "a.pcd"), points, labels.astype(np.int64) - 1)
    with pytest.raises(ValueError, match=r"write_labels_pcd: points must have shape"):
        floodplane.write_labels_pcd(str(tmp_path / "a.pcd"), points[..., :2], labels)
    with pytest.raises(FileNotFoundError, match="write_labels_pcd: path '.*/no/such/dir/a.pcd'"):
        floodplane.write_labels_pcd(str(tmp_path / "no/such/dir/a.pcd"), points, labels)
    with pytest.raises(ValueError, match=r"write_depth_png: depth must hold values in \[0, 65535\], got 65536"):
        floodplane.write_depth_png(str(tmp_path / "d.png"), np.full((2, 2), 65536, np.int32))
    with pytest.raises(FileNotFoundError, match="write_depth_png"):
        floodplane.write_depth_png(str(tmp_path / "no/d.png"), np.zeros((2, 2), np.uint16))
    assert sorted(p.name for p in tmp_path.iterdir()) == [], "a refused write leaves no file"


def test_a_write_into_a_directory_path_is_an_os_error(tmp_path):
    (tmp_path / "taken.pcd").mkdir()
    with pytest.raises(OSError, match="write_labels_pcd: path"):
        floodplane.write_labels_pcd(str(tmp_path / "taken.pcd"), two_plane_scene(8, 6), np.zeros((6, 8), np.uint32))


def test_segment_file_names_the_input_or_output_that_failed(tmp_path):
    segmenter = floodplane.Segmenter()
    with pytest.raises(FileNotFoundError, match="segment_file: input '.*missing.pcd': cannot read file"):
        segmenter.segment_file(str(tmp_path / "missing.pcd"), str(tmp_path / "out.pcd"))
    good = tmp_path / "good.pcd"
    floodplane.write_labels_pcd(str(good), two_plane_scene(), np.zeros((120, 160), np.uint32))
    with pytest.raises(FileNotFoundError, match="segment_file: output '.*/no/out.pcd'"):
        segmenter.segment_file(str(good), str(tmp_path / "no/out.pcd"))
    depth = tmp_path / "depth.png"
    floodplane.write_depth_png(str(depth), np.full((4, 5), 1000, np.uint16))
    with pytest.raises(OSError, match="needs the camera's intrinsics"):
        segmenter.segment_file(str(depth), str(tmp_path / "out.pcd"))
    with pytest.raises(ValueError, match=r"must be \(fx, fy, cx, cy\) or the 9 values of K, got 3 values"):
        segmenter.segment_file(str(depth), str(tmp_path / "out.pcd"), intrinsics=(1.0, 2.0, 3.0))
    with pytest.raises(ValueError, match="fx must be"):
        segmenter.segment_file(str(depth), str(tmp_path / "out.pcd"), intrinsics=(0.0, 2.0, 3.0, 4.0))
    assert not (tmp_path / "out.pcd").exists()

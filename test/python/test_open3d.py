# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""floodplane.open3d with Debian's Open3D (python3-open3d, 0.16): a PointCloud made from a
depth image and an RGBDImage with its intrinsics give the planes of the same depth through
the numpy API, as a cloud coloured by plane and one tight OrientedBoundingBox per plane
(Open3D's detect_planar_patches form); `import floodplane` works without Open3D."""

import subprocess
import sys

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene

try:
    import open3d
except ImportError:
    open3d = None
else:
    import floodplane.open3d

needs_open3d = pytest.mark.skipif(open3d is None,
                                  reason="Open3D's Python module is not installed (Debian: python3-open3d)")

WIDTH, HEIGHT = 160, 120
FX = FY = 525.0 * WIDTH / 640
CX, CY = (WIDTH - 1) / 2, (HEIGHT - 1) / 2


@pytest.fixture
def intrinsic():
    return open3d.camera.PinholeCameraIntrinsic(WIDTH, HEIGHT, FX, FY, CX, CY)


@pytest.fixture
def millimetres():
    """The two-plane scene's depth in millimetres, 0 in its hole."""
    return np.nan_to_num(np.round(two_plane_scene(WIDTH, HEIGHT)[..., 2] * 1000)).astype(np.uint16)


def assert_geometry_of(planes, points):
    """The PlaneGeometry fits its segmentation and the points it came from."""
    labels = planes.segmentation.labels
    flat = points.reshape(-1, 3).astype(np.float64)
    valid = np.flatnonzero(np.isfinite(flat).all(axis=1))
    np.testing.assert_array_equal(planes.pixels, valid)
    np.testing.assert_array_equal(np.asarray(planes.cloud.points), flat[valid])
    np.testing.assert_array_equal(planes.point_labels, labels.reshape(-1)[valid])
    np.testing.assert_allclose(np.asarray(planes.cloud.colors),
                               floodplane.label_colors(planes.point_labels) / 255.0)
    assert len(planes.boxes) == len(planes.segmentation.planes)
    for box, plane, color in zip(planes.boxes, planes.segmentation.planes,
                                 floodplane.label_colors(np.arange(1, len(planes.boxes) + 1)) / 255.0):
        assert isinstance(box, open3d.geometry.OrientedBoundingBox)
        rotation = np.asarray(box.R)
        np.testing.assert_allclose(rotation.T @ rotation, np.eye(3), atol=1e-12)
        assert np.linalg.det(rotation) == pytest.approx(1.0)
        np.testing.assert_allclose(rotation[:, 2], plane.normal, atol=1e-12)  # third axis: the normal
        np.testing.assert_allclose(np.asarray(box.color), color)
        extent = np.asarray(box.extent)
        assert extent[0] >= extent[1] > 0  # the longer in-plane axis first
        # Tight: every inlier inside, and each face touched by one.
        inliers = flat[labels.reshape(-1) == plane.label]
        local = (inliers - np.asarray(box.center)) @ rotation
        np.testing.assert_allclose(local.max(axis=0), extent / 2, atol=1e-9)
        np.testing.assert_allclose(local.min(axis=0), -extent / 2, atol=1e-9)


@needs_open3d
def test_a_point_cloud_made_from_a_depth_image(intrinsic, millimetres):
    cloud = open3d.geometry.PointCloud.create_from_depth_image(open3d.geometry.Image(millimetres), intrinsic,
                                                               project_valid_depth_only=False)
    planes = floodplane.open3d.segment_point_cloud(cloud, intrinsic)
    reference = floodplane.segment_depth(millimetres, intrinsic)
    assert len(planes.segmentation.planes) == 2
    agreement = np.mean(planes.segmentation.labels == reference.labels)
    assert agreement > 0.999, "Open3D's float32 back-projection differs in the last bits only"
    wall, floor = planes.segmentation.planes
    np.testing.assert_allclose(wall.normal, [0, 0, -1], atol=1e-3)
    np.testing.assert_allclose(floor.normal, [0, -1, 0], atol=1e-3)
    assert_geometry_of(planes, np.asarray(cloud.points).reshape(HEIGHT, WIDTH, 3))
    # The shape as a pair does the same; parameters pass through.
    same = floodplane.open3d.segment_point_cloud(cloud, (HEIGHT, WIDTH))
    np.testing.assert_array_equal(same.segmentation.labels, planes.segmentation.labels)
    assert floodplane.open3d.segment_point_cloud(cloud, intrinsic, min_inliers=10**6).boxes == []


@needs_open3d
def test_an_rgbd_image_with_its_intrinsics(intrinsic, millimetres):
    color = np.zeros((HEIGHT, WIDTH, 3), np.uint8)
    rgbd = open3d.geometry.RGBDImage.create_from_color_and_depth(
        open3d.geometry.Image(color), open3d.geometry.Image(millimetres), depth_scale=1000.0, depth_trunc=10.0,
        convert_rgb_to_intensity=False)
    planes = floodplane.open3d.segment_rgbd_image(rgbd, intrinsic)
    # The RGBDImage holds float32 metres: the labels of the millimetres through the numpy API.
    metres = np.asarray(rgbd.depth)
    assert metres.dtype == np.float32
    np.testing.assert_array_equal(planes.segmentation.labels, floodplane.segment_depth(metres, intrinsic).labels)
    np.testing.assert_array_equal(planes.segmentation.labels,
                                  floodplane.segment_depth(millimetres, intrinsic).labels)
    assert len(planes.boxes) == 2
    assert_geometry_of(planes, floodplane.depth_to_points(metres, intrinsic))
    # Any form of intrinsics.
    K = np.asarray(intrinsic.intrinsic_matrix)
    np.testing.assert_array_equal(floodplane.open3d.segment_rgbd_image(rgbd, K).segmentation.labels,
                                  planes.segmentation.labels)


@needs_open3d
def test_depths_beyond_open3ds_truncation_are_holes(intrinsic, millimetres):
    rgbd = open3d.geometry.RGBDImage.create_from_color_and_depth(
        open3d.geometry.Image(np.zeros((HEIGHT, WIDTH, 3), np.uint8)), open3d.geometry.Image(millimetres),
        depth_trunc=1.5, convert_rgb_to_intensity=False)
    planes = floodplane.open3d.segment_rgbd_image(rgbd, intrinsic)
    # The wall at 2 m is cut away: the floor (nearer than 1.5 m) is left.
    assert len(planes.segmentation.planes) == 1
    np.testing.assert_allclose(planes.segmentation.planes[0].normal, [0, -1, 0], atol=1e-3)
    assert np.asarray(planes.cloud.points)[:, 2].max() <= 1.5


@needs_open3d
def test_refuses_a_cloud_that_is_no_image_grid(intrinsic, millimetres):
    dense = open3d.geometry.PointCloud.create_from_depth_image(open3d.geometry.Image(millimetres), intrinsic)
    with pytest.raises(ValueError, match=r"has 19184 points, not the 120 x 160 = 19200 .*project_valid_depth_only"):
        floodplane.open3d.segment_point_cloud(dense, intrinsic)
    with pytest.raises(TypeError, match="cloud must be an open3d.geometry.PointCloud, got ndarray"):
        floodplane.open3d.segment_point_cloud(np.zeros((HEIGHT, WIDTH, 3)), intrinsic)
    with pytest.raises(TypeError, match=r"shape must be \(height, width\)"):
        floodplane.open3d.segment_point_cloud(dense, 19184)
    with pytest.raises(ValueError, match="height and width must be integers > 0"):
        floodplane.open3d.segment_point_cloud(dense, (0, 19184))
    with pytest.raises(TypeError, match="rgbd must be an open3d.geometry.RGBDImage"):
        floodplane.open3d.segment_rgbd_image(open3d.geometry.Image(millimetres), intrinsic)
    with pytest.raises(ValueError, match="geometry: points must have shape"):
        floodplane.open3d.geometry(floodplane.segment_depth(millimetres, intrinsic), np.zeros((4, 4, 3)))


def run_python(program):
    return subprocess.run([sys.executable, "-c", program], capture_output=True, text=True, timeout=120)


def test_import_floodplane_does_not_import_open3d():
    completed = run_python("import sys, floodplane; print('open3d' in sys.modules)")
    assert completed.returncode == 0, completed.stderr
    assert completed.stdout.strip() == "False"


def test_without_open3d_the_bridge_says_what_to_install():
    # sys.modules[name] = None makes `import name` fail as if it were not installed.
    completed = run_python("import sys; sys.modules['open3d'] = None\n"
                           "import floodplane\n"
                           "try:\n"
                           "    import floodplane.open3d\n"
                           "except ImportError as error:\n"
                           "    print(error)\n")
    assert completed.returncode == 0, completed.stderr
    assert "floodplane.open3d needs Open3D's Python module: apt install python3-open3d" in completed.stdout

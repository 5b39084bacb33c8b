# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The Python API over numpy arrays: what a segmentation gives, that every input layout gives
the same labels, that C-ordered float32 input is read in place, that the Segmenter's keywords
are Params' fields, and that segmenting releases the GIL."""

import os
import pathlib
import re
import sys
import threading
import tracemalloc

import numpy as np
import pytest

import floodplane
from conftest import two_plane_scene


def test_segments_the_two_planes_of_a_known_scene(scene):
    result = floodplane.segment(scene)
    assert result.labels.dtype == np.uint32
    assert result.labels.shape == (120, 160)
    assert (result.width, result.height) == (160, 120)
    assert len(result.planes) == 2
    assert result.labels.max() == 2
    # The wall (z = 2, normal towards the camera: -z) is the larger plane.
    wall, floor = result.planes
    assert wall.label == 1 and floor.label == 2
    assert wall.inliers >= floor.inliers
    np.testing.assert_allclose(wall.normal, [0, 0, -1], atol=1e-4)
    assert wall.d == pytest.approx(2.0, abs=1e-3)
    np.testing.assert_allclose(floor.normal, [0, -1, 0], atol=1e-4)
    assert floor.d == pytest.approx(0.5, abs=1e-3)
    # The counts are the label image's.
    for plane in result.planes:
        assert plane.inliers == np.count_nonzero(result.labels == plane.label)
        assert plane.centroid.shape == (3,) and plane.normal.shape == (3,)
        assert plane.covariance.shape == (3, 3) and plane.eigenvalues.shape == (3,)
        assert plane.mean_squared_error >= 0 and 0 <= plane.curvature <= 1 / 3
        assert result.labels.flat[plane.first_pixel] == plane.label
    # The hole is no plane.
    assert not result.labels[10:14, 20:24].any()


def test_the_centroid_and_offset_describe_the_inliers(scene):
    result = floodplane.segment(scene)
    for plane in result.planes:
        inliers = scene[result.labels == plane.label].astype(np.float64)
        np.testing.assert_allclose(plane.centroid, inliers.mean(axis=0), atol=1e-5)
        assert plane.normal @ plane.centroid + plane.d == pytest.approx(0.0, abs=1e-9)


def test_the_result_carries_noise_stats_and_phase_times(scene):
    segmenter = floodplane.Segmenter()
    timed = segmenter.segment(scene, measure_phases=True)
    assert timed.ms > 0
    assert timed.phases.total > 0
    assert timed.phases.total == pytest.approx(
        timed.phases.preparation + timed.phases.seed_selection + timed.phases.flood_fill + timed.phases.relabelling
        + timed.phases.merging + timed.phases.region_output)
    assert timed.phases.pcl_conversion == 0  # no PCL class in between
    untimed = segmenter.segment(scene)
    assert untimed.phases.total == 0
    assert timed.stats.seeds >= 2 and timed.stats.segments >= 2
    assert timed.stats.seed_candidates >= timed.stats.seeds
    # Exact data: the measured noise is (nearly) none.
    assert timed.noise.estimated
    assert timed.noise.sigma(2.0) < 1e-3
    fixed = floodplane.segment(scene, depth_noise_coefficient=0.0015, depth_noise_constant=0.0)
    assert not fixed.noise.estimated
    assert fixed.noise.sigma_quadratic == 0.0015
    assert fixed.noise.sigma(2.0) == pytest.approx(0.0015 * 4)
    assert "NoiseModel(" in repr(fixed.noise) and "PhaseTimes(" in repr(timed.phases)
    assert "SegmentationStats(" in repr(timed.stats) and "Plane(label=1" in repr(timed.planes[0])
    assert repr(timed).startswith("<floodplane.Segmentation 160x120, 2 planes")


def test_labels_are_a_read_only_view_that_outlives_the_next_call(scene):
    segmenter = floodplane.Segmenter()
    first = segmenter.segment(scene)
    labels = first.labels
    assert not labels.flags.writeable
    with pytest.raises(ValueError):
        labels[0, 0] = 5
    before = labels.copy()
    segmenter.segment(np.full_like(scene, np.nan))  # another frame through the same Segmenter
    np.testing.assert_array_equal(first.labels, before)
    del first
    np.testing.assert_array_equal(labels, before)  # the view keeps its result alive


def test_boundary_walks_around_a_plane(scene):
    result = floodplane.segment(scene)
    for index, plane in enumerate(result.planes):
        contour = result.boundary(index)
        assert contour.ndim == 1 and len(contour) > 4
        assert contour[0] == plane.first_pixel
        assert np.all(result.labels.flat[contour] == plane.label)
    with pytest.raises(IndexError, match="out of range"):
        result.boundary(2)
    with pytest.raises(IndexError):
        result.boundary(-1)


def test_every_layout_and_float_type_gives_the_same_labels(scene):
    expected = floodplane.segment(scene).labels
    wide = np.zeros(scene.shape[:2] + (4,), np.float32)
    wide[..., :3] = scene
    layouts = {
        "float64": scene.astype(np.float64),
        "x y z of an (H, W, 4) array": wide[..., :3],
        "Fortran order": np.asfortranarray(scene),
        "every other column of a wider grid": np.repeat(scene, 2, axis=1)[:, ::2],
        "big-endian": scene.astype(">f4"),
        "a nested list": scene.tolist(),
    }
    for name, points in layouts.items():
        np.testing.assert_array_equal(floodplane.segment(points).labels, expected, err_msg=name)


def _numpy_bytes_allocated(call):
    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        call()
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_reads_c_ordered_float32_in_place_and_copies_only_what_it_must():
    points = two_plane_scene(640, 480)
    segmenter = floodplane.Segmenter()
    segmenter.segment(points)  # buffers sized
    frame_bytes = points.nbytes  # 3.7 MB
    in_place = _numpy_bytes_allocated(lambda: segmenter.segment(points))
    view = np.concatenate([points, np.zeros((480, 640, 1), np.float32)], axis=2)[..., :3]
    strided = _numpy_bytes_allocated(lambda: segmenter.segment(view))
    converted = _numpy_bytes_allocated(lambda: segmenter.segment(points.astype(np.float64)))
    assert in_place < frame_bytes / 10, "C-ordered float32 must not be copied"
    assert strided < frame_bytes / 10, "an (H, W, 4) array's x y z must not be copied"
    assert converted > frame_bytes, "float64 is converted to float32 (sanity check of the measurement)"


def test_keywords_are_the_fields_of_params(scene):
    header = pathlib.Path(os.environ["FLOODPLANE_SOURCE_DIR"], "include/floodplane/params.h").read_text()
    struct_body = header[header.index("struct Params {"):header.index("};", header.index("struct Params {"))]
    fields = re.findall(r"^\s+(?:std::optional<[\w:]+>|double|bool|int)\s+(\w+)(?:\s*=[^;]*)?;", struct_body,
                        re.MULTILINE)
    assert fields, "no fields parsed from params.h"
    assert list(floodplane.PARAMETER_NAMES) == fields

    segmenter = floodplane.Segmenter()
    assert list(segmenter.params) == fields
    assert segmenter.params["distance_threshold"] is None and segmenter.params["min_inliers"] is None
    assert segmenter.params["subsampling"] == 4

    given = dict(distance_threshold=0.02, seed_size=0.05, angular_threshold=0.2, merge_distance=0.04,
                 min_inliers=50, maximum_curvature=0.01, subsampling=2,
                 depth_noise_coefficient=0.001, depth_noise_constant=0.0005)
    assert set(given) == set(fields)
    assert floodplane.Segmenter(**given).params == given
    assert "distance_threshold=0.02" in repr(floodplane.Segmenter(**given))
    # numpy scalars are numbers too
    assert floodplane.Segmenter(min_inliers=np.int64(7), seed_size=np.float32(0.5)).params["min_inliers"] == 7


def test_parameters_change_the_result(scene):
    assert len(floodplane.segment(scene, min_inliers=200000).planes) == 0
    coarse = floodplane.segment(scene, subsampling=4)
    assert coarse.labels.shape == (120, 160) and len(coarse.planes) == 2
    assert floodplane.Segmenter(subsampling=4).segment(scene).labels.tobytes() == coarse.labels.tobytes()


def test_segment_without_refinement_labels_no_more_pixels(scene):
    segmenter = floodplane.Segmenter()
    refined = np.count_nonzero(segmenter.segment(scene).labels)
    assert np.count_nonzero(segmenter.segment(scene, refine=False).labels) <= refined


def test_segment_depth_is_segment_of_the_back_projected_depth():
    depth = np.nan_to_num(np.round(two_plane_scene()[..., 2] * 1000)).astype(np.uint16)
    fx = fy = 525.0 * 160 / 640
    cx, cy = 79.5, 59.5
    points = floodplane.depth_to_points(depth, fx, fy, cx, cy, 1000.0)
    assert points.dtype == np.float32 and points.shape == (120, 160, 3)
    assert np.isnan(points[10, 20]).all()
    v, u = 50, 70
    z = depth[v, u] / 1000.0
    np.testing.assert_array_equal(points[v, u], np.float32([(u - cx) * z / fx, (v - cy) * z / fy, z]))
    direct = floodplane.segment_depth(depth, fx, fy, cx, cy, depth_scale=1000.0)
    np.testing.assert_array_equal(direct.labels, floodplane.segment(points).labels)
    assert len(direct.planes) == 2
    # Any integer dtype of the same values gives the same points.
    for dtype in (np.int32, np.uint32, np.int64, ">u2"):
        np.testing.assert_array_equal(floodplane.depth_to_points(depth.astype(dtype), fx, fy, cx, cy), points)
    # depth_scale divides.
    tum = floodplane.depth_to_points(depth, fx, fy, cx, cy, depth_scale=5000.0)
    np.testing.assert_allclose(tum[..., 2][depth > 0], depth[depth > 0] / 5000.0, rtol=1e-6)
    # Parameters pass through.
    assert len(floodplane.segment_depth(depth, fx, fy, cx, cy, min_inliers=10**6).planes) == 0


def test_releases_the_gil_while_it_segments():
    points = two_plane_scene(1280, 960)
    segmenter = floodplane.Segmenter()
    segmenter.segment(points)
    counter = [0]
    windows = []
    done = threading.Event()

    def work():
        # How far the main thread counts during each call. Several calls: on a busy machine
        # the main thread may not be scheduled at all during one of them.
        for _ in range(5):
            start = counter[0]
            segmenter.segment(points)
            windows.append(counter[0] - start)
            if windows[-1] > 0:
                break
        done.set()

    previous = sys.getswitchinterval()
    # A switch interval far longer than a call: a worker holding the GIL through the call is
    # not made to drop it, so the main thread could not count at all meanwhile.
    sys.setswitchinterval(2.0)
    try:
        worker = threading.Thread(target=work)
        worker.start()
        while not done.is_set():
            counter[0] += 1
        worker.join()
    finally:
        sys.setswitchinterval(previous)
    assert max(windows) > 0, f"the main thread did not run while the worker segmented: {windows}"


def test_threads_sharing_one_segmenter_take_turns_and_agree():
    points = two_plane_scene(320, 240)
    expected = floodplane.segment(points).labels
    segmenter = floodplane.Segmenter()
    results = []
    lock = threading.Lock()

    def work():
        for _ in range(5):
            labels = segmenter.segment(points).labels
            with lock:
                results.append(labels)

    threads = [threading.Thread(target=work) for _ in range(4)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    assert len(results) == 20
    for labels in results:
        np.testing.assert_array_equal(labels, expected)


def test_the_package_exports_what_it_documents():
    for name in floodplane.__all__:
        assert hasattr(floodplane, name), name
    assert re.fullmatch(r"\d+\.\d+\.\d+", floodplane.__version__)


def test_a_head_start_continues_from_the_previous_frame(scene):
    rng = np.random.default_rng(5)
    frames = [scene + rng.normal(0, 0.002, scene.shape).astype(np.float32) for _ in range(2)]
    segmenter = floodplane.Segmenter()
    first = segmenter.segment(frames[0], head_start=True)
    assert not first.stats.head_start  # nothing to continue from
    second = segmenter.segment(frames[1], head_start=True)
    assert second.stats.head_start
    assert second.noise.sigma_quadratic == first.noise.sigma_quadratic  # taken, not measured again
    cold = floodplane.Segmenter().segment(frames[1])
    assert not cold.stats.head_start
    assert len(second.planes) == len(cold.planes) == 2
    assert np.mean(second.labels == cold.labels) > 0.99
    # Another size: a cold start.
    assert not segmenter.segment(frames[1][:100], head_start=True).stats.head_start


def test_label_colors_are_the_pngs_colours_for_any_integer_labels():
    labels = floodplane.segment(two_plane_scene()).labels
    colors = floodplane.label_colors(labels)
    assert colors.dtype == np.uint8 and colors.shape == labels.shape + (3,)
    # One colour per label, the same wherever it appears, and label 0 (no plane) near-black.
    for label in (0, 1, 2):
        assert len(np.unique(colors[labels == label], axis=0)) == 1
    assert colors[labels == 0].max() < 40
    many = floodplane.label_colors(np.arange(1, 61))
    assert len(np.unique(many, axis=0)) == 60
    # Any integer dtype, any shape, large track ids too; the same label, the same colour.
    np.testing.assert_array_equal(floodplane.label_colors(labels.astype(np.int64)), colors)
    np.testing.assert_array_equal(floodplane.label_colors([[5, 4_000_000_000]])[0, 0], many[4])
    assert floodplane.label_colors(np.zeros((0,), np.uint8)).shape == (0, 3)
    with pytest.raises(TypeError, match="labels must be an integer array, got dtype float64"):
        floodplane.label_colors([1.0, 2.0])
    with pytest.raises(ValueError, match=r"labels must be in \[0, 4294967295\]"):
        floodplane.label_colors([-1, 2])

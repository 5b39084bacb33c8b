# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Reading and writing files from Python: PCD points and labels, 16-bit depth PNGs, and
segment_file, which must write what pcd_segment writes, byte for byte."""

import json
import os

import numpy as np
import pytest

import floodplane
import floodplane.distributed
from conftest import real_frames, rendered_scenes, two_plane_scene


def test_labels_pcd_round_trip_in_both_encodings(tmp_path):
    points = two_plane_scene()
    labels = floodplane.segment(points).labels
    for ascii in (False, True):
        path = tmp_path / f"labels_{ascii}.pcd"
        floodplane.write_labels_pcd(str(path), points, labels, ascii=ascii)
        assert (b"DATA ascii" in path.read_bytes()) == ascii
        np.testing.assert_array_equal(floodplane.read_pcd(str(path)), points)  # NaN == NaN here
        np.testing.assert_array_equal(floodplane.read_labels_pcd(str(path)), labels)
    # Any integer dtype and layout of labels, float64 points.
    path = tmp_path / "other.pcd"
    floodplane.write_labels_pcd(str(path), points.astype(np.float64), np.asfortranarray(labels.astype(np.int64)))
    np.testing.assert_array_equal(floodplane.read_labels_pcd(str(path)), labels)


def test_write_labels_pcd_replaces_a_file_whole(tmp_path):
    path = tmp_path / "labels.pcd"
    path.write_text("old")
    floodplane.write_labels_pcd(str(path), two_plane_scene(8, 6), np.ones((6, 8), np.uint32))
    assert floodplane.read_labels_pcd(str(path)).sum() == 48
    assert sorted(p.name for p in tmp_path.iterdir()) == ["labels.pcd"], "no temporary left behind"


def test_depth_png_round_trip_keeps_every_unit(tmp_path):
    depth = np.array([[0, 1, 255, 256], [1000, 4660, 65535, 0], [5000, 65534, 0x1234, 0xABCD]], np.uint16)
    path = tmp_path / "depth.png"
    floodplane.write_depth_png(str(path), depth)
    read = floodplane.read_depth_png(str(path))
    assert read.dtype == np.uint16
    np.testing.assert_array_equal(read, depth)
    floodplane.write_depth_png(str(path), depth.astype(np.int64))
    np.testing.assert_array_equal(floodplane.read_depth_png(str(path)), depth)


def test_accepts_path_like_objects(tmp_path):
    path = tmp_path / "depth.png"
    floodplane.write_depth_png(path, np.ones((3, 4), np.uint16))
    assert floodplane.read_depth_png(path).shape == (3, 4)


def test_read_pcd_reads_the_real_frames():
    frames = real_frames()
    if not frames:
        pytest.skip("no real data (FLOODPLANE_REAL_DATA_DIR)")
    for frame in frames:
        points = floodplane.read_pcd(str(frame))
        assert points.shape == (480, 640, 3) and points.dtype == np.float32
        assert np.isnan(points).any() and np.isfinite(points).any()


def _same_bytes_as_pcd_segment(tmp_path, pcd_segment, inputs, *extra, intrinsics=None, depth_scale=1000.0):
    out = tmp_path / "pcd_segment"
    completed = pcd_segment(*inputs, "-o", out, "-q", *extra)
    assert completed.returncode == 0, completed.stderr
    segmenter = floodplane.Segmenter()
    for input in inputs:
        name = input.name.rsplit(".", 1)[0]
        mine = tmp_path / f"{name}.python.pcd"
        summary = segmenter.segment_file(str(input), str(mine), intrinsics=intrinsics, depth_scale=depth_scale)
        theirs = out / f"{name}.labels.pcd"
        assert mine.read_bytes() == theirs.read_bytes(), input.name
        labels = floodplane.read_labels_pcd(str(mine))
        assert summary["planes"] == labels.max()
        assert (summary["height"], summary["width"]) == labels.shape
        assert summary["ms"] > 0


def test_segment_file_writes_pcd_segments_bytes_for_every_real_frame(tmp_path, pcd_segment):
    frames = real_frames()
    if not frames:
        pytest.skip("no real data (FLOODPLANE_REAL_DATA_DIR)")
    _same_bytes_as_pcd_segment(tmp_path, pcd_segment, frames)


def test_segment_file_writes_pcd_segments_bytes_for_the_rendered_scenes(tmp_path, pcd_segment):
    scenes = rendered_scenes()
    if not scenes:
        pytest.skip("no rendered scenes (FLOODPLANE_RENDERED_DIR)")
    _same_bytes_as_pcd_segment(tmp_path, pcd_segment, scenes[:6])


def test_segment_file_moves_the_sensor_to_the_origin_as_pcd_segment(tmp_path, pcd_segment):
    # A file whose VIEWPOINT is not the origin: pcd_segment's PCL class segments it in the
    # sensor's frame; segment_file must do the same and keep the pose in its output.
    points = two_plane_scene() + np.float32([0.5, -1.0, 2.0])
    plain = tmp_path / "plain.pcd"
    floodplane.write_labels_pcd(str(plain), points, np.zeros((120, 160), np.uint32), ascii=True)
    text = plain.read_text().replace("VIEWPOINT 0 0 0 1 0 0 0", "VIEWPOINT 0.5 -1 2 1 0 0 0")
    posed = tmp_path / "posed.pcd"
    posed.write_text(text)
    _same_bytes_as_pcd_segment(tmp_path, pcd_segment, [posed])
    labels = floodplane.read_labels_pcd(str(tmp_path / "posed.python.pcd"))
    assert labels.max() == 2
    np.testing.assert_array_equal(labels, floodplane.segment(two_plane_scene()).labels)


def test_segment_file_writes_pcd_segments_bytes_for_a_depth_png(tmp_path, pcd_segment):
    depth = np.round(two_plane_scene()[..., 2] * 5000).astype(np.float64)
    depth[np.isnan(depth)] = 0
    path = tmp_path / "frame.png"
    floodplane.write_depth_png(str(path), depth.astype(np.uint16))
    intrinsics = (131.25, 131.25, 79.5, 59.5)
    _same_bytes_as_pcd_segment(tmp_path, pcd_segment, [path], "--intrinsics", ",".join(map(str, intrinsics)),
                               "--depth-scale", "5000", intrinsics=intrinsics, depth_scale=5000.0)
    # And the labels are those of segment_depth on the array.
    labels = floodplane.read_labels_pcd(str(tmp_path / "frame.python.pcd"))
    expected = floodplane.segment_depth(floodplane.read_depth_png(str(path)), *intrinsics, depth_scale=5000.0).labels
    np.testing.assert_array_equal(labels, expected)
    assert labels.max() == 2


def test_segment_gives_pcd_segments_labels_bit_for_bit_on_real_frames(tmp_path, pcd_segment):
    frames = real_frames()
    if not frames:
        pytest.skip("no real data (FLOODPLANE_REAL_DATA_DIR)")
    out = tmp_path / "out"
    assert pcd_segment(*frames, "-o", out, "-q").returncode == 0
    segmenter = floodplane.Segmenter()
    for frame in frames:
        expected = floodplane.read_labels_pcd(str(out / (frame.stem + ".labels.pcd")))
        labels = segmenter.segment(floodplane.read_pcd(str(frame))).labels
        np.testing.assert_array_equal(labels, expected, err_msg=frame.name)
        assert labels.max() >= 3, "a real frame has several planes"


def test_non_default_parameters_give_pcd_segments_labels(tmp_path, pcd_segment):
    frames = real_frames()
    if not frames:
        pytest.skip("no real data (FLOODPLANE_REAL_DATA_DIR)")
    out = tmp_path / "out"
    completed = pcd_segment(frames[0], "-o", out, "-q", "--distance-threshold", "0.02", "--subsample", "2",
                            "--min-inliers", "500", "--angular-threshold", "0.15")
    assert completed.returncode == 0, completed.stderr
    expected = floodplane.read_labels_pcd(str(out / (frames[0].stem + ".labels.pcd")))
    labels = floodplane.segment(floodplane.read_pcd(str(frames[0])), distance_threshold=0.02, subsampling=2,
                                min_inliers=500, angular_threshold=0.15).labels
    np.testing.assert_array_equal(labels, expected)


def _write_coloured_pcd(path, points, colors, field):
    """An organized ASCII PCD file with x y z and a packed colour `field` (rgb or rgba) declared
    as a 32-bit unsigned integer, as non-PCL writers declare it."""
    height, width = points.shape[:2]
    packed = (colors[..., 0].astype(np.uint32) << 16) | (colors[..., 1].astype(np.uint32) << 8) | colors[..., 2]
    if field == "rgba":
        packed |= np.uint32(0xFF000000)
    lines = [f"{x!r} {y!r} {z!r} {c}" for (x, y, z), c in zip(points.reshape(-1, 3).tolist(), packed.ravel())]
    header = (f"VERSION 0.7\nFIELDS x y z {field}\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH {width}\n"
              f"HEIGHT {height}\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS {width * height}\nDATA ascii\n")
    path.write_text(header + "\n".join(lines) + "\n")


@pytest.mark.parametrize("field", ["rgb", "rgba"])
def test_read_pcd_keeps_colour_on_request(tmp_path, field):
    points = two_plane_scene(16, 12)
    rng = np.random.default_rng(3)
    colors = rng.integers(0, 256, points.shape, dtype=np.uint8)
    path = tmp_path / f"{field}.pcd"
    _write_coloured_pcd(path, points, colors, field)
    read_points, read_colors = floodplane.read_pcd(str(path), colors=True)
    np.testing.assert_array_equal(read_points, points)
    assert read_colors.dtype == np.uint8 and read_colors.shape == (12, 16, 3)
    np.testing.assert_array_equal(read_colors, colors)
    # Without the keyword, the points alone, as before.
    np.testing.assert_array_equal(floodplane.read_pcd(str(path)), points)


def test_read_pcd_gives_no_colours_for_a_file_without_them(tmp_path):
    path = tmp_path / "plain.pcd"
    floodplane.write_labels_pcd(str(path), two_plane_scene(8, 6), np.zeros((6, 8), np.uint32))
    points, colors = floodplane.read_pcd(str(path), colors=True)
    assert points.shape == (6, 8, 3) and colors is None


def test_pcd_segment_keeps_the_colours_read_pcd_reads(tmp_path, pcd_segment):
    points = two_plane_scene(40, 30)
    colors = np.random.default_rng(5).integers(0, 256, points.shape, dtype=np.uint8)
    path = tmp_path / "coloured.pcd"
    _write_coloured_pcd(path, points, colors, "rgb")
    output = tmp_path / "coloured.labels.pcd"
    completed = pcd_segment(path, "-o", output)
    assert completed.returncode == 0, completed.stderr
    np.testing.assert_array_equal(floodplane.read_pcd(str(output), colors=True)[1], colors)


def test_json_name_is_the_name_pcd_segment_writes_for_a_name_that_is_not_utf8(tmp_path, pcd_segment):
    # Latin-1's e-acute, and a euro sign cut after two of its three bytes.
    name = b"caf\xe9_\xe2\x82.pcd"
    input = os.path.join(os.fsencode(tmp_path), name)
    floodplane.write_labels_pcd(str(tmp_path / "plain.pcd"), two_plane_scene(), np.zeros((120, 160), np.uint32))
    os.rename(os.fsencode(tmp_path / "plain.pcd"), input)
    done = pcd_segment(os.fsdecode(input), "-o", tmp_path / "out", "--json", "--quiet")
    assert done.returncode == 0, done.stderr
    report = json.loads((tmp_path / "out" / os.fsdecode(b"caf\xe9_\xe2\x82.planes.json")).read_bytes())
    assert report["input"] == floodplane.json_name(input) == str(tmp_path) + "/caf\ufffd_\ufffd.pcd"
    assert floodplane.json_name(os.fsdecode(input)) == report["input"]
    assert floodplane.json_name("plain.pcd") == "plain.pcd"


def test_an_output_over_an_input_is_refused_and_the_input_kept(tmp_path):
    frame = tmp_path / "frame.pcd"
    floodplane.write_labels_pcd(str(frame), two_plane_scene(), np.zeros((120, 160), np.uint32))
    labels = tmp_path / "frame.labels.pcd"
    floodplane.write_labels_pcd(str(labels), two_plane_scene(16, 12), np.ones((12, 16), np.uint32))
    before = {path: path.read_bytes() for path in (frame, labels)}
    os.symlink(frame, tmp_path / "link.pcd")
    for output in (frame, tmp_path / "link.pcd"):
        with pytest.raises(ValueError, match="segment_file: the output .* would overwrite the input"):
            floodplane.Segmenter().segment_file(str(frame), str(output))

    class LocalClient:  # dask.distributed's map and gather, run here
        def map(self, function, *iterables, **keywords):
            keywords.pop("pure")
            return [function(*arguments, **keywords) for arguments in zip(*iterables)]

        def gather(self, futures):
            return futures

    results = floodplane.distributed.segment_files(LocalClient(), [frame, labels], tmp_path)
    assert results[0] == {"input": str(frame), "error": f"its output {labels} would overwrite the input {labels}"}
    assert "error" not in results[1], results[1]
    assert {path: path.read_bytes() for path in (frame, labels)} == before

# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The objects on the planes in Python: segment(objects=True), segment_depth, segment_file's
objects_output and Segmenter.segment carry the object labels and records of
floodplane::segmentObjects; without asking, none; they pickle."""

import pickle

import numpy as np
import pytest

import floodplane

WIDTH, HEIGHT, FOCAL = 160, 120, 150.0
BOX = (slice(40, 70), slice(60, 90))  # rows, columns: a box 20 cm high on the table


def table_depth():
    """A table 1.5 m ahead, facing the camera, with a box whose top is 1.3 m away."""
    depth = np.full((HEIGHT, WIDTH), 1.5, np.float32)
    depth[BOX] = 1.3
    return depth


def table_points():
    depth = table_depth()
    v, u = np.mgrid[0:HEIGHT, 0:WIDTH].astype(np.float32)
    x = (u - (WIDTH - 1) / 2) / FOCAL * depth
    y = (v - (HEIGHT - 1) / 2) / FOCAL * depth
    return np.stack([x, y, depth], -1)


def test_no_objects_unless_asked():
    result = floodplane.segment(table_points())
    assert result.object_labels is None
    assert result.objects is None


def test_the_box_is_the_one_object_and_the_table_none():
    result = floodplane.segment(table_points(), objects=True)
    labels = result.object_labels
    assert labels.shape == (HEIGHT, WIDTH) and labels.dtype == np.uint32
    assert not labels.flags.writeable
    assert len(result.objects) == 1
    box = result.objects[0]
    assert isinstance(box, floodplane.Object)
    assert box.id == 1
    # The box's top and nothing of the table; the refinement may leave its rim's pixels to it.
    inside = labels[BOX]
    assert (inside == 1).mean() > 0.95
    outside = labels.copy()
    outside[BOX] = 0
    assert not outside.any()
    assert box.pixels == int((labels == 1).sum())
    table = result.labels[0, 0]
    assert table != 0 and box.support == table
    assert box.centroid[2] == pytest.approx(1.3, abs=0.01)
    assert np.all(box.min <= box.centroid) and np.all(box.centroid <= box.max)


def test_segment_depth_and_segmenter_give_the_same_objects():
    fx = fy = FOCAL
    cx, cy = (WIDTH - 1) / 2, (HEIGHT - 1) / 2
    from_depth = floodplane.segment_depth(table_depth(), fx, fy, cx, cy, objects=True)
    from_segmenter = floodplane.Segmenter().segment(table_points(), objects=True)
    np.testing.assert_array_equal(from_depth.object_labels, from_segmenter.object_labels)
    assert [o.pixels for o in from_depth.objects] == [o.pixels for o in from_segmenter.objects]


def test_segment_file_writes_the_objects(tmp_path):
    source = tmp_path / "table.pcd"
    floodplane.write_labels_pcd(str(source), table_points(), np.zeros((HEIGHT, WIDTH), np.uint32))
    summary = floodplane.segment_file(source, tmp_path / "out.pcd", objects_output=tmp_path / "out.objects.pcd")
    assert summary["objects"] == 1
    written = floodplane.read_labels_pcd(str(tmp_path / "out.objects.pcd"))
    expected = floodplane.segment(table_points(), objects=True).object_labels
    np.testing.assert_array_equal(written, expected)
    assert "objects" not in floodplane.segment_file(source, tmp_path / "plain.pcd")


def test_segment_file_refuses_an_objects_output_over_the_input_or_the_labels(tmp_path):
    source = tmp_path / "in.pcd"
    floodplane.write_labels_pcd(str(source), table_points(), np.zeros((HEIGHT, WIDTH), np.uint32))
    before = source.read_bytes()
    # The input itself, by name: the objects would replace it.
    with pytest.raises(ValueError, match="would overwrite the input"):
        floodplane.segment_file(source, tmp_path / "l.pcd", objects_output=source)
    assert source.read_bytes() == before
    # The labelled cloud, by name or another spelling: the objects would replace it.
    (tmp_path / "o2").mkdir()
    for labels, objects in ((tmp_path / "s.pcd", tmp_path / "s.pcd"),
                            (tmp_path / "o2" / "s.pcd", str(tmp_path / "o2") + "/./s.pcd")):
        with pytest.raises(ValueError, match="are one file"):
            floodplane.segment_file(source, labels, objects_output=objects)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.pcd", "o2"]
    assert list((tmp_path / "o2").iterdir()) == []


def test_segment_file_writes_both_outputs_or_neither(tmp_path):
    source = tmp_path / "in.pcd"
    floodplane.write_labels_pcd(str(source), table_points(), np.zeros((HEIGHT, WIDTH), np.uint32))
    (tmp_path / "dir.objects.pcd").mkdir()
    for objects in (tmp_path / "nodir" / "t.o.pcd", tmp_path / "dir.objects.pcd"):
        with pytest.raises(OSError):
            floodplane.segment_file(source, tmp_path / "t.pcd", objects_output=objects)
        assert not (tmp_path / "t.pcd").exists(), f"{objects}: the labelled cloud left behind"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["dir.objects.pcd", "in.pcd"]


def test_objects_pickle():
    result = floodplane.segment(table_points(), objects=True)
    copied = pickle.loads(pickle.dumps(result))
    np.testing.assert_array_equal(copied.object_labels, result.object_labels)
    assert len(copied.objects) == len(result.objects)
    for a, b in zip(copied.objects, result.objects):
        assert (a.id, a.pixels, a.support) == (b.id, b.pixels, b.support)
        np.testing.assert_array_equal(a.centroid, b.centroid)
        np.testing.assert_array_equal(a.min, b.min)
        np.testing.assert_array_equal(a.max, b.max)
    plain = pickle.loads(pickle.dumps(floodplane.segment(table_points())))
    assert plain.objects is None

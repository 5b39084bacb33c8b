# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""floodplane.Tracker: ids that persist over a stream of segmentations, relabelled label images,
the tracks' records, the options as keywords, and a clear exception for every bad argument."""

import math

import numpy as np
import pytest

import floodplane
from conftest import real_frames, two_plane_scene


@pytest.fixture(scope="module")
def scene():
    return two_plane_scene()


@pytest.fixture(scope="module")
def segmented(scene):
    return floodplane.segment(scene)


def without_wall(points):
    """The scene with the wall (z = 2 m) gone: only the floor is left."""
    points = points.copy()
    points[points[..., 2] >= 1.9999] = np.nan
    return points


def moved(points, motion):
    """The points as a camera at pose `motion` (4 x 4, in the first camera's frame) sees them:
    p_current = R^T (p_previous - t)."""
    rotation, translation = motion[:3, :3], motion[:3, 3]
    return ((points.astype(np.float64) - translation) @ rotation).astype(np.float32)


def forward(metres, turn=0.0):
    """The camera's pose after moving `metres` forward (z) and turning `turn` radians about y."""
    motion = np.eye(4)
    c, s = math.cos(turn), math.sin(turn)
    motion[:3, :3] = [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    motion[2, 3] = metres
    return motion


def test_gives_the_same_ids_to_the_same_frame_segmented_twice(segmented):
    tracker = floodplane.Tracker()
    assert tracker.frame_count == 0 and tracker.tracks == []
    assert tracker.update(segmented) == [1, 2]  # the first frame's, in order of size
    assert tracker.update(segmented) == [1, 2]
    assert tracker.track_ids == [1, 2]
    assert tracker.frame_count == 2
    # On the first frame the ids are the size ranks, so the relabelled image is the label image.
    relabelled = tracker.relabel(segmented.labels)
    assert relabelled.dtype == np.uint32 and relabelled.shape == segmented.labels.shape
    np.testing.assert_array_equal(relabelled, segmented.labels)
    assert relabelled.flags.writeable and not np.shares_memory(relabelled, segmented.labels)  # the caller's

    tracks = tracker.tracks
    assert [track.id for track in tracks] == [1, 2]
    for track, plane in zip(tracks, segmented.planes):
        assert (track.first_frame, track.last_frame, track.frames_seen) == (0, 1, 2)
        assert track.plane == plane.label - 1
        assert track.inliers == plane.inliers
        np.testing.assert_allclose(track.normal, plane.normal, atol=1e-12)
        assert track.offset == pytest.approx(plane.d)
        np.testing.assert_allclose(track.centroid, plane.centroid)
        np.testing.assert_allclose(track.smoothed_normal, plane.normal, atol=1e-9)
        assert track.smoothed_offset == pytest.approx(plane.d)
        assert track.normal.shape == (3,) and track.smoothed_normal.shape == (3,)
        # The same frame twice: its best measurement is that frame's.
        assert track.best_inliers == plane.inliers
        np.testing.assert_allclose(track.best_normal, plane.normal, atol=1e-12)
        assert track.best_offset == pytest.approx(plane.d)
        np.testing.assert_allclose(track.best_centroid, plane.centroid)
    assert tracker.track(2).id == 2
    assert tracker.track(99) is None
    assert repr(tracks[0]).startswith("Track(id=1, first_frame=0, last_frame=1, frames_seen=2")
    assert repr(tracker) == "<floodplane.Tracker 2 frames, 2 tracks>"


def test_keeps_ids_when_a_plane_leaves_the_view_and_returns(scene, segmented):
    tracker = floodplane.Tracker()
    wall_id, floor_id = tracker.update(segmented)
    # The wall (the larger plane) gone: the floor is now the first plane, and keeps its id.
    floor_only = floodplane.segment(without_wall(scene))
    assert len(floor_only.planes) == 1
    assert tracker.update(floor_only) == [floor_id]
    relabelled = tracker.relabel(floor_only.labels)
    assert set(np.unique(relabelled)) == {0, floor_id}
    np.testing.assert_array_equal(relabelled == floor_id, floor_only.labels == 1)
    assert tracker.track(wall_id).plane == -1  # lost, still kept
    # Back in view: the wall gets its id back.
    assert tracker.update(segmented) == [wall_id, floor_id]
    assert tracker.track(wall_id).frames_seen == 2
    assert len(tracker.tracks) == 2


def test_a_plane_lost_for_longer_than_max_lost_frames_gets_a_new_id(scene, segmented):
    tracker = floodplane.Tracker(max_lost_frames=0)
    assert tracker.options["max_lost_frames"] == 0
    tracker.update(segmented)
    tracker.update(floodplane.segment(without_wall(scene)))
    assert tracker.track(1) is None  # dropped
    assert tracker.update(segmented) == [3, 2]


def test_follows_planes_across_a_large_move_when_given_the_motion(scene, segmented):
    motion = forward(0.3, turn=0.1)  # far beyond what a frame without a motion may change
    after = floodplane.segment(moved(scene, motion))
    assert len(after.planes) == 2
    told = floodplane.Tracker()
    told.update(segmented)
    assert told.update(after, motion=motion) == [1, 2]
    blind = floodplane.Tracker()
    blind.update(segmented)
    assert max(blind.update(after)) > 2, "without the motion, the wall 0.3 m nearer is a new surface"
    # The tracks are in the current camera's frame: the wall is 0.3 m nearer, and turned.
    wall = told.track(1)
    assert wall.offset == pytest.approx(segmented.planes[0].d - 0.3, abs=1e-3)
    assert wall.normal @ segmented.planes[0].normal == pytest.approx(math.cos(0.1), abs=1e-4)
    # Any array-like of numbers is a motion; the identity changes nothing.
    assert told.update(after, motion=np.eye(4).tolist()) == [1, 2]
    assert told.update(after, np.eye(4, dtype=np.float32)) == [1, 2]


def test_reset_forgets_the_tracks_and_keeps_the_options(segmented):
    tracker = floodplane.Tracker(smoothing=0.5, max_normal_angle=0.2)
    tracker.update(segmented)
    tracker.update(segmented)
    tracker.reset()
    assert tracker.frame_count == 0 and tracker.tracks == [] and tracker.track_ids == []
    assert tracker.options["smoothing"] == 0.5 and tracker.options["max_normal_angle"] == 0.2
    assert tracker.update(segmented) == [1, 2]
    assert tracker.tracks[0].first_frame == 0


def test_takes_every_option_as_a_keyword():
    options = {
        "max_normal_angle": 0.1,
        "max_offset_difference": 0.05,
        "max_lost_frames": 10,
        "smoothing": 1,
        "overlap_max_rotation": 0.02,
        "overlap_max_translation": np.float32(0.25),
    }
    tracker = floodplane.Tracker(**options)
    assert tracker.options == pytest.approx(options)
    assert set(floodplane.Tracker().options) == set(options)


@pytest.mark.parametrize(
    "keywords, exception, message",
    [
        ({"max_lost_frame": 3}, TypeError, "unexpected keyword argument 'max_lost_frame'.*max_lost_frames"),
        ({"smoothing": "0.5"}, TypeError, "smoothing must be a number, got str"),
        ({"smoothing": True}, TypeError, "smoothing must be a number, got bool"),
        ({"max_lost_frames": 1.5}, TypeError, "max_lost_frames must be an integer, got float"),
        ({"smoothing": 0.0}, ValueError, r"Tracker: smoothing must be in \(0, 1\]"),
        ({"max_lost_frames": -1}, ValueError, "Tracker: max_lost_frames must be >= 0"),
        ({"max_normal_angle": float("nan")}, ValueError, "max_normal_angle"),
        ({"max_offset_difference": 0}, ValueError, "max_offset_difference"),
        ({"overlap_max_translation": -1}, ValueError, "overlap_max_translation"),
    ],
)
def test_rejects_bad_options_naming_them(keywords, exception, message):
    with pytest.raises(exception, match=message):
        floodplane.Tracker(**keywords)


def test_rejects_bad_arguments_with_a_clear_message(segmented):
    tracker = floodplane.Tracker()
    with pytest.raises(ValueError, match=r"Tracker.relabel: no frame yet: call update\(\) first"):
        tracker.relabel(segmented.labels)
    with pytest.raises(TypeError, match="result must be a floodplane.Segmentation .*got numpy.ndarray"):
        tracker.update(segmented.labels)
    with pytest.raises(TypeError, match="got NoneType"):
        tracker.update(None)
    with pytest.raises(ValueError, match=r"motion must have shape \(4, 4\), got \(3, 3\)"):
        tracker.update(segmented, motion=np.eye(3))
    with pytest.raises(ValueError, match="Tracker.update: the motion must be a finite rigid transform"):
        tracker.update(segmented, motion=2 * np.eye(4))
    not_finite = np.eye(4)
    not_finite[0, 3] = np.nan
    with pytest.raises(ValueError, match="rigid"):
        tracker.update(segmented, motion=not_finite)
    with pytest.raises(TypeError, match="motion must be a 4 x 4 array"):
        tracker.update(segmented, motion="identity")
    with pytest.raises(TypeError, match="motion must be a 4 x 4 array of numbers .*got dtype bool"):
        tracker.update(segmented, motion=np.eye(4, dtype=bool))
    assert tracker.frame_count == 0, "a rejected frame is no frame"

    tracker.update(segmented)
    with pytest.raises(ValueError, match=r"labels must have shape \(120, 160\), got \(160, 120\)"):
        tracker.relabel(segmented.labels.T)
    with pytest.raises(TypeError, match="labels must be an integer array, got dtype float64"):
        tracker.relabel(segmented.labels.astype(np.float64))
    too_high = np.array(segmented.labels)
    too_high[5, 6] = 3
    with pytest.raises(ValueError, match=r"labels must hold values in \[0, 2\], got 3 at row 5, column 6"):
        tracker.relabel(too_high)
    with pytest.raises(TypeError, match="id must be an integer"):
        tracker.track("1")


def test_the_real_kinect_frames_keep_the_ids_of_their_large_planes():
    """Every plane of at least 2 % of a frame that covers the same pixels as a plane of the frame
    before (intersection over union at least 0.5) has that plane's id: no id switches."""
    frames = [f for f in real_frames() if f.name.startswith("frame_20121214T14225")]
    if len(frames) != 3:
        pytest.skip("the three consecutive Kinect frames frame_20121214T14225* are not in FLOODPLANE_REAL_DATA_DIR")
    segmenter = floodplane.Segmenter()
    tracker = floodplane.Tracker()
    labels = []
    for frame in frames:
        result = segmenter.segment(floodplane.read_pcd(frame))
        tracker.update(result)
        labels.append(tracker.relabel(result.labels))
    compared = 0
    for previous, current in zip(labels, labels[1:]):
        for track_id in np.unique(current):
            plane = current == track_id
            if track_id == 0 or np.count_nonzero(plane) < 0.02 * current.size:
                continue
            candidates, shared = np.unique(previous[plane], return_counts=True)
            overlaps = [
                (count / (np.count_nonzero(previous == candidate) + np.count_nonzero(plane) - count), candidate)
                for candidate, count in zip(candidates, shared)
                if candidate != 0
            ]
            if overlaps and max(overlaps)[0] >= 0.5:
                assert max(overlaps)[1] == track_id
                compared += 1
    assert compared >= 6  # not vacuous: most large planes of frames 2 and 3 have one in the frame before

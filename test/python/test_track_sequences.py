# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/track_sequences.py, the plane tracking figures of issue 28: its Python counting gives
what toolkit/eval/tracking_metrics.h defines on the hand-made sequences of
test/toolkit/eval/test_tracking_metrics.cpp, it reads text PCDs, a rendered sequence scored against
itself has no switch and nothing lost, --look-away renders with pcd_synth --look-away, and
pcd_segment gets the sequence's camera poses unless --no-poses."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "bench"))
import track_sequences  # noqa: E402


def labels(row):
    return [0 if c == "." else int(c) for c in row]


def scores(frames, **options):
    """Frames of 10 pixels, present from 2 of them, as in the C++ tests."""
    evaluator = track_sequences.TrackingEvaluator(**{"min_fraction": 0.2, **options})
    for ground_truth, predicted in frames:
        evaluator.add_frame(labels(ground_truth), labels(predicted), [True] * len(ground_truth))
    return evaluator.scores


def test_a_constant_sequence_has_no_switches_and_nothing_lost():
    s = scores([("1111122222", "3333344444")] * 5)
    assert (s["plane_frames"], s["matched"], s["id_switches"], s["lost"]) == (10, 10, 0, 0)


def test_two_planes_swapping_their_ids_are_two_switches():
    s = scores([("1111122222", "3333344444"), ("1111122222", "4444433333"), ("1111122222", "4444433333")])
    assert s["id_switches"] == 2


def test_an_unmatched_plane_is_lost_and_keeps_its_remembered_id():
    s = scores([("1111......", "5555......"), ("1111......", ".........."), ("1111......", "5555555555"),
                ("1111......", "5555......")])
    assert (s["matched"], s["lost"], s["id_switches"]) == (2, 2, 0)


def test_a_plane_matches_the_id_overlapping_it_most_from_iou_one_half():
    s = scores([("111111....", "777788...."), ("111111....", "888777...."), ("111111....", "7788888888")])
    assert (s["matched"], s["lost"], s["id_switches"]) == (2, 1, 0)


def test_re_entries_with_the_old_id_are_kept_and_with_a_new_one_switched():
    kept = scores([("1111122222", "5555566666")] * 3 + [("2222222222", "6666666666")] * 4
                  + [("1111122222", "5555566666")] * 2)
    assert (kept["re_entries"], kept["re_entries_kept"], kept["id_switches"], kept["plane_frames"]) == (1, 1, 0, 14)
    switched = scores([("1111122222", "5555566666"), ("2222222222", "6666666666"), ("1111122222", "7777766666")])
    assert (switched["re_entries"], switched["re_entries_switched"], switched["id_switches"]) == (1, 1, 1)
    late = scores([("1111122222", "5555566666"), ("2222222222", "6666666666"), ("1111122222", "....666666"),
                   ("1111122222", "5555566666")])
    assert (late["re_entries_kept"], late["lost"]) == (1, 1)


def test_a_plane_away_longer_than_the_gap_is_forgotten_not_switched():
    def away(frames):
        return [("1111122222", "5555566666")] + [("2222222222", "6666666666")] * frames + [("1111122222", "7777766666")]
    within = scores(away(3), max_gap=3)
    assert (within["re_entries"], within["id_switches"]) == (1, 1)
    beyond = scores(away(4), max_gap=3)
    assert (beyond["re_entries"], beyond["id_switches"]) == (0, 0)


def test_small_planes_are_absent_and_invalid_pixels_count_nowhere():
    s = scores([("1111133333", "5555577777"), ("1111111113", "5555555557"), ("1111133333", "5555577777")])
    assert (s["plane_frames"], s["re_entries_kept"]) == (5, 1)
    evaluator = track_sequences.TrackingEvaluator(min_fraction=0.2)
    evaluator.add_frame(labels("11111111.."), labels("55555555.."), [c != "x" for c in "xxxxxx...."])
    evaluator.add_frame(labels("11111111.."), labels("55555555.."), [c != "x" for c in "xxxxxxx..."])
    assert (evaluator.scores["plane_frames"], evaluator.scores["matched"]) == (1, 1)
    with pytest.raises(ValueError):
        evaluator.add_frame([1, 1], [1], [True, True])


def test_text_pcds_give_their_labels_and_finite_points(tmp_path):
    header = ("VERSION 0.7\nFIELDS x y z label\nSIZE 4 4 4 4\nTYPE F F F U\nCOUNT 1 1 1 1\nWIDTH 3\nHEIGHT 1\n"
              "VIEWPOINT 0 0 0 1 0 0 0\nPOINTS 3\nDATA ascii\n")
    path = tmp_path / "frame.pcd"
    path.write_text(header + "1 2 3 7\nnan nan nan 0\n-1 0.5 2 12\n")
    labels, valid = track_sequences.read_ascii_pcd(path)
    assert (labels.tolist(), valid.tolist()) == ([7, 0, 12], [True, False, True])
    # Fields in another order.
    path.write_text(header.replace("x y z label", "label x y z") + "7 1 2 3\n0 nan nan nan\n12 -1 0.5 2\n")
    labels, valid = track_sequences.read_ascii_pcd(path)
    assert (labels.tolist(), valid.tolist()) == ([7, 0, 12], [True, False, True])
    path.write_text(header + "1 2 3 7\nnan nan nan 0\n")
    with pytest.raises(ValueError, match="2 points, the header says 3"):
        track_sequences.read_ascii_pcd(path)
    path.write_text(header.replace("ascii", "binary_compressed"))
    with pytest.raises(ValueError, match="text PCDs only"):
        track_sequences.read_ascii_pcd(path)


def test_seed_lists():
    assert track_sequences.parse_seeds("1-3,7") == [1, 2, 3, 7]


@pytest.mark.skipif("FLOODPLANE_PCD_SYNTH" not in os.environ, reason="needs pcd_synth (FLOODPLANE_PCD_SYNTH)")
def test_the_ground_truth_scored_as_tracks_has_no_switch_and_nothing_lost(tmp_path):
    completed = subprocess.run([sys.executable, str(SOURCE / "bench/track_sequences.py"), "--seeds", "2",
                                "--frames", "3", "--ground-truth-as-tracks", "--pcd-synth",
                                os.environ["FLOODPLANE_PCD_SYNTH"], "--json", str(tmp_path / "figures.json")],
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    assert "| all | 3 |" in completed.stdout
    figures = json.loads((tmp_path / "figures.json").read_text())["all"]
    assert figures["plane_frames"] > 0
    assert figures["plane_frames"] == figures["matched"]
    assert (figures["id_switches"], figures["lost"]) == (0, 0)


@pytest.mark.skipif("FLOODPLANE_PCD_SYNTH" not in os.environ, reason="needs pcd_synth (FLOODPLANE_PCD_SYNTH)")
def test_look_away_renders_the_sequence_with_pcd_synth_look_away(tmp_path):
    completed = subprocess.run([sys.executable, str(SOURCE / "bench/track_sequences.py"), "--seeds", "2",
                                "--frames", "2", "--sensor", "none", "--look-away", "--ground-truth-as-tracks",
                                "--pcd-synth", os.environ["FLOODPLANE_PCD_SYNTH"], "--work", str(tmp_path / "work"),
                                "--json", str(tmp_path / "figures.json")], capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    assert "looking away" in completed.stdout
    assert json.loads((tmp_path / "figures.json").read_text())["look_away"] is True
    poses = json.loads((tmp_path / "work/random_0002/truth/random_0002.poses.json").read_text())
    assert poses["look_away"]["angle_degrees"] == [60.0, 90.0]


@pytest.mark.skipif("FLOODPLANE_PCD_SYNTH" not in os.environ or "FLOODPLANE_PCD_SEGMENT" not in os.environ,
                    reason="needs pcd_synth and pcd_segment (FLOODPLANE_PCD_SYNTH, FLOODPLANE_PCD_SEGMENT)")
def test_pcd_segment_gets_the_camera_poses_unless_no_poses(tmp_path):
    for no_poses in (False, True):
        figures_path = tmp_path / f"figures_{no_poses}.json"
        completed = subprocess.run([sys.executable, str(SOURCE / "bench/track_sequences.py"), "--seeds", "2",
                                    "--frames", "3", "--sensor", "none", *(["--no-poses"] if no_poses else []),
                                    "--pcd-synth", os.environ["FLOODPLANE_PCD_SYNTH"], "--pcd-segment",
                                    os.environ["FLOODPLANE_PCD_SEGMENT"], "--json", str(figures_path)],
                                   capture_output=True, text=True)
        assert completed.returncode == 0, completed.stderr
        assert ("without poses" if no_poses else "--poses <scene>.poses.json") in completed.stdout
        figures = json.loads(figures_path.read_text())
        assert figures["poses"] is not no_poses
        assert figures["all"]["plane_frames"] > 0


def test_bad_arguments_are_one_line_errors():
    script = str(SOURCE / "bench/track_sequences.py")
    for arguments, message in [(["--frames", "0"], "--frames"), (["--seeds", "x"], "--seeds"),
                               (["--min-iou", "2"], "--min-iou"),
                               (["--pcd-synth", "/nonexistent/pcd_synth"], "no binary")]:
        completed = subprocess.run([sys.executable, script, *arguments], capture_output=True, text=True)
        assert completed.returncode != 0
        assert message in completed.stderr.strip().splitlines()[-1]

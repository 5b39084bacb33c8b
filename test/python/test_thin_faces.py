# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/thin_faces.py, the thin-faces figures of issue 26: its one-to-one matching and scoring
on hand-made frames (planes and segments under the size limit left out, NaN pixels ignored, a
segment given to one plane only, best IoU first), the board face classes, and end to end: the
ground truth scored as segments finds every face, pcd_segment's output gives shares in [0, 1]."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "bench"))
import thin_faces  # noqa: E402


def labels(row):
    return [0 if c == "." else int(c) for c in row]


LISTING = [{"id": 1, "primitive": "wall 1", "face": ""},
           {"id": 2, "primitive": "standing board 1", "face": "+y"},
           {"id": 3, "primitive": "standing board 1", "face": "+z"},
           {"id": 4, "primitive": "leaning board 2", "face": "-x"}]


def records(ground_truth, predicted, valid=None, min_pixels=2, min_iou=0.8):
    valid = [True] * len(ground_truth) if valid is None else [c != "x" for c in valid]
    return thin_faces.score_frame(labels(ground_truth), labels(predicted), valid, LISTING, min_pixels, min_iou)


def score(*arguments, **options):
    return {r["id"]: (r["class"], r["pixels"], round(r["iou"], 3), r["found"])
            for r in records(*arguments, **options)}


def missed(*arguments, **options):
    return {r["id"]: r["missed"] for r in records(*arguments, **options)}


def test_faces_are_classed_by_primitive_name_and_face():
    assert thin_faces.face_class("standing board 1", "+y") == "large"
    assert thin_faces.face_class("standing board 1", "-y") == "large"
    assert thin_faces.face_class("leaning board 12", "+x") == "thin"
    assert thin_faces.face_class("shelf board 3", "-z") == "thin"
    assert thin_faces.face_class("wall 1", "") == "room"
    assert thin_faces.face_class("floor", "") == "room"
    assert thin_faces.face_class("table 1 top", "+x") == "room"
    assert thin_faces.board_kind("lying board 2") == "lying"
    assert thin_faces.board_kind("board 2") is None


def test_an_edge_taken_by_the_broad_face_is_missed_and_the_broad_face_still_found():
    # Plane 3 (an edge, 2 pixels) is labelled as part of the board's broad face (segment 7).
    s = score("1111222222223311", "5555777777777755")
    assert s[3] == ("thin", 2, 0.0, False)
    assert s[2] == ("large", 8, 0.8, True)
    assert s[1] == ("room", 6, 1.0, True)


def test_where_the_pixels_of_a_face_not_found_went():
    assert missed("1111222222223311", "5555777777777755")[3] == "mostly in a segment of its own board's broad face"
    assert missed("1111222222223311", "5555777777778855")[3] is None
    assert missed("1111222222223311", "5555777777770055")[3] == "mostly unlabelled"
    assert missed("1111222222224411", "5555777777555555")[4] == "mostly in a floor, wall or ceiling segment"
    assert missed("1111222222224411", "5555777777999955")[4] == "its own segment, IoU too low"
    # Plane 4's partner is segment 5 (IoU 1/4); most of its pixels are in segment 6, too large
    # to be anyone's partner.
    assert missed("4444..........11", "5666666666666611", min_pixels=1)[4] == "mostly in a segment matched to no plane"
    # Plane 4's pixels in segment 6, partner of plane 2 (a broad face of another board).
    assert missed("22224444", "66666669", min_pixels=1, min_iou=0.3)[4] == "mostly in another board's segment"


def test_an_edge_segmented_on_its_own_is_found():
    s = score("1111222222223311", "5555777777778855")
    assert s[3] == ("thin", 2, 1.0, True)
    assert s[2][3] is True


def test_a_segment_goes_to_one_plane_only_best_iou_first():
    # Segment 6 covers planes 2 and 4: IoU 4/6 with plane 2, 2/6 with plane 4; plane 4 gets
    # nothing (with the best over all segments it would have 1/3).
    s = score("22224411", "66666611", min_iou=0.5)
    assert s[2] == ("large", 4, 0.667, True)
    assert s[4] == ("thin", 2, 0.0, False)
    # Plane 4 overlaps segment 6 best (3/8), but plane 2 takes it (4/7): plane 4 is left with
    # segment 9 (1/4), under 0.3, where the best over all segments would have found it.
    s = score("22224444", "66666669", min_pixels=1, min_iou=0.3)
    assert s[2] == ("large", 4, 0.571, True)
    assert s[4] == ("thin", 4, 0.25, False)


def test_small_planes_and_segments_are_left_out_and_nan_pixels_ignored():
    # Plane 3 has 2 pixels, under min_pixels 3: not counted.
    assert 3 not in score("1111222222223311", "5555777777778855", min_pixels=3)
    # Segment 8 of 2 pixels is too small to be a partner.
    assert score("1111222222224444", "5555777777778899", min_pixels=3)[4][2] == 0.0
    # NaN pixels (x) count nowhere: plane 4's two valid pixels are exactly segment 8's.
    s = score("1111222222224444", "5555777777779988", valid="............xx..")
    assert s[4] == ("thin", 2, 1.0, True)
    with pytest.raises(ValueError):
        thin_faces.match_one_to_one([1, 1], [1], [True, True], 1)
    with pytest.raises(ValueError, match="label 9"):
        thin_faces.score_frame([9, 9], [1, 1], [True, True], LISTING, 1, 0.8)


def test_figures_count_per_class_kind_and_size():
    faces = [{"class": "thin", "kind": "leaning", "pixels": 400, "iou": 0.9, "found": True, "missed": None},
             {"class": "thin", "kind": "standing", "pixels": 2000, "iou": 0.5, "found": False,
              "missed": "mostly unlabelled"},
             {"class": "large", "kind": "standing", "pixels": 9000, "iou": 0.95, "found": True, "missed": None}]
    f = thin_faces.figures(faces)
    assert f["thin_missed"] == {"mostly unlabelled": 1}
    assert (f["thin"]["faces"], f["thin"]["found"], f["thin"]["share"]) == (2, 1, 0.5)
    assert f["thin"]["mean_iou"] == pytest.approx(0.7)
    assert f["room"] == {"faces": 0, "found": 0, "share": None, "mean_iou": None}
    assert f["thin_by_kind"]["leaning"]["found"] == 1
    assert (f["thin_by_pixels"]["0-1000"]["faces"], f["thin_by_pixels"]["1000-3000"]["faces"]) == (1, 1)


def test_seed_runs():
    assert thin_faces.seed_runs([1, 2, 3, 7, 8, 10]) == [[1, 3], [7, 2], [10, 1]]


@pytest.mark.skipif("FLOODPLANE_PCD_SYNTH" not in os.environ, reason="needs pcd_synth (FLOODPLANE_PCD_SYNTH)")
def test_the_ground_truth_scored_as_segments_finds_every_face(tmp_path):
    completed = subprocess.run([sys.executable, str(SOURCE / "bench/thin_faces.py"), "--seeds", "1-2",
                                "--ground-truth-as-segments", "--pcd-synth", os.environ["FLOODPLANE_PCD_SYNTH"],
                                "--json", str(tmp_path / "figures.json")], capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    figures = json.loads((tmp_path / "figures.json").read_text())["figures"]
    for sensor in ("kinect", "none"):
        for name in ("thin", "large", "room"):
            assert figures[sensor][name]["faces"] > 0, (sensor, name)
            assert figures[sensor][name]["share"] == 1.0, (sensor, name)


@pytest.mark.skipif("FLOODPLANE_PCD_SYNTH" not in os.environ or "FLOODPLANE_PCD_SEGMENT" not in os.environ,
                    reason="needs pcd_synth and pcd_segment (FLOODPLANE_PCD_SYNTH, FLOODPLANE_PCD_SEGMENT)")
def test_pcd_segment_output_is_scored_per_sensor(tmp_path):
    completed = subprocess.run([sys.executable, str(SOURCE / "bench/thin_faces.py"), "--seeds", "3",
                                "--sensors", "none", "--pcd-synth", os.environ["FLOODPLANE_PCD_SYNTH"],
                                "--pcd-segment", os.environ["FLOODPLANE_PCD_SEGMENT"], "--work",
                                str(tmp_path / "work"), "--json", str(tmp_path / "figures.json")],
                               capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    assert "| none | 2 cm edges |" in completed.stdout
    assert (tmp_path / "work/segmented/boards_0003.none.labels.pcd").is_file()
    assert not (tmp_path / "work/truth/boards_0003.kinect.pcd").exists()
    document = json.loads((tmp_path / "figures.json").read_text())
    assert list(document["figures"]) == ["none"]
    room = document["figures"]["none"]["room"]
    assert room["faces"] > 0 and 0.0 <= room["share"] <= 1.0
    assert all(0.0 <= face["iou"] <= 1.0 for face in document["faces"]["none"])


def test_bad_arguments_are_one_line_errors():
    script = str(SOURCE / "bench/thin_faces.py")
    for arguments, message in [(["--seeds", "x"], "--seeds"), (["--sensors", "scanner"], "--sensors"),
                               (["--min-iou", "2"], "--min-iou"), (["--min-pixels", "0"], "--min-pixels"),
                               (["--pcd-synth", "/nonexistent/pcd_synth"], "no binary")]:
        completed = subprocess.run([sys.executable, script, *arguments], capture_output=True, text=True)
        assert completed.returncode != 0
        assert message in completed.stderr.strip().splitlines()[-1]

# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/abw_scores.py, the ABW figures of issue 46: its summary of a hand-made pcd_compare
report (regions and correct detections by size bin, misses by class, mean IoU over the regions,
noise segments), the skip without the scans, and end to end on the scans when they are beside
the project (../shared/data/abw-tune; the test skips without them)."""

import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "bench"))
import abw_scores  # noqa: E402

SCRIPT = SOURCE / "bench/abw_scores.py"


def plane(label, pixels, iou, miss=None, unlabelled=0.0):
    return {"label": label, "pixels": pixels, "iou": iou, "miss": miss, "unlabelled_share": unlabelled}


# Two frames; method "a" finds 3 of 5 regions, method "b" (labels from files) 1 of 2 in the
# one frame it has; the first frame has no ground truth for "c" (no per_plane): not counted.
REPORT = {"scenes": [
    {"name": "abw.test.0", "methods": {
        "a": {"per_plane": [plane(10, 150, 0.9), plane(11, 999, 0.1, "no_segment", 0.95),
                            plane(12, 1000, 0.85)],
              "noise_segments": [{"label": 7}]},
        "b": {"per_plane": [plane(10, 150, 0.8), plane(11, 999, 0.6, "iou_below_t", 0.3)],
              "noise_segments": []},
        "c": {"median_ms": 1.0}}},
    {"name": "abw.test.3", "methods": {
        "a": {"per_plane": [plane(10, 10000, 0.5, "over_segmented", 0.1), plane(11, 9999, 0.95)],
              "noise_segments": [{"label": 3}, {"label": 4}]}}},
]}


def test_regions_are_counted_by_size_bin_and_miss_class():
    methods = abw_scores.summarize(REPORT)
    assert list(methods) == ["a", "b"]
    a = methods["a"]
    assert (a["regions"], a["correct"], a["noise"]) == (5, 3, 3)
    assert a["mean_iou"] == pytest.approx((0.9 + 0.1 + 0.85 + 0.5 + 0.95) / 5)
    bins = a["bins"]
    assert bins[(100, 1000)] == {"regions": 2, "correct": 1, "no_segment": 1, "under_segmented": 0,
                                 "over_segmented": 0, "iou_below_t": 0}
    assert (bins[(1000, 3000)]["regions"], bins[(1000, 3000)]["correct"]) == (1, 1)
    assert (bins[(3000, 10000)]["regions"], bins[(3000, 10000)]["correct"]) == (1, 1)
    assert bins[(10000, None)]["over_segmented"] == 1
    # Every region not found, with its frame.
    assert [(m["file"], m["label"], m["miss"]) for m in a["misses"]] == [
        ("abw.test.0", 11, "no_segment"), ("abw.test.3", 10, "over_segmented")]
    assert (methods["b"]["regions"], methods["b"]["correct"]) == (2, 1)


def test_the_tables_add_up_and_name_the_share():
    text = abw_scores.markdown(abw_scores.summarize(REPORT))
    assert "### a: 3 of 5 regions correct (60.0 %), mean IoU 0.660, 3 noise segments" in text
    assert "| 100-999 | 2 | 1 | 1 | 0 | 0 | 0 |" in text
    assert "| >= 10,000 | 1 | 0 | 0 | 0 | 1 | 0 |" in text
    assert "| all | 5 | 3 | 1 | 0 | 1 | 0 |" in text
    listing = abw_scores.listing(abw_scores.summarize(REPORT))
    assert "| abw.test.0 | 11 | no_segment | 999 | 0.10 | 95 % |" in listing


def test_without_the_scans_it_skips_with_the_reason(tmp_path):
    completed = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path), "--data", str(tmp_path / "absent")],
                               capture_output=True, text=True)
    assert completed.returncode == abw_scores.SKIPPED
    assert completed.stdout == ""
    assert completed.stderr.startswith("abw_scores.py: skipped: ")
    assert "absent not found" in completed.stderr
    (tmp_path / "empty").mkdir()
    completed = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path), "--data", str(tmp_path / "empty")],
                               capture_output=True, text=True)
    assert completed.returncode == abw_scores.SKIPPED
    assert "no abw.test.*.pcd in" in completed.stderr


def test_scores_the_ten_scans_when_they_are_there():
    files, problem = abw_scores.scans(abw_scores.DATA)
    if problem:
        pytest.skip(problem)
    build = os.environ.get("FLOODPLANE_BUILD_DIR")
    if not build or not (pathlib.Path(build) / "apps/pcd_compare/pcd_compare").is_file():
        pytest.skip("no pcd_compare in the build tree (FLOODPLANE_BUILD_DIR)")
    assert [path.name for path in files][:3] == ["abw.test.0.pcd", "abw.test.3.pcd", "abw.test.6.pcd"]
    completed = subprocess.run([sys.executable, str(SCRIPT), build], capture_output=True, text=True)
    assert completed.returncode == 0, completed.stderr
    # The figure line, and a size table whose last row adds up to its regions. (No figure of the
    # scans is written down here: they stay beside the project.)
    heading = next(line for line in completed.stdout.splitlines() if line.startswith("### floodplane: "))
    correct, regions = (int(word) for word in heading.split(": ")[1].split()[0:3:2])
    assert 0 <= correct <= regions and regions > 0
    total = next(line for line in completed.stdout.splitlines() if line.startswith("| all | "))
    counts = [int(cell) for cell in total.strip("| \n").split(" | ")[1:]]
    assert counts[:2] == [regions, correct] and sum(counts[1:]) == regions

# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/speed_accuracy_chart.py and update_figures.py --chart: the speed-against-accuracy chart
drawn from made-up pcd_compare reports of known figures, a panel per run; the figures it
places are pcd_compare's means; the same inputs give the same PNG, other inputs another; the
caption goes between bench/README.md's chart markers; what cannot be drawn is refused with
nothing written. Skipped where matplotlib is not installed."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

pytest.importorskip("matplotlib", reason="matplotlib is not installed (Debian: python3-matplotlib, "
                                         "scripts/install_deps.sh)")

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(SOURCE / "bench"))
import compare_tables  # noqa: E402
import speed_accuracy_chart  # noqa: E402

UPDATE = SOURCE / "bench/update_figures.py"
CHART = SOURCE / "bench/speed_accuracy_chart.py"
PAGE = "# Page\nbefore\n<!-- figures:chart begin -->\nold chart\n<!-- figures:chart end -->\nafter\n"
PNG_SIGNATURE = b"\x89PNG\r\n\x1a\n"


def result(ms, planes, iou=None):
    entry = {"median_ms": ms, "min_ms": ms, "planes": planes}
    if iou is not None:
        entry.update({"mean_iou": iou, "weighted_iou": iou, "false_plane_fraction": 0.0, "ground_truth_planes": 4,
                      "hoover": {"correct": 3, "over": 0, "under": 0, "missed": 1, "noise": 0}})
    return entry


def report(scenes, timing="median and min of 3 runs after one warm-up (the sequential RANSACs: one run)"):
    return {"configuration": {"timing": timing + ", of the segmentation call alone, one thread"},
            "scenes": [{"name": name, "file": f"{name}.pcd", "width": 64, "height": 48,
                        "ground_truth": any("mean_iou" in m for m in methods.values()), "methods": methods}
                       for name, methods in scenes]}


def scored_run():
    """Two files with ground truth: floodplane fast and right, OMPS slower, tuned OMPS between."""
    return report([("a.kinect", {"floodplane": result(10.0, 4, 0.9), "omps": result(40.0, 2, 0.3),
                                 "omps (tuned)": result(44.0, 3, 0.5)}),
                   ("b.none", {"floodplane": result(20.0, 4, 1.0), "omps": result(60.0, 2, 0.5),
                               "omps (tuned)": result(56.0, 3, 0.7)})])


def unscored_run():
    """Real frames: no ground truth, planes per frame."""
    return report([("office1", {"floodplane": result(30.0, 40), "floodplane/4": result(6.0, 20),
                                "ransac": result(900.0, 12)}),
                   ("five_people", {"floodplane": result(34.0, 50), "floodplane/4": result(8.0, 30),
                                    "ransac": result(1100.0, 14)})])


@pytest.fixture
def runs(tmp_path):
    (tmp_path / "scenes.json").write_text(json.dumps(scored_run()))
    (tmp_path / "real.json").write_text(json.dumps(unscored_run()))
    (tmp_path / "bench.md").write_text(PAGE)
    (tmp_path / "README.md").write_text("no markers needed\n")
    (tmp_path / "figures").mkdir()
    return tmp_path


def update(directory, *arguments):
    return subprocess.run([sys.executable, str(UPDATE), "--bench-readme", str(directory / "bench.md"),
                           "--readme", str(directory / "README.md"), *map(str, arguments)],
                          capture_output=True, text=True, timeout=300)


def chart_arguments(directory, chart="figures/chart.png", real="real.json"):
    return ["--chart", directory / chart, "--chart-run", f"bundled scenes={directory / 'scenes.json'}",
            "--chart-run", f"real frames={directory / real}"]


def test_the_points_are_pcd_compares_means():
    title, label, points = speed_accuracy_chart.panel("scenes", [compare_tables.Scene(s, "s")
                                                                 for s in scored_run()["scenes"]])
    assert (title, label) == ("scenes (2 files)", "mean IoU")
    assert points == [("floodplane", 15.0, pytest.approx(0.95)), ("omps", 50.0, pytest.approx(0.4)),
                      ("omps (tuned)", 50.0, pytest.approx(0.6))]
    title, label, points = speed_accuracy_chart.panel("real", [compare_tables.Scene(s, "s")
                                                               for s in unscored_run()["scenes"]])
    assert label == "planes found per frame (no ground truth)"
    assert points == [("floodplane", 32.0, 45.0), ("floodplane/4", 7.0, 25.0), ("ransac", 1000.0, 13.0)]


def test_tuned_baselines_keep_their_method_s_colour_and_marker_hollow():
    assert speed_accuracy_chart.style("omps (tuned)") == speed_accuracy_chart.style("omps")[:2] + (True,)
    assert speed_accuracy_chart.style("omps")[2] is False
    assert speed_accuracy_chart.style("cape")[:2] == speed_accuracy_chart.OTHER_STYLE


def test_update_figures_draws_a_panel_per_run_and_captions_it(runs):
    done = update(runs, *chart_arguments(runs))
    assert done.returncode == 0, done.stderr
    chart = (runs / "figures/chart.png").read_bytes()
    assert chart.startswith(PNG_SIGNATURE)
    width, height = int.from_bytes(chart[16:20], "big"), int.from_bytes(chart[20:24], "big")
    assert width > 1.8 * height, "two panels side by side"
    page = (runs / "bench.md").read_text()
    assert "old chart" not in page and page.startswith("# Page\nbefore\n") and page.endswith("after\n")
    assert "![Speed against accuracy of each method, a panel per data set](figures/chart.png)" in page
    assert "bundled scenes: 2 files, floodplane, omps, omps (tuned); median and min of 3 runs" in page
    assert "real frames: 2 files, floodplane, floodplane/4, ransac;" in page
    assert (runs / "README.md").read_text() == "no markers needed\n"
    assert not list((runs / "figures").glob("*.partial")), "no temporary left"


def test_the_same_runs_give_the_same_picture_and_other_runs_another(runs):
    assert update(runs, *chart_arguments(runs)).returncode == 0
    first = (runs / "figures/chart.png").read_bytes()
    assert update(runs, *chart_arguments(runs)).returncode == 0
    assert (runs / "figures/chart.png").read_bytes() == first
    faster = unscored_run()
    faster["scenes"][0]["methods"]["ransac"]["median_ms"] = 90.0
    (runs / "faster.json").write_text(json.dumps(faster))
    assert update(runs, *chart_arguments(runs, real="faster.json")).returncode == 0
    assert (runs / "figures/chart.png").read_bytes() != first


def test_the_script_alone_draws_the_same_chart(runs):
    assert update(runs, *chart_arguments(runs)).returncode == 0
    done = subprocess.run([sys.executable, str(CHART), f"bundled scenes={runs / 'scenes.json'}",
                           f"real frames={runs / 'real.json'}", "-o", str(runs / "alone.png")],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    assert (runs / "alone.png").read_bytes() == (runs / "figures/chart.png").read_bytes()


def test_a_run_with_nothing_to_draw_is_refused_and_nothing_is_written(runs):
    labels_only = report([("a", {"cape": {"median_ms": None, "min_ms": None, "planes": 3}})])
    (runs / "labels.json").write_text(json.dumps(labels_only))
    done = update(runs, *chart_arguments(runs, real="labels.json"))
    assert done.returncode == 1
    assert "real frames: no method with a time and a figure to draw" in done.stderr
    assert (runs / "bench.md").read_text() == PAGE
    assert not (runs / "figures/chart.png").exists()
    (runs / "broken.json").write_text("{")
    done = update(runs, *chart_arguments(runs, real="broken.json"))
    assert done.returncode == 1 and "broken.json is not JSON" in done.stderr
    assert not (runs / "figures/chart.png").exists()


def test_a_page_without_the_chart_markers_gets_no_chart(runs):
    (runs / "bench.md").write_text("no markers\n")
    done = update(runs, *chart_arguments(runs))
    assert done.returncode == 1
    assert "no single pair of markers <!-- figures:chart begin -->" in done.stderr
    assert not (runs / "figures/chart.png").exists()


@pytest.mark.parametrize("arguments, message", [
    (["--chart-run", "x=y.json"], "give --chart PNG too"),
    (["--chart", "c.png"], "--chart needs a pcd_compare run"),
    (["--chart", "c.png", "--chart-run", "no title"], "is not TITLE=JSON"),
])
def test_refuses_chart_options_that_cannot_work(runs, arguments, message):
    done = update(runs, *arguments)
    assert done.returncode == 2
    assert message in done.stderr

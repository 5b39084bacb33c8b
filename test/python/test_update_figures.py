# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/update_figures.py, which writes bench/README.md's tables and the README's speed
sentence from one run: made-up inputs of known figures into copies of pages with markers; the
text around the markers kept; bad input refused with nothing written; the real pages carry
every marker the script fills."""

import json
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCRIPT = SOURCE / "bench/update_figures.py"

BENCH_PAGE = """# Page
before
<!-- figures:speed begin -->
old speed
<!-- figures:speed end -->
middle
<!-- figures:accuracy begin -->
<!-- figures:accuracy end -->
<!-- figures:accuracy-quirks begin -->
<!-- figures:accuracy-quirks end -->
<!-- figures:objects begin -->
<!-- figures:objects end -->
<!-- figures:resolution begin -->
<!-- figures:resolution end -->
<!-- figures:phases begin -->
<!-- figures:phases end -->
after
"""
README_PAGE = "A frame <!-- figures:speed begin -->old<!-- figures:speed end -->; more.\n"


def interleaved(frame, omps, s1, s2, s4):
    return {"name": f"interleaved/real:{frame}/min_time:3.000", "run_type": "iteration", "omps_ms": omps,
            "s1_ms": s1, "s2_ms": s2, "s4_ms": s4, "omps_per_s1": omps / s1, "omps_per_s2": omps / s2,
            "omps_per_s4": omps / s4, "s2_per_s1": s2 / s1, "s4_per_s1": s4 / s1}


def speed_run():
    return {"context": {"date": "2026-12-05T07:00:00+00:00"},
            "benchmarks": [interleaved("office1", 30.0, 20.0, 10.0, 5.0),
                           interleaved("frame_20121214T142255.814212", 40.0, 10.0, 8.0, 2.0),
                           interleaved("five_people", 36.0, 30.0, 12.0, 6.0)]}


def result(iou, correct, planes, false_planes):
    return {"median_ms": 1.0, "min_ms": 1.0, "planes": planes, "mean_iou": iou, "weighted_iou": iou,
            "false_plane_fraction": false_planes, "ground_truth_planes": planes,
            "hoover": {"correct": correct, "over": 0, "under": 0, "missed": planes - correct, "noise": 0}}


def compare_report():
    """Two Kinect files and one exact one, floodplane at s = 1 and 2."""
    def scene(name, sensor, s1, s2):
        return {"name": name, "file": f"{name}.pcd", "width": 64, "height": 48, "ground_truth": True,
                "sensor": sensor, "methods": {"floodplane/1": s1, "floodplane/2": s2}}
    return {"configuration": {}, "scenes": [
        scene("a.kinect", "kinect", result(0.9, 9, 10, 0.0), result(0.8, 8, 10, 0.1)),
        scene("b.kinect", "kinect", result(0.7, 3, 10, 0.2), result(0.6, 2, 10, 0.3)),
        scene("a.none", "none", result(1.0, 5, 5, 0.0), result(0.95, 5, 5, 0.0))]}


@pytest.fixture
def pages(tmp_path):
    bench, readme = tmp_path / "bench.md", tmp_path / "README.md"
    bench.write_text(BENCH_PAGE)
    readme.write_text(README_PAGE)
    (tmp_path / "speed.json").write_text(json.dumps(speed_run()))
    (tmp_path / "report.json").write_text(json.dumps(compare_report()))
    return tmp_path


def run(directory, *arguments):
    return subprocess.run([sys.executable, str(SCRIPT), "--bench-readme", str(directory / "bench.md"),
                           "--readme", str(directory / "README.md"), *map(str, arguments)],
                          capture_output=True, text=True)


def test_writes_the_medians_of_the_frames_and_keeps_the_text_around(pages):
    done = run(pages, "--speed", pages / "speed.json")
    assert done.returncode == 0, done.stderr
    page = (pages / "bench.md").read_text()
    assert "old speed" not in page
    assert page.startswith("# Page\nbefore\n<!-- figures:speed begin -->\n")
    assert "middle\n<!-- figures:accuracy begin -->" in page and page.endswith("after\n")
    rows = {line.split("|")[1].strip(): [cell.strip() for cell in line.strip().strip("|").split("|")[1:]]
            for line in page.splitlines() if line.startswith("| ")}
    assert rows["office1"] == ["30.0", "20.0", "10.0", "5.0", "3.0", "6.0", "0.50", "0.25"]
    assert rows["frame_...255.814212"][:4] == ["40.0", "10.0", "8.0", "2.0"]
    # Medians of the three frames, of the per-frame ratios for the ratio columns.
    assert rows["**median**"] == ["36.0", "20.0", "10.0", "5.0", "**3.0**", "**6.0**", "**0.50**", "**0.20**"]
    assert "2026-12-05 07:00" in page
    readme = (pages / "README.md").read_text()
    assert readme.startswith("A frame <!-- figures:speed begin -->takes a median 5.0 ms at the default, "
                             "sub-sampling 4 (6.0x faster than OMPS")
    assert "10.0 ms at sub-sampling 2 and 20.0 ms at sub-sampling 1 (1.5x OMPS" in readme
    assert readme.endswith("<!-- figures:speed end -->; more.\n")


def test_reads_the_benchmark_s_stdout_with_its_configuration_before_the_json(pages):
    (pages / "speed.json").write_text("floodplane 0.1.0, PCL 1.13.0\nreal frames: 7\n" + json.dumps(speed_run(), indent=2))
    done = run(pages, "--speed", pages / "speed.json")
    assert done.returncode == 0, done.stderr
    assert "| **median** | 36.0 | 20.0 |" in (pages / "bench.md").read_text()


def test_writes_accuracy_per_factor_and_sensor_model(pages):
    done = run(pages, "--report", pages / "report.json", "--quirks", pages / "report.json")
    assert done.returncode == 0, done.stderr
    page = (pages / "bench.md").read_text()
    assert "old speed" in page, "only the parts of the inputs given change"
    lines = [line for line in page.splitlines() if line.startswith("| ")]
    assert "| | exact | Kinect |" in lines
    # Kinect at s = 1: IoU (0.9 + 0.7) / 2, correct (9 + 3) / 20 planes, false planes (0 + 0.2) / 2.
    assert "| s = 1 | 1.000 / 1.000 / 0.000 | 0.800 / 0.600 / 0.100 |" in lines
    assert "| s = 2 | 0.950 / 1.000 / 0.000 | 0.700 / 0.500 / 0.200 |" in lines
    assert (pages / "README.md").read_text() == README_PAGE


@pytest.mark.parametrize("speed, message", [
    ("not json", "speed.json"),
    (json.dumps({"benchmarks": []}), "no interleaved/real"),
    (json.dumps({"benchmarks": [{"name": "interleaved/real:x", "omps_ms": 1.0}]}), "has no s1_ms"),
])
def test_refuses_a_speed_run_it_cannot_read_and_writes_nothing(pages, speed, message):
    (pages / "speed.json").write_text(speed)
    done = run(pages, "--speed", pages / "speed.json")
    assert done.returncode == 1
    assert message in done.stderr
    assert (pages / "bench.md").read_text() == BENCH_PAGE
    assert (pages / "README.md").read_text() == README_PAGE


def test_refuses_a_page_without_its_markers_and_writes_neither_page(pages):
    (pages / "README.md").write_text("no markers here\n")
    done = run(pages, "--speed", pages / "speed.json")
    assert done.returncode == 1
    assert "no single pair of markers <!-- figures:speed begin -->" in done.stderr
    assert (pages / "bench.md").read_text() == BENCH_PAGE


def test_the_real_pages_carry_every_marker_the_script_fills():
    bench = (SOURCE / "bench/README.md").read_text()
    for name in ("speed", "accuracy", "accuracy-quirks", "chart", "objects", "phases"):
        assert bench.count(f"<!-- figures:{name} begin -->") == 1, name
        assert bench.count(f"<!-- figures:{name} end -->") == 1, name
    readme = (SOURCE / "README.md").read_text()
    for name in ("speed", "peers"):
        assert readme.count(f"<!-- figures:{name} begin -->") == 1 and readme.count(f"<!-- figures:{name} end -->") == 1
    results = (SOURCE / "docs/results.md").read_text()
    assert results.count("<!-- figures:peers begin -->") == 1 and results.count("<!-- figures:peers end -->") == 1


def resolution_rows():
    """The rows of bench/resolution_sweep.py --json: time per pixel falling with size at s = 1,
    rising at s = 4."""
    rows = []
    for s, per_pixel in ((1, [50.0, 40.0, 36.0, 32.0]), (4, [20.0, 10.0, 11.0, 13.0])):
        for (size, pixels), ns in zip((("320x240", 76800), ("640x480", 307200), ("1280x960", 1228800),
                                        ("2560x1920", 4915200)), per_pixel):
            cloud = pixels * 16 / 2**20
            rows.append({"s": s, "size": size, "ms": ns * pixels * 1e-6, "ns_per_px": ns, "added_MiB": 2.5 * cloud,
                         "cloud_MiB": cloud, "added_per_cloud": 2.5})
    return rows


def test_writes_the_resolution_sweep_with_time_per_pixel_against_640x480(pages):
    (pages / "resolution.json").write_text(json.dumps(resolution_rows()))
    done = run(pages, "--resolution", pages / "resolution.json")
    assert done.returncode == 0, done.stderr
    page = (pages / "bench.md").read_text()
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")] for line in page.splitlines()
            if line.startswith("| 2560x1920")]
    assert rows == [["2560x1920", "1", "157.3", "32.0", "0.80", "188", "75", "2.50"],
                    ["2560x1920", "4", "63.9", "13.0", "1.30", "188", "75", "2.50"]]
    assert page.endswith("<!-- figures:phases end -->\nafter\n")


def test_a_resolution_run_without_every_size_is_refused_and_nothing_is_written(pages):
    (pages / "resolution.json").write_text(json.dumps(resolution_rows()[:-1]))
    before = (pages / "bench.md").read_text()
    done = run(pages, "--resolution", pages / "resolution.json")
    assert done.returncode != 0
    assert "resolution.json" in done.stderr and "resolution_sweep.py" in done.stderr
    assert (pages / "bench.md").read_text() == before


def object_report(scored=True):
    """pcd_compare --objects --json of two files: PCL's pipeline, and another program's objects
    (--labels: no time)."""
    def mean(iou, found, under, over, support, objects, ms):
        row = {"scenes": 2, "scenes_with_ground_truth": 2, "median_ms": ms, "min_ms": ms, "objects": objects}
        scores = dict(zip(["object_iou", "objects_found", "under", "over", "support_in_objects"],
                          [iou, found, under, over, support]))
        row.update(scores if scored else {key: None for key in scores})
        return row
    return {"configuration": {}, "scenes": [{"name": "learn0"}, {"name": "learn1"}],
            "means": {"pcl_organized": mean(0.7481, 0.6704, 0.2428, 0.0, 0.0034, 2.6, 95.9),
                      "mine": mean(0.5, 0.25, 0.125, 0.0625, 0.01, 3.0, None)}}


def test_writes_the_objects_table_a_row_per_method(pages):
    (pages / "objects.json").write_text(json.dumps(object_report()))
    done = run(pages, "--objects", pages / "objects.json")
    assert done.returncode == 0, done.stderr
    page = (pages / "bench.md").read_text()
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")] for line in page.splitlines()
            if line.startswith("| PCL") or line.startswith("| mine")]
    assert rows == [["PCL's organized pipeline (`pcl_organized`, the demo's settings)", "0.748", "0.670", "0.243",
                     "0.000", "0.003", "2.6", "96"],
                    ["mine", "0.500", "0.250", "0.125", "0.062", "0.010", "3.0", "-"]]
    assert "2 files" in page and page.startswith("# Page\nbefore\n") and page.endswith("after\n")


def test_refuses_an_objects_run_without_scores(pages):
    (pages / "objects.json").write_text(json.dumps(object_report(scored=False)))
    done = run(pages, "--objects", pages / "objects.json")
    assert done.returncode == 1
    assert "no object scores" in done.stderr
    assert (pages / "bench.md").read_text() == BENCH_PAGE
    (pages / "objects.json").write_text(json.dumps(compare_report()))  # a plane comparison
    done = run(pages, "--objects", pages / "objects.json")
    assert done.returncode == 1
    assert "not the JSON of pcd_compare --objects" in done.stderr


def phases(name, prep, output, pcl, outside, call):
    return {"name": name, "run_type": "iteration", "time_unit": "ms", "real_time": call, "cpu_time": call / 2,
            "prep_ms": prep,
            "seed_ms": 1.0, "flood_ms": 1.0, "relabel_ms": 0.5, "merge_ms": 0.5, "output_ms": output, "pcl_ms": pcl,
            "outside_ms": outside}


def test_writes_each_phase_s_median_and_share_per_set_and_factor(pages):
    run_json = {"context": {"date": "2026-12-06T13:00:00+00:00"}, "benchmarks": [
        # The real frames at the default: preparation 2, 4, 6 ms of calls of 10, 10, 20 ms.
        phases("floodplane/phases4/real:a", 2.0, 1.0, 0.5, 0.25, 10.0),
        phases("floodplane/phases4/real:b", 4.0, 1.0, 0.5, -0.01, 10.0),
        phases("floodplane/phases4/real:c", 6.0, 3.0, 1.0, 0.0, 20.0),
        phases("floodplane/phases/real:a", 1.0, 2.0, 0.5, 0.0, 8.0),
        phases("floodplane/phases/exact:tabletop", 1.0, 2.0, 0.5, 0.0, 8.0),
        phases("floodplane/s1/real:a", 9.0, 9.0, 9.0, 9.0, 99.0)]}
    (pages / "phases.json").write_text(json.dumps(run_json))
    done = run(pages, "--phases", pages / "phases.json")
    assert done.returncode == 0, done.stderr
    page = (pages / "bench.md").read_text()
    assert "old speed" in page and "2026-12-06 13:00" in page
    lines = [line for line in page.splitlines() if line.startswith("| ")]
    assert lines[0] == "| phase | real frames, default | real frames, s = 1 | scenes, exact, s = 1 |"
    rows = {line.split("|")[1].strip(): [cell.strip() for cell in line.strip().strip("|").split("|")[1:]]
            for line in lines}
    # Median 4 ms; share 12 of the 40 ms of the three calls.
    assert rows["preparation"] == ["4.00 (30 %)", "1.00 (12 %)", "1.00 (12 %)"]
    # Glue: the conversion and the time outside every phase (a negative rest counts as 0).
    assert rows["PCL glue"][0] == "0.75 (6 %)"
    assert rows["**whole call**"] == ["**10.00**", "**8.00**", "**8.00**"]
    assert rows["CPU time of the call"] == ["5.00", "4.00", "4.00"]
    assert (pages / "README.md").read_text() == README_PAGE


def test_refuses_a_phase_run_without_phase_benchmarks_and_writes_nothing(pages):
    (pages / "phases.json").write_text(json.dumps(speed_run()))
    done = run(pages, "--phases", pages / "phases.json")
    assert done.returncode == 1
    assert "no floodplane/phases" in done.stderr
    assert (pages / "bench.md").read_text() == BENCH_PAGE


SIDE_BY_SIDE = """| frame | floodplane ms | CAPE ms | PEAC ms | x CAPE | x PEAC | floodplane M instr | CAPE M instr | instr x CAPE |
|---|---:|---:|---:|---:|---:|---:|---:|---:|
| office1 | 40.00 | 10.00 | 20.00 | 4.00 | 2.00 | 200.0 | 10.0 | 20.00 |
| frame_20121214T142255.814212 | 30.00 | 10.00 | 40.00 | 3.00 | 0.75 | 150.0 | 15.0 | 10.00 |
| five_people | 60.00 | 12.00 | 30.00 | 5.00 | 2.00 | 300.0 | 10.0 | 30.00 |
median over frames: floodplane / CAPE 4.00, floodplane / PEAC 2.00, instructions floodplane / CAPE 20.00
"""


def osd_means(table_iou, pieces, bleed, cover, faces, walls):
    means = dict(zip(["table_iou", "table_pieces", "bleed", "box_cover", "box_faces", "wall_on_plane"],
                     [table_iou, pieces, bleed, cover, faces, walls]))
    means.update({f"{key}_frames": 45 for key in list(means)})
    return {"frames": {}, "means": means}


@pytest.fixture
def peers(pages):
    """bench/peers.sh's folder: CAPE ahead on speed and on the table, PEAC on the cans' walls."""
    folder = pages / "peers"
    folder.mkdir()
    (folder / "speed.md").write_text("peers: speed\n" + SIDE_BY_SIDE)
    (folder / "run.txt").write_text("floodplane commit: abc1234\ndate: 2026-12-07T02:20Z\nmachine: 2 cores\n")
    for method, means in (("floodplane", osd_means(0.95, 1.2, 0.001, 0.8, 2.1, 0.05)),
                          ("cape", osd_means(0.99, 1.0, 0.001, 0.5, 0.5, 0.05)),
                          ("peac", osd_means(0.90, 1.5, 0.004, 0.6, 0.8, 0.01))):
        (folder / f"osd_{method}.json").write_text(json.dumps(means))
    (pages / "results.md").write_text("# Results\n<!-- figures:peers begin -->\nold\n<!-- figures:peers end -->\nend\n")
    (pages / "README.md").write_text("Peers: <!-- figures:peers begin -->old<!-- figures:peers end -->.\n")
    return folder


def run_peers(pages, folder):
    return subprocess.run([sys.executable, str(SCRIPT), "--bench-readme", str(pages / "bench.md"),
                           "--readme", str(pages / "README.md"), "--results", str(pages / "results.md"),
                           "--peers", str(folder)], capture_output=True, text=True)


def test_writes_the_peers_tables_and_says_where_each_peer_is_ahead(pages, peers):
    done = run_peers(pages, peers)
    assert done.returncode == 0, done.stderr
    results = (pages / "results.md").read_text()
    assert results.startswith("# Results\n<!-- figures:peers begin -->\nRun 2026-12-07T02:20Z, floodplane at `abc1234`")
    assert results.endswith("<!-- figures:peers end -->\nend\n") and "old" not in results
    rows = {line.split("|")[1].strip(): [cell.strip() for cell in line.strip().strip("|").split("|")[1:]]
            for line in results.splitlines() if line.startswith("| ")}
    assert rows["office1"] == ["40.00", "10.00", "20.00", "4.00", "2.00", "200.0", "10.0", "20.00"]
    assert rows["frame_...255.814212"][:5] == ["30.00", "10.00", "40.00", "3.00", "0.75"]
    # Medians over the frames of the per-frame ratios side_by_side.sh gave.
    assert rows["**median**"] == ["40.00", "10.00", "30.00", "**4.00**", "**2.00**", "200.0", "10.0", "**20.00**"]
    assert rows["CAPE"] == ["0.990", "1.000", "0.001", "0.500", "0.500", "0.050"]
    cape = next(line for line in results.splitlines() if line.startswith("- CAPE: "))
    assert "floodplane takes 4.0x its time" in cape and "20.0x its instructions" in cape
    assert "a higher table IoU" in cape and "fewer pieces" in cape
    assert "bleed" not in cape and "walls" not in cape and "boxes" not in cape  # even, or floodplane ahead
    peac = next(line for line in results.splitlines() if line.startswith("- PEAC: "))
    assert "2.0x its time" in peac and "less of the cans' walls on planes" in peac and "table IoU" not in peac
    readme = (pages / "README.md").read_text()
    assert readme.startswith("Peers: <!-- figures:peers begin -->on the 7 real Kinect frames floodplane takes 4.0x CAPE's "
                             "time a frame (20.0x its instructions) and 2.0x PEAC's: both are faster; on the 45 mOSD")
    assert readme.endswith("<!-- figures:peers end -->.\n")


def test_a_peers_run_with_a_failed_runner_is_refused_and_nothing_is_written(pages, peers):
    (peers / "speed.md").write_text(SIDE_BY_SIDE.replace("| 10.00 | 20.00 | 4.00", "| nan | 20.00 | nan"))
    done = run_peers(pages, peers)
    assert done.returncode == 1
    assert "office1 has no time for every method" in done.stderr
    assert "old" in (pages / "results.md").read_text() and "old" in (pages / "README.md").read_text()
    (peers / "speed.md").write_text(SIDE_BY_SIDE)
    (peers / "osd_peac.json").write_text("{}")
    done = run_peers(pages, peers)
    assert done.returncode == 1 and "osd_peac.json: not the JSON of osd_scores.py --json" in done.stderr

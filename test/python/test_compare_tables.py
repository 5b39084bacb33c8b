# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/compare_tables.py, pcd_compare's tables and CSV from its JSON, on a made-up report of
known figures (two files, two sensor models, floodplane, OMPS and floodplane at sub-sampling 2
and 4), on bad input, and against the tables pcd_compare printed for the committed results."""

import csv
import json
import os
import pathlib
import re
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCRIPT = SOURCE / "bench/compare_tables.py"
RESULTS = SOURCE / "bench/results"


def method(median, planes, scores=None, minimum=None, **extra):
    entry = {"median_ms": median, "min_ms": median if minimum is None else minimum, "planes": planes, **extra}
    if scores is not None:
        mean_iou, weighted_iou, correct, false_planes = scores
        entry.update(mean_iou=mean_iou, weighted_iou=weighted_iou, false_plane_fraction=false_planes,
                     hoover={"correct": correct, "over": 1, "under": 0, "missed": 2, "noise": 3},
                     ground_truth_planes=correct + 2, predicted_segments=planes, per_plane=[])
    return entry


def report():
    """Two files: `desk.kinect` with ground truth and phases, `hall.scanner` without ground
    truth; floodplane/4 only on the first, OMPS with its normals. The desk's false-plane
    fraction of floodplane/2 is undefined (null)."""
    desk = {"name": "desk.kinect", "file": "data/desk.kinect.pcd", "width": 640, "height": 480,
            "ground_truth": True, "min_points": 500, "sensor": "kinect",
            "methods": {"floodplane": method(10.0, 4, (0.9, 0.95, 4, 0.01), minimum=9.0),
                        "omps": method(40.0, 6, (0.9004, 0.5, 1, 0.2), parts_median_ms={"normals": 20.0}),
                        "floodplane/2": method(5.0, 4, (0.8, 0.9, 3, None)),
                        "floodplane/4": method(2.5, 3, (0.7, 0.85, 2, 0.05))},
            "phases": {"median_ms": {"preparation": 1.0, "seed_selection": 1.0, "flood_fill": 4.0,
                                     "relabelling": 1.0, "merging": 1.0, "region_output": 2.0,
                                     "pcl_conversion": 0.0},
                       "share": {}, "phases_total_ms": 10.0, "call_median_ms": 11.0}}
    hall = {"name": "hall.scanner", "file": "data/hall, big.scanner.pcd", "width": 320, "height": 240,
            "ground_truth": False, "min_points": 125, "sensor": "scanner",
            "methods": {"floodplane": method(30.0, 10),
                        "omps": method(50.0, 8, parts_median_ms={"normals": 30.0}),
                        "floodplane/2": method(20.0, 9)}}
    return {"configuration": {"floodplane": "0.1.0", "method floodplane": "library defaults: sub-sampling 1"},
            "scenes": [desk, hall], "means": {}, "failed": []}


def run(tmp_path, data, *arguments):
    path = tmp_path / "report.json"
    path.write_text(data if isinstance(data, str) else json.dumps(data))
    return subprocess.run([sys.executable, str(SCRIPT), str(path), *map(str, arguments)],
                          capture_output=True, text=True)


def tables(text):
    """{title of a table: its rows as lists of cells}, the title the nearest heading above."""
    found, title = {}, None
    for line in text.splitlines():
        if line.startswith("#"):
            title = line.lstrip("# ")
        elif line.startswith("| ") and not line.startswith("|---"):
            found.setdefault(title, []).append([cell.strip() for cell in line.strip().strip("|").split("|")])
    return found


@pytest.fixture
def output(tmp_path):
    done = run(tmp_path, report())
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""
    return tables(done.stdout)


def rows_by_first_cell(table):
    header, *rows = table
    return {row[0]: dict(zip(header, row)) for row in rows}


def test_the_mean_rows_average_times_over_every_file_and_accuracy_over_files_with_ground_truth(output):
    means = rows_by_first_cell(output["all files (2)"])
    assert list(means) == ["floodplane", "omps", "floodplane/2", "floodplane/4"]
    floodplane = means["floodplane"]
    assert (floodplane["files"], floodplane["median ms"], floodplane["min ms"], floodplane["planes"]) == \
        ("2", "20.00", "19.50", "7.0")
    # Only the desk has ground truth: its figures are the means.
    assert (floodplane["mean IoU"], floodplane["correct"], floodplane["missed"], floodplane["false planes"]) == \
        ("0.900", "4.0", "2.0", "0.010")
    omps = means["omps"]
    assert (omps["x floodplane"], omps["normals ms"]) == ("2.25", "25.00")  # 90 / 40 and (20 + 30) / 2
    assert means["floodplane/2"]["x floodplane"] == "0.62"  # 25 / 40 = 0.625, an exact tie: to even, as printf
    assert means["floodplane/2"]["false planes"] == "-"  # its only defined fraction is null


def test_x_floodplane_needs_floodplane_on_every_file_of_the_table(tmp_path):
    data = report()
    del data["scenes"][1]["methods"]["floodplane"]
    done = run(tmp_path, data)
    means = rows_by_first_cell(tables(done.stdout)["all files (2)"])
    assert means["omps"]["x floodplane"] == "-"
    assert means["floodplane"]["files"] == "1"


def test_each_sensor_model_has_its_own_table_of_means(output):
    kinect = rows_by_first_cell(output["sensor model kinect (1 files)"])
    scanner = rows_by_first_cell(output["sensor model scanner (1 files)"])
    assert kinect["floodplane/4"]["median ms"] == "2.50"
    assert "floodplane/4" not in scanner
    assert (scanner["omps"]["median ms"], scanner["omps"]["mean IoU"], scanner["omps"]["false planes"]) == \
        ("50.00", "-", "-")


def test_a_file_whose_ground_truth_keeps_no_plane_counts_for_false_planes_only(tmp_path):
    data = report()
    wall = method(8.0, 1, (None, None, 0, 0.03))
    wall.update(ground_truth_planes=0, hoover=dict.fromkeys(["correct", "over", "under", "missed", "noise"], 0))
    data["scenes"].append({"name": "wall.kinect", "file": "wall.kinect.pcd", "width": 64, "height": 48,
                           "ground_truth": True, "sensor": "kinect", "methods": {"floodplane": wall}})
    output = tables(run(tmp_path, data).stdout)
    kinect = rows_by_first_cell(output["sensor model kinect (2 files)"])["floodplane"]
    assert (kinect["files"], kinect["median ms"], kinect["mean IoU"], kinect["correct"], kinect["false planes"]) == \
        ("2", "9.00", "0.900", "4.0", "0.020")
    iou = rows_by_first_cell(output["Mean IoU per file (best in bold)"])
    assert iou["wall.kinect"] == {"file": "wall.kinect", "floodplane": "-", "omps": "-", "floodplane/2": "-",
                                  "floodplane/4": "-"}


def test_the_best_mean_iou_of_a_file_is_bold_with_every_tie_at_the_printed_precision(output):
    iou = rows_by_first_cell(output["Mean IoU per file (best in bold)"])
    assert list(iou) == ["desk.kinect"]  # the hall has no ground truth
    # 0.9004 prints as 0.900, a tie with floodplane's 0.9.
    assert iou["desk.kinect"] == {"file": "desk.kinect", "floodplane": "**0.900**", "omps": "**0.900**",
                                  "floodplane/2": "0.800", "floodplane/4": "0.700"}


def test_every_file_and_method_has_a_row(output):
    rows = output["Every file and method: runtime and accuracy"]
    assert len(rows) == 1 + 7
    hall_omps = dict(zip(rows[0], rows[6]))
    assert (hall_omps["scene"], hall_omps["method"], hall_omps["x floodplane"], hall_omps["normals ms"],
            hall_omps["planes"], hall_omps["mean IoU"], hall_omps["noise"]) == \
        ("hall.scanner", "omps", "1.67", "30.00", "8", "-", "-")
    desk_omps = dict(zip(rows[0], rows[2]))
    assert (desk_omps["mean IoU"], desk_omps["correct"], desk_omps["noise"], desk_omps["false planes"]) == \
        ("0.900", "1", "3", "0.200")


def test_the_subsampling_table_has_each_factor_with_its_speedup_over_floodplane(output):
    header, *rows = output["floodplane by sub-sampling factor (Table III)"]
    table = [dict(zip(header, row)) for row in rows]
    assert [(r["scene"], r["sub-sampling"], r["speed-up over 1"]) for r in table] == [
        ("desk.kinect", "1", "1.00"), ("desk.kinect", "2", "2.00"), ("desk.kinect", "4", "4.00"),
        ("hall.scanner", "1", "1.00"), ("hall.scanner", "2", "1.50"),
        ("**mean** (2 scenes)", "1", "1.00"), ("**mean** (2 scenes)", "2", "1.75"),
        ("**mean** (1 scenes)", "4", "4.00")]
    assert (table[2]["mean IoU"], table[2]["false planes"], table[4]["mean IoU"]) == ("0.700", "0.050", "-")
    assert table[6]["median ms"] == "12.50"


def test_the_subsampling_table_needs_a_factor_of_four_or_more(tmp_path):
    data = report()
    del data["scenes"][0]["methods"]["floodplane/4"]
    done = run(tmp_path, data)
    assert done.returncode == 0, done.stderr
    assert "Table III" not in done.stdout
    assert "Mean IoU per file" in done.stdout


def test_the_phase_table_gives_each_phase_share_in_call_order(output):
    header, *rows = output["floodplane's time by phase (Fig. 5), share of the phases' total"]
    assert header == ["scene", "preparation", "seed selection", "flood fill", "relabelling", "merging",
                      "region output", "pcl conversion", "phases ms", "call ms"]
    assert rows == [["desk.kinect", "10.0%", "10.0%", "40.0%", "10.0%", "10.0%", "20.0%", "0.0%", "10.00", "11.00"],
                    ["**mean** (1 scenes)", "10.0%", "10.0%", "40.0%", "10.0%", "10.0%", "20.0%", "0.0%", "10.00",
                     "11.00"]]


def test_phases_the_script_does_not_know_keep_the_reports_order(tmp_path):
    data = report()
    data["scenes"][0]["phases"]["median_ms"] = {"warp": 3.0, "flood_fill": 1.0}
    header, row, _ = tables(run(tmp_path, data, "--tables", "phases").stdout)[
        "floodplane's time by phase (Fig. 5), share of the phases' total"]
    assert header[1:3] == ["warp", "flood fill"]
    assert row[1:4] == ["75.0%", "25.0%", "4.00"]


def test_tables_prints_only_the_tables_asked_for_in_the_usual_order(tmp_path):
    done = run(tmp_path, report(), "--tables", "phases,means")
    assert done.returncode == 0, done.stderr
    assert re.findall(r"^## (.*)$", done.stdout, re.M) == [
        "Means per method", "floodplane's time by phase (Fig. 5), share of the phases' total"]
    assert run(tmp_path, report(), "--tables", "means,speed").returncode == 2


def test_the_csv_has_a_line_per_file_and_method_with_the_subsampling_factor(tmp_path):
    out = tmp_path / "report.csv"
    done = run(tmp_path, report(), "--csv", out)
    assert done.returncode == 0, done.stderr
    header, *lines = out.read_text().splitlines()
    assert header == ("scene,file,method,subsampling,width,height,median_ms,min_ms,ratio_to_floodplane,normals_ms,"
                      "planes,mean_iou,weighted_iou,correct,over,under,missed,noise,false_plane_fraction")
    assert len(lines) == 7
    assert [line.split(",")[2:4] for line in lines[:4]] == [
        ["floodplane", "1"], ["omps", "1"], ["floodplane/2", "2"], ["floodplane/4", "4"]]
    assert lines[2] == ('"desk.kinect","data/desk.kinect.pcd",floodplane/2,2,640,480,5.0000,5.0000,0.5000,-,4,'
                        "0.800000,0.900000,3,1,0,2,3,-")
    # No scores without ground truth; the file name's comma stays inside its quotes.
    assert lines[5] == '"hall.scanner","data/hall, big.scanner.pcd",omps,1,320,240,50.0000,50.0000,1.6667,30.0000,8,' \
                       ",,,,,,,"
    umask = os.umask(0)
    os.umask(umask)
    assert out.stat().st_mode & 0o777 == 0o666 & ~umask  # not the private mode of a temporary


def test_the_older_report_format_with_resolutions_gives_the_same_tables(tmp_path):
    data = report()
    old = json.loads(json.dumps(data))
    desk = old["scenes"][0]
    desk["resolutions"] = {"4": desk["methods"].pop("floodplane/4")}
    assert run(tmp_path, old).stdout == run(tmp_path, data).stdout


@pytest.mark.parametrize("data, message", [
    (None, "cannot read"),
    ("{ not json", "is not JSON"),
    ('{"benchmarks": []}', "is not a pcd_compare report: the report has no \"scenes\""),
    ('{"scenes": [{"name": "a"}]}', "is not a pcd_compare report: scene a has no \"file\""),
    ("[1, 2]", "is not a pcd_compare report: the report is not an object"),
])
def test_a_missing_or_foreign_file_is_one_line_and_exit_one(tmp_path, data, message):
    if data is None:
        done = subprocess.run([sys.executable, str(SCRIPT), str(tmp_path / "missing.json")],
                              capture_output=True, text=True)
    else:
        done = run(tmp_path, data)
    assert done.returncode == 1
    assert done.stdout == ""
    assert message in done.stderr
    assert len(done.stderr.splitlines()) == 1, done.stderr


def test_a_wrong_type_in_a_method_names_the_method(tmp_path):
    data = report()
    data["scenes"][1]["methods"]["omps"]["planes"] = "8"
    done = run(tmp_path, data)
    assert done.returncode == 1
    assert done.stderr.strip().endswith('scene hall.scanner, method omps: "planes" is "8"'), done.stderr


def test_an_unwritable_csv_leaves_no_file_and_fails(tmp_path):
    folder = tmp_path / "csv"
    folder.mkdir()
    # A directory where the CSV should go: the rename fails after the temporary is written.
    (folder / "report.csv").mkdir()
    done = run(tmp_path, report(), "--csv", folder / "report.csv")
    assert done.returncode == 1
    assert len(done.stderr.splitlines()) == 1 and "cannot write" in done.stderr
    assert done.stdout == ""  # no tables either: a caller keeps its previous files
    assert sorted(p.name for p in folder.iterdir()) == ["report.csv"]
    assert (folder / "report.csv").is_dir()
    done = run(tmp_path, report(), "--csv", tmp_path / "no such folder" / "report.csv")
    assert done.returncode == 1 and "cannot write" in done.stderr
    assert not (tmp_path / "no such folder").exists()


# Against reality: the committed comparisons, whose Markdown today's pcd_compare printed. Its
# JSON kept methods in alphabetical order (nlohmann::json's std::map); the tables list them in
# run order, which the .md's first table of means gives back.
COMMITTED = [name for name in ["compare_all_scenes", "compare_all_random_subset", "compare_all_random"]
             if (RESULTS / f"{name}.json").is_file() and (RESULTS / f"{name}.md").is_file()]


def in_run_order(data, markdown):
    order = []
    for line in markdown.split("## Means per method", 1)[1].splitlines():
        found = re.match(r"\| (.+?) \| \d+ \|", line)
        if found and found.group(1) not in order:
            order.append(found.group(1))
    for scene in data["scenes"]:
        scene["methods"] = {name: scene["methods"][name] for name in sorted(scene["methods"], key=order.index)}
    return data


@pytest.mark.skipif(not COMMITTED, reason="no committed compare_all_*.json and .md in bench/results")
@pytest.mark.parametrize("name", COMMITTED)
def test_the_tables_of_a_committed_comparison_are_those_pcd_compare_printed(tmp_path, name):
    markdown = (RESULTS / f"{name}.md").read_text()
    data = in_run_order(json.loads((RESULTS / f"{name}.json").read_text()), markdown)
    out = tmp_path / "out.csv"
    # The committed JSONs were written with their configuration's keys sorted, the Markdown in
    # run order: everything after the configuration.
    done = run(tmp_path, data, "--csv", out, "--tables", "means,iou,files,subsampling,phases")
    assert done.returncode == 0, done.stderr
    expected = markdown[markdown.index("## Means per method"):]
    assert done.stdout == expected
    # The CSV as pcd_compare wrote it, but for floodplane/N's sub-sampling factor: 1 there.
    committed = RESULTS / f"{name}.csv"
    if committed.is_file():
        expected = list(csv.reader(committed.read_text().splitlines()))
        for row in expected[1:]:
            factor = re.fullmatch(r"floodplane/(\d+)", row[2])
            if factor:
                assert row[3] == "1"
                row[3] = factor.group(1)
        assert list(csv.reader(out.read_text().splitlines())) == expected
        assert out.read_text().count("\n") == committed.read_text().count("\n")


def test_the_configuration_comes_first_as_pcd_compare_prints_it(tmp_path):
    data = {"configuration": {"floodplane": "0.1.0", "PCL": "1.13.0"}, "scenes": []}
    done = run(tmp_path, data, "--tables", "configuration")
    assert done.returncode == 0, done.stderr
    assert done.stdout == "## Configuration\n\n- **floodplane**: 0.1.0\n- **PCL**: 1.13.0\n\n"
    done = run(tmp_path, {"configuration": "text", "scenes": []})
    assert done.returncode == 1
    assert "is not a pcd_compare report" in done.stderr

# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""bench/tune_baselines.py, the baselines' tuner: the coordinate descent on made-up score
surfaces (no program), the checks of its inputs, the search and the output file with a stand-in
pcd_compare whose scores are known, and a real tuning with pcd_compare on two small rendered
scenes, checked against pcd_compare's own scores of the two settings."""

import importlib.util
import json
import math
import os
import pathlib
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("FLOODPLANE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
SCRIPT = SOURCE / "bench/tune_baselines.py"


def load_script():
    sys.dont_write_bytecode = True  # no __pycache__ in bench/
    spec = importlib.util.spec_from_file_location("tune_baselines", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


tb = load_script()


def tune(*arguments):
    return subprocess.run([sys.executable, str(SCRIPT), *map(str, arguments)], capture_output=True, text=True,
                          timeout=300)


def one_line_error(done, *fragments):
    """Asserts that `done` failed with exit code 1 and one error line holding `fragments`."""
    assert done.returncode == 1, done.stderr
    lines = done.stderr.splitlines()
    assert len(lines) == 1 and lines[0].startswith("tune_baselines: error: "), done.stderr
    for fragment in fragments:
        assert fragment in lines[0]


def write_pcd(path, fields=("x", "y", "z", "label")):
    """A 2 x 1 ASCII PCD: enough of a header for the tuner's checks (the stand-in never reads it)."""
    header = [".7", " ".join(fields), " ".join("4" for _ in fields), " ".join("F" for _ in fields),
              " ".join("1" for _ in fields), "2", "1", "0 0 0 1 0 0 0", "2", "ascii"]
    keys = ["VERSION", "FIELDS", "SIZE", "TYPE", "COUNT", "WIDTH", "HEIGHT", "VIEWPOINT", "POINTS", "DATA"]
    rows = [" ".join("1" for _ in fields)] * 2
    pathlib.Path(path).write_text("\n".join(f"{k} {v}" for k, v in zip(keys, header)) + "\n" + "\n".join(rows) + "\n")
    return pathlib.Path(path)


def labelled_folder(folder, names):
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        write_pcd(folder / name)
    return folder


# --- the descent, on made-up score surfaces -------------------------------------------------------

def counting(score):
    """`score` as an evaluator that records the values it is called with."""
    calls = []

    def evaluate(values):
        calls.append(tuple(values.items()))
        return score(values)

    return evaluate, calls


def test_the_descent_finds_the_best_grid_point_of_a_separable_surface_evaluating_each_setting_once():
    evaluate, calls = counting(lambda v: -(v["a"] - 3) ** 2 - 10 * (v["b"] - 0.2) ** 2)
    best, score, scores = tb.coordinate_descent({"a": 1.0, "b": 0.4}, {"a": [1, 2, 3, 4], "b": [0.1, 0.2, 0.4]},
                                                evaluate, passes=5)
    assert best == {"a": 3, "b": 0.2}
    assert score == pytest.approx(0.0)
    assert len(calls) == len(set(calls)) == len(scores)
    # The start; pass 1: a's 3 other values, then b's 2 other values at a = 3; pass 2: a's 3
    # other values at b = 0.2, b's all known; nothing changed, so no pass 3.
    assert len(calls) == 1 + 3 + 2 + 3


# Scores of a surface where the best value of `a` depends on `b`: pass 1 reaches (1, 1) = 2,
# pass 2 moves `a` to 2 (3).
COUPLED = {(0, 0): 0.0, (1, 0): 1.0, (2, 0): 0.5, (0, 1): 0.1, (1, 1): 2.0, (2, 1): 3.0,
           (0, 2): 0.0, (1, 2): 1.5, (2, 2): 0.2}


@pytest.mark.parametrize("passes, expected", [(1, {"a": 1, "b": 1}), (2, {"a": 2, "b": 1}), (9, {"a": 2, "b": 1})])
def test_the_descent_makes_at_most_the_passes_asked_for(passes, expected):
    best, score, _ = tb.coordinate_descent({"a": 0, "b": 0}, {"a": [0, 1, 2], "b": [0, 1, 2]},
                                           lambda v: COUPLED[v["a"], v["b"]], passes)
    assert best == expected
    assert score == COUPLED[expected["a"], expected["b"]]


def test_ties_keep_the_current_value():
    # A flat surface: the start stays, even though it is not a grid value.
    best, _, _ = tb.coordinate_descent({"a": 2.5, "b": 7.0}, {"a": [1, 2, 3], "b": [5, 9]}, lambda v: 0.5, 2)
    assert best == {"a": 2.5, "b": 7.0}
    # An equal grid value listed before the current one does not replace it, nor does a gain
    # within the tolerance.
    best, _, _ = tb.coordinate_descent({"a": 1}, {"a": [5, 1, 7]},
                                       lambda v: {5: 1.0, 1: 1.0, 7: 1.0 + tb.TIE / 2}[v["a"]], 2)
    assert best == {"a": 1}
    # Two equal improvements: the first one found stays.
    best, _, _ = tb.coordinate_descent({"a": 1}, {"a": [1, 2, 3]}, lambda v: {1: 0.0, 2: 1.0, 3: 1.0}[v["a"]], 2)
    assert best == {"a": 2}


def test_an_undefined_score_never_wins_and_any_number_beats_it():
    best, score, _ = tb.coordinate_descent({"a": 1}, {"a": [1, 2, 3]}, lambda v: {1: None, 2: 0.3, 3: None}[v["a"]], 2)
    assert (best, score) == ({"a": 2}, 0.3)


def test_parameters_are_read_from_the_start_of_a_configuration_line():
    values = tb.parse_parameters("angular_threshold=0.09, distance_threshold=0.02, min_inliers=50; from t.json", "k")
    assert list(values.items()) == [("angular_threshold", 0.09), ("distance_threshold", 0.02), ("min_inliers", 50.0)]
    with pytest.raises(tb.TuningError, match="does not begin with the parameters"):
        tb.parse_parameters("pcl::IntegralImageNormalEstimation AVERAGE_3D_GRADIENT, max depth change factor 0.02; "
                            "pcl::OrganizedMultiPlaneSegmentation", "method omps (tuned) [none]")


def test_the_subset_is_evenly_spaced_per_sensor_model_in_name_order(tmp_path):
    names = [f"s{k}.kinect.pcd" for k in range(5)] + ["b.none.pcd", "a.none.pcd", "unnamed.pcd",
                                                      "frame_1.814212.pcd", "c.scanner.planes.json"]
    subset = tb.tuning_subset(labelled_folder(tmp_path, names), 3)
    assert {sensor: [p.name for p in files] for sensor, files in subset.items()} == {
        "kinect": ["s0.kinect.pcd", "s1.kinect.pcd", "s3.kinect.pcd"], "none": ["a.none.pcd", "b.none.pcd"]}


# --- the command's checks of its inputs ----------------------------------------------------------

@pytest.mark.parametrize("grid, message", [
    ({"omps": {"bogus": [1.0]}}, "omps has no parameter 'bogus'"),
    ({"floodplane": {"distance_threshold": [0.01]}}, "no tunable baseline 'floodplane'"),
    ({"omps": {"angular_threshold": [0.05, -0.1]}}, "omps.angular_threshold: every value must be a positive number"),
    ({"ransac": {"distance_threshold": [0]}}, "ransac.distance_threshold: every value must be a positive number"),
    ({"ransac": {"min_inliers": [100, 250.5]}}, "ransac.min_inliers: every value must be a whole number"),
    ({"omps": {"min_inliers": []}}, "omps.min_inliers: give a non-empty list"),
    ([0.1, 0.2], "the grid must be an object"),
    ("{not json", "not JSON"),
])
def test_bad_grids_are_reported_by_file_name_before_any_run(tmp_path, grid, message):
    path = tmp_path / "grid.json"
    path.write_text(grid if isinstance(grid, str) else json.dumps(grid))
    output = tmp_path / "out.json"
    done = tune("--grid", path, "--pcd-compare", tmp_path / "none", "--output", output,
                labelled_folder(tmp_path / "tune", ["a.none.pcd"]))
    one_line_error(done, f"{path}: ", message)
    assert not output.exists()


def test_bad_folders_programs_and_outputs_are_reported_by_name(tmp_path):
    output = tmp_path / "out.json"
    missing = tmp_path / "missing"
    one_line_error(tune("--output", output, missing), f"{missing}: no such folder")

    unnamed = labelled_folder(tmp_path / "unnamed", ["staircase.pcd"])
    one_line_error(tune("--output", output, unnamed), f"{unnamed}: no <scene>.<sensor>.pcd files")

    unlabelled = tmp_path / "unlabelled"
    unlabelled.mkdir()
    write_pcd(unlabelled / "a.none.pcd", fields=("x", "y", "z"))
    one_line_error(tune("--output", output, unlabelled), f"{unlabelled / 'a.none.pcd'}: no ground-truth labels")

    folder = labelled_folder(tmp_path / "tune", ["a.none.pcd"])
    program = tmp_path / "no_pcd_compare"
    one_line_error(tune("--pcd-compare", program, "--output", output, folder), f"{program}: no such program")

    nowhere = tmp_path / "no_folder" / "out.json"
    one_line_error(tune("--output", nowhere, folder), f"{nowhere}: its folder does not exist")

    other = tmp_path / "notes.json"
    other.write_text('{"notes": 1}')
    one_line_error(tune("--output", other, folder), f"{other}: exists but is not a tuning result")
    assert other.read_text() == '{"notes": 1}'
    assert not output.exists()


@pytest.mark.parametrize("arguments", [["--clouds", "0"], ["--methods", "floodplane"], ["--passes", "x"], []])
def test_bad_usage_exits_with_2(tmp_path, arguments):
    folder = [] if not arguments else [labelled_folder(tmp_path / "tune", ["a.none.pcd"])]
    done = tune(*arguments, *folder)
    assert done.returncode == 2, done.stderr
    assert "usage:" in done.stderr and "Traceback" not in done.stderr


def test_the_script_runs_by_itself():
    done = subprocess.run([str(SCRIPT), "--help"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "truncating the sequence" in done.stdout and "--pcd-compare" in done.stdout


# --- the search and the file, with a stand-in pcd_compare -----------------------------------------

# Writes pcd_compare's JSON report as the real one does for "--methods B --tuned --json": the
# configuration line of the tuned row and the mean IoU of the default and tuned rows, the
# scores from the Python expression `score` of the spec; logs each run.
STAND_IN = r'''
import json, pathlib, sys
spec = json.loads(pathlib.Path(sys.argv[0] + ".json").read_text())
args = sys.argv[1:]
option = lambda name: args[args.index(name) + 1]
if "fail" in spec:
    sys.stderr.write(spec["fail"])
    sys.exit(1)
baseline = option("--methods")
tuned = json.loads(pathlib.Path(option("--tuned-file")).read_text())
(sensor, entry), = tuned["methods"][baseline]["by_sensor"].items()
defaults = spec["defaults"][baseline]
values = dict(defaults, **entry["parameters"])
files = [pathlib.Path(a).name for a in args if a.endswith(".pcd")]
with open(sys.argv[0] + ".log", "a") as log:
    log.write(json.dumps({"sensor": sensor, "parameters": entry["parameters"], "files": files}) + "\n")
score = lambda v: eval(spec["score"], {"math": __import__("math"), "v": v, "sensor": sensor})
listing = spec.get("listing", ", ".join(f"{k}={x:g}" for k, x in defaults.items()))
report = {"configuration": {f"method {baseline} (tuned) [{sensor}]": listing + "; from " + option("--tuned-file")},
          "means": {baseline: {"mean_iou": score(defaults)}, baseline + " (tuned)": {"mean_iou": score(values)}},
          "scenes": []}
pathlib.Path(option("--json")).write_text(json.dumps(report))
'''

RANSAC_DEFAULTS = {"distance_threshold": 0.01, "min_inliers": 100.0}
# Best at 4 cm on the Kinect, 5 mm otherwise, and at min_inliers 1000 for both.
RANSAC_SCORE = ("1 - abs(math.log(v['distance_threshold'] / (0.04 if sensor == 'kinect' else 0.005))) / 10"
                " - abs(math.log(v['min_inliers'] / 1000)) / 10")


def stand_in(tmp_path, **spec):
    program = tmp_path / "pcd_compare"
    program.write_text(f"#!{sys.executable}\n" + STAND_IN)
    program.chmod(0o755)
    pathlib.Path(str(program) + ".json").write_text(json.dumps({"defaults": {"ransac": RANSAC_DEFAULTS}, **spec}))
    return program


def runs_of(program):
    log = pathlib.Path(str(program) + ".log")
    return [json.loads(line) for line in log.read_text().splitlines()] if log.exists() else []


def test_each_sensor_gets_its_best_values_and_other_methods_of_the_file_are_kept(tmp_path):
    folder = labelled_folder(tmp_path / "tune", [f"s{k}.kinect.pcd" for k in range(5)] + ["a.none.pcd", "b.none.pcd"])
    program = stand_in(tmp_path, score=RANSAC_SCORE)
    output = tmp_path / "tuned.json"
    output.write_text(json.dumps({"methods": {
        "omps": {"by_sensor": {"none": {"parameters": {"min_inliers": 300}}}},
        "ransac": {"by_sensor": {"scanner": {"parameters": {"min_inliers": 3000}}}}}}))

    done = tune("--pcd-compare", program, "--methods", "ransac,omps", "--grid", write_grid(tmp_path),
                "--clouds", 3, "--output", output, folder)
    assert done.returncode == 0, done.stderr
    assert "ransac [kinect] #2 " in done.stderr and "ransac [none] #2 " in done.stderr
    result = json.loads(output.read_text())
    assert "tune_baselines.py" in result["description"]
    # omps was not in the grid: its entry stays; ransac's earlier entry is replaced whole.
    assert result["methods"]["omps"]["by_sensor"]["none"]["parameters"] == {"min_inliers": 300}
    ransac = result["methods"]["ransac"]
    assert set(ransac["by_sensor"]) == {"kinect", "none"}
    assert ransac["default"] == RANSAC_DEFAULTS
    assert ransac["grid"] == {"distance_threshold": [0.005, 0.01, 0.02, 0.04], "min_inliers": [100.0, 1000.0]}
    assert (ransac["clouds_per_sensor"], ransac["passes_at_most"]) == (3, 2)
    assert ransac["tuning_folder"] == str(folder)

    runs = runs_of(program)
    for sensor, best_distance, clouds in [("kinect", 0.04, ["s0.kinect", "s1.kinect", "s3.kinect"]),
                                          ("none", 0.005, ["a.none", "b.none"])]:
        winner = ransac["by_sensor"][sensor]
        assert winner["parameters"] == {"distance_threshold": best_distance, "min_inliers": 1000.0}
        assert winner["mean_iou"] == pytest.approx(1.0)
        assert winner["default_mean_iou"] == pytest.approx(1 - abs(math.log(0.01 / best_distance)) / 10
                                                           - abs(math.log(0.1)) / 10)
        assert winner["clouds"] == clouds
        mine = [run for run in runs if run["sensor"] == sensor]
        assert all(run["files"] == [c + ".pcd" for c in clouds] for run in mine)
        # One run per setting: the first with no values (the defaults), then each setting once.
        assert mine[0]["parameters"] == {}
        settings = {tuple(sorted(run["parameters"].items())) for run in mine[1:]}
        assert len(settings) == len(mine) - 1
        assert winner["settings_evaluated"] == len(mine)
        assert winner["method_runs"] == 2 * len(mine) * len(clouds)
    assert not list(tmp_path.glob("*.partial"))


def write_grid(tmp_path):
    grid = tmp_path / "grid.json"
    grid.write_text(json.dumps({"ransac": {"distance_threshold": [0.005, 0.01, 0.02, 0.04],
                                           "min_inliers": [100, 1000]}}))
    return grid


def test_quiet_prints_nothing(tmp_path):
    folder = labelled_folder(tmp_path / "tune", ["a.none.pcd"])
    done = tune("--quiet", "--pcd-compare", stand_in(tmp_path, score=RANSAC_SCORE), "--grid", write_grid(tmp_path),
                "--output", tmp_path / "tuned.json", folder)
    assert done.returncode == 0 and done.stderr == ""
    assert (tmp_path / "tuned.json").exists()


def test_a_failing_run_is_reported_with_the_end_of_its_messages_and_nothing_is_written(tmp_path):
    folder = labelled_folder(tmp_path / "tune", ["a.none.pcd"])
    program = stand_in(tmp_path, fail="PCL noise\nmore noise\npcd_compare: error: a.none.pcd: cannot read it\n")
    output = tmp_path / "tuned.json"
    done = tune("--pcd-compare", program, "--methods", "ransac", "--output", output, folder)
    one_line_error(done, "pcd_compare failed (exit 1) on ransac [none]", "a.none.pcd: cannot read it")
    assert not output.exists()


def test_a_pcd_compare_without_the_parameter_listing_is_an_error(tmp_path):
    folder = labelled_folder(tmp_path / "tune", ["a.none.pcd"])
    program = stand_in(tmp_path, score=RANSAC_SCORE,
                       listing="pcl::SACSegmentation<PointXYZ> SACMODEL_PLANE, SAC_RANSAC, distance threshold 0.01 m")
    done = tune("--pcd-compare", program, "--methods", "ransac", "--output", tmp_path / "tuned.json", folder)
    one_line_error(done, "method ransac (tuned) [none]", "does not begin with the parameters")


# --- the real pcd_compare, on two small rendered scenes -------------------------------------------

def binaries():
    found = [os.environ.get(name) for name in ("FLOODPLANE_PCD_COMPARE", "FLOODPLANE_PCD_SYNTH")]
    if not all(found) or not all(pathlib.Path(p).exists() for p in found):
        pytest.skip("pcd_compare or pcd_synth is not built (FLOODPLANE_PCD_COMPARE, FLOODPLANE_PCD_SYNTH)")
    return [pathlib.Path(p) for p in found]


@pytest.fixture(scope="module")
def rendered(tmp_path_factory):
    """pcd_compare, and a tuning folder of two exact clouds of one sensor model: far_wall (on
    which OMPS's default maximum curvature rejects every region) and the staircase."""
    pcd_compare, pcd_synth = binaries()
    folder = tmp_path_factory.mktemp("tune")
    done = subprocess.run([str(pcd_synth), "--sensor", "none", "--width", "160", "--height", "120", "--quiet",
                           "-o", str(folder), str(SOURCE / "data/scenes/staircase.json"),
                           str(SOURCE / "data/scenes/far_wall.json")], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return pcd_compare, folder


def omps_mean_iou(pcd_compare, folder, tmp_path, maximum_curvature):
    """OMPS's mean IoU over `folder` at one maximum curvature, by pcd_compare --tuned."""
    tuned, report = tmp_path / "by_hand.json", tmp_path / "by_hand_out.json"
    tuned.write_text(json.dumps({"methods": {"omps": {"by_sensor": {"none": {
        "parameters": {"maximum_curvature": maximum_curvature}}}}}}))
    done = subprocess.run([str(pcd_compare), "--repeat", "0", "--quiet", "--methods", "omps", "--tuned",
                           "--tuned-file", str(tuned), "--json", str(report), str(folder)],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(report.read_text())["means"]["omps (tuned)"]["mean_iou"]


def test_picks_the_better_of_two_grid_points_and_keeps_other_methods_of_the_file(rendered, tmp_path):
    pcd_compare, folder = rendered
    grid = tmp_path / "grid.json"
    grid.write_text(json.dumps({"omps": {"maximum_curvature": [0.001, 0.3]}}))
    output = tmp_path / "tuned.json"
    earlier = {"ransac": {"by_sensor": {"none": {"parameters": {"min_inliers": 300}}}}}
    output.write_text(json.dumps({"methods": earlier}))

    done = tune("--pcd-compare", pcd_compare, "--methods", "omps", "--grid", grid, "--output", output, folder)
    assert done.returncode == 0, done.stderr
    assert "omps [none] #2 " in done.stderr
    result = json.loads(output.read_text())

    strict = omps_mean_iou(pcd_compare, folder, tmp_path, 0.001)
    loose = omps_mean_iou(pcd_compare, folder, tmp_path, 0.3)
    assert abs(strict - loose) > 1e-6, "the two grid points must score differently"
    omps = result["methods"]["omps"]
    winner = omps["by_sensor"]["none"]
    assert winner["parameters"] == dict(omps["default"], maximum_curvature=0.001 if strict > loose else 0.3)
    assert omps["default"]["maximum_curvature"] == 0.001
    assert winner["mean_iou"] == pytest.approx(max(strict, loose), abs=1e-12)
    assert winner["default_mean_iou"] == pytest.approx(strict, abs=1e-12)
    assert sorted(winner["clouds"]) == ["far_wall.none", "staircase.none"]
    assert winner["settings_evaluated"] == 2
    assert omps["grid"] == {"maximum_curvature": [0.001, 0.3]}
    # The method not tuned in this run keeps its earlier entry.
    assert result["methods"]["ransac"]["by_sensor"]["none"]["parameters"] == {"min_inliers": 300}


def test_a_cloud_pcd_compare_cannot_read_fails_the_run_by_its_name(rendered, tmp_path):
    pcd_compare, _ = rendered
    folder = tmp_path / "tune"
    folder.mkdir()
    broken = write_pcd(folder / "broken.none.pcd")
    broken.write_text(broken.read_text().replace("POINTS 2", "POINTS 5"))  # more points than rows
    done = tune("--pcd-compare", pcd_compare, "--methods", "omps", "--output", tmp_path / "tuned.json", folder)
    one_line_error(done, "pcd_compare failed", "broken.none.pcd")
    assert not (tmp_path / "tuned.json").exists()

#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Tunes the baselines of pcd_compare (PCL's OMPS and sequential RANSAC, Open3D's sequential
RANSAC) for each sensor model, and writes the values that `pcd_compare --tuned` reads.

Per baseline and sensor model: a subset of N clouds of FOLDER (`<scene>.<sensor>.pcd` files
with a ground-truth `label` field; the tuning split, never the report split), evenly spaced in
sorted name order; coordinate descent from pcd_compare's defaults over the grid (each parameter
in turn over its grid values, the others held; passes until one changes nothing, at most
--passes; ties keep the current value), maximising the mean IoU (metrics.md) of the subset.
Every setting is scored by the real program: `pcd_compare --methods B --tuned --tuned-file T
--repeat 0 --quiet --json OUT <the subset>` with the setting in T, its row "B (tuned)" read from
OUT; a setting is run once (cached). The defaults, and the list of tunable parameters, come
from a first run with no values: pcd_compare's configuration line "method B (tuned) [sensor]"
begins with "name=value, ...;".

pcd_compare's C++ tuner (--tune, removed) scored every min_inliers of a sequential RANSAC from
one run at the smallest value, by truncating the sequence; that shortcut is dropped here: each
value is a run of its own, so RANSAC's min_inliers costs as much as its distance threshold.
pcd_compare also runs the baseline at its defaults beside every tuned row (the "B" row): its
score is read once, as default_mean_iou, and its runs count in method_runs and seconds.

The output (default bench/tuned_baselines.json) keeps the baselines this run does not tune;
it is read again just before writing, so runs tuning different baselines may overlap. Written
whole or not at all.

Example:
  bench/tune_baselines.py --methods omps,ransac --clouds 10 build/data/random/tune
  bench/tune_baselines.py --methods omps --grid my_grid.json --output /tmp/tuned.json DIR
"""

import argparse
import json
import math
import os
import pathlib
import re
import signal
import subprocess
import sys
import tempfile
import time

ROOT = pathlib.Path(__file__).resolve().parent.parent
PROGRAM = "tune_baselines"
BASELINES = ("omps", "ransac", "open3d_ransac")
COUNTS = {"min_inliers"}  # parameters that count pixels: whole numbers
TIE = 1e-9  # a change must gain more than this: ties keep the current value

# The grid searched without --grid. It names every tunable parameter of every baseline (a
# --grid file may name any of them). Each list brackets the default by a factor of 2-4 on both
# sides; the distances reach 5 mm, five times the scanner's noise at 1 m (a sequential RANSAC
# below that cuts noisy Kinect planes into hundreds of slices, and one run takes minutes).
RANSAC_DISTANCE = [0.005, 0.01, 0.02, 0.04]
RANSAC_MIN_INLIERS = [100, 300, 1000, 3000]
DEFAULT_GRID = {
    "omps": {
        "angular_threshold": [0.01, 0.02, 0.04, 0.09, 0.15, 0.25],
        "distance_threshold": [0.002, 0.005, 0.01, 0.02, 0.04, 0.08, 0.16],
        "normal_smoothing_size": [2, 4, 6, 10, 15, 20],
        "max_depth_change_factor": [0.005, 0.01, 0.02, 0.05, 0.1, 0.2],
        "maximum_curvature": [0.001, 0.003, 0.01, 0.03, 0.1, 0.3],
        "min_inliers": [20, 50, 200, 800],
    },
    "ransac": {"distance_threshold": RANSAC_DISTANCE, "min_inliers": RANSAC_MIN_INLIERS},
    "open3d_ransac": {"distance_threshold": RANSAC_DISTANCE, "min_inliers": RANSAC_MIN_INLIERS},
}

DESCRIPTION = (
    "Baseline parameters tuned by bench/tune_baselines.py: per method and sensor model, the grid values with "
    "the highest mean IoU (metrics.md) on the clouds listed, by coordinate descent from the defaults (one "
    "parameter at a time over its grid values, the others held; passes until nothing changes; ties keep the "
    "current value). Every setting is one run of pcd_compare on the clouds (no truncation shortcut); "
    "method_runs counts the runs of the method on a cloud, the default row pcd_compare runs beside each tuned "
    "row included. A run replaces the methods it tunes and keeps the others.")


class TuningError(Exception):
    """A user error or a failed run: reported as one line, exit code 1."""


# --- the search -------------------------------------------------------------------------------

def better(score, best):
    """Whether `score` beats `best` by more than TIE; None (no IoU defined) never wins."""
    return score is not None and (best is None or score > best + TIE)


def coordinate_descent(start, grid, evaluate, passes):
    """Maximises `evaluate(values)` (a number, or None when undefined) from `start` (an ordered
    {name: value}: every parameter, in the order they are visited) over `grid` ({name: [values]};
    parameters not in it keep their start value). Each pass takes every parameter in turn over
    its grid values with the others held; a value replaces the current one only if it scores
    more than TIE higher, so ties keep the current value; a pass that changes nothing ends the
    search, and at most `passes` run. Each set of values is evaluated once.

    Returns (best values, best score, {tuple of (name, value): score} of every set evaluated)."""
    scores = {}

    def score(values):
        key = tuple(values.items())
        if key not in scores:
            scores[key] = evaluate(dict(values))
        return scores[key]

    best = dict(start)
    best_score = score(best)
    for _ in range(passes):
        changed = False
        for name in start:
            for value in grid.get(name, []):
                candidate = dict(best)
                candidate[name] = value
                candidate_score = score(candidate)
                if better(candidate_score, best_score):
                    best, best_score, changed = candidate, candidate_score, True
        if not changed:
            break
    return best, best_score, scores


def describe(values):
    return ", ".join(f"{name}={value:g}" for name, value in values.items())


# --- inputs -------------------------------------------------------------------------------------

def check_values(baseline, name, values):
    """The grid values of one parameter as floats; TuningError (without the file) otherwise."""
    if not isinstance(values, list) or not values:
        raise TuningError(f"{baseline}.{name}: give a non-empty list of values")
    checked = []
    for value in values:
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value <= 0:
            raise TuningError(f"{baseline}.{name}: every value must be a positive number, got {json.dumps(value)}")
        if name in COUNTS and value != math.floor(value):
            raise TuningError(f"{baseline}.{name}: every value must be a whole number, got {value:g}")
        checked.append(float(value))
    return checked


def read_grid(path):
    """The grid of a JSON file {"omps": {"angular_threshold": [0.05, 0.09]}, ...}; every baseline
    and parameter must be known and every value positive (TuningError naming the file)."""
    try:
        data = json.loads(pathlib.Path(path).read_text())
    except OSError as error:
        raise TuningError(f"{path}: cannot read the grid file: {error.strerror or error}") from None
    except ValueError as error:
        raise TuningError(f"{path}: not JSON: {error}") from None
    try:
        if not isinstance(data, dict) or not data:
            raise TuningError('the grid must be an object naming baselines: {"omps": {"angular_threshold": [...]}}')
        grid = {}
        for baseline, parameters in data.items():
            if baseline not in DEFAULT_GRID:
                raise TuningError(f"no tunable baseline '{baseline}' (use {', '.join(BASELINES)})")
            if not isinstance(parameters, dict) or not parameters:
                raise TuningError(f"{baseline}: give an object of parameters and their values")
            for name, values in parameters.items():
                if name not in DEFAULT_GRID[baseline]:
                    raise TuningError(f"{baseline} has no parameter '{name}' "
                                      f"(it has {', '.join(DEFAULT_GRID[baseline])})")
                grid.setdefault(baseline, {})[name] = check_values(baseline, name, values)
        return grid
    except TuningError as error:
        raise TuningError(f"{path}: {error}") from None


def sensor_model(path):
    """The sensor model of `<scene>.<sensor>.pcd`, "" for other names (as pcd_compare: digits
    after the last dot are a fraction of a second, not a sensor)."""
    stem = path.name[:-4] if path.name.endswith(".pcd") else path.name
    _, dot, sensor = stem.rpartition(".")
    return "" if not dot or sensor.isdigit() else sensor


def has_labels(path):
    """Whether the PCD header of `path` has a `label` field."""
    try:
        with open(path, "rb") as f:
            for _ in range(64):
                line = f.readline(4096).decode("latin-1").split()
                if line and line[0] == "FIELDS":
                    return "label" in line[1:]
                if not line or line[0] == "DATA":
                    break
    except OSError as error:
        raise TuningError(f"{path}: cannot read: {error.strerror or error}") from None
    return False


def tuning_subset(folder, per_sensor):
    """{sensor model: the subset's files}: per sensor model, `per_sensor` files evenly spaced in
    the sorted list of that model's files (all of them when there are fewer)."""
    folder = pathlib.Path(folder)
    if not folder.is_dir():
        raise TuningError(f"{folder}: no such folder")
    by_sensor = {}
    for path in sorted(folder.iterdir(), key=lambda p: p.name):
        if path.suffix == ".pcd" and not path.is_dir() and sensor_model(path):
            by_sensor.setdefault(sensor_model(path), []).append(path)
    if not by_sensor:
        raise TuningError(f"{folder}: no <scene>.<sensor>.pcd files to tune on")
    subset = {}
    for sensor, files in sorted(by_sensor.items()):
        n = min(per_sensor, len(files))
        subset[sensor] = [files[k * len(files) // n] for k in range(n)]
        for path in subset[sensor]:
            if not has_labels(path):
                raise TuningError(f"{path}: no ground-truth labels (a `label` field) to tune on")
    return subset


# --- pcd_compare --------------------------------------------------------------------------------

def parse_parameters(text, key):
    """{name: value} in order from a configuration value beginning "name=value, ...;"."""
    head = text.split(";", 1)[0]
    values = {}
    for item in head.split(","):
        match = re.fullmatch(r"\s*([A-Za-z_]\w*)=(\S+)\s*", item)
        try:
            values[match.group(1)] = float(match.group(2))
        except (AttributeError, ValueError):
            raise TuningError(f"pcd_compare's configuration '{key}' does not begin with the parameters as "
                              f"'name=value, ...;' (got '{text[:60]}...'): is it older than this script?") from None
    return values


class PcdCompare:
    """Runs pcd_compare on one baseline with one set of values, in a scratch folder."""

    def __init__(self, binary, scratch):
        self.binary = binary
        self.tuned_file = pathlib.Path(scratch, "tuned.json")
        self.json_file = pathlib.Path(scratch, "out.json")

    def run(self, baseline, sensor, values, files):
        """pcd_compare's JSON for `baseline` at `values` (missing ones at their defaults)."""
        self.tuned_file.write_text(json.dumps(
            {"methods": {baseline: {"by_sensor": {sensor: {"parameters": values}}}}}))
        self.json_file.unlink(missing_ok=True)
        command = [str(self.binary), "--methods", baseline, "--tuned", "--tuned-file", str(self.tuned_file),
                   "--repeat", "0", "--quiet", "--json", str(self.json_file), *map(str, files)]
        what = f"{baseline} [{sensor}] at {describe(values) or 'the defaults'}"
        try:
            done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                                  errors="replace")
        except OSError as error:
            raise TuningError(f"cannot run {self.binary}: {error.strerror or error}") from None
        if done.returncode != 0:
            last = [line.strip() for line in done.stderr.splitlines() if line.strip()][-3:]
            status = f"exit {done.returncode}"
            if done.returncode < 0:
                try:
                    status = f"killed by {signal.Signals(-done.returncode).name}"
                except ValueError:
                    status = f"killed by signal {-done.returncode}"
            raise TuningError(f"pcd_compare failed ({status}) on {what}: " + (" | ".join(last) or "no message"))
        try:
            return json.loads(self.json_file.read_text())
        except (OSError, ValueError) as error:
            raise TuningError(f"pcd_compare wrote no JSON report on {what}: {error}") from None


def mean_iou(report, row):
    """The mean IoU of `row` in a pcd_compare JSON report (None when not defined)."""
    try:
        value = report["means"][row]["mean_iou"]
    except (KeyError, TypeError):
        raise TuningError(f"pcd_compare's JSON report has no mean IoU of '{row}'") from None
    return value if isinstance(value, (int, float)) else None


def fmt(score):
    return "n/a" if score is None else f"{score:.4f}"


def tune_sensor(pcd_compare, baseline, sensor, files, grid, passes, progress):
    """The search for one baseline on one sensor model's files: its entry of "by_sensor", and
    the defaults pcd_compare reported."""
    start = time.monotonic()
    row = f"{baseline} (tuned)"
    key = f"method {row} [{sensor}]"
    report = pcd_compare.run(baseline, sensor, {}, files)
    configuration = report.get("configuration") if isinstance(report, dict) else None
    text = configuration.get(key) if isinstance(configuration, dict) else None
    if not isinstance(text, str):
        raise TuningError(f"pcd_compare's JSON report has no configuration '{key}'")
    defaults = parse_parameters(text, key)
    unknown = [name for name in grid if name not in defaults]
    if unknown:
        raise TuningError(f"pcd_compare has no {baseline} parameter '{unknown[0]}' (it has {', '.join(defaults)})")
    # The tuned row at no values is the defaults' score too: the descent's first setting.
    default_score = mean_iou(report, baseline)
    start_score = mean_iou(report, row)
    known = {tuple(defaults.items()): start_score}
    runs = 1
    label = f"{baseline} [{sensor}]"
    progress(f"{label}: {len(files)} cloud{'s' if len(files) != 1 else ''}; #1 the defaults {describe(defaults)}: "
             f"mean IoU {fmt(start_score)}, {time.monotonic() - start:.1f} s")
    state = {"best": start_score}

    def evaluate(values):
        nonlocal runs
        if tuple(values.items()) in known:
            return known[tuple(values.items())]
        began = time.monotonic()
        score = mean_iou(pcd_compare.run(baseline, sensor, values, files), row)
        runs += 1
        if better(score, state["best"]):
            state["best"] = score
        progress(f"{label} #{runs} {describe(values)}: mean IoU {fmt(score)} (best {fmt(state['best'])}), "
                 f"{time.monotonic() - began:.1f} s, {time.monotonic() - start:.0f} s elapsed")
        return score

    best, best_score, scores = coordinate_descent(defaults, grid, evaluate, passes)
    seconds = time.monotonic() - start
    changed = {name: value for name, value in best.items() if value != defaults[name]}
    progress(f"{label}: mean IoU {fmt(default_score)} -> {fmt(best_score)} "
             f"({describe(changed) or 'the defaults'}), {len(scores)} settings, {seconds:.0f} s")
    entry = {"parameters": best, "mean_iou": best_score, "default_mean_iou": default_score,
             "clouds": [path.name[:-4] for path in files], "settings_evaluated": len(scores),
             # Each pcd_compare run runs the baseline twice a cloud: its default and tuned rows.
             "method_runs": 2 * runs * len(files), "seconds": seconds}
    return entry, defaults


# --- output -------------------------------------------------------------------------------------

def earlier_methods(path):
    """The "methods" of an earlier output file, {} when there is none; None when the file is
    there but is not a tuning result."""
    try:
        data = json.loads(pathlib.Path(path).read_text())
    except FileNotFoundError:
        return {}
    except (OSError, ValueError):
        return None
    methods = data.get("methods") if isinstance(data, dict) else None
    return methods if isinstance(methods, dict) else None


def check_output(path):
    """Fails before any tuning when `path` could not be written or would lose an earlier file."""
    path = pathlib.Path(path)
    if not path.parent.resolve().is_dir():
        raise TuningError(f"{path}: its folder does not exist")
    if path.is_dir():
        raise TuningError(f"{path}: is a folder, not a file")
    if not os.access(path.parent.resolve(), os.W_OK):
        raise TuningError(f"{path}: its folder is not writable")
    if earlier_methods(path) is None:
        raise TuningError(f"{path}: exists but is not a tuning result (no \"methods\" object); "
                          "move it away or choose another --output")


def write_atomically(path, text):
    """Writes `text` whole or not at all: a temporary beside `path`, then renamed over it."""
    path = pathlib.Path(path)
    partial = None
    try:
        fd, partial = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".partial")
        with os.fdopen(fd, "w") as f:
            f.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(partial, path.stat().st_mode & 0o777 if path.exists() else 0o666 & ~umask)
        os.replace(partial, path)
    except OSError as error:
        if partial:
            pathlib.Path(partial).unlink(missing_ok=True)
        raise TuningError(f"cannot write {path}: {error.strerror or error}") from None


# --- the command --------------------------------------------------------------------------------

def baseline_list(text):
    names = [name.strip() for name in text.split(",") if name.strip()]
    unknown = [name for name in names if name not in BASELINES]
    if not names or unknown:
        raise argparse.ArgumentTypeError(f"unknown baseline '{unknown[0] if unknown else text}' "
                                         f"(use {', '.join(BASELINES)})")
    return list(dict.fromkeys(names))


def positive_int(text):
    try:
        value = int(text)
    except ValueError:
        value = 0
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be a positive whole number, got '{text}'")
    return value


def tune(args, progress):
    grid = read_grid(args.grid) if args.grid else DEFAULT_GRID
    selected = {baseline: {name: [float(value) for value in values] for name, values in grid[baseline].items()}
                for baseline in args.methods if baseline in grid}
    if not selected:
        raise TuningError(f"--methods names no baseline of the grid to tune (the grid has {', '.join(grid)})")
    check_output(args.output)
    subset = tuning_subset(args.folder, args.clouds)
    binary = pathlib.Path(args.pcd_compare)
    if not binary.is_file():
        raise TuningError(f"{binary}: no such program (build pcd_compare, or give --pcd-compare)")

    tuned = {}
    with tempfile.TemporaryDirectory(prefix="tune_baselines.") as scratch:
        pcd_compare = PcdCompare(binary, scratch)
        for baseline, parameters in selected.items():
            start = time.monotonic()
            entry = {"tuning_folder": str(args.folder), "clouds_per_sensor": args.clouds,
                     "passes_at_most": args.passes, "grid": parameters, "by_sensor": {}}
            for sensor, files in subset.items():
                entry["by_sensor"][sensor], defaults = tune_sensor(pcd_compare, baseline, sensor, files, parameters,
                                                                   args.passes, progress)
                entry.setdefault("default", defaults)
            entry["seconds"] = time.monotonic() - start
            tuned[baseline] = entry

    # Read last, so that runs tuning different baselines may overlap.
    methods = earlier_methods(args.output)
    if methods is None:
        raise TuningError(f"{args.output}: changed during the run and is no longer a tuning result; not replaced")
    methods.update(tuned)
    write_atomically(args.output, json.dumps({"description": DESCRIPTION, "methods": methods},
                                             indent=2, sort_keys=True) + "\n")
    progress(f"wrote {args.output}")


def main(argv=None):
    parser = argparse.ArgumentParser(prog="tune_baselines.py", description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("folder", type=pathlib.Path, metavar="FOLDER",
                        help="the tuning split: <scene>.<sensor>.pcd files with ground-truth labels")
    parser.add_argument("--pcd-compare", default=ROOT / "build/apps/pcd_compare/pcd_compare", metavar="BIN",
                        help="the pcd_compare to run (default: %(default)s)")
    parser.add_argument("--methods", type=baseline_list, default=list(BASELINES), metavar="LIST",
                        help="baselines to tune, comma-separated (default: " + ",".join(BASELINES) + ")")
    parser.add_argument("--grid", metavar="GRID.json",
                        help='values to try: {"omps": {"angular_threshold": [0.05, 0.09]}, ...}; only the '
                             "baselines it names are tuned (default: the grid in this script)")
    parser.add_argument("--clouds", type=positive_int, default=12, metavar="N",
                        help="clouds per sensor model in the subset (default: %(default)s)")
    parser.add_argument("--passes", type=positive_int, default=2,
                        help="coordinate-descent passes at most (default: %(default)s)")
    parser.add_argument("--output", type=pathlib.Path, default=ROOT / "bench/tuned_baselines.json",
                        metavar="FILE", help="the tuned values, written atomically (default: %(default)s)")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress lines, only errors")
    args = parser.parse_args(argv)

    def progress(line):
        if not args.quiet:
            print(f"{PROGRAM}: {line}", file=sys.stderr, flush=True)

    try:
        tune(args, progress)
    except TuningError as error:
        print(f"{PROGRAM}: error: {error}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"{PROGRAM}: interrupted; {args.output} not changed", file=sys.stderr)
        return 130
    return 0


if __name__ == "__main__":
    sys.exit(main())

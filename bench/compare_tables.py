#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The tables of a pcd_compare report, from its JSON (`pcd_compare --json`): the means per
method (over every file, then one table per sensor model), the mean IoU per file (the best in
bold), every file and method, floodplane by sub-sampling factor (Table III) and floodplane's
time by phase (Fig. 5), as Markdown on stdout; with --csv also one CSV line per file and
method. pcd_compare itself prints only its configuration and the means.

Means follow pcd_compare's: times over every file, accuracy (IoU, Hoover counts per frame)
over the files whose ground truth keeps a plane, the false-plane fraction over the files where
it is defined, "x floodplane" as the ratio of the mean medians and only when floodplane ran on
every file of the table. An undefined figure prints as "-". floodplane at sub-sampling N is the
method "floodplane/N" ("floodplane" is the library's defaults, at the factor its configuration
line names: 1 in reports from before 4 became the default); the sub-sampling table is printed when a factor of
4 or more ran. Reports of the older format (a per-file "resolutions" object) are read too.

Example:
  bench/compare_tables.py bench/results/compare_all_scenes.json --csv /tmp/scenes.csv
  bench/compare_tables.py report.json --tables means,iou     # only these, in the usual order
"""

import argparse
import json
import math
import os
import pathlib
import re
import sys
import tempfile

NAN = float("nan")
TABLES = ["configuration", "means", "iou", "files", "subsampling", "phases"]
HOOVER = ["correct", "over", "under", "missed", "noise"]
# floodplane's phases in call order, as reports written before 2026-12-03 (pcd_compare --phases) hold them.
PHASES = ["preparation", "seed_selection", "flood_fill", "relabelling", "merging", "region_output",
          "pcl_conversion"]
SUBSAMPLED = re.compile(r"floodplane/([1-9][0-9]*)")
CSV_HEADER = ("scene,file,method,subsampling,width,height,median_ms,min_ms,ratio_to_floodplane,"
              "normals_ms,planes,mean_iou,weighted_iou,correct,over,under,missed,noise,false_plane_fraction\n")


class NotAReport(Exception):
    """The JSON is not a pcd_compare report; the message says where."""


# Reading the report -------------------------------------------------------------------------

def field(entry, key, where, kinds, optional=False):
    if not isinstance(entry, dict):
        raise NotAReport(f"{where} is not an object")
    if key not in entry:
        if optional:
            return None
        raise NotAReport(f"{where} has no \"{key}\"")
    value = entry[key]
    # bool is an int to Python, never to the report.
    if isinstance(value, bool) != (bool in kinds) or not isinstance(value, kinds):
        raise NotAReport(f"{where}: \"{key}\" is {json.dumps(value)[:40]}")
    return value


def number(entry, key, where):
    """A time or score: the report writes NaN as null."""
    value = field(entry, key, where, (int, float, type(None)))
    return NAN if value is None else float(value)


def count(entry, key, where):
    return field(entry, key, where, (int,))


class Result:
    """One method on one file."""

    def __init__(self, method, entry, where):
        self.method = method
        self.median_ms = number(entry, "median_ms", where)
        self.min_ms = number(entry, "min_ms", where)
        self.planes = count(entry, "planes", where)
        parts = field(entry, "parts_median_ms", where, (dict,), optional=True) or {}
        self.parts_ms = {name: number(parts, name, f"{where}.parts_median_ms") for name in parts}
        match = SUBSAMPLED.fullmatch(method)
        self.factor = int(match.group(1)) if match else None
        # Scores are there when the file has ground truth.
        self.scored = "ground_truth_planes" in entry
        if self.scored:
            self.ground_truth_planes = count(entry, "ground_truth_planes", where)
            self.mean_iou = number(entry, "mean_iou", where)
            self.weighted_iou = number(entry, "weighted_iou", where)
            hoover = field(entry, "hoover", where, (dict,))
            self.hoover = {name: count(hoover, name, f"{where}.hoover") for name in HOOVER}
            self.false_planes = number(entry, "false_plane_fraction", where)


class Scene:
    def __init__(self, entry, where):
        self.name = field(entry, "name", where, (str,))
        where = f"scene {self.name}"
        self.path = field(entry, "file", where, (str,))
        self.width = count(entry, "width", where)
        self.height = count(entry, "height", where)
        self.has_ground_truth = field(entry, "ground_truth", where, (bool,))
        self.sensor = field(entry, "sensor", where, (str,), optional=True) or ""
        methods = field(entry, "methods", where, (dict,))
        self.methods = [Result(name, result, f"{where}, method {name}") for name, result in methods.items()]
        # The older format: floodplane at sub-sampling 1, 2, 4, 8 apart from the methods.
        resolutions = field(entry, "resolutions", where, (dict,), optional=True) or {}
        for factor, result in resolutions.items():
            name = f"floodplane/{factor}"
            if self.find(name) is None:
                self.methods.append(Result(name, result, f"{where}, resolution {factor}"))
        self.phases_ms, self.call_ms = None, NAN
        phases = field(entry, "phases", where, (dict,), optional=True)
        if phases is not None:
            median = field(phases, "median_ms", f"{where}.phases", (dict,))
            self.phases_ms = {key: number(median, key, f"{where}.phases.median_ms") for key in median}
            self.call_ms = number(phases, "call_median_ms", f"{where}.phases")

    def find(self, method):
        return next((result for result in self.methods if result.method == method), None)


def read_report(path):
    """The configuration (key -> text) and the scenes of the report at `path`; exits with one line
    when it cannot be read."""
    try:
        text = pathlib.Path(path).read_text(encoding="utf-8")
    except OSError as error:
        sys.exit(f"compare_tables.py: cannot read {path}: {error.strerror or error}")
    try:
        report = json.loads(text)
    except ValueError as error:
        sys.exit(f"compare_tables.py: {path} is not JSON: {error}")
    try:
        scenes = field(report, "scenes", "the report", (list,))
        configuration = report.get("configuration", {}) if isinstance(report, dict) else {}
        if not isinstance(configuration, dict):
            raise NotAReport('"configuration" is not an object')
        scenes = [Scene(scene, f"scenes[{k}]") for k, scene in enumerate(scenes)]
        # floodplane at the library's defaults: its sub-sampling is the one its configuration
        # line names (1 in reports from before 4 became the default).
        described = re.search(r"sub-sampling ([1-9][0-9]*)", str(configuration.get("method floodplane", "")))
        for scene in scenes:
            for result in scene.methods:
                if result.method == "floodplane" and described:
                    result.factor = int(described.group(1))
        return configuration, scenes
    except NotAReport as error:
        sys.exit(f"compare_tables.py: {path} is not a pcd_compare report: {error}")


# Figures ----------------------------------------------------------------------------------

def fixed(value, decimals):
    return f"{value:.{decimals}f}" if math.isfinite(value) else "-"


def divide(a, b):
    """a / b as C++ divides doubles: by zero gives an infinity or NaN, not an exception."""
    if b != 0.0:
        return a / b
    return NAN if a == 0.0 or math.isnan(a) else math.copysign(math.inf, a) * math.copysign(1.0, b)


def ratio_to_floodplane(scene, result):
    """This method's median over floodplane's in the same file."""
    reference = scene.find("floodplane")
    return result.median_ms / reference.median_ms if reference and reference.median_ms > 0.0 else NAN


class MeanRow:
    """One method's sums over files, for its mean row (MeanRow of report.cpp)."""

    def __init__(self):
        self.scenes = self.scored = self.with_floodplane = self.with_non_plane = self.ground_truth_planes = 0
        self.median_ms = self.min_ms = self.floodplane_ms = self.planes = self.false_planes = 0.0
        self.parts_ms = {}
        self.sums = dict.fromkeys(["mean_iou", "weighted_iou", *HOOVER], 0.0)

    def add(self, scene, result):
        self.scenes += 1
        self.median_ms += result.median_ms
        self.min_ms += result.min_ms
        self.planes += result.planes
        for name, ms in result.parts_ms.items():
            self.parts_ms[name] = self.parts_ms.get(name, 0.0) + ms
        reference = scene.find("floodplane")
        if reference is not None:
            self.floodplane_ms += reference.median_ms
            self.with_floodplane += 1
        if not result.scored:
            return
        if math.isfinite(result.false_planes):
            self.false_planes += result.false_planes
            self.with_non_plane += 1
        # Files whose ground truth keeps no plane have no IoU to average.
        if result.ground_truth_planes == 0:
            return
        self.scored += 1
        self.ground_truth_planes += result.ground_truth_planes
        self.sums["mean_iou"] += result.mean_iou
        self.sums["weighted_iou"] += result.weighted_iou
        for name in HOOVER:
            self.sums[name] += result.hoover[name]

    def time(self, total):
        return total / self.scenes if self.scenes > 0 else NAN

    def accuracy(self, name):
        return self.sums[name] / self.scored if self.scored > 0 else NAN

    def false_plane_fraction(self):
        return self.false_planes / self.with_non_plane if self.with_non_plane > 0 else NAN

    def part(self, name):
        return self.time(self.parts_ms[name]) if name in self.parts_ms else NAN

    def ratio(self):
        """The ratio of the mean medians: long files weigh as they weigh in a user's waiting."""
        complete = self.with_floodplane == self.scenes and self.floodplane_ms > 0.0
        return self.median_ms / self.floodplane_ms if complete else NAN


def method_order(scenes):
    """Every method once, in the order the report first names it."""
    order = {}
    for scene in scenes:
        for result in scene.methods:
            order.setdefault(result.method, None)
    return list(order)


# Tables ------------------------------------------------------------------------------------

class Columns:
    """The optional column groups: accuracy when a file has ground truth, normals when a
    method reports its normal estimation (OMPS)."""

    def __init__(self, scenes):
        self.accuracy = any(scene.has_ground_truth for scene in scenes)
        self.normals = any(math.isfinite(r.parts_ms.get("normals", NAN)) for s in scenes for r in s.methods)

    def header(self, first):
        return (f"| {first} | median ms | min ms | x floodplane |" + (" normals ms |" if self.normals else "")
                + " planes |"
                + (" mean IoU | weighted IoU | correct | over | under | missed | noise | false planes |"
                   if self.accuracy else "") + "\n")

    def rule(self, first):
        return (f"|{first}---:|---:|---:|" + ("---:|" if self.normals else "") + "---:|"
                + ("---:|---:|---:|---:|---:|---:|---:|---:|" if self.accuracy else "") + "\n")


def accuracy_cells(mean_iou, weighted_iou, counts, false_planes, decimals):
    return (f" {fixed(mean_iou, 3)} | {fixed(weighted_iou, 3)} |"
            + "".join(f" {fixed(c, decimals)} |" for c in counts) + f" {fixed(false_planes, 3)} |")


def mean_table(title, rows, order, columns):
    out = f"### {title}\n\n" + columns.header("method | files") + columns.rule("---|---:|")
    for method in order:
        row = rows.get(method)
        if row is None:
            continue
        out += (f"| {method} | {row.scenes} | {fixed(row.time(row.median_ms), 2)} | {fixed(row.time(row.min_ms), 2)}"
                f" | {fixed(row.ratio(), 2)} |")
        if columns.normals:
            out += f" {fixed(row.part('normals'), 2)} |"
        out += f" {fixed(row.time(row.planes), 1)} |"
        if columns.accuracy:
            out += accuracy_cells(row.accuracy("mean_iou"), row.accuracy("weighted_iou"),
                                  [row.accuracy(name) for name in HOOVER], row.false_plane_fraction(), 1)
        out += "\n"
    return out + "\n"


def mean_tables(scenes):
    """The means per method over every file, then over the files of each sensor model."""
    columns, order = Columns(scenes), method_order(scenes)
    overall, by_sensor = {}, {}
    for scene in scenes:
        for result in scene.methods:
            overall.setdefault(result.method, MeanRow()).add(scene, result)
            if scene.sensor:
                by_sensor.setdefault(scene.sensor, {}).setdefault(result.method, MeanRow()).add(scene, result)
    out = "## Means per method\n\n" + mean_table(f"all files ({len(scenes)})", overall, order, columns)
    for sensor in sorted(by_sensor):
        rows = by_sensor[sensor]
        files = max(row.scenes for row in rows.values())
        out += mean_table(f"sensor model {sensor} ({files} files)", rows, order, columns)
    return out


def iou_table(scenes):
    """Mean IoU of every method on every file with ground truth; every method that ties the
    best of a file at the printed precision in bold."""
    if not any(scene.has_ground_truth for scene in scenes):
        return ""
    order = method_order(scenes)
    out = ("## Mean IoU per file (best in bold)\n\n| file |" + "".join(f" {m} |" for m in order) + "\n|---|"
           + "---:|" * len(order) + "\n")
    for scene in scenes:
        if not scene.has_ground_truth:
            continue
        ious = [r.mean_iou for r in scene.methods if r.scored and math.isfinite(r.mean_iou)]
        best = fixed(max([-1.0, *ious]), 3)
        out += f"| {scene.name} |"
        for method in order:
            result = scene.find(method)
            iou = result.mean_iou if result is not None and result.scored else NAN
            cell = fixed(iou, 3)
            out += f" **{cell}** |" if math.isfinite(iou) and cell == best else f" {cell} |"
        out += "\n"
    return out + "\n"


def files_table(scenes):
    """Runtime and accuracy of every method on every file."""
    columns = Columns(scenes)
    out = ("## Every file and method: runtime" + (" and accuracy" if columns.accuracy else "") + "\n\n"
           + columns.header("scene | method") + columns.rule("---|---|"))
    for scene in scenes:
        for r in scene.methods:
            out += (f"| {scene.name} | {r.method} | {fixed(r.median_ms, 2)} | {fixed(r.min_ms, 2)}"
                    f" | {fixed(ratio_to_floodplane(scene, r), 2)} |")
            if columns.normals:
                out += f" {fixed(r.parts_ms.get('normals', NAN), 2)} |"
            out += f" {r.planes} |"
            if columns.accuracy:
                out += (accuracy_cells(r.mean_iou, r.weighted_iou, [r.hoover[n] for n in HOOVER], r.false_planes, 0)
                        if r.scored else " - |" * 8)
            out += "\n"
    return out + "\n"


def subsampling_table(scenes):
    """floodplane at each sub-sampling factor that ran (Table III): a row per file and factor,
    the speed-up over the file's floodplane/1 (else its floodplane), and a mean row per factor. Empty unless a
    factor of 4 or more ran: floodplane/2 alone is in the other tables already."""
    if not any((r.factor or 0) >= 4 for scene in scenes for r in scene.methods):
        return ""
    accuracy = any(scene.has_ground_truth for scene in scenes)
    out = ("## floodplane by sub-sampling factor (Table III)\n\n"
           "| scene | sub-sampling | median ms | min ms | speed-up over 1 | planes |"
           + (" mean IoU | weighted IoU | false planes |" if accuracy else "") + "\n"
           "|---|---:|---:|---:|---:|---:|" + ("---:|---:|---:|" if accuracy else "") + "\n")
    means, speedups = {}, {}
    for scene in scenes:
        full = scene.find("floodplane/1") or scene.find("floodplane")
        full_ms = full.median_ms if full is not None else NAN
        for r in sorted((r for r in scene.methods if r.factor is not None), key=lambda r: r.factor):
            speedup = divide(full_ms, r.median_ms)
            means.setdefault(r.factor, MeanRow()).add(scene, r)
            speedups[r.factor] = speedups.get(r.factor, 0.0) + speedup
            out += (f"| {scene.name} | {r.factor} | {fixed(r.median_ms, 2)} | {fixed(r.min_ms, 2)}"
                    f" | {fixed(speedup, 2)} | {r.planes} |")
            if accuracy:
                cells = (r.mean_iou, r.weighted_iou, r.false_planes) if r.scored else (NAN, NAN, NAN)
                out += "".join(f" {fixed(v, 3)} |" for v in cells)
            out += "\n"
    for factor in sorted(means):
        row = means[factor]
        out += (f"| **mean** ({row.scenes} scenes) | {factor} | {fixed(row.time(row.median_ms), 2)}"
                f" | {fixed(row.time(row.min_ms), 2)} | {fixed(row.time(speedups[factor]), 2)}"
                f" | {fixed(row.time(row.planes), 1)} |")
        if accuracy:
            out += (f" {fixed(row.accuracy('mean_iou'), 3)} | {fixed(row.accuracy('weighted_iou'), 3)}"
                    f" | {fixed(row.false_plane_fraction(), 3)} |")
        out += "\n"
    return out + "\n"


def phase_keys(scenes):
    """The phase columns: floodplane's phases in call order, or the report's own order when it
    names a phase this script does not know."""
    keys = {}
    for scene in scenes:
        keys.update(dict.fromkeys(scene.phases_ms or {}))
    return [key for key in PHASES if key in keys] if set(keys) <= set(PHASES) else list(keys)


def phase_row(name, keys, phases_ms, call_ms):
    """Each phase's share of the phases' total, the total, the call."""
    total = sum(phases_ms[key] for key in keys)
    shares = "".join(f" {fixed(100.0 * phases_ms[key] / total if total > 0.0 else NAN, 1)}% |" for key in keys)
    return f"| {name} |{shares} {fixed(total, 2)} | {fixed(call_ms, 2)} |\n"


def phase_table(scenes):
    """floodplane's time by phase (Fig. 5): a row per file that has phases, and the mean."""
    timed = [scene for scene in scenes if scene.phases_ms is not None]
    if not timed:
        return ""
    keys = phase_keys(timed)
    out = ("## floodplane's time by phase (Fig. 5), share of the phases' total\n\n| scene |"
           + "".join(f" {key.replace('_', ' ')} |" for key in keys) + " phases ms | call ms |\n|---|"
           + "---:|" * len(keys) + "---:|---:|\n")
    sums, call_sum = dict.fromkeys(keys, 0.0), 0.0
    for scene in timed:
        phases_ms = {key: scene.phases_ms.get(key, NAN) for key in keys}
        out += phase_row(scene.name, keys, phases_ms, scene.call_ms)
        for key in keys:
            sums[key] += phases_ms[key]
        call_sum += scene.call_ms
    means = {key: sums[key] / len(timed) for key in keys}
    return out + phase_row(f"**mean** ({len(timed)} scenes)", keys, means, call_sum / len(timed)) + "\n"


def configuration_list(configuration):
    """pcd_compare's configuration as it prints it: a Markdown list, in the report's order."""
    if not configuration:
        return ""
    return "## Configuration\n\n" + "".join(f"- **{key}**: {text}\n" for key, text in configuration.items()) + "\n"


RENDER = {"means": mean_tables, "iou": iou_table, "files": files_table, "subsampling": subsampling_table,
          "phases": phase_table}


def csv_report(scenes):
    """One line per file and method, the factor of floodplane's sub-sampling with it."""
    out = CSV_HEADER
    for scene in scenes:
        for r in scene.methods:
            # File names may hold commas: the scene and the file are quoted.
            out += (f'"{scene.name}","{scene.path}",{r.method},{r.factor or 1},{scene.width},{scene.height},'
                    f"{fixed(r.median_ms, 4)},{fixed(r.min_ms, 4)},{fixed(ratio_to_floodplane(scene, r), 4)},"
                    f"{fixed(r.parts_ms.get('normals', NAN), 4)},{r.planes},")
            if r.scored:
                out += (f"{fixed(r.mean_iou, 6)},{fixed(r.weighted_iou, 6)},"
                        + ",".join(str(r.hoover[name]) for name in HOOVER) + f",{fixed(r.false_planes, 6)}")
            else:
                out += ",,,,,,,"
            out += "\n"
    return out


def write_atomically(path, text):
    """Writes `text` whole or not at all: a temporary beside `path`, then renamed."""
    path = pathlib.Path(path)
    try:
        fd, partial = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".partial")
    except OSError as error:
        sys.exit(f"compare_tables.py: cannot write {path}: {error.strerror or error}")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        # mkstemp makes the file private; give it the mode an ordinary new file would have.
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(partial, 0o666 & ~umask)
        os.replace(partial, path)
    except OSError as error:
        pathlib.Path(partial).unlink(missing_ok=True)
        sys.exit(f"compare_tables.py: cannot write {path}: {error.strerror or error}")


def table_list(text):
    names = [name.strip() for name in text.split(",") if name.strip()]
    unknown = [name for name in names if name not in TABLES]
    if unknown or not names:
        raise argparse.ArgumentTypeError(f"{','.join(unknown) or 'none'} (choose from {','.join(TABLES)})")
    return names


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("report", help="the JSON written by pcd_compare --json")
    parser.add_argument("--csv", help="also write one CSV line per file and method here")
    parser.add_argument("--tables", type=table_list, default=TABLES,
                        help=f"the tables to print, comma-separated; they come in this order whatever the "
                             f"order given (default: {','.join(TABLES)})")
    args = parser.parse_args()
    configuration, scenes = read_report(args.report)
    if args.csv:
        write_atomically(args.csv, csv_report(scenes))
    sys.stdout.write((configuration_list(configuration) if "configuration" in args.tables else "")
                     + "".join(RENDER[name](scenes) for name in TABLES[1:] if name in args.tables))


if __name__ == "__main__":
    main()

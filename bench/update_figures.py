#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Writes today's figures into bench/README.md and the README's speed sentence, from one run,
so that no figure there is typed by hand. Each generated part sits between a pair of markers
(<!-- figures:NAME begin --> ... <!-- figures:NAME end -->) and is replaced whole; the text
around it is left alone.

Inputs:
  --speed JSON     bench_segmentation --benchmark_filter='^interleaved/real'
                   --benchmark_out=JSON (OMPS and floodplane at s = 1, 2, 4 in one process);
                   fills "speed" (a row per frame and the medians) and the README's "speed".
  --report JSON    pcd_compare --methods floodplane/1,floodplane/2,floodplane/4 --json on the
                   report split; fills "accuracy" (mean IoU / Hoover correct share / false-plane
                   fraction per factor and sensor model).
  --quirks JSON    the same on the report split rendered with the sensor quirks; fills
                   "accuracy-quirks".
  --phases JSON    bench_segmentation --benchmark_filter='^floodplane/phases4?/(real|scene|exact):'
                   --benchmark_out=JSON (may be the --speed run's file, one run for both);
                   fills "phases": ms and share per phase, the default and s = 1, on the real
                   frames and the bundled scenes (Kinect noise and exact).
  --resolution JSON  bench/resolution_sweep.py --json (boxes_on_floor at 320x240 to 2560x1920,
                   s = 1 and the default s = 4, each benchmark in a process of its own); fills
                   "resolution" (time, time per pixel, memory added against the cloud's size).
  --chart PNG      draws the speed-against-accuracy chart (bench/speed_accuracy_chart.py,
                   matplotlib) into PNG: a panel per pcd_compare run, those of --report and
                   --quirks and each --chart-run TITLE=JSON (pcd_compare --json on another data
                   set: the bundled scenes, the real frames); fills "chart" with the image and
                   the runs it was drawn from.
  --objects JSON   pcd_compare --objects --json on the mOSD learn half (../shared/data/osd-learn);
                   fills "objects" (a row per object method: the object scores of
                   ../shared/tools/osd_scores.py --objects, objects a frame, ms).
  --peers DIR      bench/peers.sh's folder (CAPE and PEAC beside floodplane: speed.md, the table of
                   ../shared/peers/side_by_side.sh, and osd_<method>.json, osd_scores.py --json of each
                   method's labels of the mOSD learn frames); fills "peers" of docs/results.md (the
                   tables, and where a peer is ahead, said) and the README's "peers" sentence.
Any one of them may be given alone. --dry-run prints the parts instead of writing.

Example:
  build/bench/bench_segmentation --benchmark_filter='^interleaved/real' --benchmark_min_time=3 \\
      --benchmark_out=speed.json
  bench/update_figures.py --speed speed.json --report report.json --quirks report_quirks.json
  bench/update_figures.py --chart bench/figures/speed_accuracy.png \\
      --chart-run "bundled scenes=scenes.json" --chart-run "real frames=real.json"
"""

import argparse
import datetime
import json
import os
import pathlib
import re
import statistics
import subprocess
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import compare_tables  # noqa: E402  (the report reader is shared)
import resolution_sweep  # noqa: E402  (its table is shared)
import speed_accuracy_chart  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parent.parent
BENCH_README = ROOT / "bench" / "README.md"
README = ROOT / "README.md"
RESULTS = ROOT / "docs" / "results.md"
FACTORS = [("floodplane/1", "s = 1"), ("floodplane/2", "s = 2"), ("floodplane/4", "s = 4 (the default)")]
SENSORS = [("none", "exact"), ("kinect", "Kinect"), ("scanner", "scanner")]
SPEED_COLUMNS = ["omps_ms", "s1_ms", "s2_ms", "s4_ms", "omps_per_s2", "omps_per_s4", "s2_per_s1", "s4_per_s1"]
SPEED_COUNTERS = SPEED_COLUMNS + ["omps_per_s1"]  # the table's columns and the README sentence's ratio


class Unusable(Exception):
    """An input that cannot give its figures; the message says which and why."""


def commit():
    try:
        return subprocess.check_output(["git", "-C", str(ROOT), "rev-parse", "--short", "HEAD"], text=True,
                                       stderr=subprocess.DEVNULL).strip()
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def stamp(run_date):
    return f"{run_date}, main at `{commit()}`"


# Speed ---------------------------------------------------------------------------------------

def read_benchmark_run(path):
    """A Google Benchmark run's JSON, from --benchmark_out's file or bench_segmentation's stdout."""
    try:
        text = pathlib.Path(path).read_text(encoding="utf-8")
        # bench_segmentation prints its configuration before the JSON on stdout (--benchmark_out
        # writes the JSON alone): the run starts at the first line that opens an object.
        start = re.search(r"^\{", text, re.MULTILINE)
        return json.loads(text[start.start():] if start else text)
    except (OSError, ValueError) as error:
        raise Unusable(f"{path}: {error}") from error


def benchmark_date(run):
    """The run's date and time to the minute, as its context gives it."""
    return str(run.get("context", {}).get("date", ""))[:16].replace("T", " ") or "unknown date"


def read_speed(path):
    """frame -> counters of the interleaved benchmark, and the run's date."""
    run = read_benchmark_run(path)
    frames = {}
    for entry in run.get("benchmarks", []) if isinstance(run, dict) else []:
        name = entry.get("name", "")
        match = re.match(r"interleaved/real:([^/]+)", name)
        if not match or entry.get("run_type", "iteration") != "iteration":
            continue
        missing = [c for c in SPEED_COUNTERS if not isinstance(entry.get(c), (int, float))]
        if missing:
            raise Unusable(f"{path}: {name} has no {', '.join(missing)}")
        frames[match.group(1)] = {c: float(entry[c]) for c in SPEED_COUNTERS}
    if not frames:
        raise Unusable(f"{path}: no interleaved/real:<frame> benchmark (run with "
                       "--benchmark_filter='^interleaved/real' --benchmark_out=FILE)")
    run_date = benchmark_date(run)
    return frames, run_date


def short(frame):
    # frame_20121214T142255.814212 -> frame_...255.814212, as the tables have always named them.
    return re.sub(r"^frame_\d{8}T\d{3}", "frame_...", frame)


def speed_table(frames, run_date):
    medians = {c: statistics.median(f[c] for f in frames.values()) for c in SPEED_COUNTERS}
    out = (f"Run {stamp(run_date)}; medians over the frames of per-frame figures:\n\n"
           "| frame | OMPS ms | s = 1 ms | s = 2 ms | s = 4 ms | OMPS / s2 | OMPS / s4 | s2 / s1 | s4 / s1 |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n")
    for frame in sorted(frames):
        f = frames[frame]
        out += (f"| {short(frame)} | " + " | ".join(f"{f[c]:.1f}" for c in SPEED_COLUMNS[:6]) + " | "
                + " | ".join(f"{f[c]:.2f}" for c in SPEED_COLUMNS[6:]) + " |\n")
    out += ("| **median** | " + " | ".join(f"{medians[c]:.1f}" for c in SPEED_COLUMNS[:4]) + " | "
            + " | ".join(f"**{medians[c]:.1f}**" for c in SPEED_COLUMNS[4:6]) + " | "
            + " | ".join(f"**{medians[c]:.2f}**" for c in SPEED_COLUMNS[6:]) + " |\n")
    return out, medians


def speed_sentence(medians):
    return (f"takes a median {medians['s4_ms']:.1f} ms at the default, sub-sampling 4 ({medians['omps_per_s4']:.1f}x "
            f"faster than OMPS with its normals, in the same run), {medians['s2_ms']:.1f} ms at sub-sampling 2 and "
            f"{medians['s1_ms']:.1f} ms at sub-sampling 1 ({medians['omps_per_s1']:.1f}x OMPS; figures from "
            "`bench/README.md`)")


# Phases --------------------------------------------------------------------------------------

PHASE_SETS = [("real", "real frames"), ("scene", "scenes, Kinect"), ("exact", "scenes, exact")]
PHASE_FACTORS = [("phases4", "default"), ("phases", "s = 1")]
# (row, the counters it adds up): the PCL glue is the class's own conversion and whatever of the
# call no phase holds.
PHASE_ROWS = [("preparation", ["prep_ms"]), ("seed selection", ["seed_ms"]), ("flood fill", ["flood_ms"]),
              ("relabelling", ["relabel_ms"]), ("merging", ["merge_ms"]), ("region output", ["output_ms"]),
              ("PCL glue", ["pcl_ms", "outside_ms"])]
PHASE_COUNTERS = sorted({c for _, counters in PHASE_ROWS for c in counters})


def read_phases(path):
    """(set, factor) -> frame -> counters of the floodplane/phases benchmarks, and the run's date."""
    run = read_benchmark_run(path)
    runs = {}
    for entry in run.get("benchmarks", []) if isinstance(run, dict) else []:
        name = entry.get("name", "")
        match = re.match(r"floodplane/(phases4?)/(real|scene|exact):([^/]+)$", name)
        if not match or entry.get("run_type", "iteration") != "iteration":
            continue
        missing = [c for c in PHASE_COUNTERS + ["real_time", "cpu_time"] if not isinstance(entry.get(c), (int, float))]
        if missing:
            raise Unusable(f"{path}: {name} has no {', '.join(missing)}")
        if entry.get("time_unit", "ms") != "ms":
            raise Unusable(f"{path}: {name} is not in ms")
        runs.setdefault((match.group(2), match.group(1)), {})[match.group(3)] = entry
    wanted = [(s, f) for s, _ in PHASE_SETS for f, _ in PHASE_FACTORS]
    if not any(key in runs for key in wanted):
        raise Unusable(f"{path}: no floodplane/phases4?/(real|scene|exact):<frame> benchmark (run with "
                       "--benchmark_filter='^floodplane/phases4?/(real|scene|exact):' --benchmark_out=FILE)")
    run_date = benchmark_date(run)
    return runs, run_date


def phase_table(runs, run_date):
    columns = [(s, f, f"{set_name}, {factor_name}") for s, set_name in PHASE_SETS for f, factor_name in PHASE_FACTORS
               if (s, f) in runs]
    out = (f"Run {stamp(run_date)}, phase timers on (`setMeasurePhases`); per phase the median over the "
           "frames of its ms a frame, and in brackets its share of all the frames' time; the PCL glue is "
           "the class's conversion and whatever of the call no phase holds. The phases are timed on the "
           "wall clock; the call's CPU time (last row) is what it took of the processor, less than the "
           "wall clock where other processes had the machine:\n\n"
           "| phase | " + " | ".join(title for _, _, title in columns) + " |\n"
           "|---|" + "---:|" * len(columns) + "\n")
    rows = PHASE_ROWS + [("**whole call**", "real_time"), ("CPU time of the call", "cpu_time")]
    for row, counters in rows:
        cells = []
        for s, f, _ in columns:
            frames = runs[(s, f)].values()
            calls = sum(e["real_time"] for e in frames)
            if isinstance(counters, str):
                median = statistics.median(e[counters] for e in frames)
                cells.append(f"**{median:.2f}**" if counters == "real_time" else f"{median:.2f}")
                continue
            values = [sum(max(0.0, e[c]) for c in counters) for e in frames]
            cells.append(f"{statistics.median(values):.2f} ({100.0 * sum(values) / calls:.0f} %)")
        out += f"| {row} | " + " | ".join(cells) + " |\n"
    counts = ", ".join(f"{title}: {len(runs[(s, f)])}" for s, f, title in columns)
    return out + f"\nFrames per column: {counts}.\n"


# Accuracy ------------------------------------------------------------------------------------

def accuracy_cells(scenes, method, sensor):
    """mean IoU / Hoover correct as a share of the ground-truth planes / false-plane fraction,
    over the files as pcd_compare's means count them (compare_tables.MeanRow)."""
    row = compare_tables.MeanRow()
    for scene in scenes:
        result = scene.find(method)
        if scene.sensor == sensor and result is not None:
            row.add(scene, result)
    if row.scored == 0:
        return "-"
    share = compare_tables.divide(row.sums["correct"], row.ground_truth_planes)
    return (f"{compare_tables.fixed(row.accuracy('mean_iou'), 3)} / {compare_tables.fixed(share, 3)} / "
            f"{compare_tables.fixed(row.false_plane_fraction(), 3)}")


def accuracy_table(path, what):
    _, scenes = compare_tables.read_report(path)
    sensors = [(key, title) for key, title in SENSORS if any(scene.sensor == key for scene in scenes)]
    methods = [(m, title) for m, title in FACTORS if any(scene.find(m) for scene in scenes)]
    if not sensors or not methods:
        raise Unusable(f"{path}: no floodplane results with a sensor model")
    files = max(sum(scene.sensor == key for scene in scenes) for key, _ in sensors)
    out = (f"{what}, {files} files per sensor model, {stamp(datetime.date.today().isoformat())}; mean IoU / "
           "Hoover correct as a share of the ground-truth planes / false-plane fraction:\n\n"
           "| | " + " | ".join(title for _, title in sensors) + " |\n|---|" + "---|" * len(sensors) + "\n")
    for method, title in methods:
        out += f"| {title} | " + " | ".join(accuracy_cells(scenes, method, key) for key, _ in sensors) + " |\n"
    return out


# The resolution sweep ----------------------------------------------------------------------------

def resolution_part(path):
    """The sweep's table (resolution_sweep.table) from its --json rows, with the run's stamp."""
    try:
        rows = {(row["s"], row["size"]): row for row in json.loads(pathlib.Path(path).read_text(encoding="utf-8"))}
        table = resolution_sweep.table(rows)
    except (OSError, ValueError, TypeError, KeyError) as error:
        raise Unusable(f"{path}: not the JSON of bench/resolution_sweep.py --json ({error!r})") from error
    date = datetime.date.fromtimestamp(pathlib.Path(path).stat().st_mtime).isoformat()
    return (f"Run {stamp(date)}; medians over the rounds, each benchmark in a process of its own; added: the "
            "peak memory the call adds to the process (VmHWM after it, over that before it):\n\n" + table + "\n")


# The objects (issue 59) -------------------------------------------------------------------------

# pcd_compare's object methods as the table names them; another method (--labels) by its name.
OBJECT_METHODS = {
    "floodplane": "floodplane (`floodplane`)",
    "pcl_organized": "PCL's organized pipeline (`pcl_organized`, the demo's settings)",
    "lccp": "LCCP (`lccp`, PCL's example's defaults)",
    "lccp_ec_sc": "LCCP (`lccp_ec_sc`, the example's `-ec -sc`)",
}
OBJECT_SCORES = ["object_iou", "objects_found", "under", "over", "support_in_objects"]


def objects_part(path):
    """The object methods' means of a pcd_compare --objects --json run, a row each in run order."""
    try:
        report = json.loads(pathlib.Path(path).read_text(encoding="utf-8"))
        means, scenes = report["means"], report["scenes"]
        rows = []
        for method, row in means.items():
            scores = [row[key] for key in OBJECT_SCORES]
            rows.append((method, scores, row["objects"], row["median_ms"], row["scenes"]))
    except (OSError, ValueError, TypeError, KeyError) as error:
        raise Unusable(f"{path}: not the JSON of pcd_compare --objects ({error!r})") from error
    if not rows or any(not isinstance(score, (int, float)) for _, scores, *_ in rows for score in scores):
        raise Unusable(f"{path}: no object scores (pcd_compare --objects on frames with object labels)")
    date = datetime.date.fromtimestamp(pathlib.Path(path).stat().st_mtime).isoformat()
    out = (f"Run {stamp(date)}, {len(scenes)} files; means over the files, ms the mean of each file's median "
           "time:\n\n| method | object_iou | found | under | over | table in objects | objects a frame | ms |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|\n")
    for method, scores, objects, ms, files in rows:
        if files != len(scenes):
            raise Unusable(f"{path}: {method} ran on {files} of the {len(scenes)} files")
        time = "-" if ms is None else f"{ms:.0f}"  # --labels rows: not run by pcd_compare
        out += (f"| {OBJECT_METHODS.get(method, method)} | " + " | ".join(f"{score:.3f}" for score in scores)
                + f" | {objects:.1f} | {time} |\n")
    return out


# The peers: CAPE and PEAC (bench/peers.sh) ------------------------------------------------------

PEERS = [("floodplane", "floodplane"), ("cape", "CAPE"), ("peac", "PEAC")]
# osd_scores.py's plane scores: (key, title, better, what a method better at it has): higher or
# lower is better, or None for a count with no better direction (box_faces: 2-3, the faces a
# camera sees of a box).
OSD_SCORES = [("table_iou", "table IoU", "higher", "a higher table IoU"),
              ("table_pieces", "table pieces", "lower", "the table in fewer pieces"),
              ("bleed", "bleed", "lower", "less bleed across objects"),
              ("box_cover", "box cover", "higher", "more of the boxes on planes"),
              ("box_faces", "box faces", None, ""),
              ("wall_on_plane", "can walls on planes", "lower", "less of the cans' walls on planes")]


def read_side_by_side(path):
    """frame -> {column: value} and the columns, from the markdown table side_by_side.sh printed."""
    try:
        lines = [line.strip() for line in pathlib.Path(path).read_text(encoding="utf-8").splitlines()]
    except OSError as error:
        raise Unusable(f"{path}: {error}") from error
    header = next((i for i, line in enumerate(lines) if line.startswith("| frame |")), None)
    if header is None:
        raise Unusable(f"{path}: no table of ../shared/peers/side_by_side.sh (| frame | floodplane ms | ...)")
    columns = [cell.strip() for cell in lines[header].strip("|").split("|")][1:]
    for needed in ("floodplane ms", "CAPE ms", "PEAC ms"):
        if needed not in columns:
            raise Unusable(f"{path}: its table has no column '{needed}'")
    frames = {}
    for line in lines[header + 2:]:
        if not line.startswith("|"):
            break
        cells = [cell.strip() for cell in line.strip("|").split("|")]
        try:
            frames[cells[0]] = {column: float(value) for column, value in zip(columns, cells[1:])}
        except ValueError as error:
            raise Unusable(f"{path}: {cells[0]}: {error}") from error
        if any(value != value for value in frames[cells[0]].values()):  # NaN: a runner failed
            raise Unusable(f"{path}: {cells[0]} has no time for every method (a runner failed)")
    if not frames:
        raise Unusable(f"{path}: its table has no frame")
    return frames, columns


def read_osd(path):
    try:
        means = json.loads(pathlib.Path(path).read_text(encoding="utf-8"))["means"]
        return {key: float(means[key]) for key, *_ in OSD_SCORES}, int(means["table_iou_frames"])
    except (OSError, ValueError, TypeError, KeyError) as error:
        raise Unusable(f"{path}: not the JSON of osd_scores.py --json ({error!r})") from error


def read_run_notes(directory):
    """bench/peers.sh's run.txt: key: value lines (commit, date, machine)."""
    try:
        text = (pathlib.Path(directory) / "run.txt").read_text(encoding="utf-8")
    except OSError as error:
        raise Unusable(f"{directory}: no run.txt of bench/peers.sh ({error})") from error
    return dict(line.split(": ", 1) for line in text.splitlines() if ": " in line)


def ahead(peer, scores, frames_ratio, instruction_ratio):
    """What the peer does better than floodplane, as phrases."""
    said = []
    if frames_ratio > 1.0:
        said.append(f"it is faster: floodplane takes {frames_ratio:.1f}x its time a frame (median over the frames)")
        if instruction_ratio is not None:
            said[-1] += f" and {instruction_ratio:.1f}x its instructions"
    for key, title, better, phrase in OSD_SCORES:
        if better is None:
            continue
        ours, theirs = scores["floodplane"][key], scores[peer][key]
        if round(theirs, 3) != round(ours, 3) and (theirs > ours) == (better == "higher"):
            said.append(f"{phrase} ({title} {theirs:.3f} against floodplane's {ours:.3f})")
    return said


def peers_parts(directory):
    """docs/results.md's peers tables and the README's sentence, from one bench/peers.sh run."""
    directory = pathlib.Path(directory)
    notes = read_run_notes(directory)
    frames, columns = read_side_by_side(directory / "speed.md")
    scores, osd_frames = {}, {}
    for method, _ in PEERS:
        scores[method], osd_frames[method] = read_osd(directory / f"osd_{method}.json")
    if len(set(osd_frames.values())) != 1:
        raise Unusable(f"{directory}: the methods were scored on different numbers of frames ({osd_frames})")
    with_instructions = "floodplane M instr" in columns and "CAPE M instr" in columns
    # The ratios as side_by_side.sh computed them per frame (from unrounded figures), when it gave them.
    for f in frames.values():
        f.setdefault("x CAPE", f["floodplane ms"] / f["CAPE ms"])
        f.setdefault("x PEAC", f["floodplane ms"] / f["PEAC ms"])
        if with_instructions:
            f.setdefault("instr x CAPE", f["floodplane M instr"] / f["CAPE M instr"])
    ratio = {peer: statistics.median(f[f"x {title}"] for f in frames.values()) for peer, title in PEERS[1:]}
    instructions = statistics.median(f["instr x CAPE"] for f in frames.values()) if with_instructions else None
    date = notes.get("date", "unknown date")
    titles = ["frame", "floodplane ms", "CAPE ms", "PEAC ms", "floodplane / CAPE", "floodplane / PEAC"]
    if with_instructions:
        titles += ["floodplane M instr", "CAPE M instr", "instr / CAPE"]
    out = (f"Run {date}, floodplane at `{notes.get('floodplane commit', '?')}`, by `bench/peers.sh` "
           f"({notes.get('machine', 'machine unknown')}). Speed: each method's median ms a frame over the "
           "interleaved rounds of `../shared/peers/side_by_side.sh`, each method in a process of its own, one thread"
           + ("; the instructions of floodplane's `segmentAndRefine` and CAPE's `process` (callgrind)"
              if with_instructions else "") + ":\n\n"
           "| " + " | ".join(titles) + " |\n|---|" + "---:|" * (len(titles) - 1) + "\n")
    for frame in sorted(frames):
        f = frames[frame]
        cells = [f"{f['floodplane ms']:.2f}", f"{f['CAPE ms']:.2f}", f"{f['PEAC ms']:.2f}",
                 f"{f['x CAPE']:.2f}", f"{f['x PEAC']:.2f}"]
        if with_instructions:
            cells += [f"{f['floodplane M instr']:.1f}", f"{f['CAPE M instr']:.1f}", f"{f['instr x CAPE']:.2f}"]
        out += f"| {short(frame)} | " + " | ".join(cells) + " |\n"
    medians = [f"{statistics.median(f[c] for f in frames.values()):.2f}" for c in ("floodplane ms", "CAPE ms", "PEAC ms")]
    medians += [f"**{ratio['cape']:.2f}**", f"**{ratio['peac']:.2f}**"]
    if with_instructions:
        medians += [f"{statistics.median(f[c] for f in frames.values()):.1f}"
                    for c in ("floodplane M instr", "CAPE M instr")]
        medians += [f"**{instructions:.2f}**"]
    out += "| **median** | " + " | ".join(medians) + " |\n"
    out += (f"\nAccuracy on the {osd_frames['floodplane']} real Kinect frames of `../shared/data/osd-learn` "
            "(`../shared/tools/osd_scores.py`, each method's labels written by the same runners at their defaults; "
            "box cover and box faces on the box frames, can walls on the cylinder frames):\n\n"
            "| method | " + " | ".join(title for _, title, *_ in OSD_SCORES) + " |\n|---|"
            + "---:|" * len(OSD_SCORES) + "\n")
    for method, title in PEERS:
        out += f"| {title} | " + " | ".join(f"{scores[method][key]:.3f}" for key, *_ in OSD_SCORES) + " |\n"
    out += "\nWhere a peer is ahead of floodplane in this run:\n\n"
    for peer, title in PEERS[1:]:
        said = ahead(peer, scores, ratio[peer], instructions if peer == "cape" else None)
        out += f"- {title}: " + ("; ".join(said) if said else "nowhere") + ".\n"
    quicker = [title for peer, title in PEERS[1:] if ratio[peer] > 1.0]
    verdict = {0: "neither is faster", 1: f"{quicker[0] if quicker else ''} is faster", 2: "both are faster"}[len(quicker)]
    f_, c_, p_ = (scores[m] for m, _ in PEERS)
    sentence = (f"on the 7 real Kinect frames floodplane takes {ratio['cape']:.1f}x CAPE's time a frame"
                + (f" ({instructions:.1f}x its instructions)" if with_instructions else "")
                + f" and {ratio['peac']:.1f}x PEAC's: {verdict}; on the {osd_frames['floodplane']} mOSD frames the "
                f"table IoU is {f_['table_iou']:.3f} (CAPE {c_['table_iou']:.3f}, PEAC {p_['table_iou']:.3f}) and "
                f"the share of the boxes on planes {f_['box_cover']:.3f} (CAPE {c_['box_cover']:.3f}, PEAC "
                f"{p_['box_cover']:.3f}); one run, {date[:10]}, "
                "[docs/results.md](docs/results.md#the-fast-peers-cape-and-peac)")
    return out, sentence


# The chart ------------------------------------------------------------------------------------

def run_description(title, path):
    """One run of the chart's caption: its title, files, methods and timing, from its JSON."""
    configuration, scenes = compare_tables.read_report(path)
    methods = ", ".join(compare_tables.method_order(scenes))
    timing = str(configuration.get("timing", "")).split(", of the segmentation call")[0]
    return f"{title}: {len(scenes)} files, {methods}" + (f"; {timing}" if timing else "")


def chart_caption(chart, bench_readme, descriptions):
    link = os.path.relpath(chart, pathlib.Path(bench_readme).resolve().parent)
    return (f"![Speed against accuracy of each method, a panel per data set]({link})\n\n"
            f"Drawn {stamp(datetime.date.today().isoformat())} by `bench/update_figures.py --chart` from "
            "pcd_compare's JSON of " + "; ".join(descriptions) + ".\n")


def chart_runs(args):
    """The (title, JSON) of each panel: --chart-run's, then --report's and --quirks'."""
    runs = list(args.chart_run or [])
    if args.report:
        runs.append(("report split", args.report))
    if args.quirks:
        runs.append(("report split with the quirks", args.quirks))
    return runs


# Writing -------------------------------------------------------------------------------------

def replace_part(text, name, body, path):
    begin, end = f"<!-- figures:{name} begin -->", f"<!-- figures:{name} end -->"
    pattern = re.compile(re.escape(begin) + r".*?" + re.escape(end), re.DOTALL)
    if len(pattern.findall(text)) != 1:
        raise Unusable(f"{path} has no single pair of markers {begin} ... {end}")
    inline = "\n" not in body
    replacement = f"{begin}{body}{end}" if inline else f"{begin}\n{body}{end}"
    return pattern.sub(lambda _: replacement, text)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("--speed", help="Google Benchmark JSON of interleaved/real")
    parser.add_argument("--report", help="pcd_compare JSON of the report split")
    parser.add_argument("--quirks", help="pcd_compare JSON of the report split with the sensor quirks")
    parser.add_argument("--phases", help="Google Benchmark JSON of floodplane/phases4?/(real|scene|exact)")
    parser.add_argument("--resolution", help="bench/resolution_sweep.py --json of the resolution sweep")
    parser.add_argument("--chart", help="draw the speed-against-accuracy chart into this PNG "
                                        "(bench/figures/speed_accuracy.png)")
    parser.add_argument("--chart-run", action="append", type=speed_accuracy_chart.titled_run, metavar="TITLE=JSON",
                        help="a pcd_compare run of another data set, a panel of --chart's (repeatable)")
    parser.add_argument("--objects", help="pcd_compare --objects JSON of the mOSD learn half")
    parser.add_argument("--peers", metavar="DIR", help="bench/peers.sh's folder: CAPE and PEAC beside floodplane")
    parser.add_argument("--bench-readme", default=str(BENCH_README), help="the page to update")
    parser.add_argument("--results", default=str(RESULTS), help="the results page whose peers part to update")
    parser.add_argument("--readme", default=str(README), help="the README whose speed sentence to update")
    parser.add_argument("--dry-run", action="store_true", help="print the parts, write nothing")
    args = parser.parse_args()
    if args.chart_run and not args.chart:
        parser.error("--chart-run gives a panel of the chart: give --chart PNG too")
    if not (args.speed or args.phases or args.report or args.quirks or args.resolution or args.chart or args.objects
            or args.peers):
        parser.error("give at least one of --speed, --phases, --report, --quirks, --resolution, --chart, --objects, "
                     "--peers")
    if args.chart and not chart_runs(args):
        parser.error("--chart needs a pcd_compare run: --chart-run TITLE=JSON, --report or --quirks")
    try:
        bench_parts, readme_parts, results_parts = {}, {}, {}
        if args.speed:
            frames, run_date = read_speed(args.speed)
            bench_parts["speed"], medians = speed_table(frames, run_date)
            readme_parts["speed"] = speed_sentence(medians)
        if args.phases:
            bench_parts["phases"] = phase_table(*read_phases(args.phases))
        if args.report:
            bench_parts["accuracy"] = accuracy_table(args.report, "Report split (seeds 101-200, never tuned on)")
        if args.quirks:
            bench_parts["accuracy-quirks"] = accuracy_table(
                args.quirks, "Report split with the quirks (--quantize-bits 9 --warp 3 --speckle --bend 0.02)")
        if args.resolution:
            bench_parts["resolution"] = resolution_part(args.resolution)
        if args.objects:
            bench_parts["objects"] = objects_part(args.objects)
        if args.peers:
            results_parts["peers"], readme_parts["peers"] = peers_parts(args.peers)
        panels = []
        if args.chart:
            runs = chart_runs(args)
            panels = [speed_accuracy_chart.read_panel(title, path) for title, path in runs]
            bench_parts["chart"] = chart_caption(pathlib.Path(args.chart).resolve(), args.bench_readme,
                                                 [run_description(title, path) for title, path in runs])
            try:
                import matplotlib  # noqa: F401  (checked before anything is written)
            except ImportError as error:
                raise Unusable(f"--chart needs matplotlib ({error}); Debian: python3-matplotlib") from error
        if args.dry_run:
            for name, body in {**bench_parts, **{f"README {k}": v for k, v in readme_parts.items()},
                               **{f"results {k}": v for k, v in results_parts.items()}}.items():
                print(f"--- {name}\n{body}")
            return 0
        updates = []
        for path, parts in ((pathlib.Path(args.bench_readme), bench_parts), (pathlib.Path(args.readme), readme_parts),
                            (pathlib.Path(args.results), results_parts)):
            if not parts:
                continue
            text = path.read_text(encoding="utf-8")
            for name, body in parts.items():
                text = replace_part(text, name, body, path)
            updates.append((path, text, sorted(parts)))
        # Every file is checked before any is written.
        if args.chart:
            speed_accuracy_chart.draw(panels, args.chart)
            print(f"update_figures.py: the chart drawn into {args.chart}")
        for path, text, names in updates:
            compare_tables.write_atomically(path, text)
            print(f"update_figures.py: {', '.join(names)} written into {path}")
    except (Unusable, speed_accuracy_chart.Unusable, OSError) as error:
        print(f"update_figures.py: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

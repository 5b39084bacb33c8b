#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Real scans scored as SegComp scores them (issue 46): the ten ABW structured-light scans of
../shared/data/abw-tune (README there), segmented and compared by pcd_compare with ground-truth
regions of at least 100 pixels (--min-gt-points 100, SegComp's size) and Hoover's T = 0.8.
Prints, per method, the correct detections over the ground-truth regions of all ten frames (%),
the mean IoU over those regions, and the regions that are not correct detections by class
(pcd_compare --misses: no_segment, under_segmented, over_segmented, iou_below_t) and size.

The scans stay where they are: nothing of them (files, labels, figures) is written into the
project; the intermediate files go to a temporary directory. Without the folder the script
says so and exits with 77 (skipped), as a test would.

Flags after `--` go to pcd_segment, whose labels of the ten scans are then scored as one more
row, `pcd_segment` (pcd_compare's own floodplane row runs the defaults), so that a setting is
judged region by region against them:

  bench/abw_scores.py build                                # the defaults
  bench/abw_scores.py build --list                         # ... and every region not found
  bench/abw_scores.py build -- --depth-noise-constant 0.001
  bench/abw_scores.py build --methods floodplane,floodplane/2,omps
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_common import ROOT, machine, run_or_exit  # noqa: E402

DATA = ROOT.parent / "shared/data/abw-tune"
MIN_GT_POINTS = 100  # SegComp's minimum region size [pixels]
TOLERANCE = 0.8  # Hoover's T, pcd_compare's
SKIPPED = 77  # the exit code of a skipped test (ctest's SKIP_RETURN_CODE, automake)
MISSES = ("no_segment", "under_segmented", "over_segmented", "iou_below_t")
SIZE_BINS = ((100, 1000), (1000, 3000), (3000, 10000), (10000, None))
SEGMENT_ROW = "pcd_segment"


def bin_name(low, high):
    return f">= {low:,}" if high is None else f"{low:,}-{high - 1:,}"


def size_bin(pixels):
    """The SIZE_BINS entry holding `pixels`; regions under the first bin's low end go to it."""
    for low, high in SIZE_BINS:
        if high is None or pixels < high:
            return (low, high)
    raise AssertionError("unreachable")


def scans(folder):
    """The scans of `folder` (abw.test.N.pcd) in frame order, or a reason why there are none."""
    folder = pathlib.Path(folder)
    if not folder.is_dir():
        return [], f"{folder} not found (the ABW tuning scans live beside the project, never in it)"
    files = sorted(folder.glob("abw.test.*.pcd"), key=lambda path: int(path.name.split(".")[2]))
    return files, (None if files else f"no abw.test.*.pcd in {folder}")


def summarize(report):
    """Per method (report order): regions, correct detections, mean IoU over the regions,
    counts by miss class and size bin, the noise segments, and every region not found."""
    methods = {}
    for scene in report["scenes"]:
        for method, result in scene["methods"].items():
            if "per_plane" not in result:
                continue
            row = methods.setdefault(method, {"regions": 0, "correct": 0, "iou_sum": 0.0, "noise": 0,
                                              "bins": {b: dict.fromkeys(("regions", "correct") + MISSES, 0)
                                                       for b in SIZE_BINS},
                                              "misses": []})
            row["noise"] += len(result["noise_segments"])
            for plane in result["per_plane"]:
                cell = row["bins"][size_bin(plane["pixels"])]
                row["regions"] += 1
                row["iou_sum"] += plane["iou"]
                cell["regions"] += 1
                if plane["miss"] is None:
                    row["correct"] += 1
                    cell["correct"] += 1
                    continue
                cell[plane["miss"]] += 1
                row["misses"].append(dict(plane, file=scene["name"]))
    for row in methods.values():
        row["mean_iou"] = row["iou_sum"] / row["regions"] if row["regions"] else float("nan")
        del row["iou_sum"]
    return methods


def markdown(methods):
    out = []
    for method, row in methods.items():
        share = 100.0 * row["correct"] / row["regions"] if row["regions"] else float("nan")
        out.append(f"### {method}: {row['correct']} of {row['regions']} regions correct ({share:.1f} %), "
                   f"mean IoU {row['mean_iou']:.3f}, {row['noise']} noise segments\n")
        out.append("| region pixels | regions | correct | " + " | ".join(MISSES) + " |")
        out.append("|---|" + "---:|" * (2 + len(MISSES)))
        total = dict.fromkeys(("regions", "correct") + MISSES, 0)
        for size in SIZE_BINS:
            cell = row["bins"][size]
            out.append(f"| {bin_name(*size)} | " + " | ".join(str(cell[k]) for k in total) + " |")
            for key in total:
                total[key] += cell[key]
        out.append("| all | " + " | ".join(str(total[k]) for k in total) + " |\n")
    return "\n".join(out)


def listing(methods):
    out = []
    for method, row in methods.items():
        out.append(f"### {method}: the regions not found\n")
        out.append("| file | region | class | pixels | IoU | unlabelled |")
        out.append("|---|---:|---|---:|---:|---:|")
        for plane in sorted(row["misses"], key=lambda p: (p["miss"], -p["pixels"])):
            out.append(f"| {plane['file']} | {plane['label']} | {plane['miss']} | {plane['pixels']} | "
                       f"{plane['iou']:.2f} | {100.0 * plane['unlabelled_share']:.0f} % |")
        out.append("")
    return "\n".join(out)


def shown(command, files):
    """`command` as text, the scans' paths as SCANS (listed above it)."""
    words = [str(word) for word in command if word not in files]
    return " ".join(words[:1] + ["SCANS"] + words[1:])


def git_commit():
    completed = subprocess.run(["git", "-C", str(ROOT), "describe", "--always", "--dirty"], capture_output=True,
                               text=True)
    return completed.stdout.strip() or "unknown"


def parse_arguments(argv):
    segment_flags = []
    if "--" in argv:
        at = argv.index("--")
        argv, segment_flags = argv[:at], argv[at + 1:]
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter, epilog=__doc__)
    parser.add_argument("build", type=pathlib.Path, help="the build directory (its apps/pcd_compare, apps/pcd_segment)")
    parser.add_argument("--methods", default="floodplane",
                        help="pcd_compare's --methods, comma-separated (default floodplane)")
    parser.add_argument("--data", type=pathlib.Path, default=DATA, help=f"the scans' folder (default {DATA})")
    parser.add_argument("--list", action="store_true", help="also list every region not found, by class")
    parser.add_argument("--json", type=pathlib.Path, help="also write pcd_compare's report (every frame and region) "
                                                          "to this file, outside the project")
    arguments = parser.parse_args(argv)
    arguments.segment_flags = segment_flags
    if not arguments.methods:
        parser.error("--methods names no method")
    return arguments


def main(argv):
    arguments = parse_arguments(argv)
    files, problem = scans(arguments.data)
    if problem:
        print(f"abw_scores.py: skipped: {problem}", file=sys.stderr)
        return SKIPPED
    pcd_compare = arguments.build / "apps/pcd_compare/pcd_compare"
    pcd_segment = arguments.build / "apps/pcd_segment/pcd_segment"
    for binary in [pcd_compare] + ([pcd_segment] if arguments.segment_flags else []):
        if not binary.is_file():
            sys.exit(f"abw_scores.py: {binary} not found: build it (cmake --build {arguments.build} "
                     f"--target {binary.name})")
    with tempfile.TemporaryDirectory(prefix="abw_scores.") as temporary:
        temporary = pathlib.Path(temporary)
        report_file = arguments.json or temporary / "report.json"
        compare = [pcd_compare, *files, "--methods", arguments.methods, "--min-gt-points", MIN_GT_POINTS, "--repeat", 0,
                   "-q", "--json", report_file]
        segment = []
        if arguments.segment_flags:
            segment = [pcd_segment, *files, "-o", temporary / "labels", "-q", *arguments.segment_flags]
            compare += ["--labels", f"{SEGMENT_ROW}={temporary / 'labels'}"]
        print("# ABW scores\n")
        print(f"- machine: {machine()}")
        print(f"- source: {ROOT} at {git_commit()}")
        print(f"- scans (SCANS): {' '.join(path.name for path in files)} in {arguments.data}")
        print(f"- scoring: ground-truth regions and segments of at least {MIN_GT_POINTS} pixels, Hoover T = "
              f"{TOLERANCE}; correct detections over all regions of all frames, mean IoU over the same regions")
        if segment:
            print(f"- {SEGMENT_ROW} row: `{shown(segment, files)}`")
            run_or_exit(segment)
        print(f"- `{shown(compare, files)}`\n")
        run_or_exit(compare)
        methods = summarize(json.loads(pathlib.Path(report_file).read_text()))
    print(markdown(methods))
    if arguments.list:
        print(listing(methods))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""The resolution sweep (bench_segmentation's resolution/ benchmarks): boxes_on_floor with
Kinect noise at 320x240 to 2560x1920, floodplane at s = 1 and s = 4. Each benchmark runs in a
process of its own, so that the memory a call adds to the process is its own. Rounds alternate
the order of the benchmarks; the figures are medians over the rounds.

Prints a table: per size and setting the time of a call, the time per pixel and its ratio to
that at 640x480, the memory the segmentation adds and its ratio to the cloud's own size.
With --json, writes the rows for bench/update_figures.py --resolution.

Example:
  bench/resolution_sweep.py build/bench/bench_segmentation --rounds 3 --json resolution.json
"""

import argparse
import json
import re
import statistics
import subprocess
import sys

SIZES = ["320x240", "640x480", "1280x960", "2560x1920"]
SETTINGS = [1, 4]


def run_one(binary, name, min_time):
    """The counters of one benchmark, run alone in its own process."""
    command = [binary, f"--benchmark_filter=^{name}$", f"--benchmark_min_time={min_time}", "--benchmark_format=json"]
    try:
        out = subprocess.run(command, capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as error:
        sys.exit(f"resolution_sweep.py: {' '.join(command)} failed: {error}")
    # bench_segmentation prints its configuration before the JSON: the run starts at the first
    # line that opens an object.
    start = re.search(r"^\{", out, re.MULTILINE)
    try:
        run = json.loads(out[start.start():] if start else out)
    except ValueError as error:
        sys.exit(f"resolution_sweep.py: {' '.join(command)} printed no JSON: {error}")
    runs = [b for b in run.get("benchmarks", []) if b.get("run_type", "iteration") == "iteration"]
    if not runs:
        sys.exit(f"resolution_sweep.py: {binary} has no benchmark {name}")
    return runs[0]


def sweep(binary, rounds, min_time, progress=sys.stderr):
    """{(s, size): {ms, ns_per_px, added_MiB, cloud_MiB, added_per_cloud}}, medians over the rounds."""
    names = [(s, size) for s in SETTINGS for size in SIZES]
    samples = {key: [] for key in names}
    for r in range(rounds):
        order = names if r % 2 == 0 else list(reversed(names))
        for s, size in order:
            print(f"resolution_sweep: round {r + 1} of {rounds}, s = {s}, {size}", file=progress)
            samples[(s, size)].append(run_one(binary, f"resolution/s{s}/{size}", min_time))
    rows = {}
    for key, runs in samples.items():
        rows[key] = {
            "ms": statistics.median(b["real_time"] for b in runs),
            "ns_per_px": statistics.median(b["ns_per_px"] for b in runs),
            "added_MiB": statistics.median(b["added_MiB"] for b in runs),
            "cloud_MiB": runs[0]["cloud_MiB"],
            "added_per_cloud": statistics.median(b["added_per_cloud"] for b in runs),
        }
    return rows


def table(rows):
    """The sweep as a Markdown table."""
    lines = ["| size | s | ms | ns / pixel | / 640x480 | added MiB | cloud MiB | added / cloud |",
             "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for s in SETTINGS:
        base = rows[(s, "640x480")]["ns_per_px"]
        for size in SIZES:
            r = rows[(s, size)]
            lines.append(f"| {size} | {s} | {r['ms']:.1f} | {r['ns_per_px']:.1f} | {r['ns_per_px'] / base:.2f} | "
                         f"{r['added_MiB']:.0f} | {r['cloud_MiB']:.0f} | {r['added_per_cloud']:.2f} |")
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary", help="bench_segmentation (built with -DFLOODPLANE_BUILD_BENCHMARKS=ON)")
    parser.add_argument("--rounds", type=int, default=3, help="processes per benchmark (default: %(default)s)")
    parser.add_argument("--min-time", type=float, default=1.0, help="seconds per benchmark (default: %(default)s)")
    parser.add_argument("--json", help="write the rows to this file")
    args = parser.parse_args()
    if args.rounds < 1:
        sys.exit("resolution_sweep.py: --rounds must be at least 1")
    rows = sweep(args.binary, args.rounds, args.min_time)
    print(table(rows))
    if args.json:
        with open(args.json, "w", encoding="utf-8") as out:
            json.dump([{"s": s, "size": size, **row} for (s, size), row in rows.items()], out, indent=1)


if __name__ == "__main__":
    main()

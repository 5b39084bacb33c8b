#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Before/after timing of two builds of bench_segmentation on a shared, noisy machine: the two
binaries run one after the other, alternating which goes first, for several rounds; each
benchmark's median over the rounds is compared. Prints a line per benchmark (median before,
after, after / before) and the median of the ratios.

Example (the session's starting commit built in ../before):
  bench/interleaved.py ../before/bench/bench_segmentation build/bench/bench_segmentation \\
      --filter 'floodplane/(s1|s2)/real' --rounds 8
"""

import argparse
import collections
import csv
import io
import statistics
import subprocess
import sys


def run(binary, pattern, min_time):
    """{benchmark name: real time} of one run of `binary`."""
    try:
        out = subprocess.run([binary, f"--benchmark_filter={pattern}", f"--benchmark_min_time={min_time}",
                              "--benchmark_format=csv"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as error:
        sys.exit(f"interleaved.py: {binary} failed: {error}")
    start = out.find("name,")
    if start < 0:
        sys.exit(f"interleaved.py: {binary} ran no benchmark matching {pattern!r}")
    return {row["name"]: float(row["real_time"]) for row in csv.DictReader(io.StringIO(out[start:]))}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("before", help="bench_segmentation of the baseline")
    parser.add_argument("after", help="bench_segmentation of the change")
    parser.add_argument("--filter", default="floodplane/s1/real", help="benchmark regex (default: %(default)s)")
    parser.add_argument("--rounds", type=int, default=8, help="rounds of both binaries (default: %(default)s)")
    parser.add_argument("--min-time", type=float, default=0.3,
                        help="seconds per benchmark and run (default: %(default)s)")
    args = parser.parse_args()
    if args.rounds < 1:
        parser.error("--rounds must be at least 1")

    times = {"before": collections.defaultdict(list), "after": collections.defaultdict(list)}
    for round_ in range(args.rounds):
        order = [("before", args.before), ("after", args.after)]
        for tag, binary in order if round_ % 2 == 0 else reversed(order):
            for name, ms in run(binary, args.filter, args.min_time).items():
                times[tag][name].append(ms)
        print(f"round {round_ + 1} of {args.rounds} done", file=sys.stderr)

    ratios = []
    for name, before in times["before"].items():
        if name not in times["after"]:
            continue
        b, a = statistics.median(before), statistics.median(times["after"][name])
        ratios.append(a / b)
        print(f"{name:60s} before {b:9.3f} after {a:9.3f} after/before {a / b:.3f}")
    if not ratios:
        sys.exit("interleaved.py: the two binaries have no benchmark in common")
    print(f"median of {len(ratios)} ratios {statistics.median(ratios):.3f} (min {min(ratios):.3f}, max {max(ratios):.3f})")


if __name__ == "__main__":
    main()

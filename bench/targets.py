#!/usr/bin/python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Issue 16's speed targets from one run of bench_segmentation: every figure of the table comes
from the same run (one thread; on a shared machine only figures of one run compare), printed
as Markdown with the machine and, per target, the figure and whether it is met.

Targets (issue 16): median <= 1.0 ms over the real frames at full resolution and no frame above
2 ms; at least 50x PCL OMPS (with its normals) in the same run; sub-sampling 2 <= 0.5 ms and
faster than sub-sampling 1 on every frame; ms per megapixel roughly constant from 320x240 to
3840x2160 (taken here as: within 1.5x); phases add up (the time outside every named phase at
most 2 % of a call on every frame). The memory floor (one pass reading every point and writing
a label, `floor/`) is printed beside them: what no pixel-accurate method can go below.

Example:
  bench/targets.py build/bench/bench_segmentation --save bench/results/targets.json
  bench/targets.py --json bench/results/targets.json      # the table of an earlier run
"""

import argparse
import json
import os
import pathlib
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from bench_common import ROOT  # noqa: E402

FILTER = r"^(floodplane/(s1|s2|phases)/real|omps/real|floodplane/s1/size|floor/)"
SIZES = ["320x240", "640x480", "1280x960", "1920x1080", "3840x2160"]  # kFrameSizes of bench_frames.h


def megapixels(size):
    width, height = size.split("x")
    return int(width) * int(height) * 1e-6


def run(binary, min_time, save):
    """Runs the target benchmarks once; returns Google Benchmark's JSON (also written to `save`)."""
    with tempfile.TemporaryDirectory() as scratch:
        out = pathlib.Path(scratch, "run.json")
        command = [str(binary), f"--benchmark_filter={FILTER}", f"--benchmark_min_time={min_time}",
                   f"--benchmark_out={out}", "--benchmark_out_format=json"]
        print("running: " + " ".join(command), file=sys.stderr)
        try:
            subprocess.run(command, stdout=subprocess.DEVNULL, check=True)
        except (OSError, subprocess.CalledProcessError) as error:
            sys.exit(f"targets.py: {binary} failed: {error}")
        text = out.read_text()
    if save:
        # Written whole or not at all: a temporary beside the target, then renamed.
        save = pathlib.Path(save)
        fd, partial = tempfile.mkstemp(dir=save.parent, prefix=save.name, suffix=".partial")
        try:
            with os.fdopen(fd, "w") as f:
                f.write(text)
            os.replace(partial, save)
        except OSError as error:
            pathlib.Path(partial).unlink(missing_ok=True)
            sys.exit(f"targets.py: cannot write {save}: {error}")
    return json.loads(text)


def by_name(results):
    """{benchmark name: the benchmark's entry}, every time in milliseconds."""
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}
    entries = {}
    for b in results.get("benchmarks", []):
        if b.get("run_type", "iteration") != "iteration" or "error_occurred" in b:
            continue
        b = dict(b)
        b["ms"] = b["real_time"] * scale[b.get("time_unit", "ns")]
        entries[b["name"]] = b
    return entries


def per_frame(entries, prefix):
    """{frame: entry} of the benchmarks `prefix` + frame."""
    return {name[len(prefix):]: b for name, b in entries.items() if name.startswith(prefix)}


def met(ok):
    return "yes" if ok else "**no**"


def report(results, source):
    entries = by_name(results)
    s1, s2 = per_frame(entries, "floodplane/s1/real:"), per_frame(entries, "floodplane/s2/real:")
    omps, phases = per_frame(entries, "omps/real:"), per_frame(entries, "floodplane/phases/real:")
    floor = per_frame(entries, "floor/real:")
    frames = sorted(s1)
    # Every per-frame table has every frame of s = 1, so the figures below need no guards.
    tables = {"floodplane/s1/real": s1, "floodplane/s2/real": s2, "omps/real": omps,
              "floodplane/phases/real": phases, "floor/real": floor}
    missing = [what for what, table in tables.items() if not table or any(f not in table for f in frames)]
    missing += [f"floodplane/s1/size:{size}" for size in SIZES if f"floodplane/s1/size:{size}" not in entries]
    if missing:
        sys.exit("targets.py: the run has no " + ", ".join(missing) + " (are the real frames there?)")

    t1 = [s1[f]["ms"] for f in frames]
    t2 = [s2[f]["ms"] for f in frames]
    vs_omps = [omps[f]["ms"] / s1[f]["ms"] for f in frames]
    s2_faster = sum(1 for f in frames if s2[f]["ms"] < s1[f]["ms"])
    per_mp = [entries[f"floodplane/s1/size:{size}"]["ms"] / megapixels(size) for size in SIZES]
    outside = [phases[f]["outside_ms"] / phases[f]["ms"] for f in frames]
    hot_floor = statistics.median(floor[f]["ms"] for f in frames)
    cold_floor = entries["floor/cold"]["ms"] if "floor/cold" in entries else float("nan")
    med1 = statistics.median(t1)

    # The run's own machine and load (Google Benchmark's context), not this process's: with
    # --json the table may be printed long after the run, elsewhere.
    context = results.get("context", {})
    load = " ".join(f"{v:.2f}" for v in context.get("load_avg", []))
    print(f"Targets of issue 16, one run of bench_segmentation ({source}), {context.get('date', '')}")
    print(f"Machine: {context.get('num_cpus', '?')} CPUs at {context.get('mhz_per_cpu', '?')} MHz, "
          f"load average {load or '?'} at the start of the run\n")
    print("| target (issue 16) | figure | met? |")
    print("|---|---|---|")
    print(f"| median <= 1.0 ms over the {len(frames)} real frames | {med1:.2f} ms ({min(t1):.2f}-{max(t1):.2f}) "
          f"| {met(med1 <= 1.0)} |")
    print(f"| no frame above 2 ms | slowest {max(t1):.2f} ms | {met(max(t1) <= 2.0)} |")
    print(f"| >= 50x PCL OMPS in the same run | {statistics.median(vs_omps):.2f}x median "
          f"({min(vs_omps):.2f}-{max(vs_omps):.2f}x) | {met(statistics.median(vs_omps) >= 50)} |")
    print(f"| sub-sampling 2 <= 0.5 ms | {statistics.median(t2):.2f} ms median | {met(statistics.median(t2) <= 0.5)} |")
    print(f"| sub-sampling 2 faster than 1 on every frame | {s2_faster} of {len(frames)} | "
          f"{met(s2_faster == len(frames))} |")
    spread = max(per_mp) / min(per_mp)
    print(f"| linear in pixels (ms per megapixel within 1.5x, {SIZES[0]} to {SIZES[-1]}) | "
          + ", ".join(f"{v:.0f}" for v in per_mp) + f" ms/MP (spread {spread:.2f}x) | {met(spread <= 1.5)} |")
    worst = max(abs(v) for v in outside)
    print(f"| phases add up (outside every phase <= 2 % of a call) | at most {100 * worst:.2f} % "
          f"| {met(worst <= 0.02)} |")
    print(f"| (memory floor: one pass reading every point, writing a label) | {hot_floor:.3f} ms hot, "
          f"{cold_floor:.3f} ms cold; floodplane {med1 / hot_floor:.0f}x the hot floor | |")
    print("\n| frame | s = 1 ms | s = 2 ms | OMPS ms | OMPS / s = 1 | floor ms | outside phases ms |")
    print("|---|---:|---:|---:|---:|---:|---:|")
    for f in frames:
        print(f"| {f} | {s1[f]['ms']:.2f} | {s2[f]['ms']:.2f} | {omps[f]['ms']:.2f} | "
              f"{omps[f]['ms'] / s1[f]['ms']:.2f}x | {floor[f]['ms']:.3f} | {phases[f]['outside_ms']:.4f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("binary", nargs="?", default=ROOT / "build/bench/bench_segmentation",
                        help="bench_segmentation to run (default: %(default)s)")
    parser.add_argument("--json", help="report an earlier run's JSON instead of running")
    parser.add_argument("--save", help="also write the run's JSON here")
    parser.add_argument("--min-time", type=float, default=0.3,
                        help="seconds per benchmark (default: %(default)s)")
    args = parser.parse_args()
    if args.save and not pathlib.Path(args.save).resolve().parent.is_dir():
        parser.error(f"--save: the folder of {args.save} does not exist")
    if args.json:
        try:
            results = json.loads(pathlib.Path(args.json).read_text())
        except (OSError, ValueError) as error:
            sys.exit(f"targets.py: cannot read {args.json}: {error}")
        try:
            report(results, args.json)
        except (KeyError, TypeError, AttributeError) as error:
            sys.exit(f"targets.py: {args.json} is not a JSON run of bench_segmentation (no {error})")
    else:
        if not pathlib.Path(args.binary).is_file():
            parser.error(f"{args.binary} does not exist (build with -DFLOODPLANE_BUILD_BENCHMARKS=ON)")
        report(run(args.binary, args.min_time, args.save), pathlib.Path(args.binary).name)


if __name__ == "__main__":
    main()

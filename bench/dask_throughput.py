#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""Throughput of floodplane.distributed.segment_files on a dask LocalCluster of 1 and of 2
worker processes (one thread each) over the same frames, runs of both alternating, and a
check that every output is pcd_segment's, byte for byte. Each worker reads, segments and
writes its files; the figure is frames per second of the whole call (reading, segmenting,
writing, scheduling).

    /usr/bin/python3 bench/dask_throughput.py [--build build] [--frames 200] [--rounds 3] [--batch-size 4] [pcd files...]
"""

import argparse
import filecmp
import os
import pathlib
import sys
import tempfile
import time

from bench_common import ROOT, machine, median, pcd_files_or_real_frames, run_pcd_segment, use_build_tree


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("sources", nargs="*", type=pathlib.Path,
                        help="PCD files the frames are taken from in turn (default: ../shared/data/real)")
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--frames", type=int, default=200)
    parser.add_argument("--rounds", type=int, default=3, help="timed runs of each cluster, alternating")
    parser.add_argument("--batch-size", type=int, default=4, help="files per task (segment_files' batch_size)")
    arguments = parser.parse_args()
    arguments.sources = pcd_files_or_real_frames(parser, arguments.sources)
    return arguments


def make_frames(sources, count, folder):
    """`count` frames named frame_000.pcd ..., symbolic links to the sources in turn."""
    frames = []
    for i in range(count):
        frame = folder / f"frame_{i:03d}.pcd"
        frame.symlink_to(sources[i % len(sources)].resolve())
        frames.append(frame)
    return frames


def main():
    arguments = parse_arguments()
    use_build_tree(arguments.build)
    os.environ["PYTHONPATH"] = os.pathsep.join(p for p in [str(arguments.build / "python"),
                                                          os.environ.get("PYTHONPATH", "")] if p)
    import distributed
    import floodplane
    import floodplane.distributed

    print(f"machine: {machine()}")
    print(f"dask.distributed {distributed.__version__}; {arguments.frames} frames from {len(arguments.sources)} "
          f"files; LocalCluster(processes=True, threads_per_worker=1); batch_size {arguments.batch_size}; "
          f"{arguments.rounds} rounds each")
    with tempfile.TemporaryDirectory() as work:
        work = pathlib.Path(work)
        (work / "in").mkdir()
        frames = make_frames(arguments.sources, arguments.frames, work / "in")
        run_pcd_segment(arguments.build / "apps/pcd_segment/pcd_segment", [work / "in"], work / "reference")

        clusters = {n: distributed.LocalCluster(n_workers=n, threads_per_worker=1, processes=True,
                                                host="127.0.0.1", dashboard_address=":0", silence_logs=40)
                    for n in (1, 2)}
        clients = {n: distributed.Client(cluster) for n, cluster in clusters.items()}
        try:
            for n, client in clients.items():  # warm-up: imports and the first buffers on every worker
                floodplane.distributed.segment_files(client, frames[:4 * n], work / "warmup")
            rates = {1: [], 2: []}
            identical = True
            for round in range(arguments.rounds):
                for n, client in clients.items():
                    out = work / f"out_{n}_{round}"
                    start = time.perf_counter()
                    results = floodplane.distributed.segment_files(client, frames, out,
                                                                   batch_size=arguments.batch_size)
                    elapsed = time.perf_counter() - start
                    failed = [r for r in results if "error" in r]
                    if failed:
                        print(f"failed: {failed[:3]}", file=sys.stderr)
                        return 1
                    rates[n].append(len(frames) / elapsed)
                    identical = identical and all(
                        filecmp.cmp(r["output"], work / "reference" / pathlib.Path(r["output"]).name, shallow=False)
                        for r in results)
                    print(f"round {round + 1}, {n} worker{'s' if n > 1 else ''}: {elapsed:.2f} s, "
                          f"{rates[n][-1]:.1f} frames/s, median segmentation "
                          f"{median([r['ms'] for r in results]):.1f} ms")
        finally:
            for client in clients.values():
                client.close()
            for cluster in clusters.values():
                cluster.close()
    one, two = median(rates[1]), median(rates[2])
    # Each round runs 1 then 2 workers back to back: the ratio within a round is the least
    # disturbed by the shared machine's load, which changes from minute to minute.
    paired = [b / a for a, b in zip(rates[1], rates[2])]
    print()
    print("| workers | frames/s (median of rounds) | speed-up (medians) | speed-up (median of rounds' ratios) | "
          "outputs = pcd_segment's |")
    print("|---|---|---|---|---|")
    print(f"| 1 | {one:.1f} | 1.00x | 1.00x | {'yes' if identical else 'NO'} |")
    print(f"| 2 | {two:.1f} | {two / one:.2f}x | {median(paired):.2f}x (rounds: "
          f"{', '.join(f'{r:.2f}' for r in paired)}) | {'yes' if identical else 'NO'} |")
    print(f"machine after: {machine()}")
    return 0 if identical else 1


if __name__ == "__main__":
    sys.exit(main())

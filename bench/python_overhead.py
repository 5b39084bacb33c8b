#!/usr/bin/env python3
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
"""What calling floodplane from Python costs: on each frame, Segmenter.segment from Python
(perf_counter around the call: argument checks, the GIL released and taken back, the result's
copy of the labels and planes) against the core's C++ call inside it (Segmenter::segment,
timed in C++ with steady_clock: Segmentation.ms), call by call in one interleaved run. Also
checks that Python's labels are pcd_segment's, bit for bit.

    /usr/bin/python3 bench/python_overhead.py [--build build] [--repeat 30] [frames...]
"""

import argparse
import pathlib
import sys
import tempfile
import time

from bench_common import ROOT, machine, median, pcd_files_or_real_frames, run_pcd_segment, use_build_tree


def parse_arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("frames", nargs="*", type=pathlib.Path,
                        help="PCD files (default: the real frames in ../shared/data/real)")
    parser.add_argument("--build", type=pathlib.Path, default=ROOT / "build")
    parser.add_argument("--repeat", type=int, default=30, help="timed calls per frame after one warm-up")
    arguments = parser.parse_args()
    arguments.frames = pcd_files_or_real_frames(parser, arguments.frames)
    return arguments


def time_frame(floodplane, points, repeat):
    """Per call: (Python ms, C++ ms), alternating nothing else in between."""
    segmenter = floodplane.Segmenter()
    segmenter.segment(points)  # warm-up: buffers sized
    calls = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = segmenter.segment(points)
        outer = (time.perf_counter() - start) * 1000.0
        calls.append((outer, result.ms))
    return calls, result


def main():
    arguments = parse_arguments()
    use_build_tree(arguments.build)
    import floodplane
    import numpy

    print(f"machine: {machine()}")
    print(f"floodplane {floodplane.__version__} from {pathlib.Path(floodplane.__file__).parent}, numpy "
          f"{numpy.__version__}; {arguments.repeat} calls per frame after one warm-up; default parameters")
    pcd_segment = arguments.build / "apps/pcd_segment/pcd_segment"
    with tempfile.TemporaryDirectory() as out:
        run_pcd_segment(pcd_segment, arguments.frames, out)
        print()
        print("| frame | size | Python median [ms] | C++ median [ms] | overhead median [ms] | overhead | "
              "labels = pcd_segment's |")
        print("|---|---|---|---|---|---|---|")
        all_outer, all_inner, all_same = [], [], True
        for frame in arguments.frames:
            points = floodplane.read_pcd(str(frame))
            calls, result = time_frame(floodplane, points, arguments.repeat)
            outer = median([c[0] for c in calls])
            inner = median([c[1] for c in calls])
            overhead = median([c[0] - c[1] for c in calls])
            expected = floodplane.read_labels_pcd(str(pathlib.Path(out, frame.stem + ".labels.pcd")))
            same = bool((result.labels == expected).all())
            all_same = all_same and same
            all_outer.append(outer)
            all_inner.append(inner)
            height, width = points.shape[:2]
            print(f"| {frame.name} | {width}x{height} | {outer:.3f} | {inner:.3f} | {overhead:.3f} | "
                  f"{100 * (outer / inner - 1):+.1f} % | {'yes' if same else 'NO'} |")
        outer, inner = median(all_outer), median(all_inner)
        print(f"| median of the frames | | {outer:.3f} | {inner:.3f} | {outer - inner:.3f} | "
              f"{100 * (outer / inner - 1):+.1f} % | {'yes' if all_same else 'NO'} |")
    return 0 if all_same else 1


if __name__ == "__main__":
    sys.exit(main())

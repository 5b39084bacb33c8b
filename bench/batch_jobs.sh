#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# pcd_segment's batch throughput with -j 1 against -j N (default: every core), rounds of the
# two alternating, and a byte-for-byte comparison of their outputs (issue 16's batch target:
# on 2 cores a folder of 200 frames at least 1.8x faster than -j 1).
#
# Usage: bench/batch_jobs.sh FOLDER [build-dir] [rounds]
#   FOLDER: PCD files, e.g. the random report split's 640x480 clouds:
#     mkdir frames && ln -s "$PWD"/build/data/random/report/random_*.{kinect,none}.pcd frames/
set -euo pipefail
folder=${1:?usage: bench/batch_jobs.sh FOLDER [build-dir] [rounds]}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${2:-$root/build}" && pwd)
rounds=${3:-3}
jobs=$(nproc)
segment=$build/apps/pcd_segment/pcd_segment
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

echo "machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg); $(find -L "$folder" -maxdepth 1 -name '*.pcd' | wc -l) files"
for round in $(seq "$rounds"); do
  for j in 1 "$jobs"; do
    rm -rf "$out/j$j"
    start=$(date +%s.%N)
    "$segment" "$folder" -o "$out/j$j" -q -j "$j"
    end=$(date +%s.%N)
    echo "round $round -j $j $(echo "$end - $start" | bc) s"
  done
done | tee "$out/times.txt"
for file in "$out/j1"/*; do
  cmp -s "$file" "$out/j$jobs/$(basename "$file")" || { echo "outputs differ: $(basename "$file")" >&2; exit 1; }
done
echo "outputs of -j 1 and -j $jobs identical ($(find "$out/j1" -type f | wc -l) files)"
median() { grep -- "-j $1 " "$out/times.txt" | awk '{print $5}' | sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }
serial=$(median 1)
parallel=$(median "$jobs")
echo "-j 1 median $serial s, -j $jobs median $parallel s, speed-up $(echo "scale=2; $serial / $parallel" | bc)x"

#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# The figures of the results' comparison with the fast peers, CAPE and PEAC, from one run:
#   1. speed: ../shared/peers/side_by_side.sh on the 7 real Kinect frames of ../shared/data/real
#      (each method's median ms over interleaved rounds, and with INSTRUCTIONS=1, the default
#      here, the instruction counts of floodplane's and CAPE's call, which a busy machine does
#      not blur);
#   2. accuracy on real frames: each runner of ../shared/peers writes its labels of the 45
#      mOSD learn frames (../shared/data/osd-learn), which ../shared/tools/osd_scores.py scores
#      (the table in one piece, no plane across objects, box faces, no plane on a can's wall).
# Then `bench/update_figures.py --peers OUT` writes them into docs/results.md and the README.
#
#   bench/peers.sh PREFIX OUT
#
# PREFIX: a floodplane install (cmake --install build --prefix PREFIX), the build to measure.
# OUT: a folder for the runs (speed.md, osd_<method>.json, the labels). Needs libopencv-dev
# (CAPE, PEAC) and valgrind. Environment: ROUNDS, REPEAT as side_by_side.sh takes them;
# INSTRUCTIONS=0 leaves the counts out.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=$root/../shared
[ $# -eq 2 ] || { echo "usage: $0 FLOODPLANE_PREFIX OUT" >&2; exit 2; }
prefix=$(cd "$1" && pwd)
mkdir -p "$2"
out=$(cd "$2" && pwd)
[ -x "$shared/peers/side_by_side.sh" ] || { echo "peers: no $shared/peers/side_by_side.sh" >&2; exit 1; }
[ -d "$shared/data/osd-learn" ] || { echo "peers: no $shared/data/osd-learn" >&2; exit 1; }

echo "peers: speed, side_by_side.sh on the real frames (rounds ${ROUNDS:-3}, instruction counts ${INSTRUCTIONS:-1})"
INSTRUCTIONS=${INSTRUCTIONS:-1} OUT=$out "$shared/peers/side_by_side.sh" "$prefix" | tee "$out/speed.md"
runners=$out/floodplane-peers/build
{
  echo "floodplane prefix: $prefix"
  echo "floodplane commit: $(git -C "$root" rev-parse --short HEAD)"
  echo "date: $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "machine: $(nproc) cores, $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -n 1), load $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$out/run.txt"

echo "peers: accuracy, each method's labels of the mOSD learn frames"
for method in floodplane cape peac; do
  runner=$runners/${method/floodplane/fp}_runner
  mkdir -p "$out/osd_$method"
  for frame in "$shared"/data/osd-learn/learn*.pcd; do
    "$runner" --in "$frame" --repeat 1 --out "$out/osd_$method/$(basename "$frame")" > /dev/null 2>> "$out/osd_$method.log"
  done
  /usr/bin/python3 "$shared/tools/osd_scores.py" --json "$shared/data/osd-learn" "$out/osd_$method" \
    > "$out/osd_$method.json"
  echo "peers: $method scored ($out/osd_$method.json)"
done
echo "peers: done; bench/update_figures.py --peers $out writes the figures"

#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# The full comparison of bench/README.md: floodplane at sub-sampling 1 and 2 against PCL's OMPS
# and RANSAC and Open3D's RANSAC, each baseline at its default and its tuned values
# (bench/tuned_baselines.json), on the bundled scenes and on the random family's report split.
# Renders what is missing, then writes Markdown, CSV and JSON into bench/results/compare_all_*.
#
# Usage: bench/compare_all.sh [build-dir]        (default: build; configured with apps on)
# Settings (environment):
#   SCENE_REPEAT=0   timed runs per method and bundled scene after a warm-up (0: one run)
#   REPORT_STEP=20   the sequential RANSACs run on every REPORT_STEP-th seed of the report
#                    split only (Open3D's takes 5-60 s a cloud); 1 runs them on all 100 seeds
#   TUNED=bench/tuned_baselines.json
#   PARALLEL=0       1 runs the three comparisons at once (faster on 2 cores; the runtimes of
#                    one comparison are then disturbed by the others, its ratios less so)
# Never tunes: the tuned values come from the tuning split (seeds 1-100), written by
#   bench/tune_baselines.py build/data/random/tune   (see bench/README.md)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
scene_repeat=${SCENE_REPEAT:-0}
report_step=${REPORT_STEP:-20}
parallel=${PARALLEL:-0}
tuned=${TUNED:-$root/bench/tuned_baselines.json}
results=$root/bench/results
compare=$build/apps/pcd_compare/pcd_compare
tables=$root/bench/compare_tables.py

[ -f "$tuned" ] || { echo "compare_all: no $tuned: run bench/tune_baselines.py first" >&2; exit 1; }
cmake --build "$build" --parallel 2 --target pcd_compare render_scenes
# render_random_report renders every time it is built; 300 clouds are there once it has run.
if [ "$(find "$build/data/random/report" -name 'random_*.pcd' 2>/dev/null | wc -l)" -ne 300 ]; then
  cmake --build "$build" --target render_random_report
fi
mkdir -p "$results"

all=floodplane,floodplane/1,ransac,open3d_ransac,omps
fast=floodplane,floodplane/1,omps

# Writes the JSON of one pcd_compare run to <name>.json and the tables and CSV that
# compare_tables.py makes from it to <name>.md and <name>.csv (through temporaries: a run that
# fails leaves the previous files). pcd_compare's own stdout, configuration and means, is in
# the JSON.
run() {
  local name=$1
  shift
  "$compare" --tuned --tuned-file "$tuned" --json "$results/$name.json.tmp" "$@" > /dev/null
  "$tables" "$results/$name.json.tmp" --csv "$results/$name.csv.tmp" > "$results/$name.md.tmp"
  mv "$results/$name.json.tmp" "$results/$name.json"
  mv "$results/$name.csv.tmp" "$results/$name.csv"
  mv "$results/$name.md.tmp" "$results/$name.md"
}

# Runs a comparison in the background when PARALLEL=1.
start() {
  if [ "$parallel" = 1 ]; then run "$@" & else run "$@"; fi
}

subset=$(mktemp -d)
trap 'rm -rf "$subset"' EXIT
for seed in $(seq 101 "$report_step" 200); do
  ln -s "$build"/data/random/report/random_0"$seed".*.pcd "$subset"/
done

echo "compare_all: bundled scenes (every method)"
start compare_all_scenes --repeat "$scene_repeat" --methods "$all" "$build/data/rendered"
echo "compare_all: random report split, fast methods on every cloud"
start compare_all_random --repeat 0 --methods "$fast" "$build/data/random/report"
echo "compare_all: random report split, every method on every ${report_step}th seed"
start compare_all_random_subset --repeat 0 --methods "$all" "$subset"
# `wait` alone would not fail when a background run fails.
for job in $(jobs -p); do wait "$job"; done
echo "compare_all: wrote $results/compare_all_{scenes,random,random_subset}.{md,csv,json}"

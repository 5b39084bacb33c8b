#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# From a fresh clone to results: installs what is missing (Debian packages), builds what the
# demo needs (Release, no tests), renders the bundled scenes and compares floodplane with PCL's
# RANSAC and OMPS on them. Prints the summary table and where the side-by-side pictures are.
# Run again, it rebuilds only what changed.
# Usage: scripts/demo.sh [build-dir]   (default: build)
# Settings (environment): METHODS (default floodplane,floodplane/1,ransac,omps; add
# open3d_ransac for Open3D's RANSAC, several seconds a noisy cloud), REPEAT (timed runs of the
# fast methods per cloud, default 5; the sequential RANSACs are timed once).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out="$build/demo"
methods=${METHODS:-floodplane,floodplane/1,ransac,omps}
repeat=${REPEAT:-5}
start=$(date +%s)

"$root/scripts/install_deps.sh"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFLOODPLANE_BUILD_APPS=ON
fi
echo "demo: building pcd_compare, pcd_segment and the scenes (a few minutes the first time)"
# render_scenes: data/scenes/*.json -> $build/data/rendered, exact and with Kinect noise.
cmake --build "$build" --parallel "$(nproc)" --target pcd_compare pcd_segment render_scenes

mkdir -p "$out"
echo "demo: comparing $methods on $(ls "$build"/data/rendered/*.pcd | wc -l) scenes (about a minute)"
"$build/apps/pcd_compare/pcd_compare" --repeat "$repeat" --methods "$methods" --png "$out" \
  --json "$out/compare.json" "$build"/data/rendered/*.pcd > "$out/compare.md"

echo
# The means over every scene: the first table after the configuration.
awk '/^### all files/ {on = 1; print; print ""; next} on && /^\|/ {print; rows = 1; next} on && rows {exit}' "$out/compare.md"
cat <<EOF
demo: done in $(( $(date +%s) - start )) s
  the means:         $out/compare.md (and per sensor model)
  every file, plane: $out/compare.json (as tables: bench/compare_tables.py $out/compare.json)
  the pictures:      $out/<scene>.png (ground truth | RANSAC | OMPS | floodplane/1 | floodplane)
  your own frames:   $build/apps/pcd_segment/pcd_segment frame.pcd -o out/ --png --json
EOF

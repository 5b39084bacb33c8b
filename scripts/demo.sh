#!/usr/bin/env bash
# From a fresh clone to results: installs what is missing (Debian packages), builds floodplane
# (Release), renders the bundled scenes and compares floodplane with PCL's RANSAC and OMPS on
# them. Prints the comparison table and names the folder with the side-by-side pictures.
# Run again, it rebuilds only what changed.
# Usage: scripts/demo.sh [build-dir]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}
out="$build/demo"

"$root/scripts/install_deps.sh"
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DFLOODPLANE_BUILD_APPS=ON \
        -DFLOODPLANE_BUILD_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3
fi
# render_scenes is part of the default build: data/scenes/*.json -> $build/data/rendered
cmake --build "$build" --parallel "$(nproc)" --target pcd_compare pcd_segment render_scenes _floodplane

mkdir -p "$out"
"$build/apps/pcd_compare/pcd_compare" --repeat 5 --png "$out" --json "$out/compare.json" \
  "$build"/data/rendered/*.pcd
echo
echo "demo: side-by-side pictures (ground truth | RANSAC | OMPS | floodplane) in $out"

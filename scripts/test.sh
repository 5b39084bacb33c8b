#!/usr/bin/env bash
# Installs dependencies, builds floodplane with its tests and runs them all.
# Usage: scripts/test.sh [build-dir]   (default: build)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}

"$root/scripts/install_deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
      -DFLOODPLANE_BUILD_TESTS=ON -DFLOODPLANE_BUILD_APPS=ON -DFLOODPLANE_BUILD_BENCHMARKS=ON
cmake --build "$build" --parallel "$(nproc)"
cd "$build"
ctest --output-on-failure --parallel "$(nproc)"

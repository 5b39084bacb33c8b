#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Installs dependencies, builds floodplane with its tests and its Python module (for Debian's
# /usr/bin/python3, which has the packages install_deps.sh adds) and runs them all. The
# benchmarks (bench/, -DFLOODPLANE_BUILD_BENCHMARKS=ON) are not tests and are not built here:
# .ci/run builds them so that they keep compiling.
# The ROS 1 node (ros/floodplane_ros) and its rostests are built and run when ROS 1 is
# installed (scripts/install_ros_deps.sh); without it the last line says they were skipped.
# Usage: scripts/test.sh [build-dir]   (default: build)
# FLOODPLANE_WERROR=ON in the environment turns warnings into errors (CI does).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build}

"$root/scripts/install_deps.sh"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release \
      -DFLOODPLANE_BUILD_TESTS=ON -DFLOODPLANE_BUILD_APPS=ON \
      -DFLOODPLANE_BUILD_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 \
      -DFLOODPLANE_WERROR="${FLOODPLANE_WERROR:-OFF}"
cmake --build "$build" --parallel "$(nproc)"
cd "$build"
ctest --output-on-failure --parallel "$(nproc)"
echo "test.sh: the ROS 1 node is $(sed -n 's/^FLOODPLANE_ROS_STATUS:INTERNAL=//p' CMakeCache.txt)"

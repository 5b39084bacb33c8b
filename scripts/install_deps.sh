#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Installs what floodplane needs from Debian 12's packages. As root it installs them;
# otherwise it prints the command to run and fails, so nothing half-happens.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libpcl-dev libeigen3-dev libflann-dev      # PCL (brings VTK and Boost), Eigen, FLANN
  liblz4-dev libpng-dev                      # PCD compression link line, PNG output
  liblzf-dev                                 # PCD binary_compressed (LZF), written in bulk
  libgtest-dev libgmock-dev libbenchmark-dev # tests and benchmarks
  libcli11-dev nlohmann-json3-dev            # command-line parsing, JSON
  libtbb-dev                                 # pcd_segment -j: oneTBB's parallel_pipeline
  libopen3d-dev                              # pcd_compare's Open3D RANSAC baseline (0.16)
  libcairo2-dev                              # pcd_compare's picture titles (its fonts come with it)
  clang libclang-rt-14-dev                   # libFuzzer and the sanitizer runtime
  clang-format                               # scripts/check_format.sh (clang-format 14)
  doxygen                                    # the API reference (cmake --build build --target docs)
  xvfb xauth libgl1-mesa-dri                 # an X display with software OpenGL for 3-D snapshots
  python3 python3-dev pybind11-dev python3-pybind11  # the Python module (Debian's interpreter)
  python3-numpy python3-pytest                 # its arrays and its tests
  python3-dask python3-distributed             # floodplane.distributed and its test cluster
  python3-open3d                               # floodplane.open3d's tests (Open3D 0.16's Python module)
  python3-matplotlib                           # bench/'s speed-against-accuracy chart (speed_accuracy_chart.py)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

cmd="apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "install_deps: missing packages: ${missing[*]}" >&2
  echo "install_deps: run as root:  apt-get update && $cmd" >&2
  exit 1
fi
echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
$cmd

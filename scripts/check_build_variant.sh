#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Builds floodplane's libraries alone (no apps, tests or Python) from this source tree in a
# temporary directory as one of the variants that the tests' own build is not, then checks
# their install as users see it (scripts/check_install.sh):
#   shared       BUILD_SHARED_LIBS=ON: the CMake consumers, the core without PCL, the
#                components and pkg-config, each program using the installed .so files
#   without-pcl  FLOODPLANE_WITH_PCL=OFF, configured with PCL unfindable (as on a machine
#                without PCL): the core alone builds and installs, its consumers work, and
#                asking for the pcl component says that it was not built
# Usage: scripts/check_build_variant.sh <shared|without-pcl>   (CXX: the compiler, optional)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
variant=${1:-}
case $variant in
  shared)
    options=(-DBUILD_SHARED_LIBS=ON)
    checks=(consumer core components pkg-config) ;;
  without-pcl)
    options=(-DFLOODPLANE_WITH_PCL=OFF -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON)
    checks=(core components pkg-config) ;;
  *)
    echo "usage: $0 <shared|without-pcl>" >&2
    exit 2 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

compiler=()
[ -n "${CXX:-}" ] && compiler=(-DCMAKE_CXX_COMPILER="$CXX")
if ! cmake -S "$root" -B "$work/build" -DCMAKE_BUILD_TYPE=Release "${compiler[@]}" \
       -DFLOODPLANE_BUILD_TESTS=OFF -DFLOODPLANE_BUILD_APPS=OFF -DFLOODPLANE_BUILD_PYTHON=OFF \
       -DFLOODPLANE_BUILD_BENCHMARKS=OFF -DFLOODPLANE_BUILD_FUZZERS=OFF "${options[@]}" > "$work/configure.log" 2>&1; then
  cat "$work/configure.log"
  exit 1
fi
if ! cmake --build "$work/build" --parallel "$(nproc)" > "$work/build.log" 2>&1; then
  cat "$work/build.log"
  exit 1
fi
echo "check_build_variant: $variant: built" "$work"/build/src/libfloodplane*
"$root/scripts/check_install.sh" "$work/build" "${checks[@]}"

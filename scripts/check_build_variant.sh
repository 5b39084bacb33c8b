#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Builds floodplane's libraries alone (no apps, tests or Python) from this source tree in a
# temporary directory as one of the variants that the tests' own build is not, then checks
# their install as users see it (scripts/check_install.sh):
#   shared       BUILD_SHARED_LIBS=ON: the CMake consumers, the core without PCL, the
#                components, pkg-config and the components io and ros, each program using
#                the installed .so files
#   without-pcl  FLOODPLANE_WITH_PCL=OFF, configured with PCL unfindable (as on a machine
#                without PCL): the core alone builds and installs, its consumers work, and
#                asking for the pcl or io component says that it was not built
# Given a build tree of the same sources (the tests give theirs), the variant takes from it the
# objects that it compiled with the very same command and that are up to date
# (scripts/compile_or_reuse.py: the libraries' sources compile alike in every variant; what
# differs is the configure, the link and the install, which are what is checked), and uses its
# FLOODPLANE_WERROR; every other object is compiled. It says which objects it took.
# Usage: scripts/check_build_variant.sh <shared|without-pcl> [build-dir]   (CXX: the compiler, optional)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
variant=${1:-}
case $variant in
  shared)
    options=(-DBUILD_SHARED_LIBS=ON)
    checks=(consumer core components pkg-config io) ;;
  without-pcl)
    options=(-DFLOODPLANE_WITH_PCL=OFF -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON)
    checks=(core components pkg-config) ;;
  *)
    echo "usage: $0 <shared|without-pcl>" >&2
    exit 2 ;;
esac
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

reuse_from=${2:-}
compiler=()
[ -n "${CXX:-}" ] && compiler=(-DCMAKE_CXX_COMPILER="$CXX")
if [ -n "$reuse_from" ]; then
  reuse_from=$(cd "$reuse_from" && pwd)
  werror=$(sed -n 's/^FLOODPLANE_WERROR:[A-Z]*=//p' "$reuse_from/CMakeCache.txt")
  options+=(-DFLOODPLANE_WERROR="${werror:-OFF}" -DCMAKE_CXX_COMPILER_LAUNCHER="$root/scripts/compile_or_reuse.py")
  export FLOODPLANE_REUSE_BUILD=$reuse_from FLOODPLANE_REUSE_INTO=$work/build FLOODPLANE_REUSE_LOG=$work/reuse.log
  : > "$work/reuse.log"
fi
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
if [ -n "$reuse_from" ]; then
  echo "check_build_variant: $variant: $(grep -c '^reused' "$work/reuse.log" || true) objects taken from $reuse_from," \
       "$(grep -c '^compiled' "$work/reuse.log" || true) compiled:"
  sed 's/^/  /' "$work/reuse.log"
fi
"$root/scripts/check_install.sh" "$work/build" "${checks[@]}"

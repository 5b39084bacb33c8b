#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Installs the build tree's floodplane into a temporary prefix, then configures, builds and
# runs examples/consumer against it: the PCL drop-in, the PCL-free core, and every installed
# header compiled on its own. Usage: scripts/check_install.sh <build-dir>
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$root/examples/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
      -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/consumer/consumer"
"$work/consumer/core_consumer"
"$work/consumer/headers_link"
# The core needs no PCL at run time either.
if ldd "$work/consumer/core_consumer" | grep -q libpcl_; then
  echo "check_install: core_consumer links PCL, but floodplane::core should not need it" >&2
  exit 1
fi

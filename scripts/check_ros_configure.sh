#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Installing ROS must never break the README's commands. With ROS 1 installed, configures
# floodplane from scratch twice, each time with another python3 first on PATH than Debian's
# (one that lacks Debian's modules, as pyenv's or a venv's does):
#   1. as scripts/test.sh does: the configure passes and the ROS part is built (ROS's CMake
#      runs its Python tools with Debian's interpreter, not the one on PATH);
#   2. with ROS's interpreter given as one whose tools fail: the configure still passes and
#      says why the ROS part is skipped.
# Usage: scripts/check_ros_configure.sh [scratch-dir]   (default: a temporary folder)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
scratch=${1:-$(mktemp -d)}
mkdir -p "$scratch/bin"
# python3 without the site folders: no catkin_pkg, no ament_package, no numpy.
cat > "$scratch/bin/python3" <<'PY'
#!/bin/sh
exec /usr/bin/python3 -S "$@"
PY
# An interpreter whose ROS tools fail (pluginlib's ament extras), as with a broken installation.
cat > "$scratch/bin/broken-ros-python" <<'PY'
#!/bin/sh
case "$*" in *templates_2_cmake*) echo "ModuleNotFoundError: No module named 'ament_package'" >&2; exit 1 ;; esac
exec /usr/bin/python3 "$@"
PY
chmod +x "$scratch/bin/python3" "$scratch/bin/broken-ros-python"
export PATH="$scratch/bin:$PATH"
[ "$(command -v python3)" = "$scratch/bin/python3" ]
if ! /usr/bin/python3 -c 'import catkin_pkg' 2> /dev/null; then
  echo "check_ros_configure: ROS 1 is not installed (scripts/install_ros_deps.sh): nothing to check" >&2
  exit 1
fi

status() { sed -n 's/^FLOODPLANE_ROS_STATUS:INTERNAL=//p' "$1/CMakeCache.txt"; }

echo "check_ros_configure: 1. a fresh configure as scripts/test.sh does, python3 on PATH: $scratch/bin/python3"
cmake -S "$root" -B "$scratch/build" -DCMAKE_BUILD_TYPE=Release -DFLOODPLANE_BUILD_TESTS=ON \
      -DFLOODPLANE_BUILD_APPS=ON -DFLOODPLANE_BUILD_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3 \
      > "$scratch/configure1.log" 2>&1 || { tail -n 30 "$scratch/configure1.log"; exit 1; }
case "$(status "$scratch/build")" in
  built*) echo "check_ros_configure:    passed; the ROS 1 node is $(status "$scratch/build")" ;;
  *) echo "check_ros_configure:    the ROS 1 node is $(status "$scratch/build"), not built" >&2; exit 1 ;;
esac

echo "check_ros_configure: 2. a fresh configure as scripts/demo.sh does, ROS's tools failing"
cmake -S "$root" -B "$scratch/build-broken" -DCMAKE_BUILD_TYPE=Release -DFLOODPLANE_BUILD_APPS=ON \
      -DPYTHON_EXECUTABLE="$scratch/bin/broken-ros-python" \
      > "$scratch/configure2.log" 2>&1 || { tail -n 30 "$scratch/configure2.log"; exit 1; }
case "$(status "$scratch/build-broken")" in
  skipped:*ament_package*) echo "check_ros_configure:    passed; the ROS 1 node is $(status "$scratch/build-broken")" ;;
  *) echo "check_ros_configure:    the ROS 1 node is $(status "$scratch/build-broken")" >&2; exit 1 ;;
esac
[ -n "${1:-}" ] || rm -rf "$scratch"

#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# The ROS package builds the ROS way too: from scratch, in a temporary folder,
#   1. floodplane is configured without its apps, tests, Python module and ROS build (what the
#      package needs is the core, the file formats' library floodplane::io, which needs PCL,
#      and the conversions: its components core, io and ros), built and installed to a prefix
#      with `cmake --install`;
#   2. a catkin workspace whose src holds a copy of ros/floodplane_ros (a copy: nothing outside
#      the package is within its reach) is built with catkin_make against that prefix
#      (CMAKE_PREFIX_PATH), with Debian's python for catkin (-DPYTHON_EXECUTABLE) while another
#      python3 comes first on PATH, one without Debian's modules, as pyenv's or a venv's;
#   3. `catkin_make install` installs it, and from the install ROS finds the package, its
#      nodelet plugin, launch file and rviz configuration, the nodelet library loads with every
#      symbol resolved, and Debian's python imports its messages.
# Fails at the first step that fails, with the end of its log; every step is bounded by what
# is left of FLOODPLANE_CATKIN_CHECK_SECONDS (default 900) and stopped when that runs out.
# Usage: scripts/check_catkin_workspace.sh [scratch-dir]   (default: a temporary folder, removed)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${FLOODPLANE_CATKIN_CHECK_SECONDS:-900}
deadline=$(($(date +%s) + seconds))
if [ $# -ge 1 ]; then
  scratch=$1
  mkdir -p "$scratch"
else
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
fi
jobs=$(nproc)

if ! /usr/bin/python3 -c 'import catkin_pkg' 2> /dev/null || ! command -v catkin_make > /dev/null; then
  echo "check_catkin_workspace: ROS 1 with catkin_make is not installed (scripts/install_ros_deps.sh)" >&2
  exit 1
fi
# python3 without the site folders: no catkin_pkg, no genmsg, no rospkg.
mkdir -p "$scratch/bin"
cat > "$scratch/bin/python3" << 'PY'
#!/bin/sh
exec /usr/bin/python3 -S "$@"
PY
chmod +x "$scratch/bin/python3"
export PATH="$scratch/bin:$PATH"
[ "$(command -v python3)" = "$scratch/bin/python3" ]

# Runs a step with its output in <log>, within what is left of the time; on failure shows the
# log's end and fails.
step() {
  local log=$1
  shift
  local left=$((deadline - $(date +%s)))
  if [ "$left" -le 0 ]; then
    echo "check_catkin_workspace: out of time (${seconds} s) before: $*" >&2
    exit 1
  fi
  local status=0
  timeout --kill-after=10 "$left" "$@" > "$log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    tail -n 40 "$log" >&2
    if [ "$status" -eq 124 ]; then
      echo "check_catkin_workspace: stopped after ${seconds} s in all: $*" >&2
    else
      echo "check_catkin_workspace: failed ($status): $*   (log: $log)" >&2
    fi
    exit 1
  fi
}

prefix=$scratch/prefix
echo "check_catkin_workspace: 1. floodplane, the core and its components io and ros, installed to $prefix"
step "$scratch/floodplane-configure.log" cmake -S "$root" -B "$scratch/floodplane-build" -DCMAKE_BUILD_TYPE=Release \
  -DFLOODPLANE_BUILD_TESTS=OFF -DFLOODPLANE_BUILD_APPS=OFF -DFLOODPLANE_BUILD_PYTHON=OFF -DFLOODPLANE_BUILD_ROS=OFF
step "$scratch/floodplane-build.log" cmake --build "$scratch/floodplane-build" --parallel "$jobs"
step "$scratch/floodplane-install.log" cmake --install "$scratch/floodplane-build" --prefix "$prefix"

workspace=$scratch/catkin_ws
echo "check_catkin_workspace: 2. catkin_make in $workspace, python3 on PATH: $(command -v python3)"
rm -rf "$workspace"
mkdir -p "$workspace/src"
cp -r "$root/ros/floodplane_ros" "$workspace/src/"
export CMAKE_PREFIX_PATH=$prefix${CMAKE_PREFIX_PATH:+:$CMAKE_PREFIX_PATH}
cd "$workspace"
step "$scratch/catkin_make.log" catkin_make -j"$jobs" -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3

echo "check_catkin_workspace: 3. catkin_make install, and the installed package as ROS finds it"
step "$scratch/catkin_make_install.log" catkin_make install -j"$jobs" -DCMAKE_BUILD_TYPE=Release \
  -DPYTHON_EXECUTABLE=/usr/bin/python3
# setup.bash reads variables it may find unset: sourced in a shell of its own, without -u.
cat > "$scratch/check_install.sh" << 'CHECK'
set -eo pipefail
source "$1/install/setup.bash"
share=$(rospack find floodplane_ros)
[ "$share" = "$1/install/share/floodplane_ros" ] || { echo "rospack finds floodplane_ros in '$share'"; exit 1; }
for file in launch/floodplane.launch rviz/floodplane.rviz nodelet_plugins.xml; do
  [ -f "$share/$file" ] || { echo "not installed: share/floodplane_ros/$file"; exit 1; }
done
[ -x "$1/install/lib/floodplane_ros/floodplane_node" ] || { echo "not installed: lib/floodplane_ros/floodplane_node"; exit 1; }
rospack plugins --attrib=plugin nodelet | grep -q "^floodplane_ros " || { echo "no nodelet plugin of floodplane_ros"; exit 1; }
# The nodelet is a shared library: an unresolved symbol (a conversion missing from the
# installed library) shows only when it is loaded, as the nodelet manager would load it.
/usr/bin/python3 -c "import ctypes, sys; ctypes.CDLL(sys.argv[1], mode=ctypes.RTLD_GLOBAL)" \
  "$1/install/lib/libfloodplane_ros_nodelet.so"
/usr/bin/python3 -c "from floodplane_ros.msg import Planes; assert 'segmentation_time_ms' in Planes.__slots__"
echo "found $share, its nodelet plugin, launch file and rviz configuration; the nodelet loads; its messages import"
CHECK
step "$scratch/installed.log" bash "$scratch/check_install.sh" "$workspace"
echo "check_catkin_workspace: passed: $(tail -n 1 "$scratch/installed.log")"

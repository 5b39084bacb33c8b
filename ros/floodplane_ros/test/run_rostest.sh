#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Runs one rostest file in the environment of a catkin devel space, bounded and contained:
# rostest starts its own master on a free port; ROS_IP=127.0.0.1 binds it and every node to
# the loopback interface (ROS_MASTER_URI=http://127.0.0.1:<port>); ROS_HOME (logs) is a
# temporary folder. Everything runs in a process group of its own, stopped at the end, on
# failure and on the time limit alike (the master, the nodes, the test).
# Usage: run_rostest.sh <devel-space> <seconds> <file.test> [name:=value ...]   (the test's args)
set -euo pipefail
devel=$1
seconds=$2
test_file=$3
shift 3

export ROS_IP=127.0.0.1
unset ROS_HOSTNAME ROS_MASTER_URI
ROS_HOME=$(mktemp -d)
export ROS_HOME ROS_LOG_DIR="$ROS_HOME/log" ROS_TEST_RESULTS_DIR="$ROS_HOME/test_results"

setsid "$devel/env.sh" rostest "$test_file" "$@" &
group=$!
sleep "$seconds" < /dev/null > /dev/null 2>&1 &
sleeper=$!
# roslaunch starts every node in a session of its own: they are found as rostest's descendants
# before anything is stopped, and stopped by their ids.
descendants() {
  local child
  for child in $(ps -o pid= --ppid "$1" 2> /dev/null || true); do
    echo "$child"
    descendants "$child"
  done
}
stop() {
  kill "$sleeper" 2> /dev/null || true
  local pids
  pids="$group $(descendants "$group")"
  # shellcheck disable=SC2086
  kill -TERM -- "-$group" $pids 2> /dev/null || true
  for _ in $(seq 40); do
    # shellcheck disable=SC2086
    kill -0 $pids 2> /dev/null || break
    sleep 0.5
  done
  # shellcheck disable=SC2086
  kill -KILL -- "-$group" $pids 2> /dev/null || true
  rm -rf "$ROS_HOME"
}
trap stop EXIT
status=0
wait -n "$group" "$sleeper" || status=$?
if kill -0 "$group" 2> /dev/null; then
  echo "run_rostest: $test_file took over $seconds s: stopped" >&2
  status=124
fi
exit "$status"

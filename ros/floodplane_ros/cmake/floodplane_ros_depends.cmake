# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# floodplane_ros_depends: the ROS packages floodplane_ros builds on, read from the <depend> tags
# of its package.xml, the one list of them (rosdep and catkin read it too). floodplane's
# ros/CMakeLists.txt probes for them before it adds the package; the package finds them.
file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/../package.xml floodplane_ros_depend_lines REGEX "<depend>")
set(floodplane_ros_depends)
foreach(line IN LISTS floodplane_ros_depend_lines)
  string(REGEX REPLACE ".*<depend>[ \t]*([A-Za-z0-9_]+)[ \t]*</depend>.*" "\\1" package "${line}")
  list(APPEND floodplane_ros_depends ${package})
endforeach()
if(NOT floodplane_ros_depends)
  message(FATAL_ERROR "no <depend> tag in ${CMAKE_CURRENT_LIST_DIR}/../package.xml")
endif()

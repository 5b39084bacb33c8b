# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Run by `cmake --install` (COMPONENT python, after the package's files), with
# CMAKE_INSTALL_PREFIX the prefix of this install, which may differ from the configured one.
# Says where the package went and what, if anything, the user must set. When the interpreter
# reads no package from the package's folder but does read another folder under the same
# prefix (Debian's python3 under /usr/local reads lib/python3.11/dist-packages, not
# lib/python3/dist-packages), a floodplane.pth in that folder names the package's folder, so
# that the package and the ROS node's messages beside it import with nothing set.
#
# In (set by python/CMakeLists.txt's install(CODE)):
#   FLOODPLANE_PYTHON_DIR       the package's folder, relative to the prefix
#   FLOODPLANE_PYTHON_SEARCHED  the folders the interpreter reads packages from (real paths)
#   FLOODPLANE_PYTHON_PTH       a file of the build tree the .pth is written to before it installs
get_filename_component(floodplane_prefix "${CMAKE_INSTALL_PREFIX}" REALPATH)
set(floodplane_package_dir "${floodplane_prefix}/${FLOODPLANE_PYTHON_DIR}")
set(floodplane_site_dir "")
list(FIND FLOODPLANE_PYTHON_SEARCHED "${floodplane_package_dir}" floodplane_searched_at)
if(floodplane_searched_at LESS 0)
  foreach(floodplane_folder IN LISTS FLOODPLANE_PYTHON_SEARCHED)
    string(FIND "${floodplane_folder}/" "${floodplane_prefix}/lib/" floodplane_under_prefix)
    if(floodplane_under_prefix EQUAL 0)
      set(floodplane_site_dir "${floodplane_folder}")
      break()
    endif()
  endforeach()
endif()

message(STATUS "floodplane: the Python package is in ${CMAKE_INSTALL_PREFIX}/${FLOODPLANE_PYTHON_DIR}")
if(floodplane_searched_at GREATER_EQUAL 0)
  message(STATUS "floodplane: the Python interpreter reads that folder: nothing to set")
elseif(floodplane_site_dir)
  # Relative to the folder it sits in (site.py joins the two), so that a staged install
  # (DESTDIR) is as complete as the final one.
  file(RELATIVE_PATH floodplane_relative "${floodplane_site_dir}" "${floodplane_package_dir}")
  file(WRITE "${FLOODPLANE_PYTHON_PTH}" "${floodplane_relative}\n")
  file(INSTALL DESTINATION "${floodplane_site_dir}" TYPE FILE FILES "${FLOODPLANE_PYTHON_PTH}")
  message(STATUS "floodplane: ${floodplane_site_dir}/floodplane.pth adds it to the Python interpreter's path: "
                 "nothing to set")
else()
  message(STATUS "floodplane: add it to PYTHONPATH (the ROS node's messages are in it too)")
endif()

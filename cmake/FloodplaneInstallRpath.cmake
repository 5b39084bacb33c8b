# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# floodplane_set_install_rpath(<target> <install-dir>): with BUILD_SHARED_LIBS, the installed
# <target> (installed to <install-dir>, relative to the prefix) finds floodplane's shared
# libraries in <prefix>/${CMAKE_INSTALL_LIBDIR} wherever the prefix is, through an rpath
# relative to itself ($ORIGIN). The build tree needs none of this: CMake gives built targets
# the build tree's rpath. CMAKE_SKIP_INSTALL_RPATH=ON (e.g. for a distribution's package,
# which installs into the system's library path) turns it off.
function(floodplane_set_install_rpath target install_dir)
  if(NOT BUILD_SHARED_LIBS)
    return()
  endif()
  if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
    set(rpath "${CMAKE_INSTALL_LIBDIR}")
  elseif(IS_ABSOLUTE "${install_dir}")
    set(rpath "${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}")
  else()
    # Both relative to the prefix: the path from one to the other is the same in any prefix.
    file(RELATIVE_PATH to_libdir "/prefix/${install_dir}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
    string(REGEX REPLACE "/$" "" to_libdir "${to_libdir}")
    set(rpath "$ORIGIN")
    if(to_libdir)
      string(APPEND rpath "/${to_libdir}")
    endif()
  endif()
  set_target_properties(${target} PROPERTIES INSTALL_RPATH "${rpath}")
endfunction()

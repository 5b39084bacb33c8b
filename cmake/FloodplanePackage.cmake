# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# The installed package: the API headers, the CMake package floodplane (components core, pcl,
# io and ros, one targets file each: floodplaneConfig.cmake.in says why) and the pkg-config files
# floodplane-core.pc and floodplane.pc. Included by the top-level CMakeLists.txt after the
# targets are defined (src/CMakeLists.txt installs them into their export sets).
include(CMakePackageConfigHelpers)
set(floodplane_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/floodplane)

# include/floodplane is the API: every header there is installed, and nothing else; without
# the PCL class, its headers are not, so that everything installed compiles and links.
if(FLOODPLANE_WITH_PCL)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/floodplane DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp")
else()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/floodplane DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.h" PATTERN "*.hpp"
          PATTERN "flood_fill_plane_segmentation.h" EXCLUDE PATTERN "impl" EXCLUDE)
endif()
install(FILES ${PROJECT_BINARY_DIR}/include/floodplane/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/floodplane)

# ---- CMake: find_package(floodplane CONFIG [COMPONENTS core pcl io ros]) ----------------
install(EXPORT floodplane-core-targets NAMESPACE floodplane:: DESTINATION ${floodplane_cmake_dir})
if(FLOODPLANE_WITH_PCL)
  install(EXPORT floodplane-pcl-targets NAMESPACE floodplane:: DESTINATION ${floodplane_cmake_dir})
endif()
# The file formats (io/) and the ROS node's conversions on them: built with PCL.
if(TARGET floodplane_io)
  install(EXPORT floodplane-io-targets NAMESPACE floodplane:: DESTINATION ${floodplane_cmake_dir})
endif()
if(TARGET floodplane_ros_conversion)
  install(EXPORT floodplane-ros-targets NAMESPACE floodplane:: DESTINATION ${floodplane_cmake_dir})
endif()
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/floodplaneConfig.cmake.in
  ${PROJECT_BINARY_DIR}/floodplaneConfig.cmake
  INSTALL_DESTINATION ${floodplane_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/floodplaneConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/floodplaneConfig.cmake ${PROJECT_BINARY_DIR}/floodplaneConfigVersion.cmake
        DESTINATION ${floodplane_cmake_dir})

# ---- pkg-config: floodplane-core.pc, floodplane.pc ----------------------------------------
# Relocatable: the prefix is found from where the .pc file lies (${pcfiledir}), so a package
# installed with `cmake --install build --prefix <anywhere>` describes itself correctly.
if(IS_ABSOLUTE "${CMAKE_INSTALL_LIBDIR}")
  set(floodplane_pc_prefix "${CMAKE_INSTALL_PREFIX}")
else()
  file(RELATIVE_PATH floodplane_pc_up "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
  string(REGEX REPLACE "/$" "" floodplane_pc_up "${floodplane_pc_up}")
  set(floodplane_pc_prefix "\${pcfiledir}/${floodplane_pc_up}")
endif()
foreach(dir LIBDIR INCLUDEDIR)
  if(IS_ABSOLUTE "${CMAKE_INSTALL_${dir}}")
    set(floodplane_pc_${dir} "${CMAKE_INSTALL_${dir}}")
  else()
    set(floodplane_pc_${dir} "\${prefix}/${CMAKE_INSTALL_${dir}}")
  endif()
endforeach()
configure_file(${PROJECT_SOURCE_DIR}/cmake/floodplane-core.pc.in ${PROJECT_BINARY_DIR}/floodplane-core.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/floodplane-core.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# floodplane.pc requires PCL's own .pc file, whose name differs: pcl_common-<major>.<minor> as
# PCL installs it, pcl_common in Debian's package. Without one there is no floodplane.pc.
if(FLOODPLANE_WITH_PCL)
  find_package(PkgConfig QUIET)
  if(PKG_CONFIG_FOUND)
    pkg_search_module(floodplane_pcl_common_pc QUIET pcl_common-${PCL_VERSION_MAJOR}.${PCL_VERSION_MINOR} pcl_common)
  endif()
  if(floodplane_pcl_common_pc_FOUND)
    set(floodplane_pc_pcl_common ${floodplane_pcl_common_pc_MODULE_NAME})
    # FLOODPLANE_NATIVE builds the PCL class without its explicit instantiations.
    set(floodplane_pc_cflags "")
    if(FLOODPLANE_NATIVE)
      set(floodplane_pc_cflags " -DPCL_NO_PRECOMPILE")
    endif()
    configure_file(${PROJECT_SOURCE_DIR}/cmake/floodplane.pc.in ${PROJECT_BINARY_DIR}/floodplane.pc @ONLY)
    install(FILES ${PROJECT_BINARY_DIR}/floodplane.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
  else()
    message(STATUS "floodplane: no pkg-config file of PCL's common module found, so no floodplane.pc "
                   "(floodplane-core.pc and the CMake package are installed)")
  endif()
endif()

# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# The Debian package: `cpack -G DEB` in a build tree (after the build) gives
# floodplane_<version>_<arch>.deb with everything `cmake --install` installs, under /usr: the
# libraries, the headers, the CMake package and the pkg-config files, the programs (with
# FLOODPLANE_BUILD_APPS) and the Python module (with FLOODPLANE_BUILD_PYTHON). Its
# dependencies are Debian's packages: those of the programs' and the module's shared
# libraries (dpkg-shlibdeps), and what the headers and the CMake package need to compile
# against (Eigen, PCL). `apt-get install ./floodplane_*.deb` installs it with them; the test
# Package.DebianPackageServesADownstreamProject (scripts/check_install.sh --deb) checks it.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME floodplane)
set(CPACK_PACKAGE_VENDOR "The floodplane authors")
set(CPACK_PACKAGE_CONTACT "The floodplane authors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
# The package's own directory tree is all it writes: no build tree path leaks in.
set(CPACK_PACKAGE_DIRECTORY ${PROJECT_BINARY_DIR}/package)

# One package of every install component but ros_node: the catkin package's node, messages and
# setup files (ros/CMakeLists.txt) belong in a catkin workspace or ROS's own packaging, and
# catkin writes its setup files to the configured prefix, not the package's.
get_cmake_property(floodplane_install_components COMPONENTS)
list(REMOVE_ITEM floodplane_install_components ros_node)
set(CPACK_COMPONENTS_ALL ${floodplane_install_components})
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_GROUPING ALL_COMPONENTS_IN_ONE)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "Plane segmentation of organized point clouds by seeded flood fill
 A drop-in replacement for PCL's OrganizedMultiPlaneSegmentation that needs no
 normals (floodplane::FloodFillPlaneSegmentation), its PCL-free core
 (floodplane::Segmenter), the command-line programs pcd_segment, pcd_compare and
 pcd_synth, and the CMake package and pkg-config files to build against them.")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What compiling against the installed headers and CMake package needs: Eigen always (the
# core's headers), PCL for the PCL class (find_package(floodplane) asks for its common module);
# dpkg-shlibdeps adds the shared libraries the programs and the module load.
set(floodplane_debian_depends "libeigen3-dev (>= ${floodplane_min_eigen_version})")
if(FLOODPLANE_WITH_PCL)
  # The component io (floodplane::io, the file formats) also compiles and links against libpng
  # and nlohmann's JSON headers.
  list(APPEND floodplane_debian_depends "libpcl-dev (>= ${floodplane_min_pcl_version})" libpng-dev
       "nlohmann-json3-dev (>= 3.9)")
endif()
if(FLOODPLANE_BUILD_PYTHON)
  # The module is built for this interpreter's ABI (python/CMakeLists.txt found it) and
  # imports numpy.
  get_directory_property(floodplane_python_version DIRECTORY python DEFINITION Python3_VERSION)
  string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" floodplane_python_abi "${floodplane_python_version}")
  set(floodplane_python_major ${CMAKE_MATCH_1})
  math(EXPR floodplane_next_python_minor "${CMAKE_MATCH_2} + 1")
  list(APPEND floodplane_debian_depends
       "python3 (>= ${floodplane_python_abi})" "python3 (<< ${floodplane_python_major}.${floodplane_next_python_minor})"
       python3-numpy)
endif()
list(JOIN floodplane_debian_depends ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "pkg-config, cmake")
include(CPack)

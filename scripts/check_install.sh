#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# Installs a build tree's floodplane into a temporary prefix and checks it as its users see it.
# Usage: scripts/check_install.sh <build-dir> [--deb] <check>...
# --deb: the prefix is the Debian package's instead of `cmake --install`'s: `cpack -G DEB`
#        makes floodplane_<version>_<arch>.deb from the build, which is checked (its files, its
#        Depends, `apt-get install --simulate` of it: every dependency a Debian package that is
#        installed or installable here) and extracted into a scratch root (dpkg-deb -x, nothing
#        installed on the system); the checks then build against <root>/usr.
# The checks:
#   consumer    examples/consumer (CMake, both components): the PCL drop-in, a point type of
#               its own both ways the README gives, every installed header on its own
#   core        examples/consumer/core (CMake, COMPONENTS core) where PCL cannot be found
#   components  what find_package(floodplane) answers to unknown, missing and optional components
#   pkg-config  one-file programs built with `pkg-config --cflags --libs` floodplane-core (and
#               floodplane, when the PCL class is installed)
#   io          test/package/io_consumer (CMake, COMPONENTS io ros): the file formats' library and
#               the ROS node's conversions on it, each of its headers on its own; and no header
#               installed but the API's (include/floodplane), the file formats'
#               (include/floodplane/io) and the conversions' (include/floodplane_ros_conversion)
# When the install has shared libraries (BUILD_SHARED_LIBS=ON), the programs are also checked to
# use them.
#
# "Where PCL cannot be found" stands for a machine without PCL: CMAKE_DISABLE_FIND_PACKAGE_PCL
# makes every find_package(PCL) in the project fail as if PCL were not installed, PCL's headers
# are on no default include path (/usr/include/pcl-1.13), so a header that included one would
# not compile, and `ldd` shows that no PCL library is linked. The same project configured with
# PCL findable leaves no PCL_DIR in its cache: nothing even looked for PCL.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
[ $# -ge 2 ] || { echo "usage: $0 <build-dir> [--deb] <consumer|core|components|pkg-config|io>..." >&2; exit 2; }
build=$(cd "$1" && pwd)
shift
from_deb=no
if [ "$1" = --deb ]; then
  from_deb=yes
  shift
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() { echo "check_install: $*" >&2; exit 1; }
# Runs a command with its output in a log, which is shown when it fails.
logged() {
  local log=$1
  shift
  "$@" > "$log" 2>&1 || { cat "$log"; fail "failed: $*"; }
}
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$build/CMakeCache.txt"; }
cxx=$(cache_value CMAKE_CXX_COMPILER)

# The package as `apt-get install ./floodplane_*.deb` takes it: one file named as Debian names
# packages, holding the library, its headers, CMake and pkg-config files (and the programs and
# Python module when the build has them), depending on what they need.
check_deb() {  # <deb>
  local deb=$1 files depends
  files=$(dpkg-deb --contents "$deb")
  depends=$(dpkg-deb --field "$deb" Depends)
  echo "check_install: $(basename "$deb"): Depends: $depends"
  local wanted=(./usr/lib/libfloodplane_core ./usr/include/floodplane/segmenter.h ./usr/include/floodplane/version.h
                ./usr/lib/cmake/floodplane/floodplaneConfig.cmake ./usr/lib/pkgconfig/floodplane-core.pc)
  [ "$(cache_value FLOODPLANE_WITH_PCL)" = ON ] &&
    wanted+=(./usr/lib/libfloodplane. ./usr/include/floodplane/flood_fill_plane_segmentation.h
             ./usr/lib/pkgconfig/floodplane.pc)
  [ "$(cache_value FLOODPLANE_BUILD_APPS)" = ON ] &&
    wanted+=(./usr/bin/pcd_segment ./usr/bin/pcd_compare ./usr/bin/pcd_synth)
  [ "$(cache_value FLOODPLANE_BUILD_PYTHON)" = ON ] && wanted+=(./usr/lib/python3/dist-packages/floodplane/_floodplane)
  local file
  for file in "${wanted[@]}"; do
    grep -qF " $file" <<< "$files" || fail "$(basename "$deb") has no $file*"
  done
  grep -qE ' \./usr/local/| \./(home|tmp|work)/' <<< "$files" && fail "$(basename "$deb") installs outside /usr"
  grep -q 'libeigen3-dev' <<< "$depends" || fail "$(basename "$deb") does not depend on libeigen3-dev"
  if [ "$(cache_value FLOODPLANE_BUILD_APPS)" = ON ]; then
    # dpkg-shlibdeps named the packages of the programs' shared libraries.
    grep -q 'libpcl-io' <<< "$depends" || fail "$(basename "$deb") does not depend on PCL's io library (shlibdeps)"
  fi
  # apt resolves every dependency against this machine's packages and lists (nothing installed).
  logged "$work/apt-simulate.log" apt-get install --simulate --no-install-recommends "$deb"
  grep -q '^Inst floodplane ' "$work/apt-simulate.log" || { cat "$work/apt-simulate.log"; fail "apt-get would not install it"; }
}

if [ "$from_deb" = yes ]; then
  # cpack runs the build's install rules into a staging folder of its own, under -B.
  logged "$work/cpack.log" cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/package"
  debs=("$work"/package/floodplane_*.deb)
  [ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || { cat "$work/cpack.log"; fail "cpack made no floodplane_*.deb"; }
  check_deb "${debs[0]}"
  dpkg-deb --extract "${debs[0]}" "$work/root"
  prefix=$work/root/usr
  if [ -x "$prefix/bin/pcd_segment" ]; then
    "$prefix/bin/pcd_segment" --help > /dev/null || fail "the packaged pcd_segment does not run"
  fi
  if [ -d "$prefix/lib/python3/dist-packages/floodplane" ]; then
    PYTHONPATH=$prefix/lib/python3/dist-packages /usr/bin/python3 -c \
      "import floodplane, sys; sys.exit(floodplane.__file__.startswith('$prefix/') is False)" ||
      fail "the packaged Python module does not import from the package"
  fi
else
  prefix=$work/prefix
  cmake --install "$build" --prefix "$prefix" > "$work/install.log"
fi
config=$(find "$prefix" -name floodplaneConfig.cmake)
config_dir=$(dirname "$config")
libdir=$(dirname "$(find "$prefix" -name 'libfloodplane_core.*' | head -n 1)")
shared=no
[ -e "$libdir/libfloodplane_core.so" ] && shared=yes
with_pcl=no
[ -f "$config_dir/floodplane-pcl-targets.cmake" ] && with_pcl=yes

configure() {  # <source> <binary-dir> [cmake options...]
  local source=$1 binary=$2
  shift 2
  logged "$binary.configure.log" cmake -S "$source" -B "$binary" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_PREFIX_PATH="$prefix" "$@"
}
# A program that segments, built against the install, uses floodplane's shared libraries from
# the install when they are shared, and no PCL library when it needs none.
check_links() {  # <program> <needs-pcl: yes|no>
  local libraries
  libraries=$(ldd "$1")
  if [ "$shared" = yes ] && ! grep -q "libfloodplane_core\.so.* => $libdir/" <<< "$libraries"; then
    fail "$(basename "$1") does not use the installed libfloodplane_core.so:"$'\n'"$libraries"
  fi
  if [ "$2" = no ] && grep -q libpcl_ <<< "$libraries"; then
    fail "$(basename "$1") links PCL, but floodplane::core should not need it"
  fi
}

check_consumer() {
  [ "$with_pcl" = yes ] || fail "consumer: this install has no PCL class (FLOODPLANE_WITH_PCL=OFF)"
  configure "$root/examples/consumer" "$work/consumer"
  logged "$work/consumer.build.log" cmake --build "$work/consumer" --parallel "$(nproc)"
  for program in consumer custom_point_no_precompile custom_point_impl_headers; do
    "$work/consumer/$program"
    check_links "$work/consumer/$program" yes
  done
  "$work/consumer/headers_link"  # calls nothing: the linker may drop the libraries
}

check_core() {
  grep -qi pcl "$config_dir"/floodplane-core-targets*.cmake && fail "floodplane-core-targets mentions PCL"
  if [ "$with_pcl" = no ] && [ -n "$(find "$prefix" -name 'flood_fill_plane_segmentation.*')" ]; then
    fail "the PCL class's headers are installed without the PCL class"
  fi
  # With PCL findable: the core's package does not look for it.
  configure "$root/examples/consumer/core" "$work/core"
  grep -q '^PCL_DIR' "$work/core/CMakeCache.txt" && fail "find_package(floodplane COMPONENTS core) looked for PCL"
  # Without: it configures, builds and runs all the same.
  configure "$root/examples/consumer/core" "$work/core" -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON
  logged "$work/core.build.log" cmake --build "$work/core" --parallel "$(nproc)"
  "$work/core/core_consumer"
  check_links "$work/core/core_consumer" no
  "$work/core/core_headers_link"
}

# find_package(floodplane) from test/package/find_components, expected to fail with a message
# that contains `expected` (CMake wraps messages: lines are joined before comparing).
expect_find_failure() {  # <name> <expected> [cmake options...]
  local name=$1 expected=$2
  shift 2
  if cmake -S "$root/test/package/find_components" -B "$work/$name" -DCMAKE_PREFIX_PATH="$prefix" "$@" \
       > "$work/$name.log" 2>&1; then
    cat "$work/$name.log"
    fail "components: $name: find_package(floodplane) succeeded, expected it to fail"
  fi
  local message
  message=$(tr -s '\n ' '  ' < "$work/$name.log")
  if ! grep -qF -- "$expected" <<< "$message"; then
    cat "$work/$name.log"
    fail "components: $name: the message does not say \"$expected\""
  fi
  echo "components: $name fails as it should: $(sed -n 's/.*Reason given by package: *//; s/ -- Configuring incomplete.*//p' <<< "$message")"
}
# ... and expected to succeed with the result line `expected` (find_components prints it).
expect_find() {  # <name> <expected> [cmake options...]
  local name=$1 expected=$2
  shift 2
  logged "$work/$name.log" cmake -S "$root/test/package/find_components" -B "$work/$name" \
    -DCMAKE_PREFIX_PATH="$prefix" "$@"
  grep -qF -- "$expected" "$work/$name.log" || { cat "$work/$name.log"; fail "components: $name: expected \"$expected\""; }
  echo "components: $name: $expected"
}

check_components() {
  expect_find_failure unknown "unknown component 'nonsense': floodplane's components are core" \
    -DFLOODPLANE_COMPONENTS="core;nonsense"
  expect_find core-without-pcl "find_components: core=TRUE pcl= targets: core=yes floodplane=no" \
    -DFLOODPLANE_COMPONENTS=core -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON
  expect_find optional-pcl-without-pcl "find_components: core=TRUE pcl=FALSE targets: core=yes floodplane=no" \
    -DFLOODPLANE_COMPONENTS=core -DFLOODPLANE_OPTIONAL_COMPONENTS=pcl -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON
  if [ "$with_pcl" = yes ]; then
    expect_find io "io=TRUE ros= targets: io=yes ros=no" -DFLOODPLANE_COMPONENTS=io
    expect_find ros "io= ros=TRUE targets: io=yes ros=yes" -DFLOODPLANE_COMPONENTS=ros
    expect_find_failure io-without-pcl "component io (floodplane::io) needs PCL" \
      -DFLOODPLANE_COMPONENTS=io -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON
    expect_find_failure pcl-without-pcl "component pcl (floodplane::floodplane) needs PCL 1.10 or later" \
      -DFLOODPLANE_COMPONENTS=pcl -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON
    expect_find_failure default-without-pcl "component pcl (floodplane::floodplane) needs PCL" \
      -DCMAKE_DISABLE_FIND_PACKAGE_PCL=ON
    expect_find pcl "find_components: core=TRUE pcl=TRUE targets: core=yes floodplane=yes" -DFLOODPLANE_COMPONENTS=pcl
    expect_find default "find_components: core=TRUE pcl=TRUE targets: core=yes floodplane=yes"
  else
    expect_find_failure pcl-not-built "component pcl: this floodplane was built without it" \
      -DFLOODPLANE_COMPONENTS=pcl
    expect_find_failure io-not-built "component io: this floodplane was built without it" \
      -DFLOODPLANE_COMPONENTS=io
  fi
}

check_pkg_config() {
  local pc_dir
  pc_dir=$(dirname "$(find "$prefix" -name floodplane-core.pc)")
  export PKG_CONFIG_PATH=$pc_dir
  # A shared library outside the loader's path is found through LD_LIBRARY_PATH, as a
  # pkg-config user would run it.
  export LD_LIBRARY_PATH=$libdir${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
  # shellcheck disable=SC2046  # pkg-config's output is a list of words
  logged "$work/pc-core.log" "$cxx" -std=c++17 -O2 "$root/examples/consumer/core/core_main.cpp" \
    $(pkg-config --cflags --libs floodplane-core) -o "$work/core_pkg_config"
  "$work/core_pkg_config"
  check_links "$work/core_pkg_config" no
  if [ "$with_pcl" = yes ]; then
    [ -f "$pc_dir/floodplane.pc" ] || fail "pkg-config: the PCL class is installed, but floodplane.pc is not"
    # shellcheck disable=SC2046
    logged "$work/pc-pcl.log" "$cxx" -std=c++17 -O2 "$root/examples/consumer/main.cpp" \
      $(pkg-config --cflags --libs floodplane) -o "$work/pkg_config"
    "$work/pkg_config"
    check_links "$work/pkg_config" yes
  elif [ -f "$pc_dir/floodplane.pc" ]; then
    fail "pkg-config: floodplane.pc is installed without the PCL class"
  fi
}

check_io() {
  [ -f "$config_dir/floodplane-io-targets.cmake" ] || fail "io: this install has no component io"
  configure "$root/test/package/io_consumer" "$work/io-consumer"
  logged "$work/io-consumer.build.log" cmake --build "$work/io-consumer" --parallel "$(nproc)"
  "$work/io-consumer/io_consumer"
  "$work/io-consumer/ros_conversion_consumer"
  "$work/io-consumer/io_headers_link"
  local stray
  # Allowed: the API, its template definitions, io's and the conversions' headers, and where the
  # ROS build is on, the catkin package's generated messages and dynamic_reconfigure config.
  stray=$(cd "$prefix/include" && find . -type f | sed 's|^\./||' |
    grep -vE '^floodplane/([^/]+|io/[^/]+)\.h$|^floodplane/impl/[^/]+\.hpp$|^floodplane_ros_conversion/[^/]+\.h$' |
    grep -vE '^floodplane_ros/[A-Za-z]+\.h$' || true)
  [ -z "$stray" ] || fail "io: headers installed outside the API, io's and the conversions' folders:"$'\n'"$stray"
}

for check in "$@"; do
  case $check in
    consumer) check_consumer ;;
    core) check_core ;;
    components) check_components ;;
    pkg-config) check_pkg_config ;;
    io) check_io ;;
    *) echo "check_install: unknown check '$check'" >&2; exit 2 ;;
  esac
  echo "check_install: $check: passed"
done

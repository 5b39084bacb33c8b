# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# floodplane_consumer_check_headers(<name> <target> [EXCLUDE <regex>] [AT_LEAST <count>]):
# every installed floodplane header (those whose path matches <regex> left out) compiles on
# its own, and twice in a row, with nothing but <target>'s usage requirements: one translation
# unit per header, in a library that the executable <name> links. Fails at configure time
# when fewer than <count> headers (default 1) are found, so that a wrong include path is not
# a check of nothing.
set(floodplane_consumer_dir ${CMAKE_CURRENT_LIST_DIR})
function(floodplane_consumer_check_headers name target)
  cmake_parse_arguments(ARG "" "EXCLUDE;AT_LEAST" "" ${ARGN})
  if(NOT ARG_AT_LEAST)
    set(ARG_AT_LEAST 1)
  endif()
  get_target_property(include_dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  set(units)
  foreach(dir IN LISTS include_dirs)
    file(GLOB_RECURSE headers RELATIVE ${dir} ${dir}/floodplane/*.h ${dir}/floodplane/*.hpp)
    foreach(header IN LISTS headers)
      if(ARG_EXCLUDE AND header MATCHES "${ARG_EXCLUDE}")
        continue()
      endif()
      string(MAKE_C_IDENTIFIER ${header} unit)
      set(source ${CMAKE_CURRENT_BINARY_DIR}/header_units/${name}/${unit}.cpp)
      file(WRITE ${source} "#include <${header}>\n#include <${header}>\n")
      list(APPEND units ${source})
    endforeach()
  endforeach()
  list(LENGTH units count)
  if(count LESS ARG_AT_LEAST)
    message(FATAL_ERROR "expected at least ${ARG_AT_LEAST} installed floodplane headers under ${include_dirs}, "
                        "found ${count}")
  endif()
  message(STATUS "${PROJECT_NAME}: checking ${count} installed headers one by one with ${target}")
  add_library(${name}_units STATIC ${units})
  target_link_libraries(${name}_units PUBLIC ${target})
  add_executable(${name} ${floodplane_consumer_dir}/headers_link.cpp)
  target_link_libraries(${name} PRIVATE ${name}_units)
endfunction()

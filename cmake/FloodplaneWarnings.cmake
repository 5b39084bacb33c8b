# SPDX-FileCopyrightText: 2026 The floodplane authors
# SPDX-License-Identifier: BSD-3-Clause
# One place that decides the warnings for every floodplane target (KISS-ICP style).
function(floodplane_set_warnings target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow
                                             -Wnon-virtual-dtor -Wold-style-cast
                                             -Wcast-align -Woverloaded-virtual -Wconversion)
    if(FLOODPLANE_WERROR)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  endif()
endfunction()

# Opt-in native code generation. Debian's PCL is built for baseline x86-64; mixing
# -march=native objects with it changes Eigen's alignment and crashes at free(), so the
# option also sets PCL_NO_PRECOMPILE to build PCL's templates with the same flags.
# -ffp-contract=off: on a CPU with FMA the compiler would otherwise fuse a multiply and an add
# in some loops and not in others, and the scalar, four- and eight-lane code (src/util/simd.h) would
# no longer give the same floats, nor the same labels as the baseline build.
function(floodplane_set_arch target)
  if(FLOODPLANE_NATIVE)
    target_compile_options(${target} PRIVATE -march=native -ffp-contract=off)
    target_compile_definitions(${target} PUBLIC PCL_NO_PRECOMPILE)
  endif()
endfunction()

# The one SIMD switch: FLOODPLANE_SIMD=OFF builds the core's four-pixel loops pixel by pixel
# (as on CPUs without SSE2), through a private definition of every target that compiles the
# core's sources or reaches its internals (the unit tests); src/util/simd.h reads it.
function(floodplane_set_simd target)
  if(NOT FLOODPLANE_SIMD)
    target_compile_definitions(${target} PRIVATE FLOODPLANE_NO_SIMD)
  endif()
endfunction()

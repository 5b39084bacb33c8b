// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "util/simd.h"

namespace floodplane {

bool simdEnabled() { return FLOODPLANE_SIMD; }

bool cpuHasAvx() {
#if FLOODPLANE_AVX
  // GCC's and Clang's check includes the operating system's support (XSAVE of the AVX state).
  // __builtin_cpu_init first: a caller may get here from a static constructor, before the
  // runtime's own has run.
  static const bool has_avx = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx") != 0;
  }();
  return has_avx;
#else
  return false;
#endif
}

}  // namespace floodplane

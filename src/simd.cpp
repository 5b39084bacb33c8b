#include "simd.h"

namespace floodplane {

bool simdEnabled() { return FLOODPLANE_SIMD; }

bool cpuHasAvx() {
#if FLOODPLANE_AVX
  // GCC's and Clang's check includes the operating system's support (XSAVE of the AVX state).
  static const bool has_avx = __builtin_cpu_supports("avx");
  return has_avx;
#else
  return false;
#endif
}

}  // namespace floodplane

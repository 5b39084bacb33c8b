#include "simd.h"

namespace floodplane {

bool simdEnabled() { return FLOODPLANE_SIMD; }

}  // namespace floodplane

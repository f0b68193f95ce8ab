#include "host/octree_lanes.h"

#include <immintrin.h>

#include "visibility/ray_patch_test.h"  // kRayEpsilon

// The kernels pass 64-byte vectors between inlined static functions only.
#pragma GCC diagnostic ignored "-Wpsabi"

namespace ncube::octree_lanes {

namespace sse2 {
#define NCUBE_LANES_BITS 128
#include "host/octree_lanes_kernel.inc"
#undef NCUBE_LANES_BITS
}  // namespace sse2

#pragma GCC push_options
#pragma GCC target("avx2")
namespace avx2 {
#define NCUBE_LANES_BITS 256
#include "host/octree_lanes_kernel.inc"
#undef NCUBE_LANES_BITS
}  // namespace avx2
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("avx512f")
namespace avx512 {
#define NCUBE_LANES_BITS 512
#include "host/octree_lanes_kernel.inc"
#undef NCUBE_LANES_BITS
}  // namespace avx512
#pragma GCC pop_options

bool host_runs(Isa isa) {
  switch (isa) {
    case Isa::kSse2:
      return true;
    case Isa::kAvx2:
      return __builtin_cpu_supports("avx2");
    case Isa::kAvx512:
      return __builtin_cpu_supports("avx512f");
  }
  return false;
}

Isa best_isa() {
  static const Isa best = host_runs(Isa::kAvx512) ? Isa::kAvx512
                          : host_runs(Isa::kAvx2) ? Isa::kAvx2
                                                  : Isa::kSse2;
  return best;
}

const char* isa_name(Isa isa) {
  switch (isa) {
    case Isa::kSse2:
      return "sse2";
    case Isa::kAvx2:
      return "avx2";
    case Isa::kAvx512:
      return "avx512";
  }
  return "?";
}

Kernels kernels(Isa isa) {
  switch (isa) {
    case Isa::kAvx512:
      return {&avx512::rays, &avx512::meets_root, &avx512::children_met, &avx512::leaf_tests};
    case Isa::kAvx2:
      return {&avx2::rays, &avx2::meets_root, &avx2::children_met, &avx2::leaf_tests};
    case Isa::kSse2:
      break;
  }
  return {&sse2::rays, &sse2::meets_root, &sse2::children_met, &sse2::leaf_tests};
}

}  // namespace ncube::octree_lanes

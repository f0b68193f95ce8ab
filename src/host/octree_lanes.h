// The octree walk's slab tests (visibility/octree.h, Octree::segment_meets_cell) for the rays
// of a packet (fast_octree.h), eight rays per step, compiled three times: for SSE2 (every
// x86-64), AVX2 and AVX-512; best_isa() picks the widest the host's processor runs. The
// arithmetic is the walk's, lane by lane: IEEE division, and max and min as the walk's
// comparisons give them; no fused multiply-add (the build forbids contraction, CMakeLists.txt).
// So every variant gives the same bits (tests/fast_octree_test.cpp runs each variant the host
// can run against the literal walk).
//
// Quotients are reused down the tree: a child shares each of its six bounds with its parent
// or with its parent's middle (grown by the same pad, stored as the same doubles), so the
// walk's quotient (bound - from) / delta of a child's bound is the one computed for the parent
// or for its middle. A cell's children need only the two middle quotients per axis and ray.
//
// Contract (host side): it changes no answer and no count.
#pragma once

#include <cstdint>

#include "host/host_side.h"

namespace ncube::octree_lanes {

constexpr int kRays = 64;  // a packet's rays at most (kMaxShooterParts)

enum class Isa { kSse2, kAvx2, kAvx512 };
Isa best_isa();           // the widest variant the host's processor runs
bool host_runs(Isa isa);  // whether it runs this one
const char* isa_name(Isa isa);

// The root cell against rays 0 .. size-1 of a packet from `from` (deltas per axis, kRays
// each): bit r set when ray r meets the cell (grown bounds lo x, y, z, hi x, y, z). Writes each
// ray's raw quotients (bound - from) / delta of the lower and upper bound per axis.
struct RootQuery {
  const double* bounds;
  const double* from;
  const double* delta[3];
  int size;
  double* quotient_lo[3];
  double* quotient_hi[3];
};

// The 8 children of an inner cell against the packet's `rays`: `lower` and `upper` are the
// grown bounds of children 0 and 7 (all lower halves, all upper halves), own_lo / own_hi the
// raw quotients of the cell's own bounds per axis and ray (as written for it before). Sets
// met[child] to the rays that meet that child, and writes per axis the quotients of the four
// half bounds (lower half lo, lower half hi, upper half lo, upper half hi; kRays each) for the
// children's own children. Rays in the same 8-lane group as a ray of `rays` get theirs too.
struct ChildrenQuery {
  const double* lower;
  const double* upper;
  const double* from;
  const double* delta[3];
  const double* own_lo[3];
  const double* own_hi[3];
  double* quarters[3];
  std::uint64_t rays;
};

// A leaf's patch in the fast form of axis_patch_test.h (plane a = const, edges along the
// other axes) against the packet's rays in `asking`: AxisPatchTest::crosses and side, the
// same operations lane by lane. `target_on_axis`: the rays' targets' coordinate a (kRays);
// `side_of_from`: the point's side of the patch's plane.
struct LeafQuery {
  int axis, edges;
  const std::int8_t* other;
  double normal, offset;
  const double* signed_length;
  const double* corner;
  const double* from;
  const double* delta[3];
  const double* target_on_axis;
  double tolerance;
  int side_of_from;
  std::uint64_t asking;
};
struct LeafAnswer {
  std::uint64_t crossing;  // rays whose target lies strictly on the other side of the plane
  std::uint64_t blocked;   // rays the patch blocks
};

// A point's rays to targets 0 .. count-1 (per axis, kRays each): delta[axis][r] = target -
// from, as the walk computes it, and per axis the rays that run downwards (delta < 0).
struct RaysQuery {
  const double* targets[3];
  const double* from;
  int count;
  double* delta[3];
  std::uint64_t downwards[3];
};

struct Kernels {
  void (*rays)(RaysQuery& query);
  std::uint64_t (*meets_root)(const RootQuery& query);
  void (*children_met)(const ChildrenQuery& query, std::uint64_t met[8]);
  LeafAnswer (*leaf_tests)(const LeafQuery& query);
};
Kernels kernels(Isa isa);

}  // namespace ncube::octree_lanes

// The one identity of "the same question" for every host-side cache and memo (the answer
// cache, the scene blockers' memo, the shooter's target sides, the blocks posted to the
// threads computing ahead): the same shooter is the same patch with the same ray targets,
// the same block the same points on the same patches, both compared bit for bit. Not with
// ==, which takes -0.0 for 0.0: an answer is reused only for the very bits it was computed
// from, so a cache can never hand back an answer to a different question.
#pragma once

#include <cstdint>
#include <vector>

#include "host/host_side.h"
#include "visibility/point_block.h"
#include "visibility/shooter.h"

namespace ncube {

std::uint64_t question_hash(const Shooter& shooter);  // of its patch and targets
std::uint64_t question_hash(const PointBlock& block);  // of its points and patches
// The same points on the same patches, bit for bit.
bool same_block(const PointBlock& a, const PointBlock& b);

// A shooter as a cache keeps it.
struct ShooterKey {
  int patch = -1;
  std::vector<Vec3> targets;  // the shooter's part_count ray targets

  ShooterKey() = default;
  explicit ShooterKey(const Shooter& shooter);
  bool is(const Shooter& shooter) const;
  std::size_t bytes() const { return targets.size() * sizeof(Vec3); }
};

// A block as a cache keeps it.
struct BlockKey {
  std::vector<Vec3> points;
  std::vector<int> patches;

  BlockKey() = default;
  explicit BlockKey(const PointBlock& block);
  bool is(const PointBlock& block) const;
  PointBlock view() const { return PointBlock(points, patches); }
  std::size_t bytes() const { return points.size() * (sizeof(Vec3) + sizeof(int)); }
};

}  // namespace ncube

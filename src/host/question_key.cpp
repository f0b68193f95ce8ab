#include "host/question_key.h"

#include <cstring>

namespace ncube {
namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t word) {
  h ^= word + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  h *= 0xbf58476d1ce4e5b9ull;
  return h ^ (h >> 31);
}

std::uint64_t bits_of(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

bool same_bits(const void* a, const void* b, std::size_t bytes) {
  return bytes == 0 || std::memcmp(a, b, bytes) == 0;
}

}  // namespace

std::uint64_t question_hash(const Shooter& shooter) {
  std::uint64_t h = mix(std::uint64_t(std::uint32_t(shooter.patch)), std::uint64_t(shooter.part_count));
  for (int k = 0; k < shooter.part_count; ++k) {
    h = mix(h, bits_of(shooter.targets[k].x));
    h = mix(h, bits_of(shooter.targets[k].y));
    h = mix(h, bits_of(shooter.targets[k].z));
  }
  return h;
}

std::uint64_t question_hash(const PointBlock& block) {
  std::uint64_t h = mix(0, block.count);
  for (std::size_t k = 0; k < block.count; ++k) {
    h = mix(h, bits_of(block.points[k].x));
    h = mix(h, bits_of(block.points[k].y));
    h = mix(h, bits_of(block.points[k].z));
    h = mix(h, std::uint64_t(std::uint32_t(block.patches[k])));
  }
  return h;
}

ShooterKey::ShooterKey(const Shooter& shooter)
    : patch(shooter.patch),
      targets(shooter.targets.begin(), shooter.targets.begin() + shooter.part_count) {}

bool ShooterKey::is(const Shooter& shooter) const {
  return patch == shooter.patch && targets.size() == std::size_t(shooter.part_count) &&
         same_bits(targets.data(), shooter.targets.data(), targets.size() * sizeof(Vec3));
}

BlockKey::BlockKey(const PointBlock& block)
    : points(block.points, block.points + block.count),
      patches(block.patches, block.patches + block.count) {}

bool same_block(const PointBlock& a, const PointBlock& b) {
  return a.count == b.count && same_bits(a.points, b.points, a.count * sizeof(Vec3)) &&
         same_bits(a.patches, b.patches, a.count * sizeof(int));
}

bool BlockKey::is(const PointBlock& block) const { return same_block(view(), block); }

}  // namespace ncube

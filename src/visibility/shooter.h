// The shooting patch as every node sees it: its geometry cut regularly into M parts (paper
// section 2.2: "subdividing the shooting patch regularly into M parts"), one ray target per
// part, and the unshot radiosity it distributes.
#pragma once

#include <array>
#include <cstdint>
#include <glm/geometric.hpp>

#include "scene/scene.h"

namespace ncube {

// M = k * k parts, k x k cells of the patch's bilinear grid; at most 64 so that one
// visibility answer is one 64-bit mask (bit p set: part p is not blocked).
constexpr int kMaxShooterParts = 64;
using PartMask = std::uint64_t;

bool is_valid_part_count(int samples);  // a perfect square in [1, 64]

struct Shooter {
  int patch = -1;
  Polygon polygon;
  Vec3 normal{0.0};
  Rgb unshot{0.0};  // unshot radiosity, distributed by this shot
  int part_count = 0;
  std::array<Polygon, kMaxShooterParts> parts{};
  std::array<Vec3, kMaxShooterParts> targets{};  // part centroids: the rays' end points
  // The corners of the parts: grid[j * (side + 1) + i] is corner (i, j) of the side x side
  // grid; part j * side + i is (i, j), (i+1, j), (i+1, j+1), (i, j+1). A triangle's top row
  // is its vertex v2 (its last row of parts are triangles).
  int side = 0;
  std::array<Vec3, (8 + 1) * (8 + 1)> grid{};

  PartMask all_parts() const {
    return part_count == 64 ? ~PartMask(0) : (PartMask(1) << part_count) - 1;
  }
};

Shooter make_shooter(const Scene& scene, int patch, const Rgb& unshot, int samples);

// Whether a point lies in front of the shooter's plane: the shooter emits from its front only.
inline bool shooter_lights(const Shooter& shooter, const Vec3& point) {
  return glm::dot(shooter.normal, point - shooter.polygon[0]) > 0.0;
}

// Whether a receiving point can see the front of the shooter at all: it lies in front of
// the shooter's plane and some shooter vertex lies in front of its own plane. Receivers that
// fail get no rays and no light (their form factor is zero).
bool faces_shooter(const Vec3& point, const Vec3& normal, const Shooter& shooter);

}  // namespace ncube

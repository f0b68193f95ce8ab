// A block of visibility points (section 3: the radiosity processor sends its receivers'
// points "in blocks of e.g. 100"): each point with the patch it lies on, which is excluded
// from its rays' tests. A view: the points and patches are held by whoever made the block.
#pragma once

#include <cstddef>
#include <vector>

#include "geometry/polygon.h"

namespace ncube {

struct PointBlock {
  const Vec3* points = nullptr;
  const int* patches = nullptr;  // patches[k]: the scene patch point k lies on (-1: none)
  std::size_t count = 0;

  PointBlock() = default;
  PointBlock(const Vec3* points, const int* patches, std::size_t count)
      : points(points), patches(patches), count(count) {}
  PointBlock(const std::vector<Vec3>& points, const std::vector<int>& patches)
      : points(points.data()), patches(patches.data()), count(points.size()) {}

  // Points [begin, end) of this block.
  PointBlock part(std::size_t begin, std::size_t end) const {
    return PointBlock(points + begin, patches + begin, end - begin);
  }
  bool empty() const { return count == 0; }
};

}  // namespace ncube

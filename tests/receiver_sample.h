// Test helper: receiving points sampled from a scene's elements for one shooter (element
// centres, never on the shooter's own patch), as the visibility tests of several modules
// compare them with the brute-force loop.
#pragma once

#include <random>
#include <vector>

#include "scene/scene.h"

namespace ncube {

struct ReceiverSample {
  std::vector<Vec3> points;
  std::vector<int> patches;  // the patch of each point
};

inline ReceiverSample sample_receivers(const Scene& scene, int shooter_patch, int count,
                                       std::mt19937& random) {
  std::uniform_int_distribution<int> pick(0, int(scene.elements.size()) - 1);
  ReceiverSample sample;
  while (int(sample.points.size()) < count) {
    const Element& e = scene.elements[std::size_t(pick(random))];
    if (e.patch == shooter_patch) continue;
    sample.points.push_back(e.centre);
    sample.patches.push_back(e.patch);
  }
  return sample;
}

}  // namespace ncube

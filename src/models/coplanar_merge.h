// --merge-coplanar (docs/scene-format.md, "Importing models"): pairs of triangles that make a
// planar convex quad of one material become that quad.
#pragma once

#include <vector>

#include "models/model_material.h"

namespace ncube::models {

struct ImportedPatch {
  std::vector<Point> corners;
  Material material;
};

// The patches with each such pair merged; `merged` counts the pairs.
std::vector<ImportedPatch> merge_coplanar(const std::vector<ImportedPatch>& patches, long& merged);

}  // namespace ncube::models

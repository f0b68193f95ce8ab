// Each imported patch's element grid (a model has none of its own): --element-size or a share
// of --element-budget by area (docs/scene-format.md, "Importing models").
#pragma once

#include <utility>
#include <vector>

#include <glm/vec3.hpp>

namespace ncube::models {

// nu x nv for a patch with these corners: cells of about `size` on a side when size > 0,
// else `count` elements shaped after its two edge lengths; 1 to 1024 a side.
std::pair<long, long> grid(const std::vector<glm::dvec3>& corners, double size, double count);

}  // namespace ncube::models

// Adaptive subdivision (paper section 4.1): "subdividing the elements adaptively, e.g. if
// the radiosity values at the corners of an element are too different. The test is done
// after the energy has been distributed to all elements." The criterion and its limits are
// options (docs/model.md, "Adaptive subdivision").
#pragma once

#include <vector>

#include "scene/patch_mesh.h"

namespace ncube {

struct SubdivisionOptions {
  bool enabled = false;    // --subdivide
  // --subdivide-contrast: an element is cut when its corner luminances Y differ by more
  // than this contrast, (Ymax - Ymin) / (Ymax + Ymin).
  double contrast = 0.5;
  int max_level = 3;       // --subdivide-max-level: deepest cell level (0: the scene's grid)
  double min_area = 0.0;   // --subdivide-min-area: no child smaller than this (scene units^2)
};

// The contrast of element k's corner luminances (0 when all are dark).
double corner_contrast(const PatchMesh& mesh, const std::vector<Rgb>& radiosity, std::size_t k);

// Whether element k (of `cell`, `area`) is to be cut: its corner contrast exceeds the
// threshold and its children stay within the level and area limits.
bool should_cut(const SubdivisionOptions& options, const PatchMesh& mesh,
                const std::vector<Rgb>& radiosity, std::size_t k, const ElementCell& cell,
                double area);

}  // namespace ncube

#include "radiosity/subdivision.h"

#include <algorithm>

namespace ncube {

double corner_contrast(const PatchMesh& mesh, const std::vector<Rgb>& radiosity, std::size_t k) {
  double lo = 0.0, hi = 0.0;
  for (int c = 0; c < mesh.corner_count(k); ++c) {
    const double y = luminance(mesh.corner_radiosity(radiosity, k, c));
    lo = c == 0 ? y : std::min(lo, y);
    hi = c == 0 ? y : std::max(hi, y);
  }
  return hi + lo > 0.0 ? (hi - lo) / (hi + lo) : 0.0;
}

bool should_cut(const SubdivisionOptions& options, const PatchMesh& mesh,
                const std::vector<Rgb>& radiosity, std::size_t k, const ElementCell& cell,
                double area) {
  if (cell.level >= options.max_level || cell.level >= kMaxCellLevel) return false;
  if (0.25 * area < options.min_area) return false;
  return corner_contrast(mesh, radiosity, k) > options.contrast;
}

}  // namespace ncube

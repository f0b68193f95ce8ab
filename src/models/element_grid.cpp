#include "models/element_grid.h"

#include <algorithm>
#include <cmath>

#include "models/face_shapes.h"

namespace ncube::models {

// The element grid of a patch: `count` elements shaped after its two edge lengths, or cells
// of about `size` on a side.
std::pair<long, long> grid(const std::vector<Point>& corners, double size, double count) {
  const double a = norm(corners[1] - corners[0]);
  const double b = norm(corners.back() - corners[0]);
  // Counted in doubles and bounded before they become integers (a size of 1e-300 gives an
  // infinite count): at most 2^10 a side, 2^20 a patch (the loader's limit).
  const double most = double(1L << 10);
  double nu = 1, nv = 1;
  if (size > 0.0) {
    nu = std::ceil(a / size - 1e-9);
    nv = std::ceil(b / size - 1e-9);
  } else {
    nu = std::round(std::sqrt(count * a / b));
    nv = std::round(count / std::clamp(nu, 1.0, most));
  }
  return {long(std::clamp(nu, 1.0, most)), long(std::clamp(nv, 1.0, most))};
}

}  // namespace ncube::models

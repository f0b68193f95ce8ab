#include "models/face_shapes_reference.h"

#include <algorithm>

namespace ncube::models::reference {

double diameter(const std::vector<Point>& corners) {
  double d = 0.0;
  for (const Point& a : corners)
    for (const Point& b : corners) d = std::max(d, norm(a - b));
  return d;
}

std::optional<std::pair<std::size_t, std::size_t>> crossing_edges(const std::vector<Point>& corners) {
  const std::vector<glm::dvec2> flat = in_best_plane(corners);
  const std::size_t n = flat.size();
  for (std::size_t i = 0; i < n; ++i)
    // Edges i and j > i + 1, but not the last with the first (they share corner 0).
    for (std::size_t j = i + 2; j < n && !(i == 0 && j == n - 1); ++j)
      if (edges_cross(flat[i], flat[(i + 1) % n], flat[j], flat[(j + 1) % n])) return std::pair{i, j};
  return std::nullopt;
}

std::vector<std::vector<Point>> ear_clip(const std::vector<Point>& corners) {
  const std::vector<glm::dvec2> flat = in_best_plane(corners);
  std::vector<std::size_t> left(corners.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = i;
  std::vector<std::vector<Point>> triangles;
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size() && !clipped; ++k) {
      const std::size_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                        c = left[(k + 1) % left.size()];
      if (cross2(flat[a], flat[b], flat[c]) <= 0) continue;  // reflex (or straight) corner
      bool inside = false;
      for (std::size_t i = 0; i < left.size() && !inside; ++i) {
        const std::size_t p = left[i];
        if (p == a || p == b || p == c) continue;
        inside = in_closed_triangle(flat[a], flat[b], flat[c], flat[p]);
      }
      if (inside) continue;
      triangles.push_back({corners[a], corners[b], corners[c]});
      left.erase(left.begin() + std::ptrdiff_t(k));
      clipped = true;
    }
    if (!clipped) {  // an outline that touches itself: a fan keeps what can be kept
      for (std::size_t k = 1; k + 1 < left.size(); ++k)
        triangles.push_back({corners[left[0]], corners[left[k]], corners[left[k + 1]]});
      return triangles;
    }
  }
  triangles.push_back({corners[left[0]], corners[left[1]], corners[left[2]]});
  return triangles;
}

}  // namespace ncube::models::reference

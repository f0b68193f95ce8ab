#include "scene/patch_mesh.h"

#include <algorithm>
#include <stdexcept>

namespace ncube {

PatchMesh::PatchMesh(const Patch& patch, const std::vector<ElementCell>& cells)
    : patch_(patch), cells_(cells), triangle_(patch.polygon.count == 3) {
  for (const ElementCell& c : cells_) depth_ = std::max(depth_, c.level);
  width_ = std::int64_t(patch.nu) << depth_;
  height_ = std::int64_t(patch.nv) << depth_;
  index_of_cell_.reserve(cells_.size());
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const ElementCell& c = cells_[k];
    if (!index_of_cell_.emplace(cell_key(c.level, c.i, c.j), int(k)).second)
      throw std::logic_error("PatchMesh: an element appears twice");
    for (int c = 0; c < corner_count(k); ++c) {
      const Point p = corner(k, c);
      corner_points_.insert(point_key(p));
      if (is_apex(p)) apex_elements_.push_back(int(k));
    }
  }
}

int PatchMesh::corner_count(std::size_t k) const {
  const ElementCell& c = cells_[k];
  return triangle_ && c.j == (patch_.nv << c.level) - 1 ? 3 : 4;
}

PatchMesh::Point PatchMesh::corner(std::size_t k, int c) const {
  const ElementCell& cell = cells_[k];
  const int shift = depth_ - cell.level;
  const std::int64_t x0 = std::int64_t(cell.i) << shift, y0 = std::int64_t(cell.j) << shift;
  const std::int64_t x1 = std::int64_t(cell.i + 1) << shift, y1 = std::int64_t(cell.j + 1) << shift;
  if (corner_count(k) == 3 && c == 2) return {0, height_};  // the apex, v2
  switch (c) {
    case 0: return {x0, y0};
    case 1: return {x1, y0};
    case 2: return {x1, y1};
    default: return {x0, y1};
  }
}

int PatchMesh::leaf_containing(std::int64_t cx, std::int64_t cy) const {
  for (int level = depth_; level >= 0; --level) {
    const int shift = depth_ - level;
    const auto found = index_of_cell_.find(cell_key(level, cx >> shift, cy >> shift));
    if (found != index_of_cell_.end()) return found->second;
  }
  throw std::logic_error("PatchMesh: the elements do not tile the patch");
}

Rgb PatchMesh::nodal(const std::vector<Rgb>& radiosity, const Point& p) const {
  int touching[4];
  int n = 0;
  if (is_apex(p)) {
    Rgb sum(0.0);
    for (int k : apex_elements_) sum += radiosity[std::size_t(k)];
    return sum / double(apex_elements_.size());
  }
  // The finest-lattice cells around the point, one per quadrant; each lies in one element.
  for (int dy = -1; dy <= 0; ++dy)
    for (int dx = -1; dx <= 0; ++dx) {
      const std::int64_t cx = p.x + dx, cy = p.y + dy;
      if (cx < 0 || cy < 0 || cx >= width_ || cy >= height_) continue;
      const int k = leaf_containing(cx, cy);
      // Keep them distinct and in element order (insertion into at most 4).
      int at = n;
      while (at > 0 && touching[at - 1] > k) --at;
      if (at > 0 && touching[at - 1] == k) continue;
      for (int m = n; m > at; --m) touching[m] = touching[m - 1];
      touching[at] = k;
      ++n;
    }
  Rgb sum(0.0);
  for (int i = 0; i < n; ++i) sum += radiosity[std::size_t(touching[i])];
  return sum / double(n);
}

Vec3 PatchMesh::position(const Point& p) const {
  if (is_apex(p)) return patch_.polygon[2];
  return bilinear_point(patch_.polygon, double(p.x) / double(width_), double(p.y) / double(height_));
}

Rgb PatchMesh::corner_radiosity(const std::vector<Rgb>& radiosity, std::size_t k, int c) const {
  return nodal(radiosity, corner(k, c));
}

std::vector<MeshVertex> PatchMesh::boundary(const std::vector<Rgb>& radiosity, std::size_t k) const {
  std::vector<MeshVertex> result;
  const int n = corner_count(k);
  for (int c = 0; c < n; ++c) {
    const Point a = corner(k, c);
    result.push_back({position(a), nodal(radiosity, a)});
    // The lattice points strictly inside the edge to the next corner; those that are some
    // element's corner are T-vertices. Edges run along u or v in parameter space, also the
    // slanted sides of a triangle (towards the apex, v grows at fixed u).
    const Point b = corner(k, (c + 1) % n);
    const std::int64_t bx = is_apex(b) ? a.x : b.x, by = b.y;
    const std::int64_t ax = is_apex(a) ? bx : a.x, ay = a.y;
    const std::int64_t steps = std::max(std::abs(bx - ax), std::abs(by - ay));
    for (std::int64_t s = 1; s < steps; ++s) {
      const Point p{ax + (bx - ax) / steps * s, ay + (by - ay) / steps * s};
      if (corner_points_.count(point_key(p))) result.push_back({position(p), nodal(radiosity, p)});
    }
  }
  return result;
}

}  // namespace ncube

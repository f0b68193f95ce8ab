#include "models/face_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace ncube::models {
namespace {

// The corners scaled by the power of two that brings their largest coordinate into [0.5, 1):
// exact in floating point, so every test below decides as it would on the corners as given,
// but no product of two to four lengths (a normal's dot product) underflows or overflows
// whatever the model's units and --scale (a face of 1e-88 has normals' dot products near
// 1e-350, which are 0 in doubles). The faces' points themselves are never changed.
std::vector<Point> in_face_units(const std::vector<Point>& corners) {
  double largest = 0.0;
  for (const Point& p : corners)
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  int exponent = 0;
  if (largest > 0.0 && std::isfinite(largest)) std::frexp(largest, &exponent);
  std::vector<Point> scaled;
  scaled.reserve(corners.size());
  for (const Point& p : corners)
    scaled.emplace_back(std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent), std::ldexp(p.z, -exponent));
  return scaled;
}

// A face's corners projected on its best plane (Newell's normal), in the face's own units:
// where ear clipping and the crossing test work.
std::vector<glm::dvec2> in_best_plane(const std::vector<Point>& corners) {
  const std::vector<Point> unit = in_face_units(corners);
  const Point normal = newell(unit);
  const Point n = normal / norm(normal);
  const Point u = glm::normalize(std::fabs(n.x) < 0.9 ? glm::cross(n, Point(1, 0, 0))
                                                        : glm::cross(n, Point(0, 1, 0)));
  const Point v = glm::cross(n, u);
  std::vector<glm::dvec2> flat;
  flat.reserve(unit.size());
  for (const Point& p : unit) flat.emplace_back(glm::dot(p, u), glm::dot(p, v));
  return flat;
}

double cross2(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Ear clipping in the face's best plane: triangles in the face's own winding, for faces that
// are concave, bent or have more than four corners. Each step clips the first corner, in the
// face's order, that is convex with no other remaining corner in its (closed) triangle.
std::vector<std::vector<Point>> triangulate(const std::vector<Point>& corners) {
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
        inside = cross2(flat[a], flat[b], flat[p]) >= 0 && cross2(flat[b], flat[c], flat[p]) >= 0 &&
                 cross2(flat[c], flat[a], flat[p]) >= 0;
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

}  // namespace

// A vector's length without underflow or overflow of its squares (a model scaled by 1e-100
// has areas near 1e-200, whose squares a plain length would lose).
double norm(const Point& v) {
  const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (m == 0.0 || !std::isfinite(m)) return m;
  const Point u = v / m;
  return m * std::sqrt(glm::dot(u, u));
}

double diameter(const std::vector<Point>& corners) {
  double d = 0.0;
  for (const Point& a : corners)
    for (const Point& b : corners) d = std::max(d, norm(a - b));
  return d;
}

// Newell's normal: twice the vector area of a planar polygon, the best plane of a bent one.
Point newell(const std::vector<Point>& corners) {
  Point n(0.0);
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Point& a = corners[i];
    const Point& b = corners[(i + 1) % corners.size()];
    n += Point((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

bool planar_convex_quad(const std::vector<Point>& corners) {
  const std::vector<Point> q = in_face_units(corners);
  const double d = diameter(q);
  const Point n = glm::cross(q[1] - q[0], q[2] - q[0]);
  if (norm(n) <= 2 * kFlat * d * d) return false;
  const Point unit = n / norm(n);
  if (std::fabs(glm::dot(q[3] - q[0], unit)) > kPlanarity * d) return false;
  for (std::size_t i = 0; i < 4; ++i) {
    const Point turn = glm::cross(q[i] - q[(i + 3) % 4], q[(i + 1) % 4] - q[i]);
    if (glm::dot(turn, unit) <= kTurn * d * d) return false;
  }
  return true;
}

// A quad that is not planar (or not convex) is cut along its diagonal from corner 0 when
// both halves face the quad's way (the usual convention, as scenes/generate cuts the Cornell
// box's bent wall); other faces by ear clipping.
std::vector<std::vector<Point>> split(const std::vector<Point>& corners) {
  if (corners.size() == 4) {
    const std::vector<Point> q = in_face_units(corners);
    const Point n = newell(q);
    const bool a_faces = glm::dot(newell({q[0], q[1], q[2]}), n) > 0.0;
    const bool b_faces = glm::dot(newell({q[2], q[3], q[0]}), n) > 0.0;
    if (a_faces && b_faces)
      return {{corners[0], corners[1], corners[2]}, {corners[2], corners[3], corners[0]}};
  }
  return triangulate(corners);
}

std::optional<std::pair<std::size_t, std::size_t>> crossing_edges(const std::vector<Point>& corners) {
  const std::vector<glm::dvec2> flat = in_best_plane(corners);
  const std::size_t n = flat.size();
  const auto opposite = [](double a, double b) { return (a > 0 && b < 0) || (a < 0 && b > 0); };
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 p = flat[i], q = flat[(i + 1) % n];
    // Edges i and j > i + 1, but not the last with the first (they share corner 0).
    for (std::size_t j = i + 2; j < n && !(i == 0 && j == n - 1); ++j) {
      const glm::dvec2 r = flat[j], s = flat[(j + 1) % n];
      if (opposite(cross2(p, q, r), cross2(p, q, s)) && opposite(cross2(r, s, p), cross2(r, s, q)))
        return std::pair{i, j};
    }
  }
  return std::nullopt;
}

bool spans_plane(const std::vector<Point>& corners) {
  const std::vector<Point> q = in_face_units(corners);
  const double d = diameter(q);
  for (std::size_t i = 1; i + 1 < q.size(); ++i)
    if (0.5 * norm(glm::cross(q[i] - q[0], q[i + 1] - q[0])) > kSpan * d * d) return true;
  return false;
}

bool flat(const std::vector<Point>& corners) {
  const std::vector<Point> polygon = in_face_units(corners);
  const double d = diameter(polygon);
  return d == 0.0 || 0.5 * norm(newell(polygon)) <= kFlat * d * d;
}

}  // namespace ncube::models

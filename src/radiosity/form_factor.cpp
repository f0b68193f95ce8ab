#include "radiosity/form_factor.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ncube {
namespace {

// A polygon of up to 4 vertices clipped by one plane has at most 5.
struct ClippedPolygon {
  int count = 0;
  Vec3 vertices[8];
};

ClippedPolygon clip_to_front(const Vec3& point, const Vec3& normal, const Polygon& polygon) {
  ClippedPolygon out;
  for (int i = 0; i < polygon.count; ++i) {
    const Vec3& a = polygon[i];
    const Vec3& b = polygon[(i + 1) % polygon.count];
    const double da = glm::dot(normal, a - point);
    const double db = glm::dot(normal, b - point);
    if (da >= 0.0) out.vertices[out.count++] = a;
    if ((da >= 0.0) != (db >= 0.0)) out.vertices[out.count++] = a + (b - a) * (da / (da - db));
  }
  return out;
}

}  // namespace

double point_to_polygon_form_factor(const Vec3& point, const Vec3& normal,
                                    const Polygon& polygon) {
  const ClippedPolygon clipped = clip_to_front(point, normal, polygon);
  if (clipped.count < 3) return 0.0;
  double sum = 0.0;
  for (int i = 0; i < clipped.count; ++i) {
    const Vec3 a = clipped.vertices[i] - point;
    const Vec3 b = clipped.vertices[(i + 1) % clipped.count] - point;
    const Vec3 c = glm::cross(a, b);
    const double c_length = glm::length(c);
    if (c_length <= 0.0) continue;  // edge seen end-on: contributes nothing
    const double angle = std::atan2(c_length, glm::dot(a, b));
    sum += angle * glm::dot(normal, c) / c_length;
  }
  return std::fabs(sum) / (2.0 * M_PI);
}

}  // namespace ncube

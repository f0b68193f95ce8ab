#include "reference/point_polygon_factor.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace ncube::reference {

double point_polygon_factor(const Vec3& point, const Vec3& normal, const Polygon& polygon) {
  // Corners relative to the point, cut to height >= 0 above the tangent plane (Sutherland-
  // Hodgman against one plane: at most one corner more).
  // A crossing point only where the edge's ends lie strictly on opposite sides: an end on the
  // plane is kept as a corner already (the test "ha < 0 differs from hb < 0" added such an
  // end twice). Room for every corner and a crossing after each: a polygon (nearly) in the
  // point's plane has heights of rounding noise whose signs may alternate (issue 38: an
  // element and its neighbour on one patch wrote past an array of 5).
  Vec3 corners[8];
  int count = 0;
  for (int k = 0; k < polygon.count; ++k) {
    const Vec3 a = polygon[k] - point;
    const Vec3 b = polygon[(k + 1) % polygon.count] - point;
    const double ha = glm::dot(a, normal), hb = glm::dot(b, normal);
    if (ha >= 0.0) corners[count++] = a;
    if ((ha > 0.0 && hb < 0.0) || (ha < 0.0 && hb > 0.0))
      corners[count++] = a + (b - a) * (ha / (ha - hb));
  }
  if (count < 3) return 0.0;
  double sum = 0.0;
  for (int k = 0; k < count; ++k) {
    const Vec3& a = corners[k];
    const Vec3& b = corners[(k + 1) % count];
    const Vec3 axis = glm::cross(a, b);
    const double sine = glm::length(axis);
    if (sine == 0.0) continue;
    sum += std::atan2(sine, glm::dot(a, b)) * glm::dot(axis, normal) / sine;
  }
  return std::fabs(sum) / (2.0 * M_PI);
}

}  // namespace ncube::reference

#include "geometry/polygon.h"

#include <glm/geometric.hpp>

namespace ncube {

Polygon Polygon::triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Polygon p;
  p.count = 3;
  p.vertices = {a, b, c, c};
  return p;
}

Polygon Polygon::quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  Polygon p;
  p.count = 4;
  p.vertices = {a, b, c, d};
  return p;
}

Vec3 Polygon::normal() const {
  return glm::normalize(glm::cross(vertices[1] - vertices[0], vertices[2] - vertices[0]));
}

double Polygon::area() const {
  // Fan of triangles from vertex 0; exact for planar convex polygons.
  Vec3 sum(0.0);
  for (int i = 1; i + 1 < count; ++i)
    sum += glm::cross(vertices[i] - vertices[0], vertices[i + 1] - vertices[0]);
  return 0.5 * glm::length(sum);
}

Vec3 Polygon::centroid() const {
  Vec3 weighted(0.0);
  double total = 0.0;
  for (int i = 1; i + 1 < count; ++i) {
    const double a =
        glm::length(glm::cross(vertices[i] - vertices[0], vertices[i + 1] - vertices[0]));
    weighted += a * (vertices[0] + vertices[i] + vertices[i + 1]) / 3.0;
    total += a;
  }
  return total > 0.0 ? weighted / total : vertices[0];
}

Vec3 bilinear_point(const Polygon& polygon, double u, double v) {
  const Vec3& v0 = polygon.vertices[0];
  const Vec3& v1 = polygon.vertices[1];
  const Vec3& v2 = polygon.vertices[2];
  const Vec3& v3 = polygon.count == 4 ? polygon.vertices[3] : polygon.vertices[2];
  return (1.0 - v) * ((1.0 - u) * v0 + u * v1) + v * ((1.0 - u) * v3 + u * v2);
}

Polygon grid_cell(const Polygon& polygon, int nu, int nv, int i, int j) {
  const double u0 = double(i) / nu, u1 = double(i + 1) / nu;
  const double w0 = double(j) / nv, w1 = double(j + 1) / nv;
  const Vec3 a = bilinear_point(polygon, u0, w0);
  const Vec3 b = bilinear_point(polygon, u1, w0);
  if (polygon.count == 3 && j == nv - 1) return Polygon::triangle(a, b, polygon.vertices[2]);
  return Polygon::quad(a, b, bilinear_point(polygon, u1, w1), bilinear_point(polygon, u0, w1));
}

}  // namespace ncube

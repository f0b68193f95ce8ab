// A planar convex polygon with 3 or 4 vertices: the shape of every patch, element and
// shooter part in the simulator. Vertices are counter-clockwise seen from the front, so the
// front normal is normalize((v1 - v0) x (v2 - v0)).
#pragma once

#include <array>
#include <glm/vec3.hpp>

namespace ncube {

using Vec3 = glm::dvec3;

struct Polygon {
  int count = 0;                 // 3 or 4
  std::array<Vec3, 4> vertices{};  // vertices[3] unused for a triangle

  static Polygon triangle(const Vec3& a, const Vec3& b, const Vec3& c);
  static Polygon quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

  const Vec3& operator[](int i) const { return vertices[i]; }
  Vec3 normal() const;    // unit front normal
  double area() const;    // exact for planar convex polygons
  Vec3 centroid() const;  // area centroid
};

// The point at (u, v) in [0,1]^2 of the bilinear map of a polygon: a quad maps
// v0 (0,0), v1 (1,0), v2 (1,1), v3 (0,1); a triangle is the quad (v0, v1, v2, v2)
// collapsed at v2. Planar convex inputs give planar convex cells.
Vec3 bilinear_point(const Polygon& polygon, double u, double v);

// Cell (i, j) of the nu x nv bilinear grid of a polygon (i along v0->v1, j along v0->v3).
// For a triangle the cells of the last row (j = nv - 1) are triangles.
Polygon grid_cell(const Polygon& polygon, int nu, int nv, int i, int j);

}  // namespace ncube

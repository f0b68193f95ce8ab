#include "radiosity/form_factor.h"

#include <array>
#include <bitset>
#include <cmath>
#include <glm/geometric.hpp>

#include "radiosity/radiosity_engine.h"

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

// One edge's term of the contour integral, for the edge from a to b seen from the origin.
double edge_term(const Vec3& a, const Vec3& b, const Vec3& normal) {
  const Vec3 c = glm::cross(a, b);
  const double c_length = glm::length(c);
  if (c_length <= 0.0) return 0.0;  // edge seen end-on: contributes nothing
  const double angle = std::atan2(c_length, glm::dot(a, b));
  return angle * glm::dot(normal, c) / c_length;
}

}  // namespace

double point_to_polygon_form_factor(const Vec3& point, const Vec3& normal,
                                    const Polygon& polygon) {
  const ClippedPolygon clipped = clip_to_front(point, normal, polygon);
  if (clipped.count < 3) return 0.0;
  double sum = 0.0;
  for (int i = 0; i < clipped.count; ++i) {
    sum += edge_term(clipped.vertices[i] - point, clipped.vertices[(i + 1) % clipped.count] - point,
                     normal);
  }
  return std::fabs(sum) / (2.0 * M_PI);
}

double visible_parts_form_factor(const Vec3& point, const Vec3& normal, const Shooter& shooter,
                                 PartMask mask) {
  if (mask == 0) return 0.0;
  const int k = shooter.side;
  const int corners = (k + 1) * (k + 1);
  std::array<Vec3, (8 + 1) * (8 + 1)> r;
  bool clipping = false;
  for (int v = 0; v < corners; ++v) {
    r[v] = shooter.grid[v] - point;
    clipping = clipping || glm::dot(normal, r[v]) < 0.0;
  }
  if (clipping) {  // part by part, each clipped to the receiver's front
    double sum = 0.0;
    for (int part = 0; part < shooter.part_count; ++part)
      if (mask & (PartMask(1) << part))
        sum += point_to_polygon_form_factor(point, normal, shooter.parts[part]);
    return sum;
  }
  // Seen from a point in front of the shooter's plane (the only receivers that get light)
  // every part runs the same way round, so the parts' sums have one sign and add up to the
  // sum over the edges of their union. Edge weights: +1 for a visible part on its left, -1
  // for one on its right.
  auto visible = [&](int i, int j) {
    return i >= 0 && i < k && j >= 0 && j < k && (mask >> (j * k + i) & 1) ? 1 : 0;
  };
  auto corner = [&](int i, int j) -> const Vec3& { return r[j * (k + 1) + i]; };
  double sum = 0.0;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i < k; ++i) {  // (i, j) -> (i + 1, j): bottom of part (i, j)
      const int weight = visible(i, j) - visible(i, j - 1);
      if (weight != 0) sum += weight * edge_term(corner(i, j), corner(i + 1, j), normal);
    }
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j < k; ++j) {  // (i, j) -> (i, j + 1): right side of part (i - 1, j)
      const int weight = visible(i - 1, j) - visible(i, j);
      if (weight != 0) sum += weight * edge_term(corner(i, j), corner(i, j + 1), normal);
    }
  return std::fabs(sum) / (2.0 * M_PI);
}

std::uint64_t form_factor_edge_terms(const Vec3& point, const Vec3& normal, const Shooter& shooter,
                                     PartMask mask) {
  if (mask == 0) return 0;
  const int k = shooter.side;
  const int corners = (k + 1) * (k + 1);
  bool clipping = false;
  for (int v = 0; v < corners && !clipping; ++v)
    clipping = glm::dot(normal, shooter.grid[v] - point) < 0.0;
  std::uint64_t terms = 0;
  if (clipping) {  // as point_to_polygon_form_factor: the clipped polygon's edges
    for (int part = 0; part < shooter.part_count; ++part)
      if (mask & (PartMask(1) << part)) {
        const ClippedPolygon clipped = clip_to_front(point, normal, shooter.parts[part]);
        if (clipped.count >= 3) terms += std::uint64_t(clipped.count);
      }
    return terms;
  }
  // The contour: the edges whose weight is not zero (visible on one side only).
  auto visible = [&](int i, int j) {
    return i >= 0 && i < k && j >= 0 && j < k && (mask >> (j * k + i) & 1) ? 1 : 0;
  };
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i < k; ++i) terms += visible(i, j) != visible(i, j - 1);
  for (int i = 0; i <= k; ++i)
    for (int j = 0; j < k; ++j) terms += visible(i - 1, j) != visible(i, j);
  return terms;
}

std::vector<double> ray_traced_form_factors(RadiosityEngine& engine, const OccluderSet& occluders,
                                            const std::vector<ElementRef>& receivers,
                                            const Shooter& shooter, WorkCounts& counts) {
  const std::vector<PartMask> visible = visible_parts(engine, occluders, receivers, shooter, counts);
  std::vector<double> form_factors = engine.form_factors(shooter, receivers, visible);
  // As the paper's gather counts them (RadiosityEngine::add_light): the visible parts of a
  // receiver the shooter lights.
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    const StoredElement& element = engine.store().element(receivers[k]);
    if (!shooter_lights(shooter, element.centre)) continue;
    counts.form_factors += std::bitset<64>(visible[k]).count();
    const int patch = engine.store().patches()[std::size_t(receivers[k].slot)].patch;
    counts.form_factor_edge_terms += form_factor_edge_terms(
        element.centre, engine.scene().patches[std::size_t(patch)].normal, shooter, visible[k]);
  }
  return form_factors;
}

}  // namespace ncube

#include "radiosity/hemicube.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <memory>

namespace ncube {

const char* hemicube_placement_name(HemicubePlacement placement) {
  return placement == HemicubePlacement::kCentre ? "centre" : "elements";
}

const char* hemicube_back_faces_name(HemicubeBackFaces back_faces) {
  return back_faces == HemicubeBackFaces::kBlock ? "block" : "pass";
}

const char* hemicube_reciprocity_name(HemicubeReciprocity reciprocity) {
  return reciprocity == HemicubeReciprocity::kAsComputed ? "as-computed" : "clamp";
}

bool is_valid_hemicube_resolution(int resolution) {
  return resolution >= kMinHemicubeResolution && resolution <= kMaxHemicubeResolution &&
         resolution % 2 == 0;
}

DeltaFormFactors::DeltaFormFactors(int n) : resolution(n) {
  const double cell = 2.0 / n, area = cell * cell;
  top.resize(std::size_t(n) * std::size_t(n));
  side.resize(std::size_t(n / 2) * std::size_t(n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = -1.0 + (i + 0.5) * cell, y = -1.0 + (j + 0.5) * cell;
      const double r = x * x + y * y + 1.0;
      top[std::size_t(j) * std::size_t(n) + std::size_t(i)] = area / (M_PI * r * r);
    }
  for (int j = 0; j < n / 2; ++j)
    for (int i = 0; i < n; ++i) {
      const double y = -1.0 + (i + 0.5) * cell, z = (j + 0.5) * cell;
      const double r = y * y + z * z + 1.0;
      side[std::size_t(j) * std::size_t(n) + std::size_t(i)] = z * area / (M_PI * r * r);
    }
}

double DeltaFormFactors::sum() const {
  double total = 0.0;
  for (double f : top) total += f;
  for (double f : side) total += 4.0 * f;
  return total;
}

namespace {

// A point in a face's coordinates: across (a) and up (b) on the face, depth (d) towards it.
struct FacePoint {
  double a, b, d;
};

// The five faces, from the hemicube's frame (x along the tangent, y, z along the normal).
// Face 0 is the top (b from -1 to 1), faces 1 to 4 the sides (b = z from 0 to 1).
FacePoint to_face(int face, const Vec3& p) {
  switch (face) {
    case 0: return {p.x, p.y, p.z};
    case 1: return {p.y, p.z, p.x};
    case 2: return {-p.y, p.z, -p.x};
    case 3: return {p.x, p.z, p.y};
    default: return {-p.x, p.z, -p.y};
  }
}

// A polygon in the hemicube's frame.
struct FramePolygon {
  int count = 0;
  std::array<Vec3, 4> vertices;
  Vec3 normal;   // the plane's normal in the frame
  double offset;  // normal . (any vertex): the plane's signed distance from the eye
  double extent;  // largest coordinate, for the near plane
  int item;       // receiver index, or -1: takes cells but is not read out
  int key;        // ties of depth go to the lower key
  bool seen_from_behind;  // the eye behind (or in) its plane
};

constexpr int kMaxClipped = 12;  // 4 vertices + at most one per clip plane, with room
struct Clipped {
  int count = 0;
  std::array<FacePoint, kMaxClipped> v;
};

// Signed distance of a face point to clip plane `plane` of `face` (inside: >= 0).
double plane_distance(int face, int plane, const FacePoint& p, double near) {
  switch (plane) {
    case 0: return p.d - p.a;
    case 1: return p.d + p.a;
    case 2: return p.d - p.b;
    case 3: return face == 0 ? p.d + p.b : p.b;  // the sides stop at the eye's plane
    default: return p.d - near;
  }
}

// Sutherland-Hodgman against the face's view volume.
Clipped clip_to_face(int face, const FramePolygon& polygon, WorkCounts& counts) {
  Clipped in;
  for (int k = 0; k < polygon.count; ++k) in.v[std::size_t(k)] = to_face(face, polygon.vertices[std::size_t(k)]);
  in.count = polygon.count;
  const double near = 1e-9 * polygon.extent;
  for (int plane = 0; plane < 5 && in.count > 0; ++plane) {
    Clipped out;
    std::array<double, kMaxClipped> distance;
    for (int k = 0; k < in.count; ++k) distance[std::size_t(k)] = plane_distance(face, plane, in.v[std::size_t(k)], near);
    counts.hemicube_clip_tests += std::uint64_t(in.count);
    for (int k = 0; k < in.count; ++k) {
      const int next = (k + 1) % in.count;
      const double da = distance[std::size_t(k)], db = distance[std::size_t(next)];
      const FacePoint& a = in.v[std::size_t(k)];
      const FacePoint& b = in.v[std::size_t(next)];
      if (da >= 0.0) out.v[std::size_t(out.count++)] = a;
      if ((da >= 0.0) != (db >= 0.0)) {
        const double t = da / (da - db);
        out.v[std::size_t(out.count++)] = {a.a + (b.a - a.a) * t, a.b + (b.b - a.b) * t,
                                           a.d + (b.d - a.d) * t};
        ++counts.hemicube_clip_cuts;
      }
    }
    in = out;
  }
  if (in.count < 3) in.count = 0;
  return in;
}

// One face's buffers: the nearest polygon's inverse depth (0: none) and item per cell.
struct FaceBuffer {
  int columns = 0, rows = 0;
  std::vector<double> inverse_depth;
  std::vector<int> item, key;

  void clear(int c, int r) {
    columns = c;
    rows = r;
    inverse_depth.assign(std::size_t(c) * std::size_t(r), 0.0);
    item.assign(inverse_depth.size(), -1);
    key.assign(inverse_depth.size(), 0);
  }
};

// Scan-converts a clipped polygon into the face's buffer: each cell whose centre it covers
// takes its item when the polygon is nearer there than what the cell holds.
void scan_polygon(int face, const Clipped& clipped, const FramePolygon& polygon, FaceBuffer& buffer,
                  WorkCounts& counts) {
  const double half = buffer.columns / 2.0;
  const double b_origin = face == 0 ? 1.0 : 0.0;  // the top face's b runs from -1
  std::array<double, kMaxClipped> x, y;
  counts.hemicube_vertices_projected += std::uint64_t(clipped.count);
  for (int k = 0; k < clipped.count; ++k) {
    const FacePoint& p = clipped.v[std::size_t(k)];
    x[std::size_t(k)] = (p.a / p.d + 1.0) * half;
    y[std::size_t(k)] = (p.b / p.d + b_origin) * half;
  }
  double twice_area = 0.0;
  for (int k = 0; k < clipped.count; ++k) {
    const int next = (k + 1) % clipped.count;
    twice_area += x[std::size_t(k)] * y[std::size_t(next)] - x[std::size_t(next)] * y[std::size_t(k)];
  }
  if (twice_area == 0.0 || polygon.offset == 0.0) return;  // seen edge-on: covers no area
  ++counts.hemicube_polygons_scanned;
  // Inverse depth along the ray through face point (a, b, 1): (n . (a, b, 1)) / offset,
  // linear over the face; here over cell coordinates (a = x / half - 1, b = y / half - b0).
  const FacePoint n = to_face(face, polygon.normal);
  const double w_x = n.a / (half * polygon.offset), w_y = n.b / (half * polygon.offset);
  const double w_0 = (n.d - n.a - n.b * b_origin) / polygon.offset;
  const double y_low = *std::min_element(y.begin(), y.begin() + clipped.count);
  const double y_high = *std::max_element(y.begin(), y.begin() + clipped.count);
  const int first_row = std::max(0, int(std::ceil(y_low - 0.5)));
  const int last_row = std::min(buffer.rows - 1, int(std::floor(y_high - 0.5)));
  for (int row = first_row; row <= last_row; ++row) {
    ++counts.hemicube_rows_scanned;
    const double yc = row + 0.5;
    double x_left = HUGE_VAL, x_right = -HUGE_VAL;
    for (int k = 0; k < clipped.count; ++k) {  // the polygon is convex: one span per row
      const int next = (k + 1) % clipped.count;
      const double y0 = y[std::size_t(k)], y1 = y[std::size_t(next)];
      if (yc < std::min(y0, y1) || yc > std::max(y0, y1)) continue;
      const double x0 = x[std::size_t(k)], x1 = x[std::size_t(next)];
      const double xs = y0 == y1 ? x0 : x0 + (yc - y0) * (x1 - x0) / (y1 - y0);
      x_left = std::min({x_left, xs, y0 == y1 ? x1 : xs});
      x_right = std::max({x_right, xs, y0 == y1 ? x1 : xs});
    }
    if (x_left > x_right) continue;
    const int first = std::max(0, int(std::ceil(x_left - 0.5)));
    const int last = std::min(buffer.columns - 1, int(std::floor(x_right - 0.5)));
    for (int column = first; column <= last; ++column) {
      ++counts.hemicube_depth_tests;
      const double w = w_0 + w_x * (column + 0.5) + w_y * yc;
      const std::size_t cell = std::size_t(row) * std::size_t(buffer.columns) + std::size_t(column);
      if (w > buffer.inverse_depth[cell] ||
          (w == buffer.inverse_depth[cell] && polygon.key < buffer.key[cell])) {
        buffer.inverse_depth[cell] = w;
        buffer.item[cell] = polygon.item;
        buffer.key[cell] = polygon.key;
      }
    }
  }
}

FramePolygon to_frame(const HemicubePolygon& drawn, int item, const Vec3& eye, const Vec3& u,
                      const Vec3& v, const Vec3& w, WorkCounts& counts) {
  const Polygon& polygon = drawn.polygon;
  const Vec3& plane_normal = drawn.normal;
  FramePolygon f;
  f.key = drawn.key;
  f.count = polygon.count;
  f.extent = 0.0;
  for (int k = 0; k < polygon.count; ++k) {
    const Vec3 r = polygon[k] - eye;
    f.vertices[std::size_t(k)] = {glm::dot(r, u), glm::dot(r, v), glm::dot(r, w)};
    f.extent = std::max({f.extent, std::fabs(f.vertices[std::size_t(k)].x),
                         std::fabs(f.vertices[std::size_t(k)].y), std::fabs(f.vertices[std::size_t(k)].z)});
  }
  counts.hemicube_vertices_transformed += std::uint64_t(polygon.count);
  f.normal = {glm::dot(plane_normal, u), glm::dot(plane_normal, v), glm::dot(plane_normal, w)};
  f.offset = glm::dot(plane_normal, drawn.plane_point - eye);
  // A receiver seen from behind (the eye behind its plane, offset >= 0) receives nothing:
  // patches receive on their front only. Whether it blocks is HemicubeBackFaces' choice.
  f.seen_from_behind = f.offset >= 0.0;
  f.item = item >= 0 && !f.seen_from_behind ? item : -1;
  ++counts.hemicube_polygons_set_up;
  return f;
}

}  // namespace

HemicubePolygon hemicube_polygon(const Polygon& polygon, int key) {
  return {polygon, polygon.normal(), polygon[0], polygon.area(), key};
}

HemicubePolygon hemicube_polygon(const Scene& scene, int patch, const Polygon& piece, double area) {
  const Patch& p = scene.patches[std::size_t(patch)];
  return {piece, p.normal, p.polygon[0], area, patch};
}

void render_hemicube(const Vec3& eye, const Vec3& normal, const Vec3& tangent,
                     const std::vector<HemicubePolygon>& receivers,
                     const std::vector<HemicubePolygon>& occluders, const DeltaFormFactors& deltas,
                     double weight, std::vector<double>& point_form_factors, WorkCounts& counts,
                     HemicubeBackFaces back_faces) {
  const Vec3 v = glm::cross(normal, tangent);
  std::vector<FramePolygon> polygons;
  polygons.reserve(receivers.size() + occluders.size());
  // kPass culls a polygon seen from behind after its facing test (counted in its set-up): it
  // is neither clipped nor scanned.
  const auto keep = [&](const FramePolygon& polygon) {
    if (back_faces == HemicubeBackFaces::kBlock || !polygon.seen_from_behind)
      polygons.push_back(polygon);
  };
  for (std::size_t k = 0; k < receivers.size(); ++k)
    keep(to_frame(receivers[k], int(k), eye, tangent, v, normal, counts));
  for (const HemicubePolygon& occluder : occluders)
    keep(to_frame(occluder, -1, eye, tangent, v, normal, counts));
  const int n = deltas.resolution;
  FaceBuffer buffer;
  for (int face = 0; face < 5; ++face) {
    buffer.clear(n, face == 0 ? n : n / 2);
    for (const FramePolygon& polygon : polygons) {
      const Clipped clipped = clip_to_face(face, polygon, counts);
      if (clipped.count > 0) scan_polygon(face, clipped, polygon, buffer, counts);
    }
    // The item buffer read out: each cell's delta form factor to its nearest receiver.
    const std::vector<double>& table = face == 0 ? deltas.top : deltas.side;
    counts.hemicube_cells_read += std::uint64_t(buffer.item.size());
    for (std::size_t cell = 0; cell < buffer.item.size(); ++cell)
      if (buffer.item[cell] >= 0) point_form_factors[std::size_t(buffer.item[cell])] += weight * table[cell];
  }
}

std::vector<double> hemicube_form_factors(const Scene& scene, int shooter_patch,
                                          const std::vector<HemicubePolygon>& receivers,
                                          const std::vector<HemicubePolygon>& occluders,
                                          const HemicubeOptions& options, WorkCounts& counts) {
  // The table is the node's from its start (hemicube_setup_work); the host keeps the last
  // one made on this thread.
  thread_local std::unique_ptr<DeltaFormFactors> deltas;
  if (!deltas || deltas->resolution != options.resolution)
    deltas = std::make_unique<DeltaFormFactors>(options.resolution);
  const Patch& shooter = scene.patches[std::size_t(shooter_patch)];
  const Vec3 tangent = glm::normalize(shooter.polygon[1] - shooter.polygon[0]);
  // sums[k]: sum over the hemicubes of A_eye x F(eye -> receiver k) = A_shooter F(shooter -> k).
  std::vector<double> sums(receivers.size(), 0.0);
  if (options.placement == HemicubePlacement::kCentre) {
    render_hemicube(shooter.polygon.centroid(), shooter.normal, tangent, receivers, occluders,
                    *deltas, shooter.area, sums, counts, options.back_faces);
  } else {
    for (int j = 0; j < shooter.nv; ++j)
      for (int i = 0; i < shooter.nu; ++i) {
        const Polygon element = grid_cell(shooter.polygon, shooter.nu, shooter.nv, i, j);
        render_hemicube(element.centroid(), shooter.normal, tangent, receivers, occluders, *deltas,
                        element.area(), sums, counts, options.back_faces);
      }
  }
  // Reciprocity: F(k -> shooter) = F(shooter -> k) A_shooter / A_k. Above 1 it is counted
  // (an observation, charged nothing) and, with kClamp, taken as 1.
  for (std::size_t k = 0; k < receivers.size(); ++k) {
    sums[k] = receivers[k].area > 0.0 ? sums[k] / receivers[k].area : 0.0;
    if (sums[k] > 1.0) {
      ++counts.hemicube_reciprocal_above_one;
      if (options.reciprocity == HemicubeReciprocity::kClamp) sums[k] = 1.0;
    }
  }
  return sums;
}

WorkCounts hemicube_setup_work(const HemicubeOptions& options) {
  WorkCounts counts;
  counts.hemicube_delta_form_factors = std::uint64_t(hemicube_table_entries(options));
  return counts;
}

double hemicube_table_entries(const HemicubeOptions& options) {
  const double n = options.resolution;
  return n * n + n * (n / 2.0);
}

double hemicube_buffer_cells(const HemicubeOptions& options) {
  return double(options.resolution) * double(options.resolution);
}

}  // namespace ncube

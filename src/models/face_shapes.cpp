#include "models/face_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <set>

#include <glm/geometric.hpp>

namespace ncube::models {
namespace {

// The corners scaled by the power of two that brings their largest coordinate into [0.5, 1):
// exact in floating point, so every test below decides as it would on the corners as given,
// but no product of two to four lengths (a normal's dot product) underflows or overflows
// whatever the model's units and --scale (a face of 1e-88 has normals' dot products near
// 1e-350, which are 0 in doubles). The faces' points themselves are never changed.
int face_exponent(const std::vector<Point>& corners) {
  double largest = 0.0;
  for (const Point& p : corners)
    largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  int exponent = 0;
  if (largest > 0.0 && std::isfinite(largest)) std::frexp(largest, &exponent);
  return exponent;
}

std::vector<Point> in_face_units(const std::vector<Point>& corners) {
  const int exponent = face_exponent(corners);
  std::vector<Point> scaled;
  scaled.reserve(corners.size());
  for (const Point& p : corners)
    scaled.emplace_back(std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent), std::ldexp(p.z, -exponent));
  return scaled;
}

// Below this many corners the plain pairwise loops are as fast as the indexes.
constexpr std::size_t kSmallFace = 48;

// A k-d tree of points (boxes split at the median of their widest side), for the diameter: a
// point's distance to any point of a box is at most its distance to the box's farthest corner.
struct BoxTree {
  struct Node {
    Point lo, hi;
    std::size_t begin, end;  // points order[begin, end)
    std::size_t first_child = 0;  // children first_child and first_child + 1, or 0 for a leaf
  };
  std::vector<std::size_t> order;
  std::vector<Node> nodes;

  explicit BoxTree(const std::vector<Point>& points) : order(points.size()) {
    std::iota(order.begin(), order.end(), std::size_t(0));
    nodes.reserve(2 * points.size() / 4 + 1);
    nodes.push_back({Point(0.0), Point(0.0), 0, points.size()});
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      Node& node = nodes[k];
      node.lo = node.hi = points[order[node.begin]];
      for (std::size_t i = node.begin; i < node.end; ++i) {
        node.lo = glm::min(node.lo, points[order[i]]);
        node.hi = glm::max(node.hi, points[order[i]]);
      }
      if (node.end - node.begin <= 8) continue;
      const Point size = node.hi - node.lo;
      const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
      const std::size_t begin = node.begin, middle = (node.begin + node.end) / 2, end = node.end;
      std::nth_element(order.begin() + std::ptrdiff_t(begin), order.begin() + std::ptrdiff_t(middle),
                       order.begin() + std::ptrdiff_t(end),
                       [&](std::size_t a, std::size_t b) { return points[a][axis] < points[b][axis]; });
      node.first_child = nodes.size();
      nodes.push_back({Point(0.0), Point(0.0), begin, middle});  // invalidates `node`
      nodes.push_back({Point(0.0), Point(0.0), middle, end});
    }
  }
};

// The axis-aligned box of a segment or triangle, for the indexes of the crossing test and of
// ear clipping.
struct Box {
  glm::dvec2 lo, hi;
};

bool overlap(const Box& a, const Box& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

// A uniform grid of about one point a cell over a face's corners in its best plane, for ear
// clipping's "no other corner in the ear" test: the corners still in the outline, by cell.
class CornerGrid {
 public:
  explicit CornerGrid(const std::vector<glm::dvec2>& points) : points_(points) {
    lo_ = hi_ = points.front();
    for (const glm::dvec2& p : points) {
      lo_ = glm::min(lo_, p);
      hi_ = glm::max(hi_, p);
    }
    // About one corner a cell, the cells about square (a comb 1,000 times wider than high gets
    // a row of 1,000 columns, not 180 columns of 180 corners each).
    const glm::dvec2 size = hi_ - lo_;
    const double n = double(points.size());
    const double aspect = size.x > 0 && size.y > 0 ? size.x / size.y : size.x > 0 ? n : 1.0 / n;
    columns_ = std::size_t(std::clamp(std::sqrt(n * aspect), 1.0, n));
    rows_ = std::size_t(std::clamp(std::sqrt(n / aspect), 1.0, n));
    scale_ = glm::dvec2(size.x > 0 ? double(columns_) / size.x : 0.0, size.y > 0 ? double(rows_) / size.y : 0.0);
    cells_.resize(columns_ * rows_);
    for (std::size_t i = 0; i < points.size(); ++i) cells_[cell(points[i])].push_back(i);
  }
  void remove(std::size_t i) {
    std::vector<std::size_t>& c = cells_[cell(points_[i])];
    *std::find(c.begin(), c.end(), i) = c.back();
    c.pop_back();
  }
  // Some corner other than a, b and c, still in the outline, in the closed triangle a b c, or
  // points.size(). The cells searched are, row by row, those under the triangle's part in the
  // row (the x range of its edges' parts there), one more on each side against rounding: a
  // corner elsewhere is outside the triangle.
  std::size_t inside(std::size_t a, std::size_t b, std::size_t c) const {
    const glm::dvec2 pa = points_[a], pb = points_[b], pc = points_[c];
    const double low = std::min({pa.y, pb.y, pc.y}), high = std::max({pa.y, pb.y, pc.y});
    const std::size_t y0 = column(low, lo_.y, scale_.y, rows_), y1 = column(high, lo_.y, scale_.y, rows_);
    const glm::dvec2 edges[3][2] = {{pa, pb}, {pb, pc}, {pc, pa}};
    for (std::size_t y = y0; y <= y1; ++y) {
      // The row's band of y, widened by a tenth of a row against rounding.
      const double step = scale_.y > 0 ? 1.0 / scale_.y : 0.0;
      const double band_lo = y == y0 ? low : lo_.y + (double(y) - 0.1) * step;
      const double band_hi = y == y1 ? high : lo_.y + (double(y) + 1.1) * step;
      double left = std::numeric_limits<double>::infinity(), right = -left;
      for (const auto& edge : edges) {
        const glm::dvec2 p = edge[0], q = edge[1];
        const double x_min = std::min(p.x, q.x), x_max = std::max(p.x, q.x);
        if (p.y == q.y) {
          if (p.y >= band_lo && p.y <= band_hi) {
            left = std::min(left, x_min);
            right = std::max(right, x_max);
          }
          continue;
        }
        const double from = std::max(band_lo, std::min(p.y, q.y)), to = std::min(band_hi, std::max(p.y, q.y));
        if (from > to) continue;
        for (const double at : {from, to}) {
          const double x = std::clamp(p.x + (q.x - p.x) * ((at - p.y) / (q.y - p.y)), x_min, x_max);
          left = std::min(left, x);
          right = std::max(right, x);
        }
      }
      if (left > right) continue;
      const std::size_t x0 = column(left, lo_.x, scale_.x, columns_), x1 = column(right, lo_.x, scale_.x, columns_);
      for (std::size_t x = x0 > 0 ? x0 - 1 : 0; x <= std::min(columns_ - 1, x1 + 1); ++x)
        for (const std::size_t p : cells_[y * columns_ + x])
          if (p != a && p != b && p != c && in_closed_triangle(pa, pb, pc, points_[p])) return p;
    }
    return points_.size();
  }

 private:
  static std::size_t column(double v, double lo, double scale, std::size_t count) {
    const double k = std::floor((v - lo) * scale);
    return k <= 0 ? 0 : std::min(count - 1, std::size_t(k));
  }
  std::size_t cell(glm::dvec2 p) const {
    return column(p.y, lo_.y, scale_.y, rows_) * columns_ + column(p.x, lo_.x, scale_.x, columns_);
  }
  const std::vector<glm::dvec2>& points_;
  glm::dvec2 lo_, hi_, scale_;
  std::size_t columns_, rows_;
  std::vector<std::vector<std::size_t>> cells_;
};

}  // namespace

// A vector's length without underflow or overflow of its squares (a model scaled by 1e-100
// has areas near 1e-200, whose squares a plain length would lose).
double norm(const Point& v) {
  const double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (m == 0.0 || !std::isfinite(m)) return m;
  const Point u = v / m;
  return m * std::sqrt(glm::dot(u, u));
}

// The same double as the largest norm(a - b) over all pairs (face_shapes_reference.cpp), found
// by branch and bound: each corner is measured only against the boxes of a k-d tree whose
// farthest corner could be as far as the largest distance found so far, and norm() is taken
// only of pairs whose plain squared distance could reach it. The search runs on the corners
// scaled by a power of two (exact) so that the squares neither overflow nor underflow, with a
// margin of 1e-6 over the few roundings of the squares (a pair or box left out is at least
// 5e-7 shorter than a pair measured). About O(n^1.5) for corners on a circle (every corner has
// a far partner), less for most faces.
double diameter(const std::vector<Point>& corners) {
  double d = 0.0;
  if (corners.size() <= kSmallFace) {
    for (const Point& a : corners)
      for (const Point& b : corners) d = std::max(d, norm(a - b));
    return d;
  }
  const std::vector<Point> unit = in_face_units(corners);
  const int exponent = face_exponent(corners);  // unit[i] = corners[i] / 2^exponent
  // A good first guess: from corner 0 to its farthest, and from there to its farthest.
  std::size_t far = 0;
  for (int round = 0; round < 2; ++round) {
    const Point a = corners[far];
    for (std::size_t i = 0; i < corners.size(); ++i)
      if (const double r = norm(a - corners[i]); r > d) {
        d = r;
        far = i;
      }
  }
  // Too small beside the corners' place for squares in the face's units: every pair.
  if (!(std::ldexp(d, -exponent) > 1e-100)) {
    for (const Point& a : corners)
      for (const Point& b : corners) d = std::max(d, norm(a - b));
    return d;
  }
  const auto threshold = [&] {  // squared distances below this are shorter than d
    const double scaled = std::ldexp(d, -exponent);
    return scaled * scaled * (1 - 1e-6);
  };
  double enough = threshold();
  const BoxTree tree(unit);
  std::vector<std::size_t> stack;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    const Point a = unit[i];
    stack.assign(1, 0);
    while (!stack.empty()) {
      const BoxTree::Node& node = tree.nodes[stack.back()];
      stack.pop_back();
      const Point reach = glm::max(glm::abs(a - node.lo), glm::abs(a - node.hi));
      if (glm::dot(reach, reach) < enough) continue;
      if (node.first_child != 0) {
        stack.push_back(node.first_child);
        stack.push_back(node.first_child + 1);
        continue;
      }
      for (std::size_t k = node.begin; k < node.end; ++k) {
        const std::size_t j = tree.order[k];
        const Point between = a - unit[j];
        if (glm::dot(between, between) < enough) continue;
        if (const double r = norm(corners[i] - corners[j]); r > d) {
          d = r;
          enough = threshold();
        }
      }
    }
  }
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

bool edges_cross(glm::dvec2 p, glm::dvec2 q, glm::dvec2 r, glm::dvec2 s) {
  const auto opposite = [](double a, double b) { return (a > 0 && b < 0) || (a < 0 && b > 0); };
  return opposite(cross2(p, q, r), cross2(p, q, s)) && opposite(cross2(r, s, p), cross2(r, s, q));
}

bool in_closed_triangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 p) {
  return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

// Ear clipping in the face's best plane: triangles in the face's own winding. Each step clips
// the first corner, in the face's order, that is convex with no other remaining corner in its
// closed triangle (face_shapes_reference.cpp says it plainly). Here each corner's state is
// kept and looked at again only when it can change: a convex corner with no corner in its
// triangle stays an ear until a neighbour is clipped (corners only leave); a reflex one stays
// so until then; one with a corner in its triangle stays blocked until a neighbour or that
// corner is clipped. The first ear is the smallest of an ordered set, and the "corner in the
// triangle" search looks only in a uniform grid's cells under the triangle's box.
std::vector<std::vector<Point>> ear_clip(const std::vector<Point>& corners) {
  const std::vector<glm::dvec2> flat = in_best_plane(corners);
  const std::size_t n = corners.size(), none = n;
  std::vector<std::size_t> previous(n), next(n), blocker(n, none);
  for (std::size_t i = 0; i < n; ++i) {
    previous[i] = (i + n - 1) % n;
    next[i] = (i + 1) % n;
  }
  std::vector<bool> gone(n, false);
  std::vector<std::vector<std::size_t>> blocking(n);  // the corners that p blocks (some stale)
  std::set<std::size_t> ears;
  CornerGrid grid(flat);
  const auto look_at = [&](std::size_t b) {
    ears.erase(b);
    blocker[b] = none;
    const std::size_t a = previous[b], c = next[b];
    if (cross2(flat[a], flat[b], flat[c]) <= 0) return;  // reflex (or straight) corner
    const std::size_t p = grid.inside(a, b, c);
    if (p == none) {
      ears.insert(b);
    } else {
      blocker[b] = p;
      blocking[p].push_back(b);
    }
  };
  for (std::size_t b = 0; b < n; ++b) look_at(b);
  std::vector<std::vector<Point>> triangles;
  std::size_t left = n;
  while (left > 3) {
    if (ears.empty()) {  // an outline that touches itself: a fan keeps what can be kept
      std::vector<std::size_t> outline;
      for (std::size_t i = 0; i < n; ++i)
        if (!gone[i]) outline.push_back(i);
      for (std::size_t k = 1; k + 1 < outline.size(); ++k)
        triangles.push_back({corners[outline[0]], corners[outline[k]], corners[outline[k + 1]]});
      return triangles;
    }
    const std::size_t b = *ears.begin(), a = previous[b], c = next[b];
    triangles.push_back({corners[a], corners[b], corners[c]});
    ears.erase(ears.begin());
    gone[b] = true;
    grid.remove(b);
    --left;
    next[a] = c;
    previous[c] = a;
    look_at(a);
    look_at(c);
    for (const std::size_t blocked : blocking[b])
      if (!gone[blocked] && blocker[blocked] == b) look_at(blocked);
    blocking[b].clear();
  }
  std::size_t first = 0;
  while (gone[first]) ++first;
  triangles.push_back({corners[first], corners[next[first]], corners[next[next[first]]]});
  return triangles;
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
  return ear_clip(corners);
}

// The first crossing pair in the order of face_shapes_reference.cpp (i, then j), found by a
// sweep over the edges' boxes in x: only edges whose boxes meet are tested (two edges that
// cross share a point, so their boxes meet), and of the pairs that cross the first in that
// order is kept. O(n log n + the pairs of edges whose boxes meet): about linear for an
// outline of short edges, quadratic for one whose edges all span the face.
std::optional<std::pair<std::size_t, std::size_t>> crossing_edges(const std::vector<Point>& corners) {
  std::vector<glm::dvec2> flat = in_best_plane(corners);
  const std::size_t n = flat.size();
  // Swept along the outline's longer side (a comb's teeth then meet only their neighbours).
  glm::dvec2 lo = flat.front(), hi = flat.front();
  for (const glm::dvec2& p : flat) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const int along = hi.x - lo.x >= hi.y - lo.y ? 0 : 1;
  std::vector<Box> box(n);
  for (std::size_t i = 0; i < n; ++i)
    box[i] = {glm::min(flat[i], flat[(i + 1) % n]), glm::max(flat[i], flat[(i + 1) % n])};
  std::vector<std::size_t> by_start(n);
  std::iota(by_start.begin(), by_start.end(), std::size_t(0));
  std::sort(by_start.begin(), by_start.end(), [&](std::size_t a, std::size_t b) {
    return box[a].lo[along] < box[b].lo[along] || (box[a].lo[along] == box[b].lo[along] && a < b);
  });
  std::optional<std::pair<std::size_t, std::size_t>> first;
  std::vector<std::size_t> open;  // edges whose box may still meet those to come
  for (const std::size_t e : by_start) {
    std::size_t kept = 0;
    for (const std::size_t o : open) {
      if (box[o].hi[along] < box[e].lo[along]) continue;  // passed: no later box meets it
      open[kept++] = o;
      const std::size_t i = std::min(e, o), j = std::max(e, o);
      if (j < i + 2 || (i == 0 && j == n - 1) || (first && std::pair{i, j} >= *first)) continue;
      if (overlap(box[i], box[j]) && edges_cross(flat[i], flat[(i + 1) % n], flat[j], flat[(j + 1) % n]))
        first = std::pair{i, j};
    }
    open.resize(kept);
    open.push_back(e);
  }
  return first;
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

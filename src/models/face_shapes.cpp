#include "models/face_shapes.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
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
    side_ = std::max<std::size_t>(1, std::size_t(std::sqrt(double(points.size()))));
    const glm::dvec2 size = hi_ - lo_;
    scale_ = glm::dvec2(size.x > 0 ? double(side_) / size.x : 0.0, size.y > 0 ? double(side_) / size.y : 0.0);
    cells_.resize(side_ * side_);
    for (std::size_t i = 0; i < points.size(); ++i) cells_[cell(points[i])].push_back(i);
  }
  void remove(std::size_t i) {
    std::vector<std::size_t>& c = cells_[cell(points_[i])];
    *std::find(c.begin(), c.end(), i) = c.back();
    c.pop_back();
  }
  // Some corner other than a, b and c, still in the outline, in the closed triangle a b c, or
  // points.size(). The cells searched are those that the triangle's box meets: a corner outside
  // the box is outside the triangle.
  std::size_t inside(std::size_t a, std::size_t b, std::size_t c) const {
    const glm::dvec2 lo = glm::min(points_[a], glm::min(points_[b], points_[c]));
    const glm::dvec2 hi = glm::max(points_[a], glm::max(points_[b], points_[c]));
    const std::size_t x0 = column(lo.x, lo_.x, scale_.x), x1 = column(hi.x, lo_.x, scale_.x);
    const std::size_t y0 = column(lo.y, lo_.y, scale_.y), y1 = column(hi.y, lo_.y, scale_.y);
    for (std::size_t y = y0; y <= y1; ++y)
      for (std::size_t x = x0; x <= x1; ++x)
        for (const std::size_t p : cells_[y * side_ + x])
          if (p != a && p != b && p != c && in_closed_triangle(points_[a], points_[b], points_[c], points_[p]))
            return p;
    return points_.size();
  }

 private:
  std::size_t column(double v, double lo, double scale) const {
    const double k = std::floor((v - lo) * scale);
    return k <= 0 ? 0 : std::min(side_ - 1, std::size_t(k));
  }
  std::size_t cell(glm::dvec2 p) const {
    return column(p.y, lo_.y, scale_.y) * side_ + column(p.x, lo_.x, scale_.x);
  }
  const std::vector<glm::dvec2>& points_;
  glm::dvec2 lo_, hi_, scale_;
  std::size_t side_;
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
// farthest corner could be as far as the largest distance found so far. Pruning is safe in
// floating point: rounding is monotonic, so a point's computed differences to a box's points
// are no larger than those to its farthest corner, and the margin of 1e-9 covers the few
// roundings of norm(). About O(n^1.5) for corners on a circle (every corner has a far partner),
// less for most faces.
double diameter(const std::vector<Point>& corners) {
  double d = 0.0;
  if (corners.size() <= kSmallFace) {
    for (const Point& a : corners)
      for (const Point& b : corners) d = std::max(d, norm(a - b));
    return d;
  }
  const BoxTree tree(corners);
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
  std::vector<std::size_t> stack;
  for (const Point& a : corners) {
    stack.assign(1, 0);
    while (!stack.empty()) {
      const BoxTree::Node& node = tree.nodes[stack.back()];
      stack.pop_back();
      const Point reach = glm::max(glm::abs(a - node.lo), glm::abs(a - node.hi));
      if (norm(reach) * (1 + 1e-9) < d) continue;
      if (node.first_child == 0) {
        for (std::size_t i = node.begin; i < node.end; ++i) d = std::max(d, norm(a - corners[tree.order[i]]));
      } else {
        stack.push_back(node.first_child);
        stack.push_back(node.first_child + 1);
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
  const std::vector<glm::dvec2> flat = in_best_plane(corners);
  const std::size_t n = flat.size();
  std::vector<Box> box(n);
  for (std::size_t i = 0; i < n; ++i)
    box[i] = {glm::min(flat[i], flat[(i + 1) % n]), glm::max(flat[i], flat[(i + 1) % n])};
  std::vector<std::size_t> by_left(n);
  std::iota(by_left.begin(), by_left.end(), std::size_t(0));
  std::sort(by_left.begin(), by_left.end(), [&](std::size_t a, std::size_t b) {
    return box[a].lo.x < box[b].lo.x || (box[a].lo.x == box[b].lo.x && a < b);
  });
  std::optional<std::pair<std::size_t, std::size_t>> first;
  std::vector<std::size_t> open;  // edges whose box may still meet those to come
  for (const std::size_t e : by_left) {
    std::size_t kept = 0;
    for (const std::size_t o : open) {
      if (box[o].hi.x < box[e].lo.x) continue;  // left behind: no later box meets it
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

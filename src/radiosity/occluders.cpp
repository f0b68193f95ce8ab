#include "radiosity/occluders.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace ncube {
namespace {

// Ends of a shadow ray lie on the receiver and on the shooter; a relative margin keeps the
// surfaces they start and end on (and coplanar neighbours) from blocking them.
constexpr double kRayEpsilon = 1e-9;
constexpr int kLeafSize = 4;

// A segment with its reciprocal direction, computed once per ray for all box tests.
struct Segment {
  Vec3 from, delta, inverse;
  Segment(const Vec3& f, const Vec3& d) : from(f), delta(d) {
    for (int axis = 0; axis < 3; ++axis) inverse[axis] = d[axis] != 0.0 ? 1.0 / d[axis] : 0.0;
  }
};

bool segment_meets_box(const Vec3& lo, const Vec3& hi, const Segment& s) {
  double t0 = 0.0, t1 = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (s.delta[axis] == 0.0) {
      if (s.from[axis] < lo[axis] || s.from[axis] > hi[axis]) return false;
      continue;
    }
    double a = (lo[axis] - s.from[axis]) * s.inverse[axis];
    double b = (hi[axis] - s.from[axis]) * s.inverse[axis];
    if (a > b) std::swap(a, b);
    t0 = a > t0 ? a : t0;
    t1 = b < t1 ? b : t1;
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

bool segment_crosses(const Occluders::Candidate& c, const Vec3& from, const Vec3& delta) {
  const double denominator = glm::dot(c.normal, delta);
  if (denominator == 0.0) return false;  // parallel to the plane
  const double t = (c.plane_offset - glm::dot(c.normal, from)) / denominator;
  if (!(t > kRayEpsilon && t < 1.0 - kRayEpsilon)) return false;
  const Vec3 x = from + t * delta;
  for (int k = 0; k < c.vertex_count; ++k) {
    const Vec3& a = c.vertices[k];
    const Vec3& b = c.vertices[(k + 1) % c.vertex_count];
    if (glm::dot(c.normal, glm::cross(b - a, x - a)) < 0.0) return false;
  }
  return true;
}

Occluders::Occluders(const Scene& scene, std::vector<int> patch_indices, RayTestPolicy policy)
    : policy_(policy), position_of_scene_patch_(scene.patches.size(), -1) {
  // Pad boxes so that rounding in the slab test never prunes a patch the exact test hits.
  const double pad = 1e-7 * (1.0 + scene_bounds(scene).diagonal());
  side_tolerance_ = 1e-9 * (1.0 + scene_bounds(scene).diagonal());
  patches_.reserve(patch_indices.size());
  for (int scene_index : patch_indices) {
    const Patch& p = scene.patches[scene_index];
    Candidate c{};
    c.vertex_count = p.polygon.count;
    c.lo = Vec3(1e300);
    c.hi = Vec3(-1e300);
    for (int i = 0; i < p.polygon.count; ++i) {
      c.vertices[i] = p.polygon[i];
      c.lo = glm::min(c.lo, p.polygon[i]);
      c.hi = glm::max(c.hi, p.polygon[i]);
    }
    c.lo -= Vec3(pad);
    c.hi += Vec3(pad);
    c.normal = p.normal;
    c.plane_offset = glm::dot(p.normal, p.polygon[0]);
    c.scene_index = scene_index;
    position_of_scene_patch_[scene_index] = int(patches_.size());
    patches_.push_back(c);
    plane_x_.push_back(c.normal.x);
    plane_y_.push_back(c.normal.y);
    plane_z_.push_back(c.normal.z);
    plane_offset_.push_back(c.plane_offset);
  }
  order_.resize(patches_.size());
  for (int i = 0; i < int(order_.size()); ++i) order_[i] = i;
  if (!patches_.empty()) {
    nodes_.reserve(2 * patches_.size());
    build(0, int(patches_.size()));
  }
}

int Occluders::build(int first, int count) {
  const int index = int(nodes_.size());
  nodes_.push_back(Node{});
  Vec3 lo(1e300), hi(-1e300);
  int min_position = 1 << 30;
  for (int i = first; i < first + count; ++i) {
    const Candidate& c = patches_[order_[i]];
    lo = glm::min(lo, c.lo);
    hi = glm::max(hi, c.hi);
    min_position = std::min(min_position, order_[i]);
  }
  nodes_[index].lo = lo;
  nodes_[index].hi = hi;
  nodes_[index].min_position = min_position;
  if (count <= kLeafSize) {
    nodes_[index].first = first;
    nodes_[index].count = count;
    return index;
  }
  // Surface-area heuristic: on each axis, sort by box centre and take the cut that
  // minimises area(left) x n(left) + area(right) x n(right); ties broken by position so the
  // hierarchy is the same on every run.
  auto area = [](const Vec3& a, const Vec3& b) {
    const Vec3 d = b - a;
    return d.x * d.y + d.y * d.z + d.z * d.x;
  };
  auto sort_on = [&](int axis) {
    auto key = [&](int position) { return patches_[position].lo[axis] + patches_[position].hi[axis]; };
    std::sort(order_.begin() + first, order_.begin() + first + count, [&](int a, int b) {
      return key(a) < key(b) || (key(a) == key(b) && a < b);
    });
  };
  std::vector<double> right_area(std::size_t(count), 0.0);
  double best_cost = 1e300;
  int best_axis = 0, half = count / 2;
  for (int axis = 0; axis < 3; ++axis) {
    sort_on(axis);
    Vec3 r_lo(1e300), r_hi(-1e300);
    for (int k = count - 1; k > 0; --k) {
      const Candidate& c = patches_[order_[first + k]];
      r_lo = glm::min(r_lo, c.lo);
      r_hi = glm::max(r_hi, c.hi);
      right_area[k] = area(r_lo, r_hi);
    }
    Vec3 l_lo(1e300), l_hi(-1e300);
    for (int k = 1; k < count; ++k) {
      const Candidate& c = patches_[order_[first + k - 1]];
      l_lo = glm::min(l_lo, c.lo);
      l_hi = glm::max(l_hi, c.hi);
      const double cost = area(l_lo, l_hi) * k + right_area[k] * (count - k);
      if (cost < best_cost) {
        best_cost = cost;
        best_axis = axis;
        half = k;
      }
    }
  }
  sort_on(best_axis);
  const int left = build(first, half);
  const int right = build(first + half, count - half);
  nodes_[index].first = left;
  nodes_[index].right = right;
  nodes_[index].count = 0;
  return index;
}

template <class Skip, class Visit>
void Occluders::walk(const Vec3& from, const Vec3& delta, Skip skip, Visit visit) const {
  const Segment segment(from, delta);
  int stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& node = nodes_[stack[--top]];
    if (skip(node) || !segment_meets_box(node.lo, node.hi, segment)) continue;
    if (node.count == 0) {
      stack[top++] = node.right;
      stack[top++] = node.first;
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i)
      if (visit(order_[i])) return;
  }
}

int Occluders::any_blocker(const Vec3& from, const Vec3& delta, int receiver, int shooter,
                           int hint) const {
  // The last blocker usually blocks the next ray too (rays of one receiver are coherent).
  if (hint >= 0 && segment_crosses(patches_[hint], from, delta)) return hint;
  int found = -1;
  walk(from, delta, [](const Node&) { return false; }, [&](int position) {
    const Candidate& c = patches_[position];
    if (c.scene_index == receiver || c.scene_index == shooter || !segment_crosses(c, from, delta))
      return false;
    found = position;
    return true;
  });
  return found;
}

int Occluders::first_blocker(const Vec3& from, const Vec3& delta, int receiver, int shooter,
                             int hint) const {
  int best = 1 << 30;
  if (hint >= 0 && segment_crosses(patches_[hint], from, delta)) best = hint;
  // Subtrees holding only later candidates than the best blocker so far cannot matter.
  walk(from, delta, [&](const Node& node) { return node.min_position >= best; },
       [&](int position) {
         const Candidate& c = patches_[position];
         if (position < best && c.scene_index != receiver && c.scene_index != shooter &&
             segment_crosses(c, from, delta))
           best = position;
         return false;
       });
  return best == (1 << 30) ? -1 : best;
}

int Occluders::plane_side(int position, const Vec3& x) const {
  const double distance = plane_x_[position] * x.x + plane_y_[position] * x.y +
                          plane_z_[position] * x.z - plane_offset_[position];
  return distance > side_tolerance_ ? 1 : (distance < -side_tolerance_ ? -1 : 0);
}

const Occluders::TargetSides& Occluders::target_sides(const Shooter& shooter) const {
  const int m = shooter.part_count;
  if (sides_.part_count == m &&
      std::equal(shooter.targets.begin(), shooter.targets.begin() + m, sides_.targets.begin()))
    return sides_;
  const std::size_t n = patches_.size();
  sides_.part_count = m;
  sides_.targets = shooter.targets;
  sides_.in_front.assign(n, 0);
  sides_.behind.assign(n, 0);
  sides_.side.assign(n * std::size_t(m), 0);
  for (std::size_t c = 0; c < n; ++c)
    for (int k = 0; k < m; ++k) {
      const int side = plane_side(int(c), shooter.targets[k]);
      sides_.side[c * m + k] = std::int8_t(side);
      if (side > 0) ++sides_.in_front[c];
      if (side < 0) ++sides_.behind[c];
    }
  return sides_;
}

std::uint64_t Occluders::plane_crossings(const Vec3& point, const TargetSides& sides,
                                         int receiver_position, int shooter_position) const {
  // Summed per candidate instead of per ray: a candidate is crossed by the rays to the
  // targets on the other side of its plane from the point.
  auto crossings_at = [&](int c) -> std::int64_t {
    const int side = plane_side(c, point);
    return side > 0 ? sides.behind[c] : (side < 0 ? sides.in_front[c] : 0);
  };
  std::int64_t crossings = 0;
  const int n = int(plane_x_.size());
  for (int c = 0; c < n; ++c) crossings += crossings_at(c);
  if (receiver_position >= 0) crossings -= crossings_at(receiver_position);
  if (shooter_position >= 0) crossings -= crossings_at(shooter_position);
  return std::uint64_t(crossings);
}

PartMask Occluders::unblocked_parts(const Vec3& point, int receiver_patch, const Shooter& shooter,
                                    WorkCounts& counts) const {
  const int receiver_position = position_in_set(receiver_patch);
  const int shooter_position = position_in_set(shooter.patch);
  const int excluded = (receiver_position >= 0) + (shooter_position >= 0);
  const int m = shooter.part_count;
  PartMask visible = 0;
  if (patches_.empty()) {
    counts.rays += std::uint64_t(m);
    return shooter.all_parts();
  }
  const TargetSides& sides = target_sides(shooter);
  if (policy_ == RayTestPolicy::kTestAllPatches) {
    int last_blocker = -1;  // never an excluded patch: those are never found blocking
    for (int part = 0; part < m; ++part) {
      last_blocker = any_blocker(point, shooter.targets[part] - point, receiver_patch,
                                 shooter.patch, last_blocker);
      if (last_blocker < 0) visible |= PartMask(1) << part;
    }
    counts.ray_patch_tests += std::uint64_t(m) * std::uint64_t(size() - excluded);
    counts.plane_crossings += plane_crossings(point, sides, receiver_position, shooter_position);
    counts.rays += std::uint64_t(m);
    return visible;
  }
  // First blocker: the loop of each ray tests the candidates up to and including its first
  // blocker (all of them when there is none), skipping the excluded ones.
  std::vector<std::int8_t> point_side(patches_.size());
  for (int c = 0; c < size(); ++c) point_side[c] = std::int8_t(plane_side(c, point));
  int last_blocker = -1;
  for (int part = 0; part < m; ++part) {
    const int blocker = first_blocker(point, shooter.targets[part] - point, receiver_patch,
                                      shooter.patch, last_blocker);
    if (blocker >= 0) last_blocker = blocker;
    if (blocker < 0) visible |= PartMask(1) << part;
    const int end = blocker < 0 ? size() : blocker + 1;
    std::uint64_t tests = 0, crossings = 0;
    for (int c = 0; c < end; ++c) {
      if (c == receiver_position || c == shooter_position) continue;
      ++tests;
      crossings += point_side[c] * sides.side[std::size_t(c) * m + part] < 0;
    }
    counts.ray_patch_tests += tests;
    counts.plane_crossings += crossings;
  }
  counts.rays += std::uint64_t(m);
  return visible;
}

PartMask Occluders::unblocked_parts_brute_force(const Vec3& point, int receiver_patch,
                                                const Shooter& shooter, WorkCounts& counts) const {
  PartMask visible = 0;
  for (int part = 0; part < shooter.part_count; ++part) {
    const Vec3 delta = shooter.targets[part] - point;
    bool blocked = false;
    for (int position = 0; position < size(); ++position) {
      const Candidate& c = patches_[position];
      if (c.scene_index == receiver_patch || c.scene_index == shooter.patch) continue;
      ++counts.ray_patch_tests;
      if (plane_side(position, point) * plane_side(position, shooter.targets[part]) < 0)
        ++counts.plane_crossings;
      if (segment_crosses(c, point, delta)) {
        blocked = true;
        if (policy_ == RayTestPolicy::kStopAtFirstBlocker) break;
      }
    }
    ++counts.rays;
    if (!blocked) visible |= PartMask(1) << part;
  }
  return visible;
}

}  // namespace ncube

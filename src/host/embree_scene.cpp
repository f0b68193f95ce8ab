#include "host/embree_scene.h"

#include <emmintrin.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <stdexcept>

namespace ncube {
namespace {

// One Embree device for the process: it holds Embree's thread pool and ISA dispatch. BVH
// builds of these scenes are small. No "threads=N": Embree would cap every TBB arena of the
// process (host_threads.h) at N.
RTCDevice embree_device() {
  static RTCDevice device = [] {
    RTCDevice d = rtcNewDevice("set_affinity=0");
    if (!d) throw std::runtime_error("Embree: cannot create a device");
    return d;
  }();
  return device;
}

// The polygon grown by `pad` in its plane: each edge moved outwards by `pad`, each vertex
// to where its two moved edges meet. A triangle gives the quad (v0, v1, v2, v2).
void padded_quad(const PatchCandidate& c, double pad, Vec3 out[4]) {
  const int n = c.vertex_count;
  Vec3 outward[4];
  for (int k = 0; k < n; ++k) {
    const Vec3 edge = c.vertices[(k + 1) % n] - c.vertices[k];
    outward[k] = glm::normalize(glm::cross(edge, c.normal));  // CCW seen from the front
  }
  for (int k = 0; k < 4; ++k) {
    const int v = std::min(k, n - 1);
    const Vec3& before = outward[(v + n - 1) % n];
    const Vec3& after = outward[v];
    out[k] = c.vertices[v] + pad * (before + after) / (1.0 + glm::dot(before, after));
  }
}

// Triangle (a, b, c) of a padded quad, cut along its diagonal c-a, with that diagonal moved
// `pad` away from b: a and c slide outwards along the lines of the quad's edges b-a and b-c.
// The two triangles of a quad then overlap by 2 pad across its diagonal, so a crossing of
// the patch is at least `pad` inside one of them: Embree's triangle test need not be
// watertight (no RTC_SCENE_FLAG_ROBUST), as it need not be at the quad's outer edges.
struct WidenedTriangle {
  Vec3 corners[3];
  double sine;  // the smaller sine of the angles between the diagonal and the sliding edges
};

WidenedTriangle widened_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& normal,
                                 double pad) {
  const Vec3 away = glm::normalize(glm::cross(a - c, normal));  // b is on the other side
  const Vec3 along_a = glm::normalize(a - b), along_c = glm::normalize(c - b);
  const double sine_a = glm::dot(along_a, away), sine_c = glm::dot(along_c, away);
  return {{a + pad / sine_a * along_a, b, c + pad / sine_c * along_c}, std::min(sine_a, sine_c)};
}

// The two widened triangles of a padded quad, cut along the diagonal whose triangles slide
// least (a slide is pad / sine: a long thin quad cut along the wrong diagonal would get
// spikes far beyond it, costing only filter calls, but still).
void widened_triangles(const Vec3 q[4], const Vec3& normal, double pad, float* out) {
  WidenedTriangle cut[2][2];
  for (int d = 0; d < 2; ++d) {
    const Vec3 &a = q[d], &b = q[d + 1], &c = q[(d + 2) % 4], &e = q[(d + 3) % 4];
    cut[d][0] = widened_triangle(a, b, c, normal, pad);
    cut[d][1] = widened_triangle(c, e, a, normal, pad);
  }
  const int d = std::min(cut[1][0].sine, cut[1][1].sine) > std::min(cut[0][0].sine, cut[0][1].sine);
  for (int t = 0; t < 2; ++t)
    for (int k = 0; k < 3; ++k)
      for (int axis = 0; axis < 3; ++axis)
        out[9 * t + 3 * k + axis] = float(cut[d][t].corners[k][axis]);
}

// Bit i set when lane i of Embree's `valid` (0 or -1 per lane) is on: four SSE2 compares for
// the 16 lanes of rtcOccluded16, which calls the filter once per primitive met.
std::uint64_t valid_lanes(const int* valid, unsigned n) {
  if (n != 16) {
    std::uint64_t lanes = 0;
    for (unsigned i = 0; i < n; ++i) lanes |= std::uint64_t(valid[i] != 0) << i;
    return lanes;
  }
  const __m128i zero = _mm_setzero_si128();
  unsigned off = 0;
  for (int quad = 0; quad < 4; ++quad) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(valid + 4 * quad));
    off |= unsigned(_mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(v, zero)))) << (4 * quad);
  }
  return ~off & 0xffffu;
}

}  // namespace

struct EmbreeScene::Query {
  RTCIntersectContext context;  // first: Embree hands the filter this address
  const EmbreeScene* scene;
  Vec3 from;
  Vec3 delta[kMaxShooterParts];
  int excluded_a, excluded_b;
  // Per ray, the last candidate the exact test denied it: the two overlapping triangles of a
  // quadrilateral are often reported one after the other, and the test would deny again.
  int denied[kMaxShooterParts];
  const EmbreeScene::RayTargets* targets;
  std::vector<std::pair<int, int>>* hits;  // null: any blocker ends a ray; else every
                                           // (ray, position) found, and no ray ends
  const std::uint64_t* sets_of;            // not null: the sets each ray meets (ray_sets)
  std::uint64_t all_sets;
  std::uint64_t* ray_sets;
};

EmbreeScene::EmbreeScene(const std::vector<PatchCandidate>& candidates, double pad)
    : candidates_(candidates), exact_(candidates), pad_(pad), near_(candidates, kNearRadius * pad) {
  RTCDevice device = embree_device();
  scene_ = rtcNewScene(device);
  rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
  // Each patch as the triangles of its padded quad: one for a triangle, two widened ones
  // for a quadrilateral (widened_triangles).
  std::vector<float> corners;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const PatchCandidate& c = candidates[i];
    Vec3 q[4];
    padded_quad(c, pad, q);
    float triangle[9];
    if (c.vertex_count == 3) {
      for (int k = 0; k < 3; ++k)
        for (int axis = 0; axis < 3; ++axis) triangle[3 * k + axis] = float(q[k][axis]);
      corners.insert(corners.end(), triangle, triangle + 9);
      position_of_triangle_.push_back(int(i));
    } else {
      float pair[18];
      widened_triangles(q, c.normal, pad, pair);
      corners.insert(corners.end(), pair, pair + 18);
      position_of_triangle_.insert(position_of_triangle_.end(), 2, int(i));
    }
  }
  if (!position_of_triangle_.empty()) {
    RTCGeometry triangles = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    const std::size_t n = position_of_triangle_.size();
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
        triangles, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        triangles, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n));
    std::copy(corners.begin(), corners.end(), vertices);
    for (unsigned k = 0; k < 3 * n; ++k) indices[k] = k;
    rtcSetGeometryOccludedFilterFunction(triangles, &EmbreeScene::exact_filter);
    rtcCommitGeometry(triangles);
    rtcAttachGeometry(scene_, triangles);
    rtcReleaseGeometry(triangles);
  }
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
    throw std::runtime_error("Embree: cannot build the occluder scene");
}

EmbreeScene::~EmbreeScene() {
  if (scene_) rtcReleaseScene(scene_);
}

void EmbreeScene::exact_filter(const RTCFilterFunctionNArguments* args) {
  Query& q = *reinterpret_cast<Query*>(args->context);
  // Embree calls this once per primitive met, with the lanes that met it valid (often one of
  // 16): the valid lanes first, then only those. Locals, not args->..., in the loop: the
  // stores to `valid` could otherwise alias them and force reloads.
  const unsigned n = args->N;
  int* valid = args->valid;
  const unsigned* ray_ids = &RTCRayN_id(args->ray, n, 0);
  const unsigned* triangles = &RTCHitN_primID(args->hit, n, 0);
  const int* position_of = q.scene->position_of_triangle_.data();
  const AxisPatchTest& exact = q.scene->exact_;
  const std::uint64_t lanes_in = valid_lanes(valid, n);
  // The exact test, unless it denied this ray this candidate just before (same answer).
  auto crosses = [&](unsigned ray, int position) {
    if (q.denied[ray] == position) return false;
    if (exact.crosses(position, q.from, q.delta[ray])) return true;
    q.denied[ray] = position;
    return false;
  };
  for (std::uint64_t lanes = lanes_in; lanes != 0; lanes &= lanes - 1) {
    const unsigned i = unsigned(__builtin_ctzll(lanes));
    const unsigned ray = ray_ids[i];
    const int position = position_of[triangles[i]];
    if (q.sets_of) {  // only hits that can tell of a set not yet known to block are tested
      const std::uint64_t sets = q.sets_of[position];
      if (position == q.excluded_a || position == q.excluded_b || (sets & ~q.ray_sets[ray]) == 0 ||
          !crosses(ray, position)) {
        valid[i] = 0;
        continue;
      }
      q.ray_sets[ray] |= sets;
      if (q.ray_sets[ray] != q.all_sets) valid[i] = 0;  // else accepted: the ray ends
      continue;
    }
    const bool blocks = position != q.excluded_a && position != q.excluded_b && crosses(ray, position);
    if (q.hits) {  // record and reject: the traversal goes on to the end of the segment
      if (blocks) q.hits->emplace_back(int(ray), position);
      valid[i] = 0;
    } else if (!blocks) {
      valid[i] = 0;
    }
  }
}

PartMask EmbreeScene::trace(Query& query, int count, PartMask done) const {
  query.context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;  // one origin, one target patch
  PartMask blocked = 0;
  // Parameter t of the exact test; Embree's ray k covers [g_k, 1 - g_k], g_k = kEndGap pads
  // over its length (the rounding of these bounds to floats is far below the margin). A ray
  // shorter than 2 kEndGap pads is left to the near-end tests alone: every point of it is
  // within kNearRadius pads of an end.
  const double gap = kEndGap * pad_;
  for (int start = 0; start < count; start += 16) {
    alignas(64) RTCRay16 r;
    alignas(64) int valid[16];
    int any = 0;
    for (int lane = 0; lane < 16; ++lane) {
      const int k = std::min(start + lane, count - 1);  // idle lanes repeat the last ray
      const Vec3& delta = query.delta[k];
      const double g = gap / std::sqrt(glm::dot(delta, delta));
      valid[lane] = start + lane < count && !(done >> k & 1) && g < 0.5 ? -1 : 0;
      any |= valid[lane];
      r.org_x[lane] = float(query.from.x);
      r.org_y[lane] = float(query.from.y);
      r.org_z[lane] = float(query.from.z);
      r.dir_x[lane] = float(delta.x);
      r.dir_y[lane] = float(delta.y);
      r.dir_z[lane] = float(delta.z);
      r.tnear[lane] = valid[lane] ? float(g) : 0.0f;
      r.tfar[lane] = valid[lane] ? float(1.0 - g) : 0.0f;
      r.time[lane] = 0.0f;
      r.mask[lane] = ~0u;
      r.id[lane] = unsigned(k);
      r.flags[lane] = 0;
    }
    if (!any) continue;
    rtcOccluded16(valid, scene_, &query.context, &r);
    for (int lane = 0; lane < 16 && start + lane < count; ++lane)
      if (valid[lane] && r.tfar[lane] == -INFINITY) blocked |= PartMask(1) << (start + lane);
  }
  return blocked;
}

template <class Found>
void EmbreeScene::near_end_crossings(const Query& query, int count, Found&& found) const {
  const RayTargets& targets = *query.targets;
  near_.for_each_near(query.from, [&](int position) {
    if (position == query.excluded_a || position == query.excluded_b) return;
    for (int k = 0; k < count; ++k)
      if (exact_.crosses(position, query.from, query.delta[k])) found(k, position);
  });
  for (const auto& [k, position] : targets.near)
    if (position != query.excluded_a && exact_.crosses(position, query.from, query.delta[k]))
      found(k, position);
}

EmbreeScene::RayTargets EmbreeScene::ray_targets(const Vec3* targets, int count,
                                                 int shooter_position) const {
  if (count < 0 || count > kMaxShooterParts)
    throw std::logic_error("EmbreeScene: more than 64 ray targets");
  RayTargets result;
  result.patch = shooter_position;
  result.points.assign(targets, targets + count);
  for (int k = 0; k < count; ++k)
    near_.for_each_near(targets[k], [&](int position) {
      if (position != shooter_position) result.near.emplace_back(k, position);
    });
  return result;
}

void EmbreeScene::prepare(Query& query, const Vec3& from, int receiver,
                          const RayTargets& targets,
                          std::vector<std::pair<int, int>>* hits) const {
  rtcInitIntersectContext(&query.context);
  query.scene = this;
  query.from = from;
  for (int k = 0; k < targets.count(); ++k) query.delta[k] = targets.points[std::size_t(k)] - from;
  query.excluded_a = receiver;
  query.excluded_b = targets.patch;
  std::fill(query.denied, query.denied + kMaxShooterParts, -1);
  query.targets = &targets;
  query.hits = hits;
  query.sets_of = nullptr;
  query.all_sets = 0;
  query.ray_sets = nullptr;
}

// Each query: the rays' ends by the exact test first, then Embree for the rest of each ray
// that can still change the answer.
PartMask EmbreeScene::blocked(const Vec3& from, int receiver, const RayTargets& targets) const {
  const int count = targets.count();
  if (candidates_.empty() || count == 0) return 0;
  Query query;
  prepare(query, from, receiver, targets, nullptr);
  PartMask blocked = 0;
  near_end_crossings(query, count, [&](int k, int) { blocked |= PartMask(1) << k; });
  return blocked | trace(query, count, blocked);
}

void EmbreeScene::all_blockers(const Vec3& from, int receiver, const RayTargets& targets,
                               std::vector<std::pair<int, int>>& hits) const {
  const int count = targets.count();
  if (candidates_.empty() || count == 0) return;
  Query query;
  prepare(query, from, receiver, targets, &hits);
  near_end_crossings(query, count, [&](int k, int position) { hits.emplace_back(k, position); });
  trace(query, count, 0);
}

void EmbreeScene::blocked_sets(const Vec3& from, int receiver, const RayTargets& targets,
                               const std::uint64_t* sets_of, std::uint64_t all_sets,
                               std::uint64_t* ray_sets) const {
  const int count = targets.count();
  std::fill(ray_sets, ray_sets + count, std::uint64_t(0));
  if (candidates_.empty() || count == 0 || all_sets == 0) return;
  Query query;
  prepare(query, from, receiver, targets, nullptr);
  query.sets_of = sets_of;
  query.all_sets = all_sets;
  query.ray_sets = ray_sets;
  PartMask done = 0;
  near_end_crossings(query, count, [&](int k, int position) {
    ray_sets[k] |= sets_of[position];
    if (ray_sets[k] == all_sets) done |= PartMask(1) << k;
  });
  trace(query, count, done);
}

}  // namespace ncube

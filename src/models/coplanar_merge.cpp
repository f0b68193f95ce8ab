#include "models/coplanar_merge.h"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>

#include "models/face_shapes.h"

namespace ncube::models {
namespace {

// Triangle `triangle`'s edge `edge` (corner edge -> corner edge + 1), by its two points.
struct Side {
  Point a, b;
  std::uint32_t triangle;
  std::uint8_t edge;
};

// Sides ordered by their points (compared as the corners are: with <, so 0 and -0 are one
// coordinate, as == has them), then by triangle and edge.
bool points_before(const Side& s, const Point& a, const Point& b) {
  for (int c = 0; c < 3; ++c)
    if (s.a[c] != a[c]) return s.a[c] < a[c];
  for (int c = 0; c < 3; ++c)
    if (s.b[c] != b[c]) return s.b[c] < b[c];
  return false;
}

}  // namespace

// --merge-coplanar: a triangle and a later one of the same material that share an edge, lie
// in one plane and together make a planar convex quad become that quad (patches are what
// shoots: a quad cut in two by a modelling tool or by glTF, which has triangles only, shoots as
// two). The quad starts at the first triangle's first corner, so the two halves of a quad
// (a, b, c) and (a, c, d) give back (a, b, c, d).
//
// Each triangle in turn, unless already merged, takes the first later triangle that qualifies
// (the later triangle first, then the first triangle's edge, then the second's), as a scan of
// every later triangle would; the later triangles sharing an edge are found by binary search
// in the triangles' directed edges sorted by their points (a hash table of them was slower,
// its scattered accesses missing the caches), so the time is O(n log n) in the triangles
// (plus, for each triangle, the later ones that share one of its edges).
std::vector<ImportedPatch> merge_coplanar(const std::vector<ImportedPatch>& patches, long& merged_pairs) {
  std::vector<Side> sides;
  for (std::size_t j = 0; j < patches.size(); ++j)
    if (patches[j].corners.size() == 3)
      for (int f = 0; f < 3; ++f)
        sides.push_back({patches[j].corners[std::size_t(f)], patches[j].corners[std::size_t((f + 1) % 3)],
                         std::uint32_t(j), std::uint8_t(f)});
  std::sort(sides.begin(), sides.end(), [](const Side& x, const Side& y) {
    if (points_before(x, y.a, y.b)) return true;
    if (points_before(y, x.a, x.b)) return false;
    return x.triangle != y.triangle ? x.triangle < y.triangle : x.edge < y.edge;
  });
  std::vector<bool> used(patches.size(), false);
  std::vector<ImportedPatch> merged;
  std::vector<std::tuple<std::uint32_t, int, int>> candidates;  // (later triangle, e, f)
  for (std::size_t i = 0; i < patches.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    const ImportedPatch& first = patches[i];
    bool done = false;
    candidates.clear();
    if (first.corners.size() == 3)
      for (int e = 0; e < 3; ++e) {
        // The shared edge runs (a -> b) in the first triangle and (b -> a) in the second.
        const Point& a = first.corners[std::size_t(e)];
        const Point& b = first.corners[std::size_t((e + 1) % 3)];
        auto side = std::lower_bound(sides.begin(), sides.end(), std::pair{b, a},
                                     [](const Side& x, const std::pair<Point, Point>& key) {
                                       return points_before(x, key.first, key.second);
                                     });
        for (; side != sides.end() && side->a == b && side->b == a; ++side)
          if (side->triangle > i && !used[side->triangle]) candidates.emplace_back(side->triangle, e, side->edge);
      }
    std::sort(candidates.begin(), candidates.end());
    for (const auto& [j, e, f] : candidates) {
      const ImportedPatch& second = patches[j];
      if (second.material.reflectance != first.material.reflectance ||
          second.material.emission != first.material.emission)
        continue;
      const Point& far = second.corners[std::size_t((f + 2) % 3)];
      std::vector<Point> quad;
      for (int k = 0; k < 3; ++k) {
        quad.push_back(first.corners[std::size_t(k)]);
        if (k == e) quad.push_back(far);
      }
      if (!planar_convex_quad(quad)) continue;
      merged.push_back({quad, first.material});
      used[j] = true;
      done = true;
      ++merged_pairs;
      break;
    }
    if (!done) merged.push_back(first);
  }
  return merged;
}

}  // namespace ncube::models

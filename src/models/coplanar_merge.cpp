#include "models/coplanar_merge.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <tuple>
#include <unordered_map>

#include "models/face_shapes.h"

namespace ncube::models {
namespace {

// A directed edge (a -> b) by its two points, compared exactly as the corners are (== on
// doubles, so 0 and -0 are one coordinate).
struct Edge {
  Point a, b;
  bool operator==(const Edge& other) const { return a == other.a && b == other.b; }
};

struct EdgeHash {
  std::size_t operator()(const Edge& e) const {
    std::size_t h = 0;
    for (const Point* p : {&e.a, &e.b})
      for (int c = 0; c < 3; ++c)  // + 0.0 makes -0 into 0, which == treats as equal (libstdc++
                                   // hashes both to 0 already; others need not)
        h = h * 1000003u ^ std::hash<double>()((*p)[c] + 0.0);
    return h;
  }
};

// A triangle j whose edge f (corner f -> corner f + 1) is the key.
struct Side {
  std::uint32_t triangle;
  std::uint8_t edge;
};

}  // namespace

// --merge-coplanar: a triangle and a later one of the same material that share an edge, lie
// in one plane and together make a planar convex quad become that quad (patches are what
// shoots: a quad cut in two by a modelling tool or by glTF, which has triangles only, shoots as
// two). The quad starts at the first triangle's first corner, so the two halves of a quad
// (a, b, c) and (a, c, d) give back (a, b, c, d).
//
// Each triangle in turn, unless already merged, takes the first later triangle that qualifies
// (the later triangle first, then the first triangle's edge, then the second's), as a scan of
// every later triangle would; the later triangles sharing an edge are found in a hash of the
// triangles' directed edges, so the time is linear in the patches (plus, for each triangle,
// the triangles that share one of its edges).
std::vector<ImportedPatch> merge_coplanar(const std::vector<ImportedPatch>& patches, long& merged_pairs) {
  std::unordered_map<Edge, std::vector<Side>, EdgeHash> sides;
  for (std::size_t j = 0; j < patches.size(); ++j)
    if (patches[j].corners.size() == 3)
      for (int f = 0; f < 3; ++f)
        sides[{patches[j].corners[std::size_t(f)], patches[j].corners[std::size_t((f + 1) % 3)]}]
            .push_back({std::uint32_t(j), std::uint8_t(f)});
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
        const auto found = sides.find({b, a});
        if (found == sides.end()) continue;
        for (const Side& side : found->second)
          if (side.triangle > i && !used[side.triangle]) candidates.emplace_back(side.triangle, e, side.edge);
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

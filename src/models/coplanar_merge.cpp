#include "models/coplanar_merge.h"

#include "models/face_shapes.h"

namespace ncube::models {

// --merge-coplanar: a triangle and a later one of the same material that share an edge, lie
// in one plane and together make a planar convex quad become that quad (patches are what
// shoots: a quad cut in two by a modelling tool or by glTF, which has triangles only, shoots as
// two). The quad starts at the first triangle's first corner, so the two halves of a quad
// (a, b, c) and (a, c, d) give back (a, b, c, d).
std::vector<ImportedPatch> merge_coplanar(const std::vector<ImportedPatch>& patches, long& merged_pairs) {
  std::vector<bool> used(patches.size(), false);
  std::vector<ImportedPatch> merged;
  for (std::size_t i = 0; i < patches.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    const ImportedPatch& first = patches[i];
    bool done = false;
    for (std::size_t j = i + 1; j < patches.size() && first.corners.size() == 3 && !done; ++j) {
      const ImportedPatch& second = patches[j];
      if (used[j] || second.corners.size() != 3 ||
          second.material.reflectance != first.material.reflectance ||
          second.material.emission != first.material.emission)
        continue;
      // The shared edge runs (a -> b) in the first triangle and (b -> a) in the second.
      for (int e = 0; e < 3 && !done; ++e) {
        const Point& a = first.corners[std::size_t(e)];
        const Point& b = first.corners[std::size_t((e + 1) % 3)];
        for (int f = 0; f < 3 && !done; ++f) {
          if (second.corners[std::size_t(f)] != b || second.corners[std::size_t((f + 1) % 3)] != a) continue;
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
        }
      }
    }
    if (!done) merged.push_back(first);
  }
  return merged;
}

}  // namespace ncube::models

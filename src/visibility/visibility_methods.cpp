#include "visibility/visibility_methods.h"

#include "visibility/brute_force_occluders.h"
#include "visibility/octree.h"

namespace ncube {

const MethodRegistry<VisibilityMethod>& visibility_methods() {
  static const MethodRegistry<VisibilityMethod> registry(
      "visibility method",
      {
          {"brute-force", "every patch, sections 2.2 and 3; the calibrated setup",
           [](const Scene& scene, const std::vector<int>& patches, RayTestPolicy policy) {
             return std::make_unique<const BruteForceOccluders>(scene, patches, policy);
           }},
          {"octree",
           "section 6: an octree over each node's patches, the walk stops at the first "
           "blocker; --ray-test has no effect",
           [](const Scene& scene, const std::vector<int>& patches, RayTestPolicy) {
             return std::make_unique<const Octree>(scene, patches);
           }},
      });
  return registry;
}

}  // namespace ncube

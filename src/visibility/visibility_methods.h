// The visibility methods a run can choose (--visibility), each registered once
// (util/method_registry.h; docs/architecture.md, "How to add a method"): its name (the
// option's value and the result file's config.visibility), what the docs say of it, and its
// readable definition over the patches a node holds. That definition (an OccluderSet) is the
// whole of the method in the simulated program: its answers, the work it is charged for
// (unblocked_parts, build_work) and what its search structure holds (structure_items, which
// the cost model weighs).
// The host's fast version of each is registered under the same name in
// simulation/host_machinery.cpp; tests/method_registry_test.cpp checks that every consumer
// (the option, the result file, the host machinery, the memory plan) knows every name.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "util/method_registry.h"
#include "visibility/occluder_set.h"

namespace ncube {

struct VisibilityMethod {
  std::string name;
  std::string doc;
  // The readable definition over `patch_indices` (scene patches in the order the node's
  // program lists them); `policy` is --ray-test, which a method may ignore.
  std::function<std::unique_ptr<const OccluderSet>(
      const Scene& scene, const std::vector<int>& patch_indices, RayTestPolicy policy)>
      reference;
};

// The paper's brute-force loop first (the default), then the others.
const MethodRegistry<VisibilityMethod>& visibility_methods();

}  // namespace ncube

// The one place where the simulated program meets the host's speed machinery: which
// implementation answers the node programs' visibility questions (visibility/occluder_set.h)
// and what help the engines get (radiosity/host_assist.h).
//
// By default the host's fast implementations answer (src/host/: FastOccluders, the octree
// over host threads, the threads computing ahead), each registered in host_machinery.cpp
// under its visibility method's name (visibility/visibility_methods.h); with
// `reference_visibility` the method's readable definition answers alone (BruteForceOccluders,
// Octree), on one thread, with no answer cache and no lookahead. Both give the same result files byte for byte apart from host
// fields (tests/seam_test.sh), which is the contract of every host component.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "radiosity/host_assist.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene.h"
#include "visibility/occluder_set.h"

namespace ncube {

class FastOccluders;

struct HostMachinery {
  // The occluder sets of the run: the whole scene (V = 0) or the V shares, in that order.
  std::vector<std::unique_ptr<const OccluderSet>> occluders;
  // The engines' help (null: none). Declared last, so that its threads stop first.
  std::unique_ptr<HostAssist> assist;
};

// Builds the occluder sets for `patch_sets` (each in loop order) and the engines' help for a
// run of `radiosity_processors` ranks with `visibility_processors` per rank, for the method
// `options.visibility` names (std::logic_error when it has no registration here or in
// visibility_methods()).
// Registers the host version of a form-factor method added from outside the list
// (add_form_factor_method), before the registry is first read: for tests/throwaway_methods.cpp.
void add_host_form_factor_method(std::string name, std::string host_version);

void build_host_machinery(HostMachinery& machinery, const Scene& scene,
                          const std::vector<std::vector<int>>& patch_sets,
                          const ProgressiveOptions& options, int visibility_processors,
                          int radiosity_processors, int block_size, bool loads_change);

}  // namespace ncube

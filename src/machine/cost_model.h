// How counted work becomes simulated CPU time: flops per counted operation, read from
// platforms/cost_model.json (every field documented there and in docs/model.md).
#pragma once

#include <string>

#include "radiosity/work_counts.h"

namespace ncube {

struct CostModel {
  double flops_per_shooter_candidate = 0;  // one comparison in the search for the shooter
  double flops_per_receiver = 0;           // facing test of one element against the shooter
  double flops_per_ray = 0;                // setting up one shadow ray
  double flops_per_ray_patch_test = 0;     // one ray-patch intersection test
  double flops_per_form_factor = 0;        // one point-to-part contour integral
  double flops_per_element_update = 0;     // adding the shot light to one element

  double flops(const WorkCounts& counts) const;
};

CostModel load_cost_model(const std::string& path);

}  // namespace ncube

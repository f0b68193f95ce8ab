// The operations the paper's program performs, counted exactly as its brute-force method
// would do them. The cost model (platforms/cost_model.json) turns them into flops.
#pragma once

#include <cstdint>

namespace ncube {

struct WorkCounts {
  std::uint64_t shooter_candidates = 0;  // patches compared in the search for the shooter
  std::uint64_t receivers = 0;           // elements tested for facing the shooter
  std::uint64_t rays = 0;                // shadow rays set up (one per receiver and part)
  std::uint64_t ray_patch_tests = 0;     // ray-patch intersection tests (section 2.2)
  std::uint64_t plane_crossings = 0;     // tests whose ray crosses the patch's plane, so the
                                         // loop goes on to the hit point and the edge tests
  std::uint64_t octree_cells_visited = 0;  // octree cells slab-tested against a ray (octree.h)
  std::uint64_t octree_overlap_tests = 0;  // building the octree: patch box against cell box
  std::uint64_t octree_cells_built = 0;    // building the octree: cells created
  std::uint64_t form_factors = 0;        // point-to-part contour integrals (visible parts)
  std::uint64_t element_updates = 0;     // receiving elements whose radiosity was updated
  std::uint64_t subdivision_tests = 0;   // section 4.1: elements whose corners were compared
  std::uint64_t elements_created = 0;    // section 4.1: child elements made by cuts

  WorkCounts& operator+=(const WorkCounts& o) {
    shooter_candidates += o.shooter_candidates;
    receivers += o.receivers;
    rays += o.rays;
    ray_patch_tests += o.ray_patch_tests;
    plane_crossings += o.plane_crossings;
    octree_cells_visited += o.octree_cells_visited;
    octree_overlap_tests += o.octree_overlap_tests;
    octree_cells_built += o.octree_cells_built;
    form_factors += o.form_factors;
    element_updates += o.element_updates;
    subdivision_tests += o.subdivision_tests;
    elements_created += o.elements_created;
    return *this;
  }
  bool operator==(const WorkCounts& o) const {
    return shooter_candidates == o.shooter_candidates && receivers == o.receivers &&
           rays == o.rays && ray_patch_tests == o.ray_patch_tests &&
           plane_crossings == o.plane_crossings &&
           octree_cells_visited == o.octree_cells_visited &&
           octree_overlap_tests == o.octree_overlap_tests &&
           octree_cells_built == o.octree_cells_built &&
           form_factors == o.form_factors && element_updates == o.element_updates &&
           subdivision_tests == o.subdivision_tests && elements_created == o.elements_created;
  }
};

}  // namespace ncube

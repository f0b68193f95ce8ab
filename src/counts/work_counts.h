// The operations the paper's program performs, counted exactly as its brute-force method
// would do them. The cost model (platforms/cost_model.json) turns them into flops.
#pragma once

#include <cstdint>
#include <string_view>

namespace ncube {

// The one list of the radiosity and visibility counters (like pbrt-v4's STAT_COUNTER): it
// makes the WorkCounts members, their sum and comparison, the cost model's flops parameter
// of each (CostModel, loaded from platforms/cost_model.json), the flops charged, and the
// result file's "counts" (the member's name is the JSON name). Adding a counter is one line
// here, its value in platforms/cost_model.json and its row in docs/model.md.
// X(member, cost-model parameter, what is counted). The order is the order of the sum in
// CostModel::flops (kept so that the simulated times stay the same to the last bit).
#define NCUBE_WORK_COUNTERS(X)                                                                  \
  X(shooter_candidates, flops_per_shooter_candidate,                                            \
    "patches compared in the search for the shooter")                                           \
  X(receivers, flops_per_receiver,                                                              \
    "held elements looked at for a shot: every one the processor holds (the shooter's own "     \
    "and those facing away included), with or without --skip-facing-away")                      \
  X(rays, flops_per_ray, "shadow rays set up (one per receiver and part)")                      \
  X(ray_patch_tests, flops_per_ray_patch_test, "ray-patch intersection tests (section 2.2)")    \
  X(plane_crossings, flops_per_plane_crossing,                                                  \
    "tests whose ray crosses the patch's plane, so the loop goes on to the hit point and the "  \
    "edge tests")                                                                               \
  X(form_factors, flops_per_form_factor, "point-to-part contour integrals (visible parts)")      \
  X(element_updates, flops_per_element_update, "receiving elements whose radiosity was updated") \
  X(subdivision_tests, flops_per_subdivision_test,                                              \
    "section 4.1: elements whose corner radiosities were compared")                             \
  X(elements_created, flops_per_element_created, "section 4.1: child elements made by cuts")    \
  X(octree_cells_visited, flops_per_octree_cell_visited,                                        \
    "octree cells slab-tested against a ray (octree.h)")                                        \
  X(octree_overlap_tests, flops_per_octree_overlap_test,                                        \
    "building the octree: patch box against cell box")                                          \
  X(octree_cells_built, flops_per_octree_cell_built, "building the octree: cells created")        \
  X(increments_combined, flops_per_increment_combined,                                          \
    "the shooter-centred scheme: element increments received and added in the exchange")        \
  X(increments_applied, flops_per_increment_applied,                                            \
    "the shooter-centred scheme: summed element increments added to radiosity and unshot")  \
  NCUBE_HEMICUBE_COUNTERS(X)                                                                    \
  NCUBE_HOST_WORK_COUNTERS(X)

// The hemicube's counters (--form-factors hemicube, radiosity/hemicube.h), part of the list
// above. The result file writes them only for runs that use the hemicube, so that the paper's
// runs keep their result files (result_file.cpp).
#define NCUBE_HEMICUBE_COUNTERS(X)                                                              \
  X(hemicube_delta_form_factors, flops_per_hemicube_delta_form_factor,                          \
    "hemicube: entries of the delta form factors' table, computed once per node")               \
  X(hemicube_vertices_transformed, flops_per_hemicube_vertex_transformed,                       \
    "hemicube: polygon vertices moved into a hemicube's frame")                                 \
  X(hemicube_polygons_set_up, flops_per_hemicube_polygon_set_up,                                \
    "hemicube: polygons' planes moved into a hemicube's frame, with the facing test")           \
  X(hemicube_clip_tests, flops_per_hemicube_clip_test,                                          \
    "hemicube: polygon vertices tested against one clip plane of a face")                       \
  X(hemicube_clip_cuts, flops_per_hemicube_clip_cut,                                            \
    "hemicube: vertices made where a polygon's edge crosses a clip plane")                      \
  X(hemicube_vertices_projected, flops_per_hemicube_vertex_projected,                           \
    "hemicube: clipped vertices projected onto a face, each starting an edge")                  \
  X(hemicube_polygons_scanned, flops_per_hemicube_polygon_scanned,                              \
    "hemicube: clipped polygons scan-converted into a face (depth plane set up)")               \
  X(hemicube_rows_scanned, flops_per_hemicube_row_scanned,                                      \
    "hemicube: rows of cells a polygon spans on a face (its span's ends found)")                \
  X(hemicube_depth_tests, flops_per_hemicube_depth_test,                                        \
    "hemicube: cells whose centre a polygon covers, depth computed and compared")               \
  X(hemicube_cells_read, flops_per_hemicube_cell_read,                                          \
    "hemicube: item-buffer cells read out (delta form factor added to the cell's receiver)")    \
  X(hemicube_reciprocal_above_one, flops_per_hemicube_reciprocal_above_one,                     \
    "hemicube: receivers of a shot whose form factor to the shooter came out above 1 by "       \
    "reciprocity (an observation of the run, charged nothing)")

// Work a core of today does that the paper's counters do not tell apart, part of the list
// above (issue 40; docs/machines/probe.md, "Where the prediction misses"): counted always,
// charged only on a platform that gives the rate of its kind (src/machine/work_kinds.h:
// blocked_ray_speed, edge_term_speed, which only a probed machine gives) and written into a
// result file only then (simulation.cpp), so that every machine that does not give them,
// the nCube2 first, has the simulated seconds and result files it had before they existed.
// CostModel::flops, the one-flop-rate charge, leaves them out.
#define NCUBE_HOST_WORK_COUNTERS(X)                                                             \
  X(blocked_rays, flops_per_blocked_ray,                                                        \
    "shadow rays the loop found blocked (a part's bit left out of a receiver's answer): their " \
    "loop ran every edge test of the patches that stop them and turned a branch it could not "  \
    "foretell; charged only on a platform that gives blocked_ray_speed")                        \
  X(form_factor_edge_terms, flops_per_form_factor_edge_term,                                    \
    "edge terms of the contour integrals as visible_parts_form_factor sums them: the visible "  \
    "region's contour edges, or each visible part's edges clipped to the receiver's front when " \
    "the shooter straddles its plane; charged only on a platform that gives edge_term_speed")

// Whether `member` is one of NCUBE_HOST_WORK_COUNTERS.
inline bool is_host_work_counter(const char* member) {
  const std::string_view name(member);
#define NCUBE_HOST_NAME(m, cost, doc) \
  if (name == #m) return true;
  NCUBE_HOST_WORK_COUNTERS(NCUBE_HOST_NAME)
#undef NCUBE_HOST_NAME
  return false;
}

struct WorkCounts {
#define NCUBE_MEMBER(member, cost, doc) std::uint64_t member = 0;
  NCUBE_WORK_COUNTERS(NCUBE_MEMBER)
#undef NCUBE_MEMBER

  WorkCounts& operator+=(const WorkCounts& o) {
#define NCUBE_ADD(member, cost, doc) member += o.member;
    NCUBE_WORK_COUNTERS(NCUBE_ADD)
#undef NCUBE_ADD
    return *this;
  }
  bool operator==(const WorkCounts& o) const {
    bool equal = true;
#define NCUBE_EQUAL(member, cost, doc) equal = equal && member == o.member;
    NCUBE_WORK_COUNTERS(NCUBE_EQUAL)
#undef NCUBE_EQUAL
    return equal;
  }
};

}  // namespace ncube

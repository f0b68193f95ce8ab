// Which kind of work each counted operation is, and so which of a machine's rates runs it
// (src/machine/machine_parameters.h: test_speed, ray_speed, arithmetic_speed, memory_speed).
// A machine is a cost per kind of work: the cost model (platforms/cost_model.json) says how
// many flops an operation is, the machine how fast it runs flops of each kind. Why these kinds and why each
// counter is where it is: docs/machines/README.md, "Rates per kind of work".
#pragma once

#include <string>
#include <vector>

#include "machine/cost_model.h"
#include "machine/platform_config.h"

namespace ncube {

// X(cost-model parameter, the machine parameter that is its rate). Every parameter of
// NCUBE_WORK_COUNTERS and NCUBE_RENDER_COUNTERS once (tests/cost_model_test.cpp).
#define NCUBE_WORK_KINDS(X)                                                                     \
  X(flops_per_shooter_candidate, test_speed)                                                    \
  X(flops_per_receiver, test_speed)                                                             \
  X(flops_per_ray, ray_speed)                                                                   \
  X(flops_per_ray_patch_test, test_speed)                                                       \
  X(flops_per_plane_crossing, test_speed)                                                       \
  X(flops_per_form_factor, arithmetic_speed)                                                    \
  X(flops_per_element_update, arithmetic_speed)                                                 \
  X(flops_per_subdivision_test, arithmetic_speed)                                               \
  X(flops_per_element_created, arithmetic_speed)                                                \
  X(flops_per_octree_cell_visited, test_speed)                                                  \
  X(flops_per_octree_overlap_test, test_speed)                                                  \
  X(flops_per_octree_cell_built, arithmetic_speed)                                              \
  X(flops_per_increment_combined, memory_speed)                                                 \
  X(flops_per_increment_applied, memory_speed)                                                  \
  X(flops_per_hemicube_delta_form_factor, arithmetic_speed)                                     \
  X(flops_per_hemicube_vertex_transformed, projection_speed)                                    \
  X(flops_per_hemicube_polygon_set_up, projection_speed)                                        \
  X(flops_per_hemicube_clip_test, projection_speed)                                             \
  X(flops_per_hemicube_clip_cut, projection_speed)                                              \
  X(flops_per_hemicube_vertex_projected, projection_speed)                                      \
  X(flops_per_hemicube_polygon_scanned, projection_speed)                                       \
  X(flops_per_hemicube_row_scanned, raster_speed)                                               \
  X(flops_per_hemicube_depth_test, raster_speed)                                                \
  X(flops_per_hemicube_cell_read, raster_speed)                                                 \
  X(flops_per_hemicube_reciprocal_above_one, raster_speed)                                      \
  X(flops_per_blocked_ray, blocked_ray_speed)                                                   \
  X(flops_per_form_factor_edge_term, edge_term_speed)                                           \
  X(flops_per_render_vertex, arithmetic_speed)                                                  \
  X(flops_per_clip_vertex, arithmetic_speed)                                                    \
  X(flops_per_projected_vertex, arithmetic_speed)                                               \
  X(flops_per_triangle, arithmetic_speed)                                                       \
  X(flops_per_sample_tested, test_speed)                                                        \
  X(flops_per_sample_inside, test_speed)                                                        \
  X(flops_per_sample_written, arithmetic_speed)                                                 \
  X(flops_per_exposure_sample, test_speed)                                                      \
  X(flops_per_histogram_bucket, memory_speed)                                                   \
  X(flops_per_pixel_resolved, arithmetic_speed)

// X(rate, the rate that runs its kind when a machine leaves it out). A rate not listed here
// falls back to node_speed; one listed falls back to its fallback's rate, and that to
// node_speed. ray_speed splits a ray's own cost (its set-up, its loop's start and exit, the
// patches it skips) from test_speed, which ran it before the per-ray kind existed: a machine
// that does not give ray_speed runs rays at its test_speed, as before, to the last bit
// (docs/machines/README.md, "Rates per kind of work").
#define NCUBE_RATE_FALLBACKS(X) X(ray_speed, test_speed)

// X(cost-model parameter, the rate that runs it when a machine leaves its kind's rate out).
// The hemicube's kinds (projection_speed: a polygon's way into a face, its vertices moved,
// clipped and projected and its scan set up; raster_speed: the rows and cells of the scan
// conversion and the item buffer's read-out) were split from the kinds that ran them before
// (tests, arithmetic, memory); a machine that does not give them runs each of their counters
// at the rate it ran at before, to the last bit (docs/machines/probe.md, "The hemicube").
#define NCUBE_COUNTER_FALLBACKS(X) \
  X(flops_per_hemicube_vertex_transformed, arithmetic_speed)                                    \
  X(flops_per_hemicube_polygon_set_up, arithmetic_speed)                                        \
  X(flops_per_hemicube_clip_test, test_speed)                                                   \
  X(flops_per_hemicube_clip_cut, arithmetic_speed)                                              \
  X(flops_per_hemicube_vertex_projected, arithmetic_speed)                                      \
  X(flops_per_hemicube_polygon_scanned, arithmetic_speed)                                       \
  X(flops_per_hemicube_row_scanned, arithmetic_speed)                                           \
  X(flops_per_hemicube_depth_test, test_speed)                                                  \
  X(flops_per_hemicube_cell_read, memory_speed)                                                 \
  X(flops_per_hemicube_reciprocal_above_one, memory_speed)

// X(host work counter, the paper's counter whose work it is). On a platform that charges the
// host counter, the paper's counter is not charged: the same work, counted as the host does
// it (the gather's form factors: the paper computes each visible part's, 180 flops each; the
// host sums the visible region's contour, and its cost follows the edge terms, not the parts:
// docs/machines/probe.md). The paper's counter is still counted and written.
#define NCUBE_HOST_REPLACES(X) X(form_factor_edge_terms, form_factors)

// Whether a platform charges `member`, a counter of NCUBE_WORK_COUNTERS: always, but for the
// host work counters (NCUBE_HOST_WORK_COUNTERS), charged only when the platform gives their
// kind's own rate (no fallback: a machine that does not give it is charged, and its result
// file written, as before the counter existed); a counter a charged host counter replaces
// (NCUBE_HOST_REPLACES) is not.
bool charges_counter(const PlatformConfig& platform, const std::string& member);

// The rates' names (machine parameters), in the order they first appear above.
const std::vector<std::string>& work_rate_names();

// The rate that runs `rate`'s kind when a machine leaves `rate` out ("" for node_speed).
std::string fallback_rate_of(const std::string& rate);

// The rate that runs a cost-model parameter's flops ("" for one the list lacks).
std::string work_rate_of(const std::string& cost_parameter);

// Whether the platform gives any rate per kind of work. A platform that gives none runs all
// counted work at node_speed, with the very expression it had before the rates existed, so
// that its simulated seconds stay the same to the last bit.
bool gives_work_rates(const PlatformConfig& platform);

// The flops of `counts` whose kind runs at `rate` (a name of work_rate_names()) on a platform
// that gives every rate (the host work counters charged, the counters they replace not): what
// a probe of the rate divides by the seconds it measured (build/machine_probe).
double kind_flops(const CostModel& costs, const WorkCounts& counts, const std::string& rate);

// Simulated CPU seconds of counted work on one node of `platform`: the flops of each kind at
// that kind's rate (node_speed for a kind the platform does not give).
double compute_seconds(const CostModel& costs, const PlatformConfig& platform,
                       const WorkCounts& counts);
double compute_seconds(const CostModel& costs, const PlatformConfig& platform,
                       const RenderCounts& counts);

}  // namespace ncube

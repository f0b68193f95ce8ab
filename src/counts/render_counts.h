// The operations of the rendering phase (paper section 2.3), counted exactly as the
// rasteriser performs them; platforms/cost_model.json turns them into flops.
#pragma once

#include <cstdint>

namespace ncube {

// The one list of the rendering phase's counters, as NCUBE_WORK_COUNTERS
// (counts/work_counts.h) for the radiosity run: X(member, cost-model parameter, what is
// counted), in the order of the sum in CostModel::flops.
#define NCUBE_RENDER_COUNTERS(X)                                                                \
  X(vertices, flops_per_render_vertex, "element corners taken to camera space, near-tested")    \
  X(clip_vertices, flops_per_clip_vertex, "new vertices where an edge crosses the near plane")  \
  X(projected_vertices, flops_per_projected_vertex,                                             \
    "vertices projected to the screen (1/z, radiosity/z)")                                      \
  X(triangles, flops_per_triangle, "triangles set up (area, bounding box, row range)")          \
  X(samples_tested, flops_per_sample_tested,                                                    \
    "samples of a triangle's box in the node's rows: 3 edge functions")                         \
  X(samples_inside, flops_per_sample_inside,                                                    \
    "of them inside the triangle: depth interpolated, z-tested")                                \
  X(samples_written, flops_per_sample_written,                                                  \
    "of them nearer than the z-buffer: shaded (Gouraud) and stored")                            \
  X(exposure_samples, flops_per_exposure_sample,                                                \
    "visible samples visited in a round of the exposure selection")                             \
  X(histogram_buckets, flops_per_histogram_bucket, "histogram buckets added up on the way to node 0") \
  X(pixels_resolved, flops_per_pixel_resolved, "pixels tone mapped from their 3 x 3 samples")

struct RenderCounts {
#define NCUBE_MEMBER(member, cost, doc) std::uint64_t member = 0;
  NCUBE_RENDER_COUNTERS(NCUBE_MEMBER)
#undef NCUBE_MEMBER

  RenderCounts& operator+=(const RenderCounts& o) {
#define NCUBE_ADD(member, cost, doc) member += o.member;
    NCUBE_RENDER_COUNTERS(NCUBE_ADD)
#undef NCUBE_ADD
    return *this;
  }
  bool operator==(const RenderCounts& o) const {
    bool equal = true;
#define NCUBE_EQUAL(member, cost, doc) equal = equal && member == o.member;
    NCUBE_RENDER_COUNTERS(NCUBE_EQUAL)
#undef NCUBE_EQUAL
    return equal;
  }
};

}  // namespace ncube

// The operations of the rendering phase (paper section 2.3), counted exactly as the
// rasteriser performs them; platforms/cost_model.json turns them into flops.
#pragma once

#include <cstdint>

namespace ncube {

struct RenderCounts {
  std::uint64_t vertices = 0;            // element corners taken to camera space, near-tested
  std::uint64_t clip_vertices = 0;       // new vertices where an edge crosses the near plane
  std::uint64_t projected_vertices = 0;  // vertices projected to the screen (1/z, radiosity/z)
  std::uint64_t triangles = 0;           // triangles set up (area, bounding box, row range)
  std::uint64_t samples_tested = 0;      // samples of a triangle's box in the node's rows: 3 edge functions
  std::uint64_t samples_inside = 0;      // of them inside the triangle: depth interpolated, z-tested
  std::uint64_t samples_written = 0;     // of them nearer than the z-buffer: shaded (Gouraud) and stored
  std::uint64_t exposure_samples = 0;    // visible samples visited in a round of the exposure selection
  std::uint64_t histogram_buckets = 0;   // histogram buckets added up on the way to node 0
  std::uint64_t pixels_resolved = 0;     // pixels tone mapped from their 3 x 3 samples

  RenderCounts& operator+=(const RenderCounts& o) {
    vertices += o.vertices;
    clip_vertices += o.clip_vertices;
    projected_vertices += o.projected_vertices;
    triangles += o.triangles;
    samples_tested += o.samples_tested;
    samples_inside += o.samples_inside;
    samples_written += o.samples_written;
    exposure_samples += o.exposure_samples;
    histogram_buckets += o.histogram_buckets;
    pixels_resolved += o.pixels_resolved;
    return *this;
  }
  bool operator==(const RenderCounts& o) const {
    return vertices == o.vertices && clip_vertices == o.clip_vertices &&
           projected_vertices == o.projected_vertices && triangles == o.triangles &&
           samples_tested == o.samples_tested && samples_inside == o.samples_inside &&
           samples_written == o.samples_written && exposure_samples == o.exposure_samples &&
           histogram_buckets == o.histogram_buckets && pixels_resolved == o.pixels_resolved;
  }
};

}  // namespace ncube

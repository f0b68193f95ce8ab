// How counted work becomes simulated CPU time: flops per counted operation, read from
// platforms/cost_model.json (every field documented there and in docs/model.md).
#pragma once

#include <string>

#include "radiosity/work_counts.h"
#include "render/render_counts.h"

namespace ncube {

struct CostModel {
  double flops_per_shooter_candidate = 0;  // one comparison in the search for the shooter
  double flops_per_receiver = 0;           // facing test of one element against the shooter
  double flops_per_ray = 0;                // setting up one shadow ray
  double flops_per_ray_patch_test = 0;     // one ray-patch test up to the plane hit (t)
  double flops_per_plane_crossing = 0;     // the rest of a test whose ray crosses the plane
  double flops_per_form_factor = 0;        // one point-to-part contour integral
  double flops_per_element_update = 0;     // adding the shot light to one element
  // Adaptive subdivision (section 4.1, --subdivide).
  double flops_per_subdivision_test = 0;   // an element's corner radiosities compared
  double flops_per_element_created = 0;    // one child element's geometry made by a cut
  // Octree visibility (section 6, --visibility octree).
  double flops_per_octree_cell_visited = 0;  // slab test of a ray segment against a cell
  double flops_per_octree_overlap_test = 0;  // building: a patch's box against a cell's
  double flops_per_octree_cell_built = 0;    // building: a cell's bounds from its parent's
  // The rendering phase (section 2.3), per counted operation of render/render_counts.h.
  double flops_per_render_vertex = 0;      // an element corner to camera space, near test
  double flops_per_clip_vertex = 0;        // a vertex where an edge crosses the near plane
  double flops_per_projected_vertex = 0;   // a vertex projected (1/z, screen, radiosity/z)
  double flops_per_triangle = 0;           // triangle setup: area, bounding box, row range
  double flops_per_sample_tested = 0;      // three edge functions at one sample
  double flops_per_sample_inside = 0;      // depth interpolation and z test
  double flops_per_sample_written = 0;     // Gouraud radiosity of a sample that is nearest
  double flops_per_exposure_sample = 0;    // luminance and key of a visible sample, per round
  double flops_per_histogram_bucket = 0;   // adding one bucket of a child's histogram
  double flops_per_pixel_resolved = 0;     // tone mapping of a pixel from its 3 x 3 samples

  // Modeled sizes of the program's data, as laid out by a 1990s 32-bit C implementation
  // (4-byte floats, ints and pointers); docs/model.md gives each layout.
  double message_header_bytes = 0;     // type, sender, block number of every message
  double shooter_record_bytes = 0;     // patch index, geometry, unshot radiosity and power
  double point_bytes = 0;              // one visibility point sent to a visibility processor
  double patch_geometry_bytes = 0;     // a patch as stored for intersection tests
  double patch_radiosity_bytes = 0;    // an owned patch's radiosity data (besides geometry)
  double element_bytes = 0;            // one element with its radiosity
  double octree_cell_bytes = 0;        // one octree cell: bounds, children, patch list
  double octree_reference_bytes = 0;   // one entry of a leaf's patch list
  double node_reserve_bytes = 0;       // program, operating system and stack on every node
  double load_record_bytes = 0;        // a radiosity processor's load, with its candidate (4.2)
  double transfer_order_bytes = 0;     // one balancing order, with the shooter (4.2)
  double render_element_bytes = 0;     // one element as the renderer sends and holds it
  double render_vertex_bytes = 0;      // one more boundary point (T-vertex) of such an element
  double frame_sample_bytes = 0;       // one sample of the frame and z-buffer
  double pixel_bytes = 0;              // one finished pixel, as collected at node 0
  double exposure_histogram_bytes = 0; // a round's luminance histograms and maxima
  double exposure_selection_bytes = 0; // a round's chosen digits and remaining ranks

  double flops(const WorkCounts& counts) const;
  double flops(const RenderCounts& counts) const;
};

CostModel load_cost_model(const std::string& path);

}  // namespace ncube

// How counted work becomes simulated CPU time: flops per counted operation, read from
// platforms/cost_model.json (every field documented there and in docs/model.md).
#pragma once

#include <string>
#include <vector>

#include "counts/held_items.h"
#include "counts/render_counts.h"
#include "counts/work_counts.h"

namespace ncube {

// Modeled sizes of the program's data, as laid out by a 1990s 32-bit C implementation
// (4-byte floats, ints and pointers); docs/model.md gives each layout. The one list of them:
// X(parameter, smallest value, largest value, what it is). Every size is a whole number of
// bytes; the largest values are sanity bounds (a typo, not a model, beyond them).
#define NCUBE_DATA_SIZES(X)                                                                     \
  X(message_header_bytes, 0, 1e9, "type and block number of every message")                    \
  X(shooter_record_bytes, 1, 1e9, "patch index, geometry, unshot radiosity and power")          \
  X(point_bytes, 1, 1e9, "one visibility point sent to a visibility processor")                 \
  X(patch_geometry_bytes, 1, 1e9, "a patch as stored for intersection tests")                   \
  X(patch_radiosity_bytes, 1, 1e9, "an owned patch's radiosity data (besides geometry)")        \
  X(element_bytes, 1, 1e9, "one element with its radiosity")                                    \
  X(radiosity_increment_bytes, 1, 1e9, "one element's RGB increment (--parallelisation shooters)") \
  X(octree_cell_bytes, 1, 1e9, "one octree cell: bounds, children, patch list")                 \
  X(octree_reference_bytes, 1, 1e9, "one entry of a leaf's patch list")                         \
  X(hemicube_cell_bytes, 1, 1e9, "one cell of a hemicube face's item and depth buffers")       \
  X(delta_form_factor_bytes, 1, 1e9, "one entry of the hemicube's delta form factors' table")    \
  X(node_reserve_bytes, 0, 0x1p50, "program, operating system and stack on every node")         \
  X(load_record_bytes, 1, 1e9, "a radiosity processor's load, with its candidate (4.1, 4.2)")   \
  X(transfer_order_bytes, 1, 1e9, "one balancing order, with the shooter (4.2)")                \
  X(render_element_bytes, 1, 1e9, "one element as the renderer sends and holds it")             \
  X(render_vertex_bytes, 1, 1e9, "one more boundary point (T-vertex) of such an element")       \
  X(frame_sample_bytes, 1, 1e9, "one sample of the frame and z-buffer")                         \
  X(pixel_bytes, 1, 1e9, "one finished pixel, as collected at node 0")                          \
  X(exposure_histogram_bytes, 1, 1e9, "a round's luminance histograms and maxima")              \
  X(exposure_selection_bytes, 1, 1e9, "a round's chosen digits and remaining ranks")

struct CostModel {
  // Flops per counted operation: one parameter per counter of NCUBE_WORK_COUNTERS (the
  // radiosity run) and NCUBE_RENDER_COUNTERS (the rendering phase, section 2.3).
#define NCUBE_FLOPS_FIELD(member, cost, doc) double cost = 0;
  NCUBE_WORK_COUNTERS(NCUBE_FLOPS_FIELD)
  NCUBE_RENDER_COUNTERS(NCUBE_FLOPS_FIELD)
#undef NCUBE_FLOPS_FIELD

#define NCUBE_SIZE_FIELD(name, min, max, doc) double name = 0;
  NCUBE_DATA_SIZES(NCUBE_SIZE_FIELD)
#undef NCUBE_SIZE_FIELD

  double flops(const WorkCounts& counts) const;
  double flops(const RenderCounts& counts) const;
  // The bytes of what a node holds, each item at its data size.
  double bytes(const HeldItems& items) const;
};

// A parameter of the cost model: its name in platforms/cost_model.json and its field.
struct CostParameter {
  const char* name;
  double CostModel::*field;
};
// Every parameter, in the order of the lists (work flops, render flops, data sizes).
const std::vector<CostParameter>& cost_parameters();

CostModel load_cost_model(const std::string& path);

}  // namespace ncube

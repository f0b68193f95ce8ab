// What a node holds for the method it runs beside its patches and elements, counted in items
// (an octree's cells, a hemicube's buffer cells): the physics (visibility/, radiosity/) says
// how many, and only the machine (machine/cost_model.h, its data sizes) says what one weighs,
// as WorkCounts says what is done and the cost model what it costs.
#pragma once

namespace ncube {

// The one list of held items: X(member, the cost model's data size of one, what it is). A
// member whose size the cost model lacks does not compile (CostModel::bytes). The order is the
// order of the sum in CostModel::bytes.
#define NCUBE_HELD_ITEMS(X)                                                                     \
  X(octree_cells, octree_cell_bytes, "octree cells (section 6), the root included")             \
  X(octree_references, octree_reference_bytes, "entries of the octree leaves' patch lists")     \
  X(delta_form_factors, delta_form_factor_bytes, "entries of the hemicube's delta form factors") \
  X(hemicube_cells, hemicube_cell_bytes, "cells of a hemicube face's item and depth buffers")

struct HeldItems {
#define NCUBE_HELD_MEMBER(member, size, doc) double member = 0;
  NCUBE_HELD_ITEMS(NCUBE_HELD_MEMBER)
#undef NCUBE_HELD_MEMBER
};

}  // namespace ncube

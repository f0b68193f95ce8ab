// An element as a cell of its patch's parametric grid (paper section 4: each patch is cut
// into elements; section 4.1: elements are cut again where the light changes too fast).
// Level 0 is the patch's nu x nv grid (Patch::nu, Patch::nv); a cell of level L is (i, j) of
// the (nu << L) x (nv << L) grid, and its four children are the cells (2i + a, 2j + b) of
// level L + 1. Because every cell is a rectangle of the patch's bilinear map, neighbours of
// any levels share their corner points bit for bit (see patch_mesh.h).
#pragma once

#include <array>
#include <cstdint>

#include "scene/scene.h"

namespace ncube {

// Deepest level a cell may have: nu << level stays within an int for any nu the scene
// loader accepts (at most 2^20), and 8 levels cut an element into 65,536.
constexpr int kMaxCellLevel = 8;

struct ElementCell {
  int level = 0;
  int i = 0, j = 0;

  // Children in the order (0,0), (1,0), (0,1), (1,1): the order they replace their parent
  // in a patch's element list.
  std::array<ElementCell, 4> children() const;
  bool operator==(const ElementCell& o) const {
    return level == o.level && i == o.i && j == o.j;
  }
};

// The cell's polygon: a quad, or a triangle in the last row of a triangular patch (whose
// bilinear map collapses its top edge to vertex v2). Level 0 gives the same polygon, bit for
// bit, as grid_cell(patch.polygon, nu, nv, i, j).
Polygon cell_polygon(const Patch& patch, const ElementCell& cell);

// Whether the cell lies in its patch's grid at its level.
bool cell_in_patch(const Patch& patch, const ElementCell& cell);

}  // namespace ncube

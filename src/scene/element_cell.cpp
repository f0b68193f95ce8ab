#include "scene/element_cell.h"

namespace ncube {

std::array<ElementCell, 4> ElementCell::children() const {
  const int l = level + 1, ci = 2 * i, cj = 2 * j;
  return {ElementCell{l, ci, cj}, ElementCell{l, ci + 1, cj}, ElementCell{l, ci, cj + 1},
          ElementCell{l, ci + 1, cj + 1}};
}

Polygon cell_polygon(const Patch& patch, const ElementCell& cell) {
  return grid_cell(patch.polygon, patch.nu << cell.level, patch.nv << cell.level, cell.i, cell.j);
}

bool cell_in_patch(const Patch& patch, const ElementCell& cell) {
  return cell.level >= 0 && cell.level <= kMaxCellLevel && cell.i >= 0 && cell.j >= 0 &&
         cell.i < (patch.nu << cell.level) && cell.j < (patch.nv << cell.level);
}

}  // namespace ncube

// The elements of one patch as a mesh (paper section 4.1): which elements meet at each
// corner point, the radiosity there, and where an element's edge carries the corner of a
// smaller neighbour (a T-vertex). The subdivision criterion reads the corner radiosities;
// the renderer draws each element with its whole boundary, so that shading is continuous
// across elements of different sizes (no T-vertex seams, docs/model.md).
//
// Points are addressed on the patch's finest lattice: with D the deepest level among its
// elements, point (x, y) is (u, v) = (x / (nu << D), y / (nv << D)) of the bilinear map.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "scene/element_cell.h"

namespace ncube {

// The solution of one patch as its owner holds it: its elements, in the owner's order,
// with their radiosities.
struct PatchSolution {
  int patch = -1;
  std::vector<ElementCell> cells;
  std::vector<Rgb> radiosity;  // one per cell
};

struct MeshVertex {
  Vec3 position;
  Rgb radiosity;
};

class PatchMesh {
 public:
  // `cells` must tile the patch (as the cells of an element list always do).
  PatchMesh(const Patch& patch, const std::vector<ElementCell>& cells);

  // Corners of element k: 4, or 3 for a triangle in the last row of a triangular patch.
  int corner_count(std::size_t k) const;
  // The radiosity at corner c of element k (vertex order of cell_polygon): the mean of the
  // radiosities of the elements that touch that point (nodal averaging, Cohen et al. 1986),
  // summed in element order. `radiosity` has one entry per cell.
  Rgb corner_radiosity(const std::vector<Rgb>& radiosity, std::size_t k, int corner) const;
  // Element k's boundary, counter-clockwise from its corner 0 as in cell_polygon: its
  // corners, and between them the corners of neighbours lying on its edges, each with the
  // point's radiosity as above. Positions are bit-identical to the neighbours' corners.
  std::vector<MeshVertex> boundary(const std::vector<Rgb>& radiosity, std::size_t k) const;

  int depth() const { return depth_; }

 private:
  struct Point {
    std::int64_t x, y;
  };
  Point corner(std::size_t k, int c) const;
  bool is_apex(const Point& p) const { return triangle_ && p.y == height_; }
  Rgb nodal(const std::vector<Rgb>& radiosity, const Point& p) const;
  Vec3 position(const Point& p) const;
  int leaf_containing(std::int64_t cx, std::int64_t cy) const;  // finest-lattice cell
  static std::uint64_t cell_key(int level, std::int64_t i, std::int64_t j) {
    return (std::uint64_t(level) << 58) | (std::uint64_t(i) << 29) | std::uint64_t(j);
  }
  std::uint64_t point_key(const Point& p) const {
    return is_apex(p) ? ~std::uint64_t(0) : (std::uint64_t(p.x) << 32) | std::uint64_t(p.y);
  }

  const Patch& patch_;
  std::vector<ElementCell> cells_;
  bool triangle_ = false;
  int depth_ = 0;
  std::int64_t width_ = 0, height_ = 0;  // lattice cells along u and v
  std::unordered_map<std::uint64_t, int> index_of_cell_;
  std::unordered_set<std::uint64_t> corner_points_;
  std::vector<int> apex_elements_;  // triangle: the elements touching v2, in order
};

}  // namespace ncube

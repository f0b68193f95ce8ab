// The mesh of a patch's elements (scene/patch_mesh.h, scene/element_cell.h), checked on
// cells worked out by hand.
#include <gtest/gtest.h>

#include "scene/patch_mesh.h"

namespace ncube {
namespace {

Patch unit_square(int nu, int nv) {
  Patch p;
  p.polygon = Polygon::quad(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(4, 2, 0), Vec3(0, 2, 0));
  p.nu = nu;
  p.nv = nv;
  return p;
}

Patch unit_triangle(int nu, int nv) {
  Patch p;
  p.polygon = Polygon::triangle(Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(2, 4, 0));
  p.nu = nu;
  p.nv = nv;
  return p;
}

TEST(ElementCell, LevelZeroIsTheGridCellBitForBit) {
  const Patch quad = unit_square(3, 5), tri = unit_triangle(3, 5);
  for (const Patch* p : {&quad, &tri})
    for (int j = 0; j < p->nv; ++j)
      for (int i = 0; i < p->nu; ++i) {
        const Polygon a = cell_polygon(*p, {0, i, j}), b = grid_cell(p->polygon, p->nu, p->nv, i, j);
        ASSERT_EQ(a.count, b.count);
        for (int c = 0; c < a.count; ++c) EXPECT_EQ(a[c], b[c]);
      }
}

TEST(ElementCell, ChildrenTileTheParent) {
  const Patch p = unit_square(2, 1);
  const ElementCell parent{0, 1, 0};
  double area = 0.0;
  for (const ElementCell& child : parent.children()) {
    EXPECT_EQ(child.level, 1);
    area += cell_polygon(p, child).area();
  }
  EXPECT_DOUBLE_EQ(area, cell_polygon(p, parent).area());  // 2 x 2
  EXPECT_EQ(parent.children()[3], (ElementCell{1, 3, 1}));
  EXPECT_TRUE(cell_in_patch(p, {1, 3, 1}));
  EXPECT_FALSE(cell_in_patch(p, {1, 4, 1}));
}

TEST(PatchMesh, CornerRadiosityIsTheMeanOfTheElementsAtThePoint) {
  // 2 x 2 elements with radiosities 1, 2, 3, 4: the centre point is shared by all four.
  const Patch p = unit_square(2, 2);
  const PatchMesh mesh(p, {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 1, 1}});
  const std::vector<Rgb> b{Rgb(1.0), Rgb(2.0), Rgb(3.0), Rgb(4.0)};
  EXPECT_EQ(mesh.corner_radiosity(b, 0, 2), Rgb(2.5));  // centre
  EXPECT_EQ(mesh.corner_radiosity(b, 0, 0), Rgb(1.0));  // patch corner: one element
  EXPECT_EQ(mesh.corner_radiosity(b, 0, 1), Rgb(1.5));  // bottom edge midpoint: two
  EXPECT_EQ(mesh.boundary(b, 0).size(), 4u);            // no T-vertex
}

TEST(PatchMesh, ASubdividedNeighbourPutsATVertexOnTheEdge) {
  // Patch 4 x 2 cut 2 x 1; the left element is cut into four (level 1). The right element's
  // left edge (x = 2) then carries the children's shared corner (2, 1).
  const Patch p = unit_square(2, 1);
  const std::vector<ElementCell> cells{{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};
  const std::vector<Rgb> b{Rgb(1.0), Rgb(2.0), Rgb(3.0), Rgb(4.0), Rgb(10.0)};
  const PatchMesh mesh(p, cells);
  EXPECT_EQ(mesh.depth(), 1);
  const std::vector<MeshVertex> right = mesh.boundary(b, 4);
  ASSERT_EQ(right.size(), 5u);
  EXPECT_EQ(right[0].position, Vec3(2, 0, 0));
  EXPECT_EQ(right[3].position, Vec3(2, 2, 0));
  // The T-vertex is the children's corner, bit for bit, between (2, 2) and (2, 0).
  EXPECT_EQ(right[4].position, cell_polygon(p, cells[1])[2]);
  EXPECT_EQ(right[4].position, Vec3(2, 1, 0));
  // At (2, 1): children (1, 0) and (1, 1) and the right element.
  EXPECT_EQ(right[4].radiosity, Rgb((2.0 + 4.0 + 10.0) / 3.0));
  // At (2, 0): child (1, 0) and the right element; the child's corner 1 sees the same.
  EXPECT_EQ(right[0].radiosity, Rgb(6.0));
  EXPECT_EQ(mesh.corner_radiosity(b, 1, 1), Rgb(6.0));
  // A child's own boundary has no extra points (its neighbours are as small or larger).
  EXPECT_EQ(mesh.boundary(b, 1).size(), 4u);
}

TEST(PatchMesh, TheApexOfATriangleIsOnePoint) {
  // A triangle cut 2 x 1: both elements are triangles sharing v2.
  const Patch p = unit_triangle(2, 1);
  const PatchMesh mesh(p, {{0, 0, 0}, {0, 1, 0}});
  const std::vector<Rgb> b{Rgb(1.0), Rgb(3.0)};
  EXPECT_EQ(mesh.corner_count(0), 3);
  EXPECT_EQ(mesh.corner_radiosity(b, 0, 2), Rgb(2.0));
  EXPECT_EQ(mesh.boundary(b, 1)[2].position, p.polygon[2]);
  // Cut the left one: its children of the last row are triangles; the right element's left
  // side (towards the apex) carries the children's corner at mid height.
  const std::vector<ElementCell> cells{{1, 0, 0}, {1, 1, 0}, {1, 0, 1}, {1, 1, 1}, {0, 1, 0}};
  const PatchMesh fine(p, cells);
  const std::vector<Rgb> c{Rgb(1.0), Rgb(1.0), Rgb(1.0), Rgb(1.0), Rgb(3.0)};
  EXPECT_EQ(fine.corner_count(2), 3);
  const std::vector<MeshVertex> right = fine.boundary(c, 4);
  ASSERT_EQ(right.size(), 4u);  // (2,0), (4,0), apex, and (1, 1) of the lattice on the way down
  EXPECT_EQ(right[3].position, cell_polygon(p, cells[1])[2]);
  EXPECT_EQ(right[2].radiosity, Rgb((1.0 + 1.0 + 3.0) / 3.0));  // apex: two children, right
}

TEST(PatchMesh, RefusesCellsThatDoNotTile) {
  const Patch p = unit_square(2, 1);
  const PatchMesh mesh(p, {{0, 0, 0}});  // the right half is missing
  EXPECT_THROW(mesh.corner_radiosity({Rgb(1.0)}, 0, 1), std::logic_error);
}

}  // namespace
}  // namespace ncube

// What the renderer draws (paper section 2.3): one record per element of a radiosity
// solution, with the element's whole boundary (its corners and the T-vertices that smaller
// neighbours put on its edges, section 4.1) and the Gouraud radiosity at each point.
#pragma once

#include <vector>

#include "scene/patch_mesh.h"
#include "scene/scene.h"

namespace ncube {

// One element as the renderer needs it.
struct RenderElement {
  // Running index of the element in scene order (patches in order, each patch's elements in
  // its solution's order): the drawing key, a depth tie going to the lower index.
  int element = 0;
  int corners = 4;  // 3 for a triangle in the last row of a triangular patch's grid
  // Counter-clockwise from corner 0 as in cell_polygon: the corners and, between them, the
  // T-vertices, each with its nodal radiosity (PatchMesh::boundary).
  std::vector<MeshVertex> boundary;
  bool emitter = false;

  int t_vertices() const { return int(boundary.size()) - corners; }
};

// The solution before subdivision: every patch's level-0 cells in grid order (j-major, as
// Scene::build_elements orders them) with the radiosities of the scene's element list.
// Throws InputError when there is not one radiosity per element.
std::vector<PatchSolution> uniform_solution(const Scene& scene,
                                            const std::vector<Rgb>& element_radiosity);

// The records of the given patches' elements, in scene order. `solution` has one entry per
// scene patch, in scene patch order. Throws InputError for a solution that does not fit the
// scene.
std::vector<RenderElement> render_elements(const Scene& scene,
                                           const std::vector<PatchSolution>& solution,
                                           const std::vector<int>& patches);

}  // namespace ncube

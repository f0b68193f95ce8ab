// The radiosity solution as a mesh (--mesh, docs/cli.md "The solution as a mesh"): what
// radiosity tools hand back, to be looked at from anywhere in MeshLab or Blender and analysed.
// Every element is one polygon face with its whole boundary as the picture draws it: its
// corners and the T-vertices that finer neighbours put on its edges (adaptive subdivision,
// section 4.1), so the mesh is crack-free. A vertex is shared by the faces of one patch that
// meet there (positions are bit-identical, PatchMesh::boundary) and carries the nodal
// radiosity: as 8-bit colours tone-mapped as the picture is, and as raw doubles.
#pragma once

#include <string>
#include <vector>

#include "scene/patch_mesh.h"
#include "scene/scene.h"

namespace ncube {

// A binary little-endian PLY file. Vertex properties: x y z (double), red green blue (uchar:
// the picture's tone mapping with exposure scale `exposure`: clamp(radiosity x exposure) to
// [0, 1], sRGB, x 255 rounded), radiosity_r radiosity_g radiosity_b (double, the solution's
// nodal values). Face properties: vertex_indices (uchar count, or uint when a face has more
// than 255 vertices; int indices, counter-clockwise seen from the patch's front), patch and
// element (int: the scene patch, and the running element index in scene order),
// radiosity_r radiosity_g radiosity_b (double: the element's own radiosity, whose
// area-weighted mean over a patch is the result file's patch_radiosity). Deterministic: the
// same solution gives the same bytes.
std::string solution_mesh_ply(const Scene& scene, const std::vector<PatchSolution>& solution,
                              double exposure);

}  // namespace ncube

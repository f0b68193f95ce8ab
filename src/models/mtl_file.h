// What Assimp 5.2 does not say of an OBJ's materials: whether an MTL material gives its
// diffuse colour, and which faces it gives a material they did not ask for. Assimp fills a missing Kd with its own 0.6 grey (and so a face without
// `usemtl`), which looks like a colour the file gave; the importer's documented default is 0.5.
#pragma once

#include <set>
#include <string>
#include <vector>

namespace ncube::models {

// The names of the materials with a `Kd` line in the files among `files` that end in .mtl
// (the material libraries an OBJ read).
std::set<std::string> mtl_materials_with_kd(const std::vector<std::string>& files);

// The line number (from 1) of the first face of the OBJ at `path` that follows an `mtllib`
// line with no `usemtl` before it, 0 if there is none. Assimp 5.2 gives such faces the last
// material of the library, in silence: the importer refuses them instead.
long obj_face_without_usemtl(const std::string& path);

}  // namespace ncube::models

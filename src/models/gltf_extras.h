// What Assimp 5.2 does not read of a glTF file, read from the file's JSON itself.
#pragma once

#include <string>
#include <vector>

namespace ncube::models {

// KHR_materials_emissive_strength of each material in the file's order (Assimp keeps that
// order), 1 where a material has none; `binary` for a .glb (its JSON chunk). Empty when the
// JSON cannot be read (Assimp has then refused the file already).
std::vector<double> gltf_emissive_strengths(const std::string& path, bool binary);

}  // namespace ncube::models

// What Assimp 5.2 does not read of a glTF file, read from the file's JSON itself.
#pragma once

#include <string>
#include <vector>

namespace ncube::models {

struct GltfMaterialExtras {
  double emissive_strength = 1.0;  // KHR_materials_emissive_strength, 1 without it
  bool base_colour = false;        // whether pbrMetallicRoughness.baseColorFactor is given
};

// Each material's extras in the file's order (Assimp keeps that order); `binary` for a .glb
// (its JSON chunk). Empty when the JSON cannot be read (Assimp has then refused the file).
// Assimp gives a material without baseColorFactor glTF's default of white, indistinguishable
// from a white that is written: the importer needs to know which it is.
std::vector<GltfMaterialExtras> gltf_material_extras(const std::string& path, bool binary);

// The files the glTF's images name (their URIs percent-decoded, relative to the model's folder
// as the specification reads them; data: URIs are inside the file and left out). The import
// never reads a texture, but the model names these files, so no output may be one of them.
std::vector<std::string> gltf_image_files(const std::string& path, bool binary);

}  // namespace ncube::models

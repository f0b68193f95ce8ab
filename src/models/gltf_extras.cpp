#include "models/gltf_extras.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include <nlohmann/json.hpp>

#include "util/input_file.h"

namespace ncube::models {

// Assimp 5.2 does not read KHR_materials_emissive_strength; its materials keep the file's order.
std::vector<GltfMaterialExtras> gltf_material_extras(const std::string& path, bool binary) {
  std::string text = read_input_file(path, kModelFile);
  if (binary) {  // 12-byte header, then the JSON chunk
    if (text.size() < 20) return {};
    std::uint32_t length = 0;
    std::memcpy(&length, text.data() + 12, 4);
    text = text.substr(20, std::min<std::size_t>(length, text.size() - 20));
  }
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  std::vector<GltfMaterialExtras> materials;
  if (!document.is_object() || !document.contains("materials") || !document["materials"].is_array())
    return materials;
  for (const nlohmann::json& material : document["materials"]) {
    GltfMaterialExtras extras;
    if (!material.is_object()) {
      materials.push_back(extras);
      continue;
    }
    const auto pbr = material.find("pbrMetallicRoughness");
    extras.base_colour = pbr != material.end() && pbr->is_object() && pbr->contains("baseColorFactor");
    const auto extensions = material.find("extensions");
    if (extensions != material.end() && extensions->is_object() &&
        extensions->contains("KHR_materials_emissive_strength")) {
      const nlohmann::json& e = (*extensions)["KHR_materials_emissive_strength"];
      if (e.is_object() && e.contains("emissiveStrength") && e["emissiveStrength"].is_number())
        extras.emissive_strength = e["emissiveStrength"].get<double>();
    }
    materials.push_back(extras);
  }
  return materials;
}

}  // namespace ncube::models

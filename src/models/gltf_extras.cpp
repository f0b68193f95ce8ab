#include "models/gltf_extras.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>

#include <nlohmann/json.hpp>

namespace ncube::models {

// KHR_materials_emissive_strength of each glTF material, in the file's order (Assimp 5.2 does
// not read it; its materials keep the file's order). 1 where a material has none.
std::vector<double> gltf_emissive_strengths(const std::string& path, bool binary) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (binary) {  // 12-byte header, then the JSON chunk
    if (text.size() < 20) return {};
    std::uint32_t length = 0;
    std::memcpy(&length, text.data() + 12, 4);
    text = text.substr(20, std::min<std::size_t>(length, text.size() - 20));
  }
  const nlohmann::json document = nlohmann::json::parse(text, nullptr, false);
  std::vector<double> strengths;
  if (!document.is_object() || !document.contains("materials") || !document["materials"].is_array())
    return strengths;
  for (const nlohmann::json& material : document["materials"]) {
    double strength = 1.0;
    const nlohmann::json* extensions = material.is_object() && material.contains("extensions")
                                           ? &material["extensions"] : nullptr;
    if (extensions && extensions->is_object() && extensions->contains("KHR_materials_emissive_strength")) {
      const nlohmann::json& e = (*extensions)["KHR_materials_emissive_strength"];
      if (e.is_object() && e.contains("emissiveStrength") && e["emissiveStrength"].is_number())
        strength = e["emissiveStrength"].get<double>();
    }
    strengths.push_back(strength);
  }
  return strengths;
}

}  // namespace ncube::models

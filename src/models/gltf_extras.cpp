#include "models/gltf_extras.h"

#include <algorithm>
#include <cstdint>
#include <cctype>
#include <cstring>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "util/input_file.h"

namespace ncube::models {

namespace {

// The file's JSON (a .glb's JSON chunk); discarded (not an object) when it cannot be parsed.
nlohmann::json gltf_document(const std::string& path, bool binary) {
  std::string text = read_input_file(path, kModelFile);
  if (binary) {  // 12-byte header, then the JSON chunk
    if (text.size() < 20) return nlohmann::json();
    std::uint32_t length = 0;
    std::memcpy(&length, text.data() + 12, 4);
    text = text.substr(20, std::min<std::size_t>(length, text.size() - 20));
  }
  return nlohmann::json::parse(text, nullptr, false);
}

// A URI's %XX escapes as the bytes they stand for (RFC 3986); other characters as written.
std::string percent_decoded(const std::string& uri) {
  std::string decoded;
  for (std::size_t k = 0; k < uri.size(); ++k) {
    if (uri[k] == '%' && k + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[k + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[k + 2]))) {
      decoded += char(std::stoi(uri.substr(k + 1, 2), nullptr, 16));
      k += 2;
    } else {
      decoded += uri[k];
    }
  }
  return decoded;
}

}  // namespace

// Assimp 5.2 does not read KHR_materials_emissive_strength; its materials keep the file's order.
std::vector<GltfMaterialExtras> gltf_material_extras(const std::string& path, bool binary) {
  const nlohmann::json document = gltf_document(path, binary);
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

std::vector<std::string> gltf_image_files(const std::string& path, bool binary) {
  const nlohmann::json document = gltf_document(path, binary);
  std::vector<std::string> files;
  if (!document.is_object() || !document.contains("images") || !document["images"].is_array())
    return files;
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  for (const nlohmann::json& image : document["images"]) {
    if (!image.is_object() || !image.contains("uri") || !image["uri"].is_string()) continue;
    const std::string uri = image["uri"].get<std::string>();
    if (uri.empty() || uri.rfind("data:", 0) == 0) continue;
    const std::string name = percent_decoded(uri);
    files.push_back(std::filesystem::path(name).is_absolute() ? name : (folder / name).string());
  }
  return files;
}

}  // namespace ncube::models

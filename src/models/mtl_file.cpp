#include "models/mtl_file.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

namespace ncube::models {

std::set<std::string> mtl_materials_with_kd(const std::vector<std::string>& files) {
  std::set<std::string> with_kd;
  for (const std::string& file : files) {
    std::string extension = file.size() >= 4 ? file.substr(file.size() - 4) : "";
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".mtl") continue;
    std::ifstream in(file);
    std::string line, material;
    while (std::getline(in, line)) {
      std::istringstream words(line);
      std::string keyword;
      words >> keyword;
      // A name is the rest of the line, trimmed, as Assimp takes it.
      if (keyword == "newmtl") {
        std::getline(words >> std::ws, material);
        while (!material.empty() && std::isspace((unsigned char)material.back())) material.pop_back();
      }
      if (keyword == "Kd" && !material.empty()) with_kd.insert(material);
    }
  }
  return with_kd;
}

long obj_face_without_usemtl(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  bool library = false;
  for (long number = 1; std::getline(in, line); ++number) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "usemtl") return 0;  // every later face names its material
    if (keyword == "mtllib") library = true;
    if (keyword == "f" && library) return number;
  }
  return 0;
}

}  // namespace ncube::models

#include "models/mtl_file.h"

#include <algorithm>
#include <cctype>

#include "util/input_file.h"

namespace ncube::models {
namespace {

// The line's keyword and the rest of it, trimmed (a material name is the rest of the line, as
// Assimp takes it). Plain string work: an OBJ may have millions of lines.
void split_line(const std::string& line, std::string& keyword, std::string& rest) {
  std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string::npos) start = line.size();
  std::size_t end = line.find_first_of(" \t\r", start);
  if (end == std::string::npos) end = line.size();
  keyword.assign(line, start, end - start);
  const std::size_t first = line.find_first_not_of(" \t", end);
  const std::size_t last = line.find_last_not_of(" \t\r");
  rest = first == std::string::npos || last == std::string::npos || last < first
             ? std::string()
             : line.substr(first, last - first + 1);
}

}  // namespace

MtlNames mtl_names(const std::vector<std::string>& files) {
  MtlNames names;
  for (const std::string& file : files) {
    std::string extension = file.size() >= 4 ? file.substr(file.size() - 4) : "";
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".mtl") continue;
    InputStream in(file, kModelPart);
    std::string line, keyword, rest, material;
    while (std::getline(in, line)) {
      split_line(line, keyword, rest);
      if (keyword == "newmtl") names.defined.insert(material = rest);
      if (keyword == "Kd" && !material.empty()) names.with_kd.insert(material);
    }
  }
  return names;
}

std::string obj_material_problem(const std::string& path, const MtlNames& names) {
  InputStream in(path, kModelFile);
  std::string line, keyword, rest;
  bool library = false, chosen = false;
  for (long number = 1; std::getline(in, line); ++number) {
    if (line.empty() || (line[0] != 'u' && line[0] != 'm' && line[0] != 'f' && line[0] != ' ' &&
                         line[0] != '\t'))
      continue;  // vertices, comments, groups: most lines
    split_line(line, keyword, rest);
    if (keyword == "mtllib") library = true;
    if (keyword == "f" && library && !chosen)
      return "line " + std::to_string(number) + ": a face after mtllib and before any usemtl " +
             "(Assimp would give it the library's last material): put a usemtl before it";
    if (keyword == "usemtl") {
      chosen = true;
      if (!names.defined.count(rest))
        return "line " + std::to_string(number) + ": usemtl " + rest +
               ": no material library of the model defines it";
    }
  }
  return "";
}

long obj_library_line(const std::string& path, long n) {
  InputStream in(path, kModelFile);
  std::string line, keyword, rest;
  for (long number = 1; std::getline(in, line); ++number) {
    if (line.empty() || (line[0] != 'm' && line[0] != ' ' && line[0] != '\t')) continue;
    split_line(line, keyword, rest);
    if (keyword == "mtllib" && --n == 0) return number;
  }
  return 0;
}

}  // namespace ncube::models

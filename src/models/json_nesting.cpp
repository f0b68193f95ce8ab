#include "models/json_nesting.h"

#include <algorithm>
#include <cstdint>

#include "scene/scene_loader.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube::models {

std::size_t too_deep_at(const std::string& json, int limit) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (in_string) {
      if (c == '\\')
        ++i;  // the escaped character, a quote or a backslash among them
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > limit) return i;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return json.size();
}

namespace {

std::uint32_t little_endian_word(const std::string& bytes, std::size_t offset) {
  const auto* b = reinterpret_cast<const unsigned char*>(bytes.data() + offset);
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 | std::uint32_t(b[3]) << 24;
}

// The JSON of a .glb, from byte 20 with its length at byte 12: glTF 2's first chunk (a 12-byte
// header, then the chunk's length and type "JSON") or glTF 1's content (a 20-byte header whose
// fourth word is the content's length). Anything else is left to Assimp, which refuses it.
std::string glb_json(const std::string& bytes) {
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return "";
  const std::uint32_t version = little_endian_word(bytes, 4);
  const std::uint32_t length = little_endian_word(bytes, 12);
  if (version == 2 && bytes.compare(16, 4, "JSON") != 0) return "";
  return bytes.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

}  // namespace

void check_gltf_nesting(const std::string& path, bool binary) {
  const std::string bytes = read_input_file(path, kModelFile);
  const std::string json = binary ? glb_json(bytes) : bytes;
  const std::size_t at = too_deep_at(json, kMaxNestingDepth);
  if (at < json.size())
    throw InputError(path + ": JSON nested deeper than " + std::to_string(kMaxNestingDepth) +
                     " arrays and objects (the limit, as for scene files), at byte " +
                     std::to_string(at + (binary ? 20 : 0)) + (binary ? " (in its JSON chunk)" : ""));
}

}  // namespace ncube::models

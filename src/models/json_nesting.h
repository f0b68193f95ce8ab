// A glTF's JSON nesting, checked before Assimp parses it (docs/scene-format.md, "Importing
// models"): Assimp's JSON reader recurses once per level, so a 400 KB file of nested arrays
// overflowed the stack. Models are held to the scene files' limit, kMaxNestingDepth.
#pragma once

#include <cstddef>
#include <string>

namespace ncube::models {

// The byte offset in `json` of the first array or object opened deeper than `limit`, or
// `json.size()` when none is. A scan without recursion that skips strings; it does not check
// that the text is JSON (the parser does that after).
std::size_t too_deep_at(const std::string& json, int limit);

// Throws InputError "<path>: JSON nested deeper than ..." when the JSON of the glTF at `path`
// (the JSON chunk of a .glb when `binary`) nests deeper than kMaxNestingDepth.
void check_gltf_nesting(const std::string& path, bool binary);

}  // namespace ncube::models

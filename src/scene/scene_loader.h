// Reads and validates a scene file (format: docs/scene-format.md).
#pragma once

#include <string>

#include "scene/scene.h"

namespace ncube {

// Largest number of elements a single patch may be cut into, and in a whole scene; larger
// values are rejected as "absurdly large" (a typo, not a scene).
constexpr long kMaxElementsPerPatch = 1L << 20;
constexpr long kMaxElementsPerScene = 1L << 24;

// Loads the scene at `path`, validates every field and builds its elements. Throws
// InputError with one message naming the file, the patch index and the field.
Scene load_scene(const std::string& path);

// The same from text already read; `path` is used in messages only.
Scene parse_scene(const std::string& text, const std::string& path);

}  // namespace ncube

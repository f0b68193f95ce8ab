// Reads and validates a scene file (format: docs/scene-format.md).
#pragma once

#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "util/input_file.h"

namespace ncube {

// Largest number of elements a single patch may be cut into, and in a whole scene; larger
// values are rejected as "absurdly large" (a typo, not a scene).
constexpr long kMaxElementsPerPatch = 1L << 20;
constexpr long kMaxElementsPerScene = 1L << 24;

// Largest scene file read, in bytes: a larger file (or an endless one such as /dev/zero) is
// rejected before it is parsed. 256 MiB is the memory of the whole 64-node nCube2, and
// far beyond the paper's scenes (scene3: 0.3 MB).
constexpr std::size_t kMaxSceneFileBytes = kSceneFile.max_bytes;
// Deepest nesting of JSON arrays and objects accepted; a scene needs 5.
constexpr int kMaxNestingDepth = 16;
// Non-zero emission channels must lie in [kMinEmission, kMaxEmission]: emission units are
// arbitrary (only ratios matter), and within these bounds every sum of powers and
// radiosities stays far from overflow and underflow.
constexpr double kMinEmission = 1e-100;
constexpr double kMaxEmission = 1e100;
// A scene whose bounding box's largest extent is outside [2^(e-1), 2^e) for e in
// [kSmallestUnscaledExponent, kLargestUnscaledExponent] (about 1.5e-5 to 65536 units) is
// scaled by a power of two into [0.5, 1) when it is loaded (exact in floating point).
constexpr int kSmallestUnscaledExponent = -15;
constexpr int kLargestUnscaledExponent = 16;

// Whether loading builds the elements (the grid cells of every patch). The command line
// builds them only after the memory check, so that a scene too large for the modeled
// machine is refused before the host allocates its elements.
enum class SceneElements { kBuild, kLater };

// Loads the scene at `path`, validates every field and builds its elements. Throws
// InputError with one message naming the file, the patch index and the field.
Scene load_scene(const std::string& path, SceneElements elements = SceneElements::kBuild);

// The same from text already read; `path` is used in messages only.
Scene parse_scene(const std::string& text, const std::string& path,
                  SceneElements elements = SceneElements::kBuild);

// The same from a JSON document already parsed (an imported model's, src/models): every check
// but the text's own (syntax, duplicate keys, nesting), which a document built in memory
// cannot fail.
Scene scene_from_document(const nlohmann::json& document, const std::string& path,
                          SceneElements elements = SceneElements::kBuild);

}  // namespace ncube

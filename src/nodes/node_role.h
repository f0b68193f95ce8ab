// What a node does in a run (section 3): a radiosity processor, one of its visibility
// processors, or (only when the rendering phase runs out of memory) a rendering node.
#pragma once

namespace ncube {

enum class NodeRole { kRadiosity, kVisibility, kRendering };

// The role's name in the result file and the messages: "radiosity", "visibility",
// "rendering".
inline const char* role_name(NodeRole role) {
  switch (role) {
    case NodeRole::kRadiosity: return "radiosity";
    case NodeRole::kVisibility: return "visibility";
    case NodeRole::kRendering: return "rendering";
  }
  return "?";
}

}  // namespace ncube

#include "tools/input_lookup.h"

#include <filesystem>

#include "util/input_error.h"

namespace ncube {

namespace {

struct RoleFolders {
  std::vector<const char*> folders;     // under the repository root, in the order tried
  std::vector<const char*> extensions;  // added to a bare name without one of them
};

// The one table of where each role's bare names live.
RoleFolders folders_of(InputRole role) {
  switch (role) {
    case InputRole::kScene:
      return {{"scenes"}, {".json"}};
    case InputRole::kPlatform:
      return {{"platforms", "platforms/machines"}, {".json", ".xml"}};
    case InputRole::kCostModel:
      return {{"platforms"}, {".json"}};
  }
  return {};
}

}  // namespace

const char* input_role_name(InputRole role) {
  switch (role) {
    case InputRole::kScene:
      return "scene";
    case InputRole::kPlatform:
      return "platform";
    case InputRole::kCostModel:
      return "cost model";
  }
  return "input";
}

std::vector<std::string> input_candidates(const std::string& name, InputRole role,
                                          const std::string& root) {
  namespace fs = std::filesystem;
  std::vector<std::string> candidates = {name};
  const fs::path path(name);
  if (name.empty() || path.is_absolute()) return candidates;
  candidates.push_back((fs::path(root) / path).string());
  if (name.find('/') != std::string::npos) return candidates;
  const RoleFolders where = folders_of(role);
  for (const char* folder : where.folders) {
    const fs::path in_folder = fs::path(root) / folder;
    candidates.push_back((in_folder / name).string());
    for (const char* extension : where.extensions)
      if (path.extension() != extension) candidates.push_back((in_folder / (name + extension)).string());
  }
  return candidates;
}

std::string find_input(const std::string& name, InputRole role, const std::string& root) {
  namespace fs = std::filesystem;
  const std::vector<std::string> candidates = input_candidates(name, role, root);
  for (const std::string& candidate : candidates) {
    std::error_code error;
    // symlink_status: a dangling link or a loop is there for the gate to report (exit 2), as
    // is a path whose existence cannot be told (a folder without permission).
    const fs::file_status status = fs::symlink_status(candidate, error);
    if (status.type() != fs::file_type::not_found) return candidate;
  }
  std::string tried;
  for (const std::string& candidate : candidates) tried += (tried.empty() ? "" : ", ") + candidate;
  throw InputError(name + ": no such " + input_role_name(role) + " file (looked for: " + tried + ")");
}

}  // namespace ncube

#include "tools/input_lookup.h"

#include <algorithm>
#include <filesystem>

#include "tools/suggestions.h"
#include "util/input_error.h"
#include "util/shown_text.h"

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

// "platforms/ and platforms/machines/".
std::string folders_text(const RoleFolders& where) {
  std::vector<std::string> folders;
  for (const char* folder : where.folders) folders.push_back(std::string(folder) + "/");
  std::string text;
  for (std::size_t i = 0; i < folders.size(); ++i)
    text += (i == 0 ? "" : i + 1 == folders.size() ? " and " : ", ") + folders[i];
  return text;
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

std::vector<std::string> input_names(InputRole role, const std::string& root) {
  namespace fs = std::filesystem;
  std::vector<std::string> names;
  const RoleFolders where = folders_of(role);
  for (const char* folder : where.folders) {
    std::error_code error;
    std::vector<std::string> here;
    for (fs::directory_iterator entry(fs::path(root) / folder, error), end; !error && entry != end;
         entry.increment(error)) {
      const fs::path file = entry->path().filename();
      if (std::find(where.extensions.begin(), where.extensions.end(), file.extension().string()) !=
          where.extensions.end())
        here.push_back(file.stem().string());
    }
    std::sort(here.begin(), here.end());
    for (const std::string& name : here)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  }
  return names;
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
  for (const std::string& candidate : candidates)
    tried += (tried.empty() ? "" : ", ") + shown_text(candidate);
  // The names the role's folders hold, nearest first: the file's name without the role's
  // extension, compared with theirs; for a bare name (which step 3 looks for there) the
  // nearest even when none is close.
  const RoleFolders where = folders_of(role);
  const fs::path file = fs::path(name).filename();
  const bool role_extension = std::find(where.extensions.begin(), where.extensions.end(),
                                        file.extension().string()) != where.extensions.end();
  const std::string typed = role_extension ? file.stem().string() : file.string();
  const std::vector<std::string> known = input_names(role, root);
  std::string names;
  if (const std::vector<std::string> close = close_names(typed, known); !close.empty())
    names = "; did you mean " + either_of(close) + "?";
  else if (const std::vector<std::string> nearest = nearest_names(typed, known);
           name.find('/') == std::string::npos && !nearest.empty())
  {
    names = "; the nearest names in " + folders_text(where) + ":";
    for (std::size_t i = 0; i < nearest.size(); ++i) names += (i == 0 ? " " : ", ") + nearest[i];
  }
  throw InputError(shown_text(name) + ": no such " + input_role_name(role) + " file" + names +
                   " (looked for: " + tried + ")");
}

}  // namespace ncube

#include "models/recording_io.h"

#include <assimp/MemoryIOWrapper.h>
#include <strings.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube::models {
namespace {

namespace fs = std::filesystem;

}  // namespace

bool lies_in(const std::string& path, const std::string& folder) {
  if (folder == "/") return true;
  return path == folder ||
         (path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
          path[folder.size()] == '/');
}

RecordingIOSystem::RecordingIOSystem(const std::string& model,
                                     const std::vector<std::string>& folders,
                                     std::vector<std::string>& files,
                                     std::vector<std::string>& problems)
    : model_(model), files_(files), problems_(problems) {
  // Assimp joins the model's folder, as written in the model's path, and the name the model
  // gives (relative or not): "dir/" + "x.mtl", "dir/" + "/etc/x".
  const std::size_t slash = model.find_last_of('/');
  prefix_ = slash == std::string::npos ? "" : model.substr(0, slash + 1);
  const std::string folder = slash == std::string::npos ? "."
                             : slash == 0               ? "/"
                                                        : model.substr(0, slash);
  std::error_code error;
  allowed_.push_back(fs::canonical(folder, error).string());
  if (error) throw InputError(model + ": cannot find the model's folder: " + error.message());
  for (const std::string& extra : folders) {
    const fs::path canonical = fs::canonical(extra, error);
    if (error || !fs::is_directory(canonical))
      throw InputError("--model-folder " + extra + ": not a folder" +
                       (error ? " (" + error.message() + ")" : std::string()));
    allowed_.push_back(canonical.string());
  }
}

std::string RecordingIOSystem::outside(const std::string& reference,
                                       const std::string& real) const {
  for (const std::string& folder : allowed_)
    if (lies_in(real, folder)) return "";
  std::string why = "through a symbolic link";
  if (!reference.empty() && reference[0] == '/') {
    why = "an absolute path";
  } else {
    const std::string lexical = (fs::path(allowed_[0]) / reference).lexically_normal().string();
    if (!lies_in(lexical, allowed_[0])) why = "a .. path";
  }
  return model_ + ": names " + reference + ", which lies outside the model's folder " +
         allowed_[0] + " (" + why +
         "); a model reads only files in its own folder or one named with --model-folder";
}

RecordingIOSystem::Asked RecordingIOSystem::checked(const std::string& file) const {
  if (file == model_) return {file, file};  // the model itself: the user named it
  const std::string reference = !prefix_.empty() && file.compare(0, prefix_.size(), prefix_) == 0
                                    ? file.substr(prefix_.size())
                                    : file;
  if (strncasecmp(reference.c_str(), "file:", 5) == 0) {
    note(problems_, model_ + ": names " + reference +
                        ", a file: URI (a model names its files by paths relative to its folder)");
    return {"", reference};
  }
  // An absolute name is itself, whatever folder Assimp put before it: so a model named by a
  // relative or an absolute path reads the same files.
  const std::string target = reference.empty() || reference[0] != '/' ? file : reference;
  std::error_code error;
  const fs::path canonical = fs::weakly_canonical(target, error);
  if (!error) {  // else (a loop of links) the gate's open says why
    const std::string problem = outside(reference, canonical.string());
    if (!problem.empty()) {
      note(problems_, problem);
      return {"", reference};
    }
  }
  return {target, reference};
}

bool RecordingIOSystem::Exists(const char* file) const {
  const auto [target, reference] = checked(file);
  if (target.empty()) return false;
  try {
    const bool part = target != model_;
    const InputFile input(target, part ? kModelPart : kModelFile, part ? model_ + ": names " : "",
                          reference);
    if (part) {
      // What was opened, links resolved now: no link swapped in after the check above.
      const std::string problem = outside(reference, input.real_path());
      if (!problem.empty()) throw InputError(problem);
    }
    return true;
  } catch (const InputError& e) {
    note(problems_, e.what());
    return false;
  }
}

Assimp::IOStream* RecordingIOSystem::Open(const char* file, const char* mode) {
  if (std::strchr(mode, 'w') || std::strchr(mode, 'a') || std::strchr(mode, '+')) return nullptr;
  const auto [target, reference] = checked(file);
  if (target.empty()) return nullptr;
  try {
    const bool part = target != model_;
    InputFile input(target, part ? kModelPart : kModelFile, part ? model_ + ": names " : "",
                    reference);
    if (part) {
      const std::string problem = outside(reference, input.real_path());
      if (!problem.empty()) throw InputError(problem);
    }
    const std::string bytes = input.read_all();
    auto* buffer = new std::uint8_t[bytes.size()];
    std::memcpy(buffer, bytes.data(), bytes.size());
    note(files_, target);
    return new Assimp::MemoryIOStream(buffer, bytes.size(), true);  // owns the buffer
  } catch (const InputError& e) {
    note(problems_, e.what());
    return nullptr;
  }
}

void RecordingIOSystem::note(std::vector<std::string>& list, const std::string& text) const {
  if (std::find(list.begin(), list.end(), text) == list.end()) list.push_back(text);
}

}  // namespace ncube::models

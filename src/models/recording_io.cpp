#include "models/recording_io.h"

#include <assimp/MemoryIOWrapper.h>
#include <strings.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "models/mtl_file.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube::models {
namespace {

namespace fs = std::filesystem;

// A name as a message shows it: a model may name a file by a whole line of 100,000 characters.
std::string shown_name(const std::string& name) {
  constexpr std::size_t kShown = 120;
  return name.size() <= kShown ? name
                               : name.substr(0, kShown) + "... (" + std::to_string(name.size()) +
                                     " characters)";
}

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
  return model_ + ": names " + shown_name(reference) + ", which lies outside the model's folder " +
         allowed_[0] + " (" + why +
         "); a model reads only files in its own folder or one named with --model-folder";
}

RecordingIOSystem::Asked RecordingIOSystem::checked(const std::string& file) const {
  if (file == model_) return {file, file};  // the model itself: the user named it
  const std::string reference = !prefix_.empty() && file.compare(0, prefix_.size(), prefix_) == 0
                                    ? file.substr(prefix_.size())
                                    : file;
  if (strncasecmp(reference.c_str(), "file:", 5) == 0) {
    note(problems_, model_ + ": names " + shown_name(reference) +
                        ", a file: URI (a model names its files by paths relative to its folder)");
    return {"", reference};
  }
  // An absolute name is itself, whatever folder Assimp put before it: so a model named by a
  // relative or an absolute path reads the same files.
  const std::string target = reference.empty() || reference[0] != '/' ? file : reference;
  std::error_code error;
  // Made absolute first: the weakly canonical form of a relative name that does not exist
  // stays relative, and was then taken for a link out of the folder.
  const fs::path canonical = fs::weakly_canonical(fs::absolute(target, error), error);
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
  // After a problem the import is refused with the first: nothing more is looked at (a model
  // naming 20,000 missing libraries took seconds).
  if (!problems_.empty()) return false;
  if (read_once_.count(file)) return true;  // read through the gate already
  const auto [target, reference] = checked(file);
  if (target.empty()) return false;
  try {
    const bool part = target != model_;
    const InputFile input(target, part ? kModelPart : kModelFile, part ? model_ + ": names " : "",
                          shown_name(reference));
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
  // A file named again is handed as first read, without its checks (the name Assimp asks
  // for is the key: the same name is the same target).
  if (!problems_.empty()) return nullptr;  // refused already: the first problem is reported
  auto kept = read_once_.find(file);
  const auto [target, reference] =
      kept != read_once_.end() ? Asked{file, kept->second.first} : checked(file);
  if (target.empty()) return nullptr;
  const auto stream = [](const std::string& bytes) {
    auto* buffer = new std::uint8_t[bytes.size()];
    std::memcpy(buffer, bytes.data(), bytes.size());
    return new Assimp::MemoryIOStream(buffer, bytes.size(), true);  // owns the buffer
  };
  try {
    if (target == model_) {  // the model itself: the user named it
      InputFile input(target, kModelFile);
      const std::string bytes = input.read_all();
      note(files_, target);
      return stream(bytes);
    }
    ++part_opens_;
    if (kept == read_once_.end()) {
      InputFile input(target, kModelPart, model_ + ": names ", shown_name(reference));
      const std::string problem = outside(reference, input.real_path());
      if (!problem.empty()) throw InputError(problem);
      kept = read_once_.emplace(file, std::make_pair(reference, input.read_all())).first;
      note(files_, target);
    } else if ((bytes_again_ += kept->second.second.size()) > kBytesNamedAgain) {
      const long line = obj_library_line(model_, part_opens_);
      throw InputError(model_ + (line > 0 ? ": line " + std::to_string(line) : std::string()) +
                       ": names " + shown_name(reference) + " again: more than " +
                       std::to_string(kBytesNamedAgain >> 20) +
                       " MiB of files named again (the limit: Assimp reads a material library "
                       "again at every mtllib line; name each once)");
    }
    const std::string& bytes = kept->second.second;
    return stream(bytes);
  } catch (const InputError& e) {
    note(problems_, e.what());
    return nullptr;
  }
}

void RecordingIOSystem::note(std::vector<std::string>& list, const std::string& text) const {
  if (std::find(list.begin(), list.end(), text) == list.end()) list.push_back(text);
}

}  // namespace ncube::models

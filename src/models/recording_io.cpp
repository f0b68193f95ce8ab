#include "models/recording_io.h"

#include <sys/stat.h>

#include <algorithm>

namespace ncube::models {

bool RecordingIOSystem::Exists(const char* file) const {
  const bool exists = Assimp::DefaultIOSystem::Exists(file);
  if (!exists) note(missing_, file);
  return exists;
}

Assimp::IOStream* RecordingIOSystem::Open(const char* file, const char* mode) {
  struct stat info {};
  if (stat(file, &info) == 0 && std::size_t(info.st_size) > largest_) {
    note(too_large_, file);
    return nullptr;
  }
  Assimp::IOStream* stream = Assimp::DefaultIOSystem::Open(file, mode);
  note(stream ? files_ : missing_, file);
  return stream;
}

void RecordingIOSystem::note(std::vector<std::string>& list, const char* file) {
  if (std::find(list.begin(), list.end(), file) == list.end()) list.push_back(file);
}

}  // namespace ncube::models

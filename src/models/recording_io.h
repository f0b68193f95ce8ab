// Assimp's file system for the importer: every file a model reads is noted (its identity for
// provenance and sweeps) and every file it names but cannot open (a missing MTL, which Assimp
// alone would replace by a default material in silence).
#pragma once

#include <string>
#include <vector>

#include <assimp/DefaultIOSystem.h>

namespace ncube::models {

// Assimp's file system, noting every file the model reads (the MTL, glTF buffers): the
// model's identity for sweeps and provenance is all of them.
// A file the model names but that is missing (an MTL library) is an error, where Assimp
// would go on with a default material.
class RecordingIOSystem : public Assimp::DefaultIOSystem {
 public:
  RecordingIOSystem(std::vector<std::string>& files, std::vector<std::string>& missing)
      : files_(files), missing_(missing) {}
  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode) override;

 private:
  static void note(std::vector<std::string>& list, const char* file);
  std::vector<std::string>& files_;
  std::vector<std::string>& missing_;
};

}  // namespace ncube::models

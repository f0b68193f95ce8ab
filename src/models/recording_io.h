// Assimp's file system for the importer: every file a model reads is noted (its identity for
// provenance and sweeps) and every file it names but cannot open (a missing MTL, which Assimp
// alone would replace by a default material in silence).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <assimp/DefaultIOSystem.h>

namespace ncube::models {

// Assimp's file system, noting every file the model reads (the MTL, glTF buffers): the
// model's identity for sweeps and provenance is all of them.
// A file the model names but that is missing (an MTL library) is an error, where Assimp
// would go on with a default material.
// A file over `largest` bytes is not opened at all (noted in `too_large`): a model's size
// limit holds for its parts before Assimp reads them, not after.
class RecordingIOSystem : public Assimp::DefaultIOSystem {
 public:
  RecordingIOSystem(std::vector<std::string>& files, std::vector<std::string>& missing,
                    std::vector<std::string>& too_large, std::size_t largest)
      : files_(files), missing_(missing), too_large_(too_large), largest_(largest) {}
  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode) override;

 private:
  static void note(std::vector<std::string>& list, const char* file);
  std::vector<std::string>& files_;
  std::vector<std::string>& missing_;
  std::vector<std::string>& too_large_;
  std::size_t largest_;
};

}  // namespace ncube::models

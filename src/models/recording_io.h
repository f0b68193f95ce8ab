// Assimp's file system for the importer: every file Assimp opens goes through the input gate
// (util/input_file.h), every file the model names must lie in the model's own folder (or a
// folder the user names with --model-folder), and every file read is noted (its identity for
// provenance and sweeps). A file the model names that cannot be read (missing, a FIFO, too
// large, outside the folder) is an error, where Assimp alone would go on without it (a
// default material in place of a missing MTL).
#pragma once

#include <assimp/DefaultIOSystem.h>

#include <map>
#include <string>
#include <vector>

namespace ncube::models {

class RecordingIOSystem : public Assimp::DefaultIOSystem {
 public:
  // `model`: the model's path as the user named it; `folders`: further folders its files may
  // lie in. `files` receives every file read (the model first), `problems` one message for
  // each file the model names that is not read (Assimp swallows exceptions: the importer
  // throws the first after Assimp returns).
  RecordingIOSystem(const std::string& model, const std::vector<std::string>& folders,
                    std::vector<std::string>& files, std::vector<std::string>& problems);
  bool Exists(const char* file) const override;
  Assimp::IOStream* Open(const char* file, const char* mode) override;

 private:
  // A file Assimp asks for: the path to open ("" when refused, the problem noted) and the
  // name the model gives it (Assimp's folder prefix taken off).
  struct Asked {
    std::string target, reference;
  };
  Asked checked(const std::string& file) const;
  // `problem` when the opened file (links resolved) lies in no allowed folder, else "".
  std::string outside(const std::string& reference, const std::string& real) const;
  void note(std::vector<std::string>& list, const std::string& text) const;

  // Every file the model names is read through the gate once and kept: an OBJ may name its
  // material library on every line, and Assimp opens it again each time (20,000 mtllib lines
  // took seconds of gate work). What Assimp is handed again is counted, as if read again,
  // against kBytesNamedAgain.
  // By the name Assimp asks for: (the name the model gives, the bytes).
  std::map<std::string, std::pair<std::string, std::string>> read_once_;
  std::size_t bytes_again_ = 0;  // of the files named again, at every naming after the first
  long part_opens_ = 0;          // the openings of files the model names (the nth mtllib)

  std::string model_;
  std::string prefix_;                // the model's folder as Assimp writes it before a name
  std::vector<std::string> allowed_;  // canonical folders
  std::vector<std::string>& files_;
  std::vector<std::string>& problems_;
};

// The bytes of files a model names again that Assimp may be handed (every naming after the
// first counts the file's size). Assimp parses an OBJ's material library again at every
// mtllib line: a 0.6 MB library named 200 times took 3 s and 800 MB, 20,000 times would take
// many minutes. Past this the model is refused (exit 2) naming the OBJ's line; a file named
// once is held to its own limit only (kModelPart).
inline constexpr std::size_t kBytesNamedAgain = std::size_t(64) << 20;

// Whether `path` (canonical) lies in `folder` (canonical) or below it.
bool lies_in(const std::string& path, const std::string& folder);

}  // namespace ncube::models

// The output files of one run (--json, --trace, --image), all or nothing: every path is
// checked before the simulation starts, each output is written to a temporary file in its
// target's folder, and the temporary files are renamed onto their targets only once all of
// them are written. If anything fails, no output file is created or changed.
#pragma once

#include <string>
#include <vector>

namespace ncube {

class OutputFiles {
 public:
  struct Output {
    std::string option;  // "--json", for messages
    std::string path;    // empty: this output is not wanted
  };

  // Checks each wanted output and creates its temporary file. Throws InputError naming the
  // option and the path when a path is empty, names a folder, lies in a folder that does
  // not exist or cannot be written, is one of `inputs` (the scene, platform and cost-model
  // files) or is the same file as another output.
  OutputFiles(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);
  ~OutputFiles();  // removes the temporary files of a run that did not commit
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // Writes the whole content of output `option` to its temporary file. Throws OutputError
  // (disk full, file-size limit, I/O error).
  void write(const std::string& option, const std::string& content);
  // Renames the temporary files that were written onto their targets (the others are
  // removed). Throws OutputError if a rename fails.
  void commit();

 private:
  void open(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);
  void remove_temporaries();

  struct Pending {
    std::string option, path, temporary;
    int descriptor = -1;
    bool written = false;
  };
  std::vector<Pending> pending_;
};

}  // namespace ncube

// The output files of one run (--json, --trace, --image), all or nothing, by one rule per kind
// of path (docs/cli.md, "Output files"). Every path is checked before the simulation starts:
//  - a new path or a regular file is written to a temporary file in its folder and renamed
//    onto it once every output is written (atomic replacement is for files);
//  - a symbolic link is followed (at most 40 links) and its target written as above: the link
//    stays, and a dangling link's target is created;
//  - a character device or a FIFO (/dev/null, /dev/full, a named pipe) is written where it
//    points, streamed at commit time, before the files are renamed: a write error (a full
//    device, a closed pipe) is exit 5 and leaves every file output unchanged;
//  - "-", or any path that is the process's standard output (/dev/stdout, /proc/self/fd/1),
//    is standard output, streamed like a device;
//  - anything else that exists (a folder, a socket, a block device) is refused before the run
//    (OutputError: exit 5). Nothing that is not a regular file is ever replaced.
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

  // Checks each wanted output and creates the temporary file of each file output. Throws
  // InputError naming the option and the path when a path is empty or ends in '/', lies in a
  // folder that does not exist or cannot be written, has a chain of links too long, is one of
  // `inputs` (the scene, platform and cost-model files) or the same as another output; throws
  // OutputError when it names something that cannot be written (a folder, a socket, a block
  // device).
  OutputFiles(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);
  ~OutputFiles();  // removes the temporary files of a run that did not commit
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // Whether some output goes to standard output (the summary then goes to stderr).
  bool uses_standard_output() const;

  // Writes the whole content of output `option`: to its temporary file, or, for a stream,
  // kept until commit. Throws OutputError (disk full, file-size limit, I/O error).
  void write(const std::string& option, const std::string& content);
  // Writes the streams, then renames the temporary files that were written onto their
  // targets (the others are removed). Throws OutputError if a write or a rename fails.
  void commit();

 private:
  enum class Kind { kFile, kStream, kStandardOutput };
  struct Pending {
    std::string option, path;
    Kind kind = Kind::kFile;
    std::string target;     // the path written: `path` with its links followed
    std::string temporary;  // kFile: the temporary file until it is renamed
    int descriptor = -1;
    std::string content;    // streams: what commit writes
    bool written = false;
  };

  void open(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);
  void open_file(Pending& pending, const std::string& where);
  void stream(const Pending& pending) const;
  void remove_temporaries();

  std::vector<Pending> pending_;
};

}  // namespace ncube

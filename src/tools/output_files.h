// The output files of one run (--json, --trace, --image, --mesh, --export-scene, the activity
// record, the files SimGrid writes at the user's request), all or nothing, by one rule per
// kind of path (docs/cli.md, "Output files"). Every path is checked before the simulation
// starts, and each output is written to a temporary file that has no name until commit
// (tools/temporary_file.h), so no exit of the process leaves one behind:
//  - a new path or a regular file is replaced, at commit, by its temporary file (atomic
//    replacement is for files);
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

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "tools/temporary_file.h"

namespace ncube {

class OutputFiles {
 public:
  struct Output {
    std::string option;  // "--json", for messages
    std::string path;    // empty: this output is not wanted
  };

  // Checks each wanted output and creates its temporary file. Throws InputError naming the
  // option and the path when a path is empty or ends in '/', lies in a folder that does not
  // exist or cannot be written, has a chain of links too long, is one of `inputs` (every file
  // the run reads: the scene or model and every file the model names, the platform and
  // cost-model files) or the same as another output; throws
  // OutputError when it names something that cannot be written (a folder, a socket, a block
  // device).
  OutputFiles(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);
  OutputFiles(const OutputFiles&) = delete;
  OutputFiles& operator=(const OutputFiles&) = delete;

  // Whether some output goes to standard output (the summary then goes to stderr).
  bool uses_standard_output() const;

  // Appends to output `option`'s temporary file (its content is what the calls wrote, in
  // order). Throws OutputError (disk full, file-size limit, I/O error).
  void write(const std::string& option, std::string_view content);
  // A path that another writer (SimGrid) opens to write output `option`'s content, which is
  // then committed like the others; "" if `option` is not wanted.
  std::string writer_path(const std::string& option);
  // Writes the streams, then gives every file output that was written a name beside its
  // target and renames these onto the targets (the others vanish). Throws OutputError if a
  // write, a link or a rename fails.
  void commit();
  // Every output written (after commit: in place), in the order they were asked for.
  std::vector<Output> written() const;

 private:
  enum class Kind { kFile, kStream, kStandardOutput };
  struct Pending {
    std::string option, path;
    Kind kind = Kind::kFile;
    std::string target;  // the path written: `path` with its links followed
    std::unique_ptr<TemporaryFile> temporary;
    bool written = false;
  };

  void open(const std::vector<Output>& outputs, const std::vector<std::string>& inputs);
  void open_file(Pending& pending, const std::string& where);
  void stream(const Pending& pending) const;
  Pending* find(const std::string& option);

  std::vector<Pending> pending_;
};

}  // namespace ncube

// A temporary file that has no name until it is kept, so that no exit of the process (a crash
// inside SimGrid, SIGKILL, SIGINT, exit(), an exception) can leave one
// behind (docs/cli.md, "Output files"):
//  - in a folder: opened with O_TMPFILE (an inode with no name), and given a name only by
//    keep_as(), which links it under a fresh random name and renames that onto the target
//    with every catchable signal blocked;
//  - where the file system has no O_TMPFILE (NFS, some FUSE file systems): a named file
//    `<stem>.partial-XXXXXX` created exclusively (O_EXCL: never through a planted link), and
//    removed by the destructor, by exit() and by a handler of every fatal signal (which then
//    ends the process by the same signal);
//  - anywhere(): the temporary folder's file, unlinked at once (for what is streamed to a
//    device or a pipe at the end).
// Writers that open a path themselves (SimGrid's log appenders and trace) get writer_path():
// /proc/self/fd/N, which opens the same inode, or the file's name.
#pragma once

#include <string>
#include <string_view>

namespace ncube {

class TemporaryFile {
 public:
  // A temporary file in `folder` (for a target named `stem` there); throws std::system_error
  // if it cannot be created. `anonymous` false forces the named form (for tests).
  static TemporaryFile in_folder(const std::string& folder, const std::string& stem,
                                 bool anonymous = true);
  // A temporary file that never has a name (its content is copied out by copy_to).
  static TemporaryFile anywhere();

  TemporaryFile(TemporaryFile&& other) noexcept;
  TemporaryFile& operator=(TemporaryFile&& other) noexcept;
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile();  // closes it and removes its name, if it has one and was not kept

  // Appends; false (errno set) on an error (disk full, file-size limit, I/O error).
  bool append(std::string_view bytes);
  // A path another writer can open (fopen "w") to write this file's content.
  std::string writer_path() const;
  // Whether it has a name now (the named form), for tests.
  bool named() const { return !name_.empty(); }
  // Gives an anonymous file a fresh random name beside `target` (registered for removal
  // like the named form's), the first half of keep_as; false (errno set) if it cannot.
  bool name_beside(const std::string& target);
  // Makes the content the file `target` (in the folder the file was made in), replacing it
  // atomically; false (errno set) if it cannot.
  bool keep_as(const std::string& target);
  // Writes the whole content to `descriptor` (a device, a pipe); false (errno set) on error.
  bool copy_to(int descriptor) const;

 private:
  TemporaryFile() = default;
  void release();

  int descriptor_ = -1;
  std::string folder_;
  std::string name_;  // the named form's path, until kept or removed
};

}  // namespace ncube

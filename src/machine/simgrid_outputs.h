// The files SimGrid writes at the user's request, under the one output rule (docs/cli.md,
// "Output files"): a log appender's file (--log=CATEGORY.app:file:PATH, rollfile:SIZE:PATH)
// and the Paje trace (--cfg=tracing:yes writes tracing/filename, simgrid.trace by default).
// SimGrid never sees these paths: the arguments it gets name the outputs' temporary files
// (tools/output_files.h, writer_path), committed with the run's other outputs, and the settings check's
// child process writes to /dev/null. Parsed as SimGrid 3.32 parses them: a --log control is
// split at spaces with \ escapes and " or ' quotes (boost::escaped_list_separator), each
// setting CATEGORY.OPTION:VALUE with any prefix of "appender" naming the appender; a --cfg is
// split at spaces, tabs, newlines and commas into NAME:VALUE settings.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace ncube {

struct SimgridOutput {
  std::string setting;  // what asks for it, for messages: "--log=root.app:file:run.log"
  std::string path;
};

class SimgridOutputs {
 public:
  // Throws InputError naming the argument for what cannot be put under the rule: a
  // splitfile appender (an unknown number of files), the TI trace format (a folder of files
  // per actor), an appender or trace file with an empty name, a log control SimGrid would
  // half apply (a bad \ escape).
  explicit SimgridOutputs(const std::vector<std::string>& arguments);

  // The outputs, each named by the setting that asks for it ("--log=root.app:file:run.log",
  // "--cfg=tracing/filename", "--cfg=tracing" for the default simgrid.trace).
  const std::vector<SimgridOutput>& outputs() const { return outputs_; }
  // Files SimGrid reads for these settings (tracing/comment-file): never an output.
  const std::vector<std::string>& inputs() const { return inputs_; }
  // The arguments for SimGrid's Engine: each output's path replaced by path_of(its setting)
  // (the output's temporary file), and always a tracing/filename: the trace's temporary file,
  // or /dev/null when these settings write no trace (a SimGrid platform file's <config> tags
  // cannot override it, so a platform turning tracing on writes nowhere).
  std::vector<std::string> engine_arguments(
      const std::function<std::string(const std::string& setting)>& path_of) const;

 private:
  std::vector<std::string> arguments_;
  std::vector<SimgridOutput> outputs_;
  std::vector<std::string> inputs_;
};

// `argument` as the settings check's child process gets it: every file it would make SimGrid
// write is /dev/null (the check must not truncate the scene it names).
std::string simgrid_argument_for_check(const std::string& argument);

}  // namespace ncube

// The files SimGrid writes at the user's request, found as SimGrid 3.32 parses its settings.
#include "machine/simgrid_outputs.h"

#include <gtest/gtest.h>

#include "util/input_error.h"

namespace ncube {
namespace {

// "setting -> path" for each output, for short comparisons.
std::vector<std::string> outputs_of(const std::vector<std::string>& arguments) {
  std::vector<std::string> found;
  const SimgridOutputs outputs(arguments);
  for (const SimgridOutput& o : outputs.outputs()) found.push_back(o.setting + " -> " + o.path);
  return found;
}

using Outputs = std::vector<std::string>;

TEST(SimgridOutputs, FindsEveryLogFile) {
  EXPECT_EQ(outputs_of({"--log=root.app:file:run.log"}), Outputs{"--log=root.app:file:run.log -> run.log"});
  // Any abbreviation of "appender" (SimGrid compares with strncmp), '=' or ':' before the value.
  EXPECT_EQ(outputs_of({"--log=root.appe=file:a.log"}), Outputs{"--log=root.appe=file:a.log -> a.log"});
  EXPECT_EQ(outputs_of({"--log=x.ap:rollfile:100:dir/b:c.log"}),
            Outputs{"--log=x.ap:rollfile:100:dir/b:c.log -> dir/b:c.log"});
  // Several settings in one control, split at spaces; quotes keep a space in a name.
  EXPECT_EQ(outputs_of({"--log=root.thresh:debug \"root.app:file:my run.log\" s4u.app:file:'b.log'"}),
            (Outputs{"--log=root.app:file:my run.log -> my run.log", "--log=s4u.app:file:b.log -> b.log"}));
  EXPECT_EQ(outputs_of({"--log=root.app:file:a\\\"b"}), Outputs{"--log=root.app:file:a\"b -> a\"b"});
}

TEST(SimgridOutputs, IgnoresWhatWritesNoFile) {
  EXPECT_TRUE(outputs_of({"--log=root.thresh:debug", "--log=root.app:stdout", "--log=no_loc",
                          "--log=root.a:file:x",  // "a" abbreviates additivity first
                          "--log=root.fmt:file:x", "--cfg=tracing/filename:t.trace",
                          "--cfg=tracing:no", "--cfg=network/model:CM02"})
                  .empty());
}

TEST(SimgridOutputs, FindsTheTrace) {
  EXPECT_EQ(outputs_of({"--cfg=tracing:yes"}), Outputs{"--cfg=tracing:yes -> simgrid.trace"});
  EXPECT_EQ(outputs_of({"--cfg=tracing/filename:t.trace", "--cfg=tracing:1"}),
            Outputs{"--cfg=tracing/filename:t.trace -> t.trace"});
  // One --cfg holds several settings, split at spaces, tabs, newlines and commas.
  EXPECT_EQ(outputs_of({"--cfg=tracing:on,tracing/filename:u.trace"}),
            Outputs{"--cfg=tracing/filename:u.trace -> u.trace"});
  EXPECT_EQ(SimgridOutputs({"--cfg=tracing/comment-file:notes.txt"}).inputs(),
            std::vector<std::string>{"notes.txt"});
}

TEST(SimgridOutputs, RefusesWhatCannotFollowTheRule) {
  for (const char* argument :
       {"--log=root.app:splitfile:100:x%", "--log=root.app:file:", "--log=root.app:file:a\\q",
        "--cfg=tracing/filename:", })
    EXPECT_THROW(SimgridOutputs({argument}), InputError) << argument;
  EXPECT_THROW(SimgridOutputs({"--cfg=tracing:yes", "--cfg=tracing/smpi/format:TI"}), InputError);
  EXPECT_NO_THROW(SimgridOutputs({"--cfg=tracing/smpi/format:TI"}));  // no trace: no file
}

TEST(SimgridOutputs, GivesSimGridTheTemporaryFiles) {
  const SimgridOutputs outputs({"--log=root.thresh:debug \"root.app:file:my run.log\"",
                                "--cfg=network/model:CM02,tracing/filename:t.trace", "--cfg=tracing:yes",
                                "--log=no_loc"});
  const auto temporary = [](const std::string& setting) {
    return setting.rfind("--log", 0) == 0 ? "/proc/self/fd/7" : "/proc/self/fd/8";
  };
  EXPECT_EQ(outputs.engine_arguments(temporary),
            (std::vector<std::string>{"--log=\"root.thresh:debug\" \"root.app:file:/proc/self/fd/7\"",
                                      "--cfg=network/model:CM02", "--cfg=tracing:yes", "--log=no_loc",
                                      "--cfg=tracing/filename:/proc/self/fd/8"}));
}

TEST(SimgridOutputs, NoTraceAskedForGoesNowhere) {
  EXPECT_EQ(SimgridOutputs({"--cfg=tracing/filename:t.trace"}).engine_arguments([](const std::string&) {
    return "/proc/self/fd/9";
  }),
            std::vector<std::string>{"--cfg=tracing/filename:/dev/null"});
}

TEST(SimgridOutputs, TheSettingsCheckWritesNothing) {
  EXPECT_EQ(simgrid_argument_for_check("--log=root.app:file:scene.json"), "--log=\"root.app:file:/dev/null\"");
  EXPECT_EQ(simgrid_argument_for_check("--log=root.app:rollfile:10:scene.json"),
            "--log=\"root.app:rollfile:10:/dev/null\"");
  EXPECT_EQ(simgrid_argument_for_check("--cfg=tracing/filename:scene.json"), "--cfg=tracing/filename:/dev/null");
  EXPECT_EQ(simgrid_argument_for_check("--log=root.thresh:debug"), "--log=root.thresh:debug");
  EXPECT_THROW(simgrid_argument_for_check("--log=root.app:file:scene.json x\\q"), InputError);
}

}  // namespace
}  // namespace ncube

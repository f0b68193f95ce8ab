#include "machine/simgrid_settings.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Host.hpp>
#include <simgrid/s4u/NetZone.hpp>
#include <xbt/log.h>

#include "machine/simgrid_outputs.h"
#include "machine/simgrid_setting_ranges.h"
#include "util/input_error.h"

namespace ncube {
namespace {

// The form SimGrid needs before it is asked: NAME:VALUE with both parts, a non-empty control.
std::string syntax_problem(const std::string& argument) {
  const std::string cfg = "--cfg=", log = "--log=";
  if (argument.rfind(cfg, 0) == 0) {
    const std::string setting = argument.substr(cfg.size());
    const std::size_t colon = setting.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == setting.size())
      return "a SimGrid setting is NAME:VALUE, e.g. --cfg=network/model:CM02";
    return "";
  }
  if (argument.rfind(log, 0) == 0)
    return argument.size() == log.size() ? "an empty log setting" : "";
  return "not a SimGrid setting (--cfg=NAME:VALUE or --log=CONTROL)";
}

// A --cfg value SimGrid would take but that ends or hangs the run (the table of
// src/machine/simgrid_setting_ranges.h); "" for --log and for names SimGrid does not know
// (SimGrid refuses those itself).
std::string range_problem(const std::string& argument) {
  const std::string cfg = "--cfg=";
  if (argument.rfind(cfg, 0) != 0) return "";
  const std::string setting = argument.substr(cfg.size());
  const std::size_t colon = setting.find(':');
  const SimgridSettingRange* range = simgrid_setting_range(setting.substr(0, colon));
  return range ? setting_range_problem(*range, setting.substr(colon + 1)) : "";
}

// A --cfg setting SimGrid takes without being asked: its row lists the value as a choice (each
// choice runs a simulation in tests/simgrid_setting_ranges_test.cpp), or its row is a boolean
// and the value one of the spellings SimGrid reads (tests/simgrid_settings_test.cpp asks SimGrid
// each). A platform's usual settings (a model, a solver, crosstraffic on or off) then need no
// child at all.
bool taken_without_asking(const std::string& argument) {
  const std::string cfg = "--cfg=";
  if (argument.rfind(cfg, 0) != 0) return false;
  const std::string setting = argument.substr(cfg.size());
  const std::size_t colon = setting.find(':');
  if (colon == std::string::npos) return false;
  const SimgridSettingRange* range = simgrid_setting_range(setting.substr(0, colon));
  if (!range) return false;
  const std::string value = setting.substr(colon + 1);
  if (range->kind == SettingKind::kBoolean) {
    for (const char* spelling : kSimgridBooleanSpellings)
      if (value == spelling) return true;
    return false;
  }
  return range->kind == SettingKind::kChoice && setting_range_problem(*range, value).empty();
}

// In the child: SimGrid with these settings, up to the network model's creation, which is
// when a model name is checked. Never returns.
[[noreturn]] void try_in_child(const std::vector<std::string>& arguments, int error_pipe) {
  dup2(error_pipe, STDERR_FILENO);
  dup2(error_pipe, STDOUT_FILENO);  // --cfg=help and the like print their text here
  // tracing:yes opens its trace (simgrid.trace unless named) when the platform starts: the
  // check writes nothing, so the child's goes to /dev/null. A tracing/filename being checked
  // comes after and wins, but every file an argument names (a log appender's, the trace's) is
  // /dev/null too.
  std::vector<std::string> storage{"simulate", "--cfg=tracing/filename:/dev/null"};
  try {
    for (const std::string& argument : arguments)
      storage.push_back(simgrid_argument_for_check(argument));  // never the user's files
    std::vector<char*> argv;
    for (std::string& argument : storage) argv.push_back(argument.data());
    argv.push_back(nullptr);
    int argc = int(storage.size());
    xbt_log_control_set("root.thresh:critical");
    simgrid::s4u::Engine engine(&argc, argv.data());
    auto* zone = simgrid::s4u::create_full_zone("check");
    zone->create_host("check", 1e6);
    zone->seal();
    _exit(argc == 1 ? 0 : 4);  // SimGrid consumes the arguments it understood
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    std::fflush(stderr);
    _exit(3);
  }
}

// The one line to show of what SimGrid said: its CRITICAL message, or the exception's first line.
std::string first_message_line(const std::string& said) {
  std::size_t start = said.find("CRITICAL] ");
  start = start == std::string::npos ? 0 : start + 10;
  const std::size_t end = said.find('\n', start);
  return said.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// What SimGrid says of these settings together: "" when it takes them all.
std::string simgrid_refusal(const std::vector<std::string>& arguments) {
  if (arguments.empty()) return "";
  // A process has one Engine: once it exists (a test that ran a simulation, a platform file
  // read through SimGrid), a child cannot make its own, and the settings are SimGrid's already.
  if (simgrid::s4u::Engine::is_initialized()) return "";
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return "";  // cannot check: the run itself will tell
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child < 0) {
    close(pipe_ends[0]);
    close(pipe_ends[1]);
    return "";
  }
  if (child == 0) {
    close(pipe_ends[0]);
    try_in_child(arguments, pipe_ends[1]);
  }
  close(pipe_ends[1]);
  std::string said;
  char buffer[4096];
  for (ssize_t n; (n = read(pipe_ends[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0) break;
    if (said.size() < 65536) said.append(buffer, std::size_t(n));
  }
  close(pipe_ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  if (WIFEXITED(status) && WEXITSTATUS(status) == 4)
    return arguments.size() == 1 ? "SimGrid does not take this argument"
                                 : "SimGrid does not take one of these arguments";
  const std::string line = first_message_line(said);
  if (line.rfind("Bad config key", 0) == 0)
    return line + " (SimGrid's settings: https://simgrid.org/doc/3.32/Configuring_SimGrid.html)";
  return line.empty() ? "SimGrid refuses it" : line;
}

}  // namespace

std::string simgrid_setting_form_problem(const std::string& argument) {
  if (std::string problem = syntax_problem(argument); !problem.empty()) return problem;
  return range_problem(argument);
}

std::string simgrid_setting_problem(const std::string& argument) {
  if (std::string problem = simgrid_setting_form_problem(argument); !problem.empty()) return problem;
  return simgrid_refusal({argument});
}

SettingRefusal simgrid_refusal_of(const std::vector<std::string>& arguments) {
  // One child for them all: a run's settings are nearly always taken, and each child is an
  // Engine's start (about 20 ms of CPU with its fork). Only when SimGrid refuses them is each
  // asked alone, so that the message names the one it refuses, as it would alone.
  bool all_known = true;
  for (const std::string& argument : arguments) all_known &= taken_without_asking(argument);
  if (all_known) return {arguments.size(), ""};
  const std::string together = simgrid_refusal(arguments);
  if (together.empty()) return {arguments.size(), ""};
  for (std::size_t i = 0; i < arguments.size(); ++i)
    if (std::string alone = simgrid_refusal({arguments[i]}); !alone.empty()) return {i, alone};
  // Each taken alone, not together: the first whose addition SimGrid refuses.
  for (std::size_t i = 1; i < arguments.size(); ++i)
    if (std::string problem = simgrid_refusal({arguments.begin(), arguments.begin() + long(i) + 1});
        !problem.empty())
      return {i, problem + " (with the settings before it)"};
  return {arguments.size() - 1, together + " (with the settings before it)"};
}

void check_simgrid_settings(const std::vector<std::string>& arguments) {
  // The checks in this process first, in order; SimGrid is asked about the arguments before
  // the first they refuse, so the first argument refused is the one named, as one by one.
  std::size_t first_bad_form = 0;
  std::string form_problem;
  for (; first_bad_form < arguments.size(); ++first_bad_form)
    if (!(form_problem = simgrid_setting_form_problem(arguments[first_bad_form])).empty()) break;
  const SettingRefusal refused =
      simgrid_refusal_of({arguments.begin(), arguments.begin() + long(first_bad_form)});
  if (refused.index < first_bad_form)
    throw InputError(arguments[refused.index] + ": " + refused.problem);
  if (first_bad_form < arguments.size())
    throw InputError(arguments[first_bad_form] + ": " + form_problem);
}

}  // namespace ncube

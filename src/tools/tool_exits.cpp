#include "tools/tool_exits.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <iostream>
#include <set>
#include <new>
#include <stdexcept>

#include "tools/suggestions.h"
#include "util/input_error.h"
#include "util/shown_text.h"

namespace ncube {

int run_tool(const char* tool, const std::function<int()>& run, OtherRuntimeErrors other) {
  const std::string prefix = std::string(tool) + ": ";
  // Messages echo what the user gave (file names, values): shown_text escapes and cuts them.
  const auto shown = [](const char* message) { return shown_text(message); };
  try {
    return run();
  } catch (const InputError& e) {
    std::cerr << prefix << shown(e.what()) << "\n";
    return kExitBadInput;
  } catch (const OutputError& e) {
    std::cerr << prefix << shown(e.what()) << " (no output file was written)\n";
    return kExitCannotWrite;
  } catch (const HostMemoryError& e) {
    std::cerr << prefix << shown(e.what()) << " (no output file was written)\n";
    return kExitHostOutOfMemory;
  } catch (const std::bad_alloc&) {
    std::cerr << prefix << "the host ran out of memory (no output file was written)\n";
    return kExitHostOutOfMemory;
  } catch (const std::runtime_error& e) {
    if (other == OtherRuntimeErrors::kSimulationFailed) {
      std::cerr << prefix << "the simulation failed: " << shown(e.what()) << "\n";
      return kExitSimulationFailed;
    }
    std::cerr << prefix << "internal error: " << shown(e.what()) << "\n";
    return kExitInternalError;
  } catch (const std::exception& e) {
    std::cerr << prefix << "internal error: " << shown(e.what()) << "\n";
    return kExitInternalError;
  } catch (...) {
    std::cerr << prefix << "internal error: an unknown exception\n";
    return kExitInternalError;
  }
}

namespace {

// Every long and short name of the app's options, with their dashes (--iterations, -h).
std::vector<std::string> option_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* option : app.get_options()) {
    for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    for (const std::string& name : option->get_snames()) names.push_back("-" + name);
  }
  return names;
}

// A dash and a letter: an option's name, not a negative number.
bool looks_like_option(const std::string& argument) {
  const std::size_t letter = argument.find_first_not_of('-');
  return letter != 0 && letter != std::string::npos &&
         std::isalpha(static_cast<unsigned char>(argument[letter]));
}

// The arguments the parser did not take, in the command line's order (CLI11 lists them
// backwards: "5 --iteration").
std::vector<std::string> left_over(const CLI::App& app, int argc, char** argv) {
  const std::vector<std::string> remaining = app.remaining();
  const std::set<std::string> extras(remaining.begin(), remaining.end());
  std::vector<std::string> left;
  for (int i = 1; i < argc; ++i)
    if (extras.count(argv[i]) > 0) left.push_back(argv[i]);
  if (left.empty()) left.assign(remaining.rbegin(), remaining.rend());
  return left;
}

// Arguments the parser did not take: the first that looks like an option is named with the
// options nearest to it; else the first.
std::string unexpected_arguments(const CLI::App& app, const std::vector<std::string>& left) {
  for (const std::string& argument : left) {
    if (!looks_like_option(argument)) continue;
    const std::string option = argument.substr(0, argument.find('='));
    const std::string suggestion = did_you_mean(option, option_names(app));
    return "unknown option " + shown_text(option) + (suggestion.empty() ? "" : "; " + suggestion);
  }
  if (left.empty()) return "an argument was not expected";
  return "unexpected argument " + shown_text(left.front()) +
         (left.size() > 1 ? " (and " + std::to_string(left.size() - 1) + " more)" : "");
}

}  // namespace

std::optional<int> parse_command_line(CLI::App& app, const char* tool, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kExitOk;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return kExitOk;
  } catch (const CLI::ExtrasError&) {
    std::cerr << tool << ": " << unexpected_arguments(app, left_over(app, argc, argv)) << " (see "
              << tool << " --help)\n";
    return kExitBadInput;
  } catch (const CLI::RequiredError& e) {
    // CLI11 checks what is required before what is unknown: "--platfrom cm5" would be
    // answered "--platform is required"; the mistyped option is the message.
    const std::vector<std::string> left = left_over(app, argc, argv);
    const bool mistyped = std::any_of(left.begin(), left.end(), [](const std::string& argument) {
      return looks_like_option(argument);
    });
    std::cerr << tool << ": " << (mistyped ? unexpected_arguments(app, left) : shown_text(e.what()))
              << " (see " << tool << " --help)\n";
    return kExitBadInput;
  } catch (const CLI::ParseError& e) {
    std::cerr << tool << ": " << shown_text(e.what()) << " (see " << tool << " --help)\n";
    return kExitBadInput;
  }
  return std::nullopt;
}

}  // namespace ncube

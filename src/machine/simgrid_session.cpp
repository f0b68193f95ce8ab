#include "machine/simgrid_session.h"

#include <csignal>
#include <memory>
#include <xbt/config.hpp>
#include <xbt/log.h>

namespace ncube {

simgrid::s4u::Engine& simgrid_engine(const std::vector<std::string>& arguments) {
  static simgrid::s4u::Engine* engine = nullptr;  // lives until the process ends
  if (!engine) {
    xbt_log_control_set("root.thresh:warning");
    static std::vector<std::string> storage;  // SimGrid keeps pointers into argv
    storage = {"simulate"};
    storage.insert(storage.end(), arguments.begin(), arguments.end());
    static std::vector<char*> argv;
    for (std::string& argument : storage) argv.push_back(argument.data());
    argv.push_back(nullptr);
    int argc = int(storage.size());
    // SimGrid's Engine sets a SIGINT handler that calls exit(1): exit() inside a signal
    // handler runs the static destructors and atexit handlers wherever the signal landed, and
    // deadlocked there when it landed inside malloc (the allocator's lock held, a destructor
    // waiting for it: Ctrl-C hung the run). What SIGINT did before is given back (the default,
    // or the temporary files' handler, src/tools/temporary_file.h, which removes their names
    // and ends the process by the signal), so Ctrl-C ends the process as SIGINT does. Ignored
    // before (a command a script started in the background) becomes the default: SimGrid's
    // handler ended such runs too, and whoever stops a sweep's runs relies on it.
    struct sigaction interrupt_before {};
    const bool saved = sigaction(SIGINT, nullptr, &interrupt_before) == 0;
    engine = new simgrid::s4u::Engine(&argc, argv.data());
    if (saved) {
      if (!(interrupt_before.sa_flags & SA_SIGINFO) && interrupt_before.sa_handler == SIG_IGN)
        interrupt_before.sa_handler = SIG_DFL;
      sigaction(SIGINT, &interrupt_before, nullptr);
    }
  }
  return *engine;
}

void apply_simgrid_defaults(const std::map<std::string, std::string>& settings) {
  for (const auto& [name, value] : settings)
    if (simgrid::config::is_default(name.c_str())) simgrid::config::set_as_string(name.c_str(), value);
}

std::map<std::string, std::string> simgrid_settings_used(const std::vector<std::string>& arguments) {
  namespace config = simgrid::config;
  std::map<std::string, std::string> used = {
      {"network/model", config::get_value<std::string>("network/model")},
      {"network/solver", config::get_value<std::string>("network/solver")},
      {"network/crosstraffic", config::get_value<bool>("network/crosstraffic") ? "1" : "0"}};
  const std::string prefix = "--cfg=";
  for (const std::string& argument : arguments) {
    if (argument.rfind(prefix, 0) != 0) continue;
    const std::string setting = argument.substr(prefix.size());
    const std::size_t colon = setting.find(':');
    if (colon == std::string::npos) continue;
    const std::string name = setting.substr(0, colon);
    if (!used.count(name)) used[name] = setting.substr(colon + 1);
  }
  return used;
}

}  // namespace ncube

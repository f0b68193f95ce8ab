#include "machine/simgrid_outputs.h"

#include "util/input_error.h"

namespace ncube {
namespace {

const std::string kCfg = "--cfg=", kLog = "--log=";

// Whether `option` abbreviates `word` as SimGrid's strncmp(option, word, length) takes it.
bool abbreviates(const std::string& option, const std::string& word) {
  return option.size() <= word.size() && word.compare(0, option.size(), option) == 0;
}

// A --log control split as boost::escaped_list_separator<char>("\\", " ", "\"'") splits it.
// Throws InputError on an escape SimGrid's tokenizer refuses (after applying what precedes).
std::vector<std::string> log_settings(const std::string& argument) {
  const std::string control = argument.substr(kLog.size());
  std::vector<std::string> settings(1);
  bool quoted = false;
  for (std::size_t i = 0; i < control.size(); ++i) {
    const char c = control[i];
    if (c == '\\') {
      const char next = i + 1 < control.size() ? control[++i] : '\0';
      if (next != 'n' && next != '\\' && next != '"' && next != '\'')
        throw InputError(argument + ": a \\ in a log setting comes before n, \\, \" or ' only");
      settings.back() += next == 'n' ? '\n' : next;
    } else if (c == ' ' && !quoted) {
      settings.emplace_back();
    } else if (c == '"' || c == '\'') {
      quoted = !quoted;
    } else {
      settings.back() += c;
    }
  }
  return settings;
}

// A setting quoted so that the tokenizer gives it back unchanged.
std::string quoted(const std::string& setting) {
  std::string text = "\"";
  for (char c : setting) {
    if (c == '\n') text += "\\n";
    else if (c == '\\' || c == '"' || c == '\'') text += std::string("\\") + c;
    else text += c;
  }
  return text + "\"";
}

// Where the file name starts in a log setting CATEGORY.OPTION:VALUE whose appender writes a
// file (std::string::npos if it writes none). Throws InputError for a splitfile appender.
std::size_t log_file_start(const std::string& argument, const std::string& setting) {
  const std::size_t name_end = setting.find_first_of(".:= ");
  if (name_end == std::string::npos || setting[name_end] != '.') return std::string::npos;
  const std::size_t value = setting.find_first_of(":= ", name_end + 1);
  if (value == std::string::npos || setting[value] == ' ') return std::string::npos;
  const std::string option = setting.substr(name_end + 1, value - name_end - 1);
  if (abbreviates(option, "threshold") || abbreviates(option, "additivity") ||
      !abbreviates(option, "appender"))
    return std::string::npos;
  const std::string appender = setting.substr(value + 1);
  if (appender.rfind("file:", 0) == 0) return value + 1 + 5;
  if (appender.rfind("splitfile:", 0) == 0)
    throw InputError(argument + ": a splitfile appender writes files whose number is known "
                     "only at the end; use file:PATH or rollfile:SIZE:PATH");
  if (appender.rfind("rollfile:", 0) == 0) {
    const std::size_t colon = appender.find(':', 9);
    if (colon != std::string::npos) return value + 1 + colon + 1;
  }
  return std::string::npos;
}

// The NAME:VALUE settings of a --cfg argument, as SimGrid's config::set_parse splits them.
std::vector<std::string> cfg_settings(const std::string& argument) {
  std::vector<std::string> settings;
  const std::string text = argument.substr(kCfg.size());
  const char* separators = " \t\n,";
  for (std::size_t start = text.find_first_not_of(separators); start != std::string::npos;) {
    const std::size_t end = text.find_first_of(separators, start);
    settings.push_back(text.substr(start, end == std::string::npos ? end : end - start));
    start = end == std::string::npos ? end : text.find_first_not_of(separators, end);
  }
  return settings;
}

std::string name_of(const std::string& setting) { return setting.substr(0, setting.find(':')); }
std::string value_of(const std::string& setting) {
  const std::size_t colon = setting.find(':');
  return colon == std::string::npos ? "" : setting.substr(colon + 1);
}

// `argument` (a --log) with each file its appenders write replaced by file_of(setting, path).
// The control is written back quoted only when something was replaced ("no_loc" is a
// control of its own that quoting would break).
std::string replace_log_files(
    const std::string& argument,
    const std::function<std::string(const std::string& setting, const std::string& path)>& file_of) {
  std::vector<std::string> settings = log_settings(argument);
  bool replaced = false;
  for (std::string& setting : settings) {
    const std::size_t start = log_file_start(argument, setting);
    if (start == std::string::npos) continue;
    setting = setting.substr(0, start) + file_of(setting, setting.substr(start));
    replaced = true;
  }
  if (!replaced) return argument;
  std::string control;
  for (const std::string& setting : settings) control += (control.empty() ? "" : " ") + quoted(setting);
  return kLog + control;
}

}  // namespace

SimgridOutputs::SimgridOutputs(const std::vector<std::string>& arguments) : arguments_(arguments) {
  bool tracing = false, ti_format = false;
  std::string trace_setting, trace_file = "simgrid.trace";
  for (const std::string& argument : arguments) {
    if (argument.rfind(kLog, 0) == 0) {
      replace_log_files(argument, [&](const std::string& setting, const std::string& path) {
        if (path.empty()) throw InputError(argument + ": a log file with no name");
        outputs_.push_back({kLog + setting, path});
        return path;
      });
      continue;
    }
    if (argument.rfind(kCfg, 0) != 0) continue;
    for (const std::string& setting : cfg_settings(argument)) {
      const std::string name = name_of(setting), value = value_of(setting);
      if (name == "tracing") {
        tracing = value == "yes" || value == "on" || value == "true" || value == "1";
        if (trace_setting.empty() || trace_setting.rfind(kCfg + "tracing:", 0) == 0)
          trace_setting = kCfg + setting;
      } else if (name == "tracing/filename") {
        if (value.empty()) throw InputError(argument + ": a trace file with no name");
        trace_file = value;
        trace_setting = kCfg + setting;
      } else if (name == "tracing/smpi/format") {
        ti_format = value != "Paje";
      } else if (name == "tracing/comment-file" && !value.empty()) {
        inputs_.push_back(value);
      }
    }
  }
  if (!tracing) return;
  if (ti_format)
    throw InputError("--cfg=tracing/smpi/format: the TI format writes a folder of files per "
                     "actor; only the Paje format (the default) is supported");
  outputs_.push_back({trace_setting, trace_file});
}

std::vector<std::string> SimgridOutputs::engine_arguments(
    const std::function<std::string(const std::string& setting)>& path_of) const {
  std::vector<std::string> engine;
  for (const std::string& argument : arguments_) {
    if (argument.rfind(kLog, 0) == 0) {
      engine.push_back(replace_log_files(
          argument, [&](const std::string& setting, const std::string&) { return path_of(kLog + setting); }));
      continue;
    }
    if (argument.rfind(kCfg, 0) != 0) {
      engine.push_back(argument);
      continue;
    }
    // The user's trace file goes; the trace's temporary file is set last, on its own.
    std::string kept;
    for (const std::string& setting : cfg_settings(argument))
      if (name_of(setting) != "tracing/filename") kept += (kept.empty() ? "" : ",") + setting;
    if (!kept.empty()) engine.push_back(kCfg + kept);
  }
  std::string trace = "/dev/null";  // a trace nobody asked for here (a platform's <config>)
  for (const SimgridOutput& output : outputs_)
    if (output.setting.rfind(kCfg, 0) == 0) trace = path_of(output.setting);
  engine.push_back(kCfg + "tracing/filename:" + trace);
  return engine;
}

std::string simgrid_argument_for_check(const std::string& argument) {
  if (argument.rfind(kLog, 0) == 0)  // throws where SimGrid would half apply it
    return replace_log_files(argument, [](const std::string&, const std::string&) { return "/dev/null"; });
  if (argument.rfind(kCfg, 0) != 0) return argument;
  std::string checked;
  for (const std::string& setting : cfg_settings(argument))
    checked += (checked.empty() ? "" : ",") +
               (name_of(setting) == "tracing/filename" ? "tracing/filename:/dev/null" : setting);
  return checked.empty() ? argument : kCfg + checked;
}

}  // namespace ncube

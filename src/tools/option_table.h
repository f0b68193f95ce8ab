// The command-line options of a tool, each registered once: the registration sets up CLI11's
// parser and keeps the option's description (kind, default, range, choices, the result-file
// field it is recorded in), so `simulate --describe-options`, the sweep tool's validation
// (analysis/ncube/options.py) and docs/cli.md's table all read what the parser enforces.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace ncube {

// A closed or half-open interval of allowed values.
struct ValueRange {
  double low, high;
  bool low_included = true, high_included = true;
};

// A count in decimal within [low, high], the rule of OptionTable::integer for a tool whose
// options are not in a table (CLI11 alone reads "0x10" as 16 and "010" as 8).
CLI::Validator decimal_count(long low, long high);

class OptionTable {
 public:
  explicit OptionTable(CLI::App& app) : app_(app) {}

  // `field`: the member of the result file's "config" object that records the option
  // (empty: not recorded, e.g. an output file). The default shown is the variable's value
  // at registration.
  CLI::Option* integer(const std::string& flag, int& value, long low, long high,
                       const std::string& help, const std::string& field);
  // An integer that must also be a perfect square (--samples).
  CLI::Option* square(const std::string& flag, int& value, long low, long high,
                      const std::string& help, const std::string& field);
  // An integer that must also be even (--hemicube-resolution).
  CLI::Option* even(const std::string& flag, int& value, long low, long high,
                    const std::string& help, const std::string& field);
  // Every floating-point option: a finite decimal number in `range`. NaN and the
  // infinities are refused for all of them by this one rule; -0 reads as 0.
  CLI::Option* number(const std::string& flag, double& value, ValueRange range,
                      const std::string& help, const std::string& field);
  CLI::Option* choice(const std::string& flag, std::string& value,
                      const std::vector<std::string>& values, const std::string& help,
                      const std::string& field);
  CLI::Option* flag(const std::string& flag, bool& value, const std::string& help,
                    const std::string& field);
  // A file name: an input ("file") or an output ("output"); never empty. `shown_default`:
  // the default as the description shows it (a path relative to the repository, not this
  // machine's absolute one).
  CLI::Option* file(const std::string& flag, std::string& value, const std::string& kind,
                    const std::string& help, const std::string& shown_default = "");
  // A repeatable text setting passed on (SimGrid's --cfg and --log).
  CLI::Option* setting(const std::string& flag, std::vector<std::string>& values,
                       const std::string& type_name, const std::string& help);
  // A text value of a form of its own (--trace-iterations A:B): `check` returns "" when the
  // text is well formed, else why not (the parser's message). Not recorded in the result file.
  CLI::Option* text(const std::string& flag, std::string& value, const std::string& value_name,
                    std::function<std::string(const std::string&)> check, const std::string& help);
  // A positional argument.
  CLI::Option* positional(const std::string& name, std::string& value, const std::string& help);

  // Adds `key: value` to the description of `flag` (e.g. "applies_to": "model files").
  void annotate(const std::string& flag, const std::string& key, const nlohmann::json& value);

  // Every option registered, in order, as JSON (docs/cli.md, "Describing the options").
  nlohmann::json describe() const;

 private:
  nlohmann::json& entry(const std::string& flag, const std::string& kind,
                        const std::string& help, const std::string& field);

  CLI::App& app_;
  nlohmann::json entries_ = nlohmann::json::array();
};

}  // namespace ncube

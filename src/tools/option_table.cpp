#include "tools/option_table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "tools/suggestions.h"
#include "util/shown_text.h"

namespace ncube {

namespace {

std::string show(double value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// "from 0 to 1", "above 0 and at most 1": the words of a range in an error message.
std::string range_words(const ValueRange& range) {
  const std::string low = (range.low_included ? "from " : "above ") + show(range.low);
  const std::string high = (range.high_included ? " to " : " and below ") + show(range.high);
  return low + high;
}

bool in_range(double value, const ValueRange& range) {
  const bool above = range.low_included ? value >= range.low : value > range.low;
  const bool below = range.high_included ? value <= range.high : value < range.high;
  return above && below;
}

// Counts are written in decimal: CLI11 would read "010" as 8 (octal) and accept "0x10";
// both are almost surely typos in a command line of this program.
CLI::Validator decimal_integer(ValueRange range, bool square, bool even = false) {
  return CLI::Validator(
      [range, square, even](std::string& text) -> std::string {
        static const std::regex decimal("-?(0|[1-9][0-9]{0,9})");
        if (!std::regex_match(text, decimal))
          return "'" + text + "' is not a decimal integer (digits without leading zeros or "
                 "prefixes)";
        const double value = std::strtod(text.c_str(), nullptr);
        if (!in_range(value, range)) return "'" + text + "' is out of range: must be " + range_words(range);
        const long root = std::lround(std::sqrt(value));
        if (square && root * root != long(value))
          return "'" + text + "' is not a perfect square";
        if (even && long(value) % 2 != 0) return "'" + text + "' is not even";
        return "";
      },
      "INT");
}

// One rule for every floating-point option: a decimal number (no hexadecimal, no "nan" or
// "inf", no value beyond the largest double) inside the option's range. A NaN compares false
// with every bound, so an option left to CLI11's own conversion would silently mean "never".
CLI::Validator finite_number(ValueRange range) {
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        static const std::regex decimal("[-+]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][-+]?[0-9]+)?");
        if (!std::regex_match(text, decimal))
          return "'" + text + "' is not a finite decimal number";
        const double value = std::strtod(text.c_str(), nullptr);
        if (!std::isfinite(value)) return "'" + text + "' is not a finite number";
        if (!in_range(value, range)) return "'" + text + "' is out of range: must be " + range_words(range);
        // -0 is 0: CLI11 would store -0.0, and the result file would record "-0.0".
        if (value == 0.0) text = "0";
        return "";
      },
      "NUMBER");
}

// A choice (a method, a parallelisation): one of `values`, else the message names the nearest
// (docs/cli.md, "Names corrected").
CLI::Validator one_of(const std::vector<std::string>& values) {
  return CLI::Validator(
      [values](std::string& text) -> std::string {
        if (std::find(values.begin(), values.end(), text) != values.end()) return "";
        std::string choices;
        for (const std::string& v : values) choices += (choices.empty() ? "" : ", ") + v;
        const std::string suggestion = did_you_mean(text, values);
        return "'" + shown_text(text) + "' is not one of " + choices +
               (suggestion.empty() ? "" : "; " + suggestion);
      },
      "");
}

// Integer ranges are described with integer ends.
nlohmann::json range_json(const ValueRange& range, bool integer) {
  const auto end = [integer](double value) -> nlohmann::json {
    if (integer) return long(value);
    return value;
  };
  return {{"low", end(range.low)},
          {"low_included", range.low_included},
          {"high", end(range.high)},
          {"high_included", range.high_included}};
}

// What --help shows after an option's flag: the placeholder docs/cli.md's table uses (N, X,
// FILE, the choices, a setting's NAME:VALUE) and the default, instead of CLI11's C++ types and
// validator names ("INT:INT=1", "FLOAT:NUMBER").
CLI::Option* shown_as(CLI::Option* option, const std::string& placeholder,
                      const std::string& shown_default) {
  return option->option_text(placeholder +
                             (shown_default.empty() ? "" : " (default " + shown_default + ")"));
}

}  // namespace

CLI::Validator decimal_count(long low, long high) {
  return decimal_integer(ValueRange{double(low), double(high)}, false);
}

nlohmann::json& OptionTable::entry(const std::string& flag, const std::string& kind,
                                   const std::string& help, const std::string& field) {
  entries_.push_back({{"flag", flag}, {"kind", kind}, {"help", help}});
  if (!field.empty()) entries_.back()["field"] = field;
  return entries_.back();
}

CLI::Option* OptionTable::integer(const std::string& flag, int& value, long low, long high,
                                  const std::string& help, const std::string& field) {
  const ValueRange range{double(low), double(high)};
  entry(flag, "integer", help, field).update({{"default", value}, {"range", range_json(range, true)}});
  CLI::Option* option = app_.add_option(flag, value, help)->capture_default_str()->check(
      decimal_integer(range, false));
  return shown_as(option, "N", option->get_default_str());
}

CLI::Option* OptionTable::square(const std::string& flag, int& value, long low, long high,
                                 const std::string& help, const std::string& field) {
  const ValueRange range{double(low), double(high)};
  entry(flag, "integer", help, field)
      .update({{"default", value}, {"range", range_json(range, true)}, {"perfect_square", true}});
  CLI::Option* option = app_.add_option(flag, value, help)->capture_default_str()->check(
      decimal_integer(range, true));
  return shown_as(option, "N", option->get_default_str());
}

CLI::Option* OptionTable::even(const std::string& flag, int& value, long low, long high,
                               const std::string& help, const std::string& field) {
  const ValueRange range{double(low), double(high)};
  entry(flag, "integer", help, field)
      .update({{"default", value}, {"range", range_json(range, true)}, {"even", true}});
  CLI::Option* option = app_.add_option(flag, value, help)->capture_default_str()->check(
      decimal_integer(range, false, true));
  return shown_as(option, "N", option->get_default_str());
}

CLI::Option* OptionTable::number(const std::string& flag, double& value, ValueRange range,
                                 const std::string& help, const std::string& field) {
  entry(flag, "number", help, field)
      .update({{"default", value}, {"range", range_json(range, false)}});
  // transform, not check: a check's changes to the text are discarded (CLI11), and -0 has to
  // become 0 before CLI11 converts it.
  CLI::Option* option = app_.add_option(flag, value, help)->capture_default_str()->transform(
      finite_number(range));
  return shown_as(option, "X", show(value));
}

CLI::Option* OptionTable::choice(const std::string& flag, std::string& value,
                                 const std::vector<std::string>& values, const std::string& help,
                                 const std::string& field) {
  entry(flag, "choice", help, field).update({{"default", value}, {"values", values}});
  std::string choices;
  for (const std::string& v : values) choices += (choices.empty() ? "" : "|") + v;
  return shown_as(
      app_.add_option(flag, value, help)->capture_default_str()->check(one_of(values)),
      choices, value);
}

CLI::Option* OptionTable::flag(const std::string& flag, bool& value, const std::string& help,
                               const std::string& field) {
  entry(flag, "flag", help, field)["default"] = value;
  return app_.add_flag(flag, value, help);
}

CLI::Option* OptionTable::file(const std::string& flag, std::string& value,
                               const std::string& kind, const std::string& help,
                               const std::string& shown_default) {
  nlohmann::json& described = entry(flag, kind, help, "");
  if (!shown_default.empty()) described["default"] = shown_default;
  // An empty file name is an error, not "no file".
  const CLI::Validator not_empty(
      [](std::string& text) -> std::string { return text.empty() ? "the file name is empty" : ""; },
      "FILE");
  return shown_as(app_.add_option(flag, value, help)->check(not_empty), "FILE", shown_default);
}

CLI::Option* OptionTable::setting(const std::string& flag, std::vector<std::string>& values,
                                  const std::string& type_name, const std::string& help) {
  entry(flag, "setting", help, "").update({{"repeatable", true}, {"value_name", type_name}});
  return shown_as(app_.add_option(flag, values, help)->allow_extra_args(false),
                  type_name + " (repeatable)", "");
}

CLI::Option* OptionTable::text(const std::string& flag, std::string& value,
                               const std::string& value_name,
                               std::function<std::string(const std::string&)> check,
                               const std::string& help) {
  entry(flag, "text", help, "")["value_name"] = value_name;
  const CLI::Validator well_formed(
      [check](std::string& text) -> std::string { return check(text); }, "");
  return shown_as(app_.add_option(flag, value, help)->check(well_formed), value_name, "");
}

CLI::Option* OptionTable::positional(const std::string& name, std::string& value,
                                     const std::string& help) {
  entry(name, "file", help, "")["positional"] = true;
  return shown_as(app_.add_option(name, value, help), "FILE", "");
}

void OptionTable::annotate(const std::string& flag, const std::string& key,
                           const nlohmann::json& value) {
  for (nlohmann::json& entry : entries_)
    if (entry["flag"] == flag) entry[key] = value;
}

nlohmann::json OptionTable::describe() const { return entries_; }

}  // namespace ncube

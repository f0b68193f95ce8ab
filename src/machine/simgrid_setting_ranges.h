// The values of each SimGrid setting (--cfg=NAME:VALUE, a platform's simgrid_config) that a
// run survives: one row per key SimGrid 3.32 lists in its --help, with the range ./simulate
// accepts and why (what SimGrid's code does outside it, or the test run that proves the
// values harmless). SimGrid itself only checks a value's type and a few names: NaN precisions,
// a 1 KiB actor stack or a zero bandwidth factor pass it and end the run in SIGSEGV or abort.
// Every key SimGrid lists has a row (tests/simgrid_setting_ranges_test.cpp asks SimGrid), so
// a SimGrid upgrade that adds a key fails a test until the key is judged here.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ncube {

enum class SettingKind {
  kAny,             // any value SimGrid's own type check takes (the setting cannot crash a run)
  kBoolean,         // SimGrid's booleans (yes/no, on/off, true/false, 1/0), checked by SimGrid
  kInteger,         // a whole number in [low, high]
  kIntegerOrNone,   // -1 (none) or a whole number in [low, high]
  kReal,            // a finite number in [low, high]
  kChoice,          // one of `choices`
  kEmpty,           // only the empty value (the feature is refused)
  kFactorList,      // SIZE:FACTOR;SIZE:FACTOR... (SMPI's piecewise factors), finite factors > 0
  kThreeFactors,    // A;B;C, three finite numbers > 0 (the IB model's penalty factors)
  kOutputFile,      // the path of a file SimGrid writes: taken from ./simulate's command line
                    // only, under the output rule (src/machine/simgrid_outputs.h); a platform
                    // file never chooses where anything is written (platform_setting_problem)
};

struct SimgridSettingRange {
  std::string_view name;
  SettingKind kind;
  double low = 0, high = 0;     // kInteger, kIntegerOrNone, kReal
  std::string_view choices{};   // kChoice: comma-separated
  std::string_view why{};       // what goes wrong outside the range, or why any value is safe
};

// Every row, in SimGrid's order (alphabetical).
const std::vector<SimgridSettingRange>& simgrid_setting_ranges();

// The row of a key; nullptr for a name SimGrid does not know (SimGrid refuses it).
const SimgridSettingRange* simgrid_setting_range(std::string_view name);

// The range in words: "a finite number in [1e-15, 0.01]", "one of LV08, CM02, SMPI, IB".
std::string describe_range(const SimgridSettingRange& range);

// "" when `value` lies in the row's range, else what it must be, e.g.
// "maxmin/precision must be a finite number in [1e-15, 0.01] (NaN ... end in abort)".
std::string setting_range_problem(const SimgridSettingRange& range, const std::string& value);

// What is wrong with a setting that a platform file gives (a JSON platform's simgrid_config,
// a SimGrid platform file's <config> tags): its range problem, or, for a setting that names a
// file SimGrid writes (kOutputFile), that a platform file may not choose it. "" when fine.
std::string platform_setting_problem(std::string_view name, const std::string& value);

}  // namespace ncube

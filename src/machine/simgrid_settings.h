// SimGrid's own command-line settings (--cfg=NAME:VALUE, --log=CONTROL), checked before the
// run's Engine sees them. SimGrid ends the process on a bad one (an abort with a backtrace,
// exit 134, or an exception listing every key), so each setting is first tried in a child
// process that creates an Engine with it and builds a one-host platform (one child for all of
// a run's settings, one each only when that child refuses; none when every setting is a choice
// the range table lists or a boolean, which SimGrid takes); what SimGrid says
// there becomes one InputError line (exit 2) naming the setting. Before that, a --cfg value
// must lie in the range a run survives (src/machine/simgrid_setting_ranges.h): SimGrid takes
// many values (a NaN precision, a 1 KiB stack) that end the run later.
#pragma once

#include <string>
#include <vector>

namespace ncube {

// Throws InputError for the first argument SimGrid refuses: "--cfg=network/model:bogus: Model
// 'bogus' is invalid! Valid models are: LV08, Constant, SMPI, IB, CM02, ns-3." Arguments are
// as the Engine gets them ("--cfg=...", "--log=...").
void check_simgrid_settings(const std::vector<std::string>& arguments);

// What SimGrid (or the NAME:VALUE form, or the range table) says against one argument; ""
// when it is taken.
std::string simgrid_setting_problem(const std::string& argument);

// What the NAME:VALUE form and the range table say against one argument, without asking
// SimGrid (no child); "" when they take it.
std::string simgrid_setting_form_problem(const std::string& argument);

// SimGrid asked about `arguments` together, in one child: {arguments.size(), ""} when it takes
// them all; else the first it refuses (alone, or only with the arguments before it) and what
// it says.
// The spellings of a boolean SimGrid reads (xbt's config parser); a --cfg boolean spelled so,
// or a choice its row of the range table lists, is taken without a child.
inline constexpr const char* kSimgridBooleanSpellings[] = {"yes", "no",    "on", "off",
                                                           "true", "false", "1", "0"};

struct SettingRefusal {
  std::size_t index;
  std::string problem;
};
SettingRefusal simgrid_refusal_of(const std::vector<std::string>& arguments);

}  // namespace ncube

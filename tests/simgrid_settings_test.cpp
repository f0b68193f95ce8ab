// SimGrid's settings are checked before the run's Engine sees them: what SimGrid would answer
// with an abort (exit 134) or an exception listing every key becomes one line naming the
// setting. Each test runs in its own process (ctest), with no Engine yet.
#include "machine/simgrid_settings.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/input_error.h"

namespace ncube {
namespace {

// The message for `argument` among `others` (checked together, `argument` last): it must
// name `argument`.
std::string refusal(const std::string& argument, std::vector<std::string> others = {}) {
  try {
    others.push_back(argument);
    check_simgrid_settings(others);
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << "more than one line: " << message;
    EXPECT_EQ(message.rfind(argument + ": ", 0), 0u) << "does not name the setting: " << message;
    return message;
  }
  return "";
}

TEST(SimgridSettings, AnUnknownNameIsNamed) {
  EXPECT_NE(refusal("--cfg=bogus/name:1").find("Bad config key: bogus/name"), std::string::npos);
}

TEST(SimgridSettings, AnUnknownValueListsTheValidOnes) {
  const std::string model = refusal("--cfg=network/model:bogus");
  // The models a run survives (src/machine/simgrid_setting_ranges.h), not all SimGrid has.
  EXPECT_NE(model.find("network/model must be one of LV08, CM02, SMPI, IB"), std::string::npos)
      << model;
  EXPECT_NE(refusal("--cfg=cpu/model:bogus").find("one of Cas01"), std::string::npos);
  EXPECT_NE(refusal("--cfg=network/solver:bogus").find("fairbottleneck"), std::string::npos);
  EXPECT_NE(refusal("--cfg=network/crosstraffic:maybe").find("boolean"), std::string::npos);
  EXPECT_NE(refusal("--log=ncube_messages.thresh:loud").find("debug"), std::string::npos);
}

TEST(SimgridSettings, AMissingValueIsRefusedBeforeSimgridSeesIt) {
  for (const char* bad : {"--cfg=network/model", "--cfg=network/model:", "--cfg=:CM02"})
    EXPECT_NE(refusal(bad).find("NAME:VALUE"), std::string::npos) << bad;
}

TEST(SimgridSettings, AMalformedLogControlIsRefused) {
  EXPECT_NE(refusal("--log=:::").find("Invalid control string"), std::string::npos);
  EXPECT_NE(refusal("--log=ncube_messages.bogus:debug").find("bogus"), std::string::npos);
}

TEST(SimgridSettings, GoodSettingsPass) {
  EXPECT_NO_THROW(check_simgrid_settings({"--cfg=network/model:CM02", "--cfg=network/crosstraffic:0",
                                          "--cfg=network/solver:fairbottleneck",
                                          "--log=ncube_messages.thresh:debug"}));
}

// The spellings taken without asking SimGrid are SimGrid's: asked in a child, it takes each.
TEST(SimgridSettings, TheBooleanSpellingsTakenWithoutAChildAreSimgrids) {
  for (const char* spelling : kSimgridBooleanSpellings)
    EXPECT_EQ(simgrid_setting_problem(std::string("--cfg=network/crosstraffic:") + spelling), "")
        << spelling;
  EXPECT_NE(simgrid_setting_problem("--cfg=network/crosstraffic:Yes"), "");
}

// A run's settings are asked of SimGrid in one child; the one it refuses is still named with
// what it says of it alone, and an earlier refused one before a later one of bad form.
TEST(SimgridSettings, AmongOthersTheRefusedOneIsNamedAsAlone) {
  const std::vector<std::string> good = {"--cfg=network/model:CM02", "--cfg=network/solver:fairbottleneck",
                                         "--log=ncube_messages.thresh:debug"};
  for (const char* bad : {"--cfg=network/crosstraffic:maybe", "--log=:::", "--cfg=bogus/name:1"})
    EXPECT_EQ(refusal(bad, good), refusal(bad)) << bad;
  try {
    check_simgrid_settings({"--cfg=network/crosstraffic:maybe", "--cfg=network/model:bogus"});
    ADD_FAILURE() << "taken";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), refusal("--cfg=network/crosstraffic:maybe"));
  }
}

}  // namespace
}  // namespace ncube

// "Did you mean" (src/tools/suggestions.h): the edit distance on pairs worked out by hand, and
// which known names are offered for a mistyped one.
#include "tools/suggestions.h"

#include <gtest/gtest.h>

#include "tools/option_table.h"

namespace ncube {
namespace {

TEST(EditDistance, CountsInsertionsDeletionsSubstitutionsAndSwaps) {
  EXPECT_EQ(edit_distance("", ""), 0u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("octree", "octree"), 0u);
  // kitten -> sitten -> sittin -> sitting.
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("--iteration", "--iterations"), 1u);  // one insertion
  EXPECT_EQ(edit_distance("cm-5", "cm5"), 1u);                   // one deletion
  EXPECT_EQ(edit_distance("scene2", "scene3"), 1u);              // one substitution
  EXPECT_EQ(edit_distance("ab", "ba"), 1u);                      // one swap of neighbours
  EXPECT_EQ(edit_distance("hemicbue", "hemicube"), 1u);
  // Optimal string alignment: a swapped pair is not edited again (ca -> ac -> abc would be 2).
  EXPECT_EQ(edit_distance("ca", "abc"), 3u);
  // Symmetric.
  EXPECT_EQ(edit_distance("flaw", "lawn"), 2u);
  EXPECT_EQ(edit_distance("lawn", "flaw"), 2u);
}

const std::vector<std::string> kOptions = {"--R", "--V", "--iterations", "--image",
                                           "--image-width", "--trace", "--trace-nodes"};

TEST(CloseNames, OffersTheOptionOneEditAway) {
  EXPECT_EQ(close_names("--iteration", kOptions), std::vector<std::string>{"--iterations"});
  EXPECT_EQ(did_you_mean("--iteration", kOptions), "did you mean --iterations?");
  EXPECT_EQ(close_names("--imagewidth", kOptions), std::vector<std::string>{"--image-width"});
  // A single dash for two.
  EXPECT_EQ(close_names("-iterations", kOptions), std::vector<std::string>{"--iterations"});
}

TEST(CloseNames, OffersWhatTheNameBegins) {
  // "--iter" is 6 edits from --iterations but begins it.
  EXPECT_EQ(close_names("--iter", kOptions), std::vector<std::string>{"--iterations"});
  EXPECT_EQ(close_names("first", {"all", "first-blocker"}), std::vector<std::string>{"first-blocker"});
}

TEST(CloseNames, CaseAsideAndNearestFirst) {
  // --r is --R in the wrong case (distance 0 case aside); --V is a whole other name.
  EXPECT_EQ(close_names("--r", kOptions), std::vector<std::string>{"--R"});
  // Only the nearest: --trace-node is one edit from --trace-nodes, five from --trace.
  EXPECT_EQ(close_names("--trace-node", kOptions), std::vector<std::string>{"--trace-nodes"});
  // Ties all offered, nearest first; what the name begins after them.
  EXPECT_EQ(close_names("--imag", kOptions),
            (std::vector<std::string>{"--image", "--image-width"}));
  EXPECT_EQ(did_you_mean("--imag", kOptions), "did you mean --image or --image-width?");
  EXPECT_EQ(close_names("scen2", {"scene0", "scene1", "scene2"}), std::vector<std::string>{"scene2"});
}

TEST(CloseNames, NothingForANameFarFromAll) {
  EXPECT_TRUE(close_names("--bogus", kOptions).empty());
  EXPECT_EQ(did_you_mean("--bogus", kOptions), "");
  EXPECT_TRUE(close_names("octree", {"octree"}).empty());  // the name itself is no suggestion
  EXPECT_TRUE(close_names(std::string(5000, 'x'), kOptions).empty());
}

TEST(CloseNames, MethodsAndMachines) {
  EXPECT_EQ(close_names("octre", {"brute-force", "octree"}), std::vector<std::string>{"octree"});
  EXPECT_EQ(close_names("bruteforce", {"brute-force", "octree"}),
            std::vector<std::string>{"brute-force"});
  EXPECT_EQ(close_names("shooter", {"receivers", "shooters", "circulation"}),
            std::vector<std::string>{"shooters"});
  const std::vector<std::string> machines = {"cm5", "cm5-n1024", "ipsc860", "paragon", "ncube2"};
  EXPECT_EQ(close_names("cm-5", machines), (std::vector<std::string>{"cm5"}));
  EXPECT_EQ(close_names("paragn", machines), std::vector<std::string>{"paragon"});
}

TEST(NearestNames, TheNearestHoweverFar) {
  const std::vector<std::string> scenes = {"cornell-box", "scene0", "scene1", "scene2"};
  EXPECT_EQ(nearest_names("xyz", scenes, 2), (std::vector<std::string>{"scene0", "scene1"}));
  EXPECT_EQ(nearest_names("cornell-bx", scenes, 1), std::vector<std::string>{"cornell-box"});
  EXPECT_EQ(either_of({"a"}), "a");
  EXPECT_EQ(either_of({"a", "b"}), "a or b");
  EXPECT_EQ(either_of({"a", "b", "c"}), "a, b or c");
}

// A choice registered in the option table names the nearest choice when refused.
TEST(ChoiceOption, RefusalNamesTheNearestChoice) {
  CLI::App app;
  OptionTable table(app);
  std::string visibility = "brute-force";
  table.choice("--visibility", visibility, {"brute-force", "octree"}, "how", "visibility");
  const auto refusal = [&app](const char* value) -> std::string {
    try {
      app.parse(std::vector<std::string>{value, "--visibility"});  // CLI11 reads it backwards
    } catch (const CLI::ParseError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(refusal("octre"),
            "--visibility: 'octre' is not one of brute-force, octree; did you mean octree?");
  EXPECT_EQ(refusal("xyz"), "--visibility: 'xyz' is not one of brute-force, octree");
  EXPECT_EQ(refusal("octree"), "");
  EXPECT_EQ(visibility, "octree");
}

}  // namespace
}  // namespace ncube

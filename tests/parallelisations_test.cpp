// One registration per parallelisation (src/simulation/parallelisations.h; docs/architecture.md,
// "How to add a method"), as tests/method_registry_test.cpp holds the visibility methods to
// theirs: every consumer of a parallelisation's name knows every registered name. For each:
// --parallelisation accepts it and --describe-options lists it with its doc, the result file
// records it, and it has a check, a memory plan with one entry per node, node programs and a
// report; an unregistered name is refused at the command line (exit 2) and is an internal
// error anywhere else (std::logic_error), never the paper's program by default.
#include <gtest/gtest.h>

#include <algorithm>

#include "hand_counted_scene.h"
#include "simulate_arguments.h"
#include "machine/cost_model.h"
#include "simulation/memory_check.h"
#include "simulation/parallelisations.h"
#include "simulation/result_file.h"
#include "tools/simulate_options.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

TEST(Parallelisations, ThePapersReceiversAreTheDefault) {
  EXPECT_EQ(parallelisations().paper_default().name, "receivers");
  EXPECT_EQ(ProgramOptions{}.parallelisation, "receivers");
  EXPECT_EQ(ProgramOptions{}.shooters_per_iteration, 0);
  EXPECT_TRUE(parallelisations().contains("shooters"));
}

TEST(Parallelisations, EveryOneIsAValueOfTheOptionWithItsDoc) {
  SimulateOptions described;
  std::string text;
  ASSERT_EQ(parse({"--describe-options"}, described, &text), 0);
  const nlohmann::json options = nlohmann::json::parse(text);
  const auto entry = std::find_if(options.begin(), options.end(), [](const nlohmann::json& o) {
    return o.value("flag", "") == "--parallelisation";
  });
  ASSERT_NE(entry, options.end());
  EXPECT_EQ((*entry)["values"].get<std::vector<std::string>>(), parallelisations().names());
  EXPECT_EQ((*entry)["default"], "receivers");
  EXPECT_EQ((*entry)["field"], "parallelisation");
  for (const Parallelisation& p : parallelisations().all()) {
    EXPECT_NE((*entry)["help"].get<std::string>().find(p.name + " (" + p.doc + ")"),
              std::string::npos)
        << p.name;
    SimulateOptions options;
    ASSERT_EQ(parse({"--parallelisation", p.name}, options), -1) << p.name;
    EXPECT_EQ(options.config.parallelisation, p.name);
  }
  SimulateOptions unknown;
  EXPECT_EQ(parse({"--parallelisation", "visibility"}, unknown), kExitBadInput);
  SimulateOptions three;
  ASSERT_EQ(parse({"--parallelisation", "shooters", "--shooters-per-iteration", "3"}, three), -1);
  EXPECT_EQ(three.config.shooters_per_iteration, 3);
}

TEST(Parallelisations, EveryOneIsRecordedInTheResultFile) {
  const Scene scene = hand_counted_scene();
  for (const Parallelisation& p : parallelisations().all()) {
    SimulationConfig config;
    config.parallelisation = p.name;
    config.shooters_per_iteration = 2;
    const nlohmann::json recorded = result_to_json(scene, config, SimulationResult{})["config"];
    // The paper's program keeps its result files: the fields are written for the others only.
    if (p.name == parallelisations().paper_default().name) {
      EXPECT_FALSE(recorded.contains("parallelisation"));
      EXPECT_FALSE(recorded.contains("shooters_per_iteration"));
      continue;
    }
    EXPECT_EQ(recorded.value("parallelisation", ""), p.name);
    EXPECT_EQ(recorded.value("shooters_per_iteration", -1), 2);
  }
  SimulationConfig config;
  config.parallelisation = "everywhere";
  EXPECT_THROW(result_to_json(scene, config, SimulationResult{}), std::logic_error);
  EXPECT_THROW(node_memory(scene, config, load_cost_model(repo("platforms/cost_model.json"))),
               std::logic_error);
}

// Every registration is whole, and its memory plan has one entry per node in node order.
TEST(Parallelisations, EveryOneHasItsStepsAndPlansEveryNode) {
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  for (const Parallelisation& p : parallelisations().all()) {
    EXPECT_TRUE(p.check && p.plan_memory && p.launch && p.collect) << p.name;
    SimulationConfig config;
    config.parallelisation = p.name;
    config.radiosity_processors = 2;
    const std::vector<NodeMemory> memory = node_memory(scene, config, costs);
    ASSERT_EQ(memory.size(), 2u) << p.name;
    for (int node = 0; node < 2; ++node) {
      EXPECT_EQ(memory[std::size_t(node)].node, node) << p.name;
      EXPECT_GT(memory[std::size_t(node)].bytes, costs.node_reserve_bytes) << p.name;
    }
  }
}

}  // namespace
}  // namespace ncube

// One registration per method (docs/architecture.md, "How to add a method"): every consumer
// of a visibility method's name knows every registered name, so a method registered in
// visibility_methods() and forgotten anywhere fails here instead of falling back to another
// method. For each registered method: --visibility accepts it and --describe-options lists it
// with its doc, the result file records it, the host builds its fast version, which answers
// and counts as the method's readable definition (V = 0 and V = 2, one and two host threads,
// and --reference-visibility), and the memory plan holds its search structure on every node
// that tests rays.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

#include "hand_counted_scene.h"
#include "simulate_arguments.h"
#include "machine/cost_model.h"
#include "nodes/memory_plan.h"
#include "nodes/placement.h"
#include "receiver_sample.h"
#include "scene/scene_loader.h"
#include "simulation/host_machinery.h"
#include "simulation/result_file.h"
#include "tools/simulate_options.h"
#include "util/input_error.h"
#include "visibility/visibility_methods.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

struct Named {
  std::string name, doc;
};

TEST(MethodRegistry, AnUnregisteredNameIsABugNotAFallback) {
  const MethodRegistry<Named> registry("test method", {{"a", "first"}, {"b", "second"}});
  EXPECT_EQ(registry.paper_default().name, "a");
  EXPECT_EQ(registry.at("b").doc, "second");
  EXPECT_THROW(registry.at("c"), std::logic_error);
  EXPECT_FALSE(registry.contains("c"));
  EXPECT_EQ(registry.described(), "a (first) or b (second)");
  EXPECT_EQ(MethodRegistry<Named>("m", {{"a", "1"}, {"b", "2"}, {"c", "3"}}).described(),
            "a (1), b (2) or c (3)");
  EXPECT_THROW(MethodRegistry<Named>("test method", {{"a", "1"}, {"a", "2"}}), std::logic_error);
  EXPECT_THROW(MethodRegistry<Named>("test method", {}), std::logic_error);
}

// The paper's loop is the default everywhere (the calibrated setup), and the octree of
// section 6 is registered.
TEST(VisibilityMethods, ThePapersLoopIsTheDefault) {
  EXPECT_EQ(visibility_methods().paper_default().name, "brute-force");
  EXPECT_EQ(ProgressiveOptions{}.visibility, "brute-force");
  EXPECT_TRUE(visibility_methods().contains("octree"));
}

TEST(VisibilityMethods, EveryMethodIsAValueOfTheOptionWithItsDoc) {
  SimulateOptions described;
  std::string text;
  ASSERT_EQ(parse({"--describe-options"}, described, &text), 0);
  const nlohmann::json options = nlohmann::json::parse(text);
  const auto entry = std::find_if(options.begin(), options.end(), [](const nlohmann::json& o) {
    return o.value("flag", "") == "--visibility";
  });
  ASSERT_NE(entry, options.end());
  EXPECT_EQ((*entry)["values"].get<std::vector<std::string>>(), visibility_methods().names());
  EXPECT_EQ((*entry)["default"], visibility_methods().paper_default().name);
  EXPECT_EQ((*entry)["field"], "visibility");
  for (const VisibilityMethod& method : visibility_methods().all()) {
    EXPECT_NE((*entry)["help"].get<std::string>().find(method.name + " (" + method.doc + ")"),
              std::string::npos)
        << method.name;
    SimulateOptions options;
    ASSERT_EQ(parse({"--visibility", method.name}, options), -1) << method.name;
    EXPECT_EQ(options.config.options.visibility, method.name);
  }
  SimulateOptions unknown;
  EXPECT_EQ(parse({"--visibility", "hemicube"}, unknown), kExitBadInput);
}

TEST(VisibilityMethods, EveryMethodIsRecordedInTheResultFile) {
  const Scene scene = hand_counted_scene();
  for (const VisibilityMethod& method : visibility_methods().all()) {
    SimulationConfig config;
    config.options.visibility = method.name;
    EXPECT_EQ(result_to_json(scene, config, SimulationResult{})["config"]["visibility"],
              method.name);
  }
  SimulationConfig config;
  config.options.visibility = "hemicube";
  EXPECT_THROW(result_to_json(scene, config, SimulationResult{}), std::logic_error);
}

// The host's version of each method, built as a run builds it, gives the readable
// definition's answers and counts for every occluder set, on a sample of receivers of a few
// shooters of the Cornell box (its two blocks shadow the floor).
TEST(VisibilityMethods, EveryMethodsHostVersionAnswersAndCountsAsItsDefinition) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const int shooters[] = {0, 3, int(scene.patches.size()) - 1};
  for (const VisibilityMethod& method : visibility_methods().all()) {
    for (const int V : {0, 2}) {
      std::vector<std::vector<int>> sets;
      const int shares = std::max(V, 1);
      for (int j = 0; j < shares; ++j) sets.push_back(visibility_share(scene, shares, j));
      for (const int threads : {1, 2}) {
        for (const bool reference : {false, true}) {
          const std::string where = method.name + ", V = " + std::to_string(V) + ", " +
                                    std::to_string(threads) + " threads" +
                                    (reference ? ", reference" : "");
          ProgressiveOptions options;
          options.visibility = method.name;
          options.host_threads = threads;
          options.reference_visibility = reference;
          HostMachinery machinery;
          build_host_machinery(machinery, scene, sets, options, V, 2, 100, false);
          ASSERT_EQ(machinery.occluders.size(), sets.size()) << where;
          std::mt19937 random(7);
          long blocked = 0;
          for (std::size_t s = 0; s < sets.size(); ++s) {
            const auto definition = method.reference(scene, sets[s], options.ray_policy);
            EXPECT_EQ(machinery.occluders[s]->patch_indices(), sets[s]) << where;
            EXPECT_EQ(machinery.occluders[s]->build_work(), definition->build_work()) << where;
            for (const int shooter_patch : shooters) {
              const Shooter shooter = make_shooter(scene, shooter_patch, Rgb(1.0), 16);
              const ReceiverSample sample = sample_receivers(scene, shooter_patch, 200, random);
              const PointBlock block(sample.points, sample.patches);
              std::vector<PartMask> host(block.count), defined(block.count);
              WorkCounts host_counts, defined_counts;
              machinery.occluders[s]->unblocked_parts(block, shooter, host.data(), host_counts);
              definition->unblocked_parts(block, shooter, defined.data(), defined_counts);
              EXPECT_EQ(host, defined) << where << ", shooter " << shooter_patch;
              EXPECT_EQ(host_counts, defined_counts) << where << ", shooter " << shooter_patch;
              for (const PartMask mask : defined) blocked += 16 - __builtin_popcountll(mask);
            }
          }
          EXPECT_GT(blocked, 0) << where << ": no ray blocked, nothing compared";
        }
      }
    }
  }
  ProgressiveOptions options;
  options.visibility = "hemicube";
  HostMachinery machinery;
  EXPECT_THROW(build_host_machinery(machinery, scene, {{0, 1}}, options, 0, 1, 100, false),
               std::logic_error);
}

// Every node that tests rays holds its method's search structure over its set: the whole
// scene's on each radiosity processor with V = 0, its share's on each visibility processor.
TEST(VisibilityMethods, EveryMethodsSearchStructureIsInTheMemoryPlan) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const auto plan = [&](const std::string& name, int V) {
    ProgramOptions program;
    program.options.visibility = name;
    return plan_memory(ProgramSetup{scene, Placement{2, V}, program, 1.0},
                       partition_patches_by_elements(scene, 2), costs);
  };
  for (const int V : {0, 3}) {
    const std::vector<NodeMemory> none = plan("brute-force", V);
    for (const VisibilityMethod& method : visibility_methods().all()) {
      const std::vector<NodeMemory> with = plan(method.name, V);
      ASSERT_EQ(with.size(), none.size());
      for (std::size_t n = 0; n < with.size(); ++n) {
        double expected = 0.0;  // a radiosity processor with V > 0 tests no rays
        if (V == 0)
          expected = costs.bytes(
              method.reference(scene, visibility_share(scene, 1, 0), RayTestPolicy{})
                  ->structure_items());
        else if (with[n].role == NodeRole::kVisibility)
          expected = costs.bytes(
              method
                  .reference(scene, visibility_share(scene, V, (with[n].node - 1) % (V + 1)),
                             RayTestPolicy{})
                  ->structure_items());
        EXPECT_DOUBLE_EQ(with[n].bytes - none[n].bytes, expected)
            << method.name << ", V = " << V << ", node " << with[n].node;
      }
    }
  }
  // The brute-force loop holds nothing beyond the patches; the octree holds cells.
  EXPECT_EQ(costs.bytes(visibility_methods().at("brute-force").reference(scene, {0, 1, 2}, RayTestPolicy{})
                            ->structure_items()),
            0.0);
  EXPECT_GT(costs.bytes(visibility_methods().at("octree").reference(scene, {0, 1, 2}, RayTestPolicy{})
                            ->structure_items()),
            0.0);
}

}  // namespace
}  // namespace ncube

// The shooter-centred scheme (--parallelisation shooters; src/nodes/shooter_processor.h,
// src/nodes/increment_exchange.h, docs/model.md "The shooter-centred scheme"), against
// values worked out independently: the paper's program at R = 1 (the same radiosities to the
// last bit), the sequential solver's unshot powers for the choice of several shooters, the
// exchange's bytes by hand, the memory of every node by hand, and the configurations it
// refuses. Each TEST runs its own SimGrid Engine, hence its own process under ctest.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "host/fast_occluders.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/increment_exchange.h"
#include "scene/scene_loader.h"
#include "simulation/configuration_check.h"
#include "simulation/memory_check.h"
#include "simulation/simulation.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

SimulationConfig shooters(int R, int iterations) {
  SimulationConfig config;
  config.parallelisation = "shooters";
  config.radiosity_processors = R;
  config.options.samples = 16;
  config.options.max_iterations = iterations;
  return config;
}

SimulationResult run(const Scene& scene, const SimulationConfig& config) {
  return run_simulation(scene, config, load_platform_config(repo("platforms/ncube2.json")),
                        load_cost_model(repo("platforms/cost_model.json")));
}

// Issue 31: "with one node and one shooter per iteration, shooters with ray-traced form
// factors gives the same radiosities as the paper's program at R = 1". The paper's program
// at R = 1 is the host's sequential solver to the last bit (tests/parallel_equivalence_test.cpp;
// one SimGrid run per process, so it stands in for it here); tests/shooters_test.sh compares
// the two ./simulate runs' meshes byte for byte. The same shots in the same order, each
// element's light added by the same operations: equal to the last bit.
void expect_same_as_sequential_at_one_node(const std::string& scene_name, bool skip_facing_away) {
  const Scene scene = load_scene(repo("scenes/" + scene_name));
  SimulationConfig scheme = shooters(1, 30);
  scheme.options.skip_facing_away = skip_facing_away;
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  RadiosityEngine sequential(scene, all);
  const FastOccluders occluders(scene, all, scheme.options.ray_policy);
  const ProgressiveRun paper = run_progressive(sequential, occluders, scheme.options);
  const SimulationResult b = run(scene, scheme);
  ASSERT_EQ(b.status, RunStatus::kOk);
  EXPECT_EQ(b.iterations, 30);
  EXPECT_EQ(b.shooters, paper.shooters);
  for (int p = 0; p < int(scene.patches.size()); ++p) {
    EXPECT_EQ(b.patch_radiosity[std::size_t(p)], sequential.patch_radiosity(p)) << "patch " << p;
    const StoredPatch& expected = sequential.store().patches()[std::size_t(p)];
    ASSERT_EQ(b.solution[std::size_t(p)].radiosity.size(), expected.elements.size());
    for (std::size_t k = 0; k < expected.elements.size(); ++k)
      ASSERT_EQ(b.solution[std::size_t(p)].radiosity[k], expected.elements[k].radiosity)
          << "patch " << p << " element " << k;
  }
  // The same rays, tests and form factors; the shooter scheme adds the increments it applies.
  EXPECT_EQ(b.counts.rays, paper.total.rays);
  EXPECT_EQ(b.counts.ray_patch_tests, paper.total.ray_patch_tests);
  EXPECT_EQ(b.counts.form_factors, paper.total.form_factors);
  EXPECT_EQ(b.counts.element_updates, paper.total.element_updates);
  EXPECT_EQ(b.counts.increments_applied, 30u * std::uint64_t(scene.element_total()));
  EXPECT_EQ(b.counts.increments_combined, 0u);  // one node: nothing to exchange
}

TEST(ShooterScheme, OneNodeGivesThePapersRadiositiesScene0) {
  expect_same_as_sequential_at_one_node("scene0.json", false);
}
TEST(ShooterScheme, OneNodeGivesThePapersRadiositiesCornellBoxSkippingFacingAway) {
  expect_same_as_sequential_at_one_node("cornell-box.json", true);
}

// Several shooters at once: after the light's shot, the S patches with the most unshot
// power as the sequential solver leaves them after one shot, best first.
std::vector<int> first_shooter_then_best(const Scene& scene, std::size_t S) {
  ProgressiveOptions options;
  options.samples = 16;
  options.max_iterations = 1;
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  RadiosityEngine sequential(scene, all);
  const FastOccluders occluders(scene, all, options.ray_policy);
  const ProgressiveRun first = run_progressive(sequential, occluders, options);
  std::vector<std::pair<double, int>> power;
  for (int p = 0; p < int(scene.patches.size()); ++p) {
    const Rgb& u = sequential.unshot(p);
    power.push_back({-(u.r + u.g + u.b) * scene.patches[std::size_t(p)].area, p});
  }
  std::sort(power.begin(), power.end());
  std::vector<int> shooters = first.shooters;
  for (std::size_t k = 0; k < S; ++k) {
    EXPECT_LT(power[k].first, 0.0) << "patch " << power[k].second << " has nothing to shoot";
    shooters.push_back(power[k].second);
  }
  return shooters;
}

TEST(ShooterScheme, ShootsTheFourPatchesWithMostUnshotPowerOnFourNodes) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const SimulationResult r = run(scene, shooters(4, 2));
  ASSERT_EQ(r.status, RunStatus::kOk);
  EXPECT_EQ(r.iterations, 2);
  EXPECT_EQ(r.shooters, first_shooter_then_best(scene, 4));
}

// --shooters-per-iteration 2 on 4 nodes: the two best; nodes 2 and 3 shoot nothing but
// still take part in the exchange with their vectors of zeros.
TEST(ShooterScheme, ShootersPerIterationTakesTheBest) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  SimulationConfig two = shooters(4, 2);
  two.shooters_per_iteration = 2;
  const SimulationResult r = run(scene, two);
  ASSERT_EQ(r.status, RunStatus::kOk);
  EXPECT_EQ(r.shooters, first_shooter_then_best(scene, 2));
  EXPECT_DOUBLE_EQ(r.nodes[3].bytes_sent, 2 * 2 * (1078 * 12 + 8.0));
  EXPECT_EQ(r.nodes[3].counts.rays, 0u);
  EXPECT_GT(r.nodes[1].counts.rays, 0u);
}

// The exchange's bytes by hand: the Cornell box has 1078 elements; an increment vector is
// 1078 x 12 bytes (3 floats) plus the 8-byte header = 12944 bytes a message. R = 4: every
// node swaps its vector across dimensions 0 and 1, 2 messages an iteration; two iterations
// 4 messages, 51776 bytes per node, 207104 bytes in all, and 2 x 2 x 1078 increments added.
TEST(ShooterScheme, ExchangeBytesOfFourNodesByHand) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  ASSERT_EQ(scene.element_total(), 1078);
  const SimulationResult r = run(scene, shooters(4, 2));
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.nodes.size(), 4u);
  double total = 0.0;
  for (const NodeStats& n : r.nodes) {
    EXPECT_EQ(n.messages_sent, 4) << "node " << n.node;
    EXPECT_EQ(n.messages_received, 4) << "node " << n.node;
    EXPECT_DOUBLE_EQ(n.bytes_sent, 51776.0) << "node " << n.node;
    EXPECT_EQ(n.counts.increments_combined, 4312u) << "node " << n.node;
    EXPECT_EQ(n.counts.increments_applied, 2156u) << "node " << n.node;
    total += n.bytes_sent;
  }
  EXPECT_DOUBLE_EQ(total, 207104.0);
}

// R = 3 is not a power of two: node 2 gives its vector to node 0 (one hop, bit 1) and gets
// the sum back; nodes 0 and 1 swap across dimension 0. Messages 2, 1, 1 an iteration.
TEST(ShooterScheme, ExchangeBytesOfThreeNodesByHand) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const SimulationResult r = run(scene, shooters(3, 1));
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.nodes.size(), 3u);
  const double message = 1078 * 12 + 8;
  EXPECT_DOUBLE_EQ(r.nodes[0].bytes_sent, 2 * message);
  EXPECT_DOUBLE_EQ(r.nodes[1].bytes_sent, message);
  EXPECT_DOUBLE_EQ(r.nodes[2].bytes_sent, message);
  EXPECT_EQ(r.nodes[0].counts.increments_combined, 2u * 1078u);  // node 2's, then node 1's
  EXPECT_EQ(r.nodes[1].counts.increments_combined, 1078u);
  EXPECT_EQ(r.nodes[2].counts.increments_combined, 0u);        // gets the sum whole
  for (int R : {1, 2, 3, 4, 5, 6, 7, 8, 64}) {
    int messages = 0;
    for (int rank = 0; rank < R; ++rank) messages += IncrementExchange::messages_sent(rank, R);
    // p log2 p dimension messages for the largest power of two p, and two per node above it.
    int p = 1, log2p = 0;
    while (2 * p <= R) p *= 2, ++log2p;
    EXPECT_EQ(messages, p * log2p + 2 * (R - p)) << "R=" << R;
  }
}

// Every node holds the whole scene (section 2.2's first version) and two increment vectors:
// scene2 (832 patches, 18952 elements) needs 786432 + 2 x 88 + 832 x (68 + 48) + 18952 x 184
// + 2 x 18952 x 12 = 4825136 bytes on every node, whatever R, more than the nCube2's 4 MB.
TEST(ShooterScheme, EveryNodeHoldsTheWholeSceneAndScene2DoesNotFit) {
  const Scene scene = load_scene(repo("scenes/scene2.json"));
  ASSERT_EQ(scene.patches.size(), 832u);
  ASSERT_EQ(scene.element_total(), 18952);
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  for (int R : {1, 8, 64}) {
    const std::vector<NodeMemory> memory = node_memory(scene, shooters(R, 1), costs);
    ASSERT_EQ(memory.size(), std::size_t(R));
    for (const NodeMemory& m : memory) EXPECT_DOUBLE_EQ(m.bytes, 4825136.0) << "R=" << R;
    const OutOfMemory over = first_node_out_of_memory(scene, shooters(R, 1), platform, costs);
    EXPECT_EQ(over.node, 0);
    EXPECT_DOUBLE_EQ(over.needed_bytes, 4825136.0);
  }
}

// What the scheme cannot run: refused before anything is built (exit 2 at the command line).
TEST(ShooterScheme, RefusesWhatItCannotRun) {
  const Scene scene = load_scene(repo("scenes/scene0.json"));
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const auto refused = [&](const SimulationConfig& config) {
    try {
      check_configuration(scene, config, platform);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(refused(shooters(4, 1)), "");
  SimulationConfig config = shooters(4, 1);
  config.visibility_processors = 1;
  EXPECT_NE(refused(config).find("V=1"), std::string::npos) << refused(config);
  config = shooters(4, 1);
  config.options.subdivision.enabled = true;
  EXPECT_NE(refused(config).find("--subdivide"), std::string::npos);
  config = shooters(4, 1);
  config.balancing.enabled = true;
  EXPECT_NE(refused(config).find("--balance"), std::string::npos);
  config = shooters(4, 1);
  config.render.enabled = true;
  EXPECT_NE(refused(config).find("--render-parallel"), std::string::npos);
  config = shooters(4, 1);
  config.shooters_per_iteration = 5;
  EXPECT_NE(refused(config).find("--shooters-per-iteration 5"), std::string::npos);
  config.shooters_per_iteration = 4;
  EXPECT_EQ(refused(config), "");
  config.parallelisation = "receivers";  // the paper's program shoots one patch an iteration
  EXPECT_NE(refused(config).find("--shooters-per-iteration 4"), std::string::npos);
}

}  // namespace
}  // namespace ncube

// The circulation scheme built from the abstracts of Çapın, Aykanat & Özgüç (--parallelisation
// circulation; src/nodes/circulation_processor.h, src/nodes/ring_circulation.h, docs/model.md
// "The circulation opponent"), against values worked out independently: the sequential solver at
// R = 1 (the same radiosities to the last bit), the sequential solver to convergence at R = 4
// (the same physics, another order of shots: within a stated tolerance), the shares' best
// patches for the choice, the ring's messages and bytes in closed form, every node's memory by
// hand with the refusal at the 4 MB cap, and the configurations it refuses. Each TEST runs its
// own SimGrid Engine, hence its own process under ctest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "host/fast_occluders.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/placement.h"
#include "nodes/ring_circulation.h"
#include "scene/scene_loader.h"
#include "simulation/configuration_check.h"
#include "simulation/memory_check.h"
#include "simulation/simulation.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

SimulationConfig circulation(int R, int iterations) {
  SimulationConfig config;
  config.parallelisation = "circulation";
  config.radiosity_processors = R;
  config.options.samples = 16;
  config.options.max_iterations = iterations;
  return config;
}

SimulationResult run(const Scene& scene, const SimulationConfig& config) {
  return run_simulation(scene, config, load_platform_config(repo("platforms/ncube2.json")),
                        load_cost_model(repo("platforms/cost_model.json")));
}

std::vector<int> every_patch(const Scene& scene) {
  std::vector<int> all(scene.patches.size());
  std::iota(all.begin(), all.end(), 0);
  return all;
}

// One node owns every patch: its best is the global best, so the scheme is the sequential
// program (which the paper's program at R = 1 is to the last bit,
// tests/parallel_equivalence_test.cpp): the same shooters and radiosities to the last bit.
TEST(CirculationScheme, OneNodeGivesTheSequentialRadiosities) {
  const Scene scene = load_scene(repo("scenes/scene0.json"));
  const SimulationConfig scheme = circulation(1, 30);
  RadiosityEngine sequential(scene, every_patch(scene));
  const FastOccluders occluders(scene, every_patch(scene), scheme.options.ray_policy);
  const ProgressiveRun paper = run_progressive(sequential, occluders, scheme.options);
  const SimulationResult r = run(scene, scheme);
  ASSERT_EQ(r.status, RunStatus::kOk);
  EXPECT_EQ(r.iterations, 30);
  EXPECT_EQ(r.shooters, paper.shooters);
  for (int p = 0; p < int(scene.patches.size()); ++p) {
    const StoredPatch& expected = sequential.store().patches()[std::size_t(p)];
    ASSERT_EQ(r.solution[std::size_t(p)].radiosity.size(), expected.elements.size());
    for (std::size_t k = 0; k < expected.elements.size(); ++k)
      ASSERT_EQ(r.solution[std::size_t(p)].radiosity[k], expected.elements[k].radiosity)
          << "patch " << p << " element " << k;
  }
  EXPECT_EQ(r.counts.rays, paper.total.rays);
  EXPECT_EQ(r.counts.increments_combined, 0u);  // one node: nothing circulates
  EXPECT_EQ(r.nodes[0].messages_sent, 0);
}

// Same physics, another order of shots: to convergence at 1e-5 of the emitted power, the
// Cornell box on 4 nodes against the sequential program (the paper's program's answer) to the
// same criterion. Both stop with under 1e-5 of the emitted power unshot in any one patch, so
// their elements may differ by about what the remaining unshot light would still add; stated
// tolerance: the RMS of the per-element differences within 1e-4 of the RMS radiosity, and no
// element more than 0.2 % off its own value (measured with ./simulate at M = 16: 1.4e-6 and
// 1.9e-4, a tenth of the tolerances; at 1e-4 of the emitted power they would be ten times more).
TEST(CirculationScheme, ConvergesToTheSequentialAnswerOnFourNodes) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  SimulationConfig scheme = circulation(4, -1);
  scheme.options.convergence_fraction = 1e-5;
  RadiosityEngine sequential(scene, every_patch(scene));
  const FastOccluders occluders(scene, every_patch(scene), scheme.options.ray_policy);
  run_progressive(sequential, occluders, scheme.options);
  const SimulationResult r = run(scene, scheme);
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_TRUE(r.converged);
  double diff2 = 0.0, value2 = 0.0, worst = 0.0;
  int count = 0;
  for (int p = 0; p < int(scene.patches.size()); ++p) {
    const StoredPatch& expected = sequential.store().patches()[std::size_t(p)];
    for (std::size_t k = 0; k < expected.elements.size(); ++k) {
      const Rgb& a = r.solution[std::size_t(p)].radiosity[k];
      const Rgb& b = expected.elements[k].radiosity;
      const double d = std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
      const double v = b.r + b.g + b.b;
      diff2 += d * d;
      value2 += v * v;
      if (v > 0.0) worst = std::max(worst, d / v);
      ++count;
    }
  }
  ASSERT_EQ(count, 1078);
  EXPECT_LT(std::sqrt(diff2 / value2), 1e-4) << "relative RMS difference";
  EXPECT_LT(worst, 2e-3) << "largest relative element difference";
}

// Several shooters at once: after the light's shot (the only emitter, so the only candidate
// with power in iteration 1), every node's best owned patch as the sequential solver leaves
// them after one shot, best first; the shares are the paper's (partition_patches_by_elements).
TEST(CirculationScheme, ShootsEveryNodesBestPatch) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  ProgressiveOptions options;
  options.samples = 16;
  options.max_iterations = 1;
  RadiosityEngine sequential(scene, every_patch(scene));
  const FastOccluders occluders(scene, every_patch(scene), options.ray_policy);
  const ProgressiveRun first = run_progressive(sequential, occluders, options);
  std::vector<std::pair<double, int>> bests;  // (-power, patch) of each share's best
  for (const std::vector<int>& share : partition_patches_by_elements(scene, 4)) {
    std::pair<double, int> best{0.0, -1};
    for (int p : share) {
      const Rgb& u = sequential.unshot(p);
      best = std::min(best, {-(u.r + u.g + u.b) * scene.patches[std::size_t(p)].area, p});
    }
    ASSERT_LT(best.first, 0.0);
    bests.push_back(best);
  }
  std::sort(bests.begin(), bests.end());
  std::vector<int> expected = first.shooters;
  for (const auto& b : bests) expected.push_back(b.second);
  const SimulationResult r = run(scene, circulation(4, 2));
  ASSERT_EQ(r.status, RunStatus::kOk);
  EXPECT_EQ(r.shooters, expected);
}

// The ring's messages in closed form. R = 4, k = 2 iterations on the Cornell box (1078
// elements, E_j elements owned by rank j): every iteration, and once more for the decision
// that ends the run, each node passes R - 1 = 3 candidates of 88 + 8 bytes; every iteration
// each node passes R - 1 = 3 blocks, those of the other owners, 12 E_j + 8 bytes each. So a
// node sends 3 (k + 1) + 3 k = 15 messages and receives as many; over the machine
// (k + 1) R (R - 1) 96 + k (R - 1) (12 E + 8 R) = 3456 + 2 x 3 x 12968 = 81264 bytes. A node
// adds its increments to every block it receives, every owner's but its ring predecessor's
// (that block starts at it, taken from its own vector): k (E - E_predecessor) adds.
TEST(CirculationScheme, RingMessagesInClosedForm) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  ASSERT_EQ(scene.element_total(), 1078);
  const int R = 4, k = 2;
  const std::vector<std::vector<int>> shares = partition_patches_by_elements(scene, R);
  const SimulationResult r = run(scene, circulation(R, k));
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.nodes.size(), std::size_t(R));
  double total = 0.0;
  const auto elements_of = [&](int rank) {
    double count = 0.0;
    for (int p : shares[std::size_t(rank)]) count += scene.patches[std::size_t(p)].element_count();
    return count;
  };
  for (int rank = 0; rank < R; ++rank) {
    const double own = elements_of(rank);
    const int predecessor =
        RingCirculation::rank_at((RingCirculation::position_of(rank, R) + R - 1) % R, R);
    const NodeStats& n = r.nodes[std::size_t(rank)];
    EXPECT_EQ(n.messages_sent, 15) << "rank " << rank;
    EXPECT_EQ(n.messages_received, 15) << "rank " << rank;
    EXPECT_DOUBLE_EQ(n.bytes_sent, (k + 1) * 3 * 96.0 + k * (12.0 * (1078 - own) + 3 * 8.0))
        << "rank " << rank;
    EXPECT_DOUBLE_EQ(double(n.counts.increments_combined), k * (1078 - elements_of(predecessor)))
        << "rank " << rank;
    EXPECT_DOUBLE_EQ(double(n.counts.increments_applied), k * own) << "rank " << rank;
    total += n.bytes_sent;
  }
  EXPECT_DOUBLE_EQ(total, 81264.0);
}

// The ring is a Gray code when R is a power of two: ring neighbours differ in one bit, so
// every step is one hypercube hop; the positions are a permutation of the ranks.
TEST(CirculationScheme, RingNeighboursAreHypercubeNeighbours) {
  for (int R : {2, 4, 8, 16, 64}) {
    std::vector<int> seen;
    for (int i = 0; i < R; ++i) {
      const int a = RingCirculation::rank_at(i, R), b = RingCirculation::rank_at((i + 1) % R, R);
      EXPECT_EQ(__builtin_popcount(unsigned(a ^ b)), 1) << "R=" << R << " position " << i;
      EXPECT_EQ(RingCirculation::position_of(a, R), i);
      seen.push_back(a);
    }
    std::sort(seen.begin(), seen.end());
    for (int i = 0; i < R; ++i) EXPECT_EQ(seen[std::size_t(i)], i);
  }
  EXPECT_EQ(RingCirculation::rank_at(2, 3), 2);  // not a power of two: rank order
}

// Memory as the source holds it (docs/model.md): scene2 (832 patches, 18952 elements) on one
// node needs 786432 + 2 x 88 + 832 x 68 + 18952 x 12 + 2 x 18952 x 12 + 832 x 48 + 18952 x 184
// = 5052560 bytes, over the nCube2's 4 MB (refused, exit 3); on two nodes each holds half the
// elements and it fits, where the `shooters` variant does not fit at any R.
TEST(CirculationScheme, MemoryByHandAndTheCap) {
  const Scene scene = load_scene(repo("scenes/scene2.json"));
  ASSERT_EQ(scene.patches.size(), 832u);
  ASSERT_EQ(scene.element_total(), 18952);
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const std::vector<NodeMemory> one = node_memory(scene, circulation(1, 1), costs);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_DOUBLE_EQ(one[0].bytes, 5052560.0);
  const OutOfMemory over = first_node_out_of_memory(scene, circulation(1, 1), platform, costs);
  EXPECT_EQ(over.node, 0);
  EXPECT_DOUBLE_EQ(over.needed_bytes, 5052560.0);
  const std::vector<std::vector<int>> shares = partition_patches_by_elements(scene, 2);
  double own[2] = {0.0, 0.0};
  for (int rank = 0; rank < 2; ++rank)
    for (int p : shares[std::size_t(rank)]) own[rank] += scene.patches[std::size_t(p)].element_count();
  const double largest = std::max(own[0], own[1]);
  const std::vector<NodeMemory> two = node_memory(scene, circulation(2, 1), costs);
  for (int rank = 0; rank < 2; ++rank)
    EXPECT_DOUBLE_EQ(two[std::size_t(rank)].bytes,
                     786432 + 3 * 88 + 832 * 68 + 18952 * 12 + 2 * largest * 12 +
                         double(shares[std::size_t(rank)].size()) * 48 + own[rank] * 184)
        << "rank " << rank;
  EXPECT_EQ(first_node_out_of_memory(scene, circulation(2, 1), platform, costs).node, -1);
}

TEST(CirculationScheme, RefusesWhatItCannotRun) {
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
  EXPECT_EQ(refused(circulation(4, 1)), "");
  SimulationConfig config = circulation(4, 1);
  config.visibility_processors = 1;
  EXPECT_NE(refused(config).find("V=1"), std::string::npos) << refused(config);
  config = circulation(4, 1);
  config.options.subdivision.enabled = true;
  EXPECT_NE(refused(config).find("--subdivide"), std::string::npos);
  config = circulation(4, 1);
  config.balancing.enabled = true;
  EXPECT_NE(refused(config).find("--balance"), std::string::npos);
  config = circulation(4, 1);
  config.render.enabled = true;
  EXPECT_NE(refused(config).find("--render-parallel"), std::string::npos);
  config = circulation(4, 1);
  config.shooters_per_iteration = 5;
  EXPECT_NE(refused(config).find("--shooters-per-iteration 5"), std::string::npos);
  config.shooters_per_iteration = 2;
  EXPECT_EQ(refused(config), "");
}

}  // namespace
}  // namespace ncube

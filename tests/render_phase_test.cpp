// The simulated rendering phase (paper section 2.3, --render-parallel): the picture
// assembled from the nodes' parts is the sequential render pixel for pixel, for both
// partitions, both distributions and several node counts; and on the hand-counted scene
// every message and byte of the phase, and each node's memory, against values worked out
// below. Each TEST runs its own SimGrid Engine, hence its own process under ctest.
#include <gtest/gtest.h>

#include <tuple>

#include "hand_counted_scene.h"
#include "simulated_machine.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "render/rasterizer.h"
#include "render/render_records.h"
#include "simulation/render_phase.h"
#include "scene/scene_loader.h"
#include "simulation/simulation.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

constexpr double kOverheadPerMessage = 80e-6;  // LogP (Culler et al. 1993), per side

SimulationConfig render_config(int R, int V, RowPartition partition,
                               RenderDistribution distribution, int width, int height,
                               int iterations) {
  SimulationConfig config;
  config.radiosity_processors = R;
  config.visibility_processors = V;
  config.options.samples = 4;
  config.options.max_iterations = iterations;
  config.render = {true, partition, distribution, width, height};
  return config;
}

SimulationResult run(const Scene& scene, const SimulationConfig& config) {
  return run_simulation(scene, config, load_platform_config(repo("platforms/ncube2.json")),
                        load_cost_model(repo("platforms/cost_model.json")));
}

// ------------------------------------------------ the picture is the sequential picture

// (partition, distribution, R, V): N = R (V + 1) nodes, among them 3 and 6 (not powers of
// two: ring only), and a picture height (47) that no N divides.
using PictureCase = std::tuple<RowPartition, RenderDistribution, int, int>;
class RenderPhasePicture : public testing::TestWithParam<PictureCase> {};

std::string case_name(const testing::TestParamInfo<PictureCase>& info) {
  const auto [partition, distribution, R, V] = info.param;
  return std::string(row_partition_name(partition)) + "_" + render_distribution_name(distribution) +
         "_R" + std::to_string(R) + "V" + std::to_string(V);
}

TEST_P(RenderPhasePicture, IsTheSequentialRenderPixelForPixel) {
  const auto [partition, distribution, R, V] = GetParam();
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const SimulationResult r =
      run(scene, render_config(R, V, partition, distribution, 61, 47, 6));
  ASSERT_EQ(r.status, RunStatus::kOk) << r.failure;
  ASSERT_TRUE(r.render.ran);
  ASSERT_EQ(r.render.nodes.size(), std::size_t(R * (V + 1)));
  const Image sequential = render_solution(scene, scene.camera, uniform_solution(scene, r.element_radiosity), 61, 47);
  ASSERT_EQ(r.render.picture.width, 61);
  ASSERT_EQ(r.render.picture.height, 47);
  int lit = 0;
  for (const glm::vec3& p : sequential.pixels) lit += p.r + p.g + p.b > 0.1f;
  ASSERT_GT(lit, 61 * 47 / 2) << "the comparison needs a picture with something in it";
  EXPECT_EQ(encode_png(r.render.picture), encode_png(sequential));
  for (int y = 0; y < 47; ++y)
    for (int x = 0; x < 61; ++x)
      ASSERT_EQ(r.render.picture.at(x, y), sequential.at(x, y)) << "pixel " << x << ", " << y;
  int rows = 0;
  for (const RenderNodeStats& n : r.render.nodes) rows += n.rows;
  EXPECT_EQ(rows, 47);
}

INSTANTIATE_TEST_SUITE_P(
    PowersOfTwo, RenderPhasePicture,
    testing::Combine(testing::Values(RowPartition::kBlocks, RowPartition::kScanlines),
                     testing::Values(RenderDistribution::kRing, RenderDistribution::kHypercube),
                     testing::Values(1, 2, 4), testing::Values(0, 1)),
    case_name);
INSTANTIATE_TEST_SUITE_P(
    RingOnOddCounts, RenderPhasePicture,
    testing::Combine(testing::Values(RowPartition::kBlocks, RowPartition::kScanlines),
                     testing::Values(RenderDistribution::kRing), testing::Values(3),
                     testing::Values(0, 1)),
    case_name);

// ------------------------------------------------ hand-counted messages, bytes, memory

// The hand-counted scene (tests/hand_counted_scene.h) with R = 2, V = 1: N = 4 nodes.
// Node 0 is radiosity processor 0 with patches {0, 1} (light and floor: 6 elements), node
// 2 radiosity processor 1 with {2, 3} (table and wall: 5 elements); the visibility
// processors 1 and 3 start with no elements. A 16 x 16 picture, blocks of 4 rows.
// Record sizes of platforms/cost_model.json: an element 104 bytes, a message header 8, a
// round's histograms 2 x (256 x 4 + 8) = 2064, a round's selection 2 x (8 + 4 + 8) = 40, a
// pixel 3.
// The camera looks at the scene from z = 8 (the scene's default camera sees nothing).
Scene hand_counted_in_view() {
  Scene scene = hand_counted_scene();
  scene.camera.eye = Vec3(2.5, 1.0, 8.0);
  scene.camera.look_at = Vec3(2.5, 1.0, 0.0);
  return scene;
}

constexpr double kHeader = 8, kRecord = 104, kHistogram = 2064 + 8, kSelection = 40 + 8;
constexpr double kPiece = 4 * 16 * 3 + 8;  // a node's 4 rows of 16 pixels

// Exposure (8 rounds, a binomial tree over nodes 0..3): histograms go 1 -> 0, 3 -> 2,
// 2 -> 0; the selection 0 -> 2, 0 -> 1, 2 -> 3. The gather: 1, 2 and 3 send their rows to 0.
//
// Ring (Gray code: 0 -> 1 -> 3 -> 2 -> 0), N - 1 = 3 steps: in step s a node sends what it
// received in step s - 1 (its own share in step 1) and, in steps 1 and 2, returns a credit
// (a bare header) to its predecessor once it has taken the message.
//   node 0 sends: own 6 records, then node 2's 5, then node 3's 0;
//   node 1 sends: own 0, node 0's 6, node 2's 5;
//   node 3 sends: own 0, node 1's 0, node 0's 6;
//   node 2 sends: own 5, node 3's 0, node 1's 0.
TEST(RenderPhaseMessages, RingOfFourNodes) {
  const SimulationResult r = run(hand_counted_in_view(),
                                 render_config(2, 1, RowPartition::kBlocks,
                                               RenderDistribution::kRing, 16, 16, 1));
  ASSERT_EQ(r.status, RunStatus::kOk) << r.failure;
  ASSERT_EQ(r.render.nodes.size(), 4u);
  const auto elements = [](double records) { return records * kRecord + kHeader; };
  const double credits = 2 * kHeader;
  struct Want { long sent; double bytes; long received; };
  const Want want[4] = {
      // node 0: 3 element messages, 2 credits, 8 x 2 selections; receives 3 + 2, 8 x 2
      // histograms (from 1 and 2) and 3 pieces.
      {3 + 2 + 16, elements(6) + elements(5) + elements(0) + credits + 16 * kSelection,
       3 + 2 + 16 + 3},
      // node 1: 3 + 2, 8 histograms, its piece; receives 3 + 2 and 8 selections.
      {3 + 2 + 8 + 1, elements(0) + elements(6) + elements(5) + credits + 8 * kHistogram + kPiece,
       3 + 2 + 8},
      // node 2: 3 + 2, 8 histograms to node 0, 8 selections to node 3, its piece; receives
      // 3 + 2, 8 histograms (from 3) and 8 selections (from 0).
      {3 + 2 + 8 + 8 + 1,
       elements(5) + elements(0) + elements(0) + credits + 8 * kHistogram + 8 * kSelection + kPiece,
       3 + 2 + 8 + 8},
      // node 3: like node 1.
      {3 + 2 + 8 + 1, elements(0) + elements(0) + elements(6) + credits + 8 * kHistogram + kPiece,
       3 + 2 + 8},
  };
  for (int node = 0; node < 4; ++node) {
    const NodeStats& n = r.render.nodes[std::size_t(node)].stats;
    EXPECT_EQ(n.messages_sent, want[node].sent) << "node " << node;
    EXPECT_DOUBLE_EQ(n.bytes_sent, want[node].bytes) << "node " << node;
    EXPECT_EQ(n.messages_received, want[node].received) << "node " << node;
    EXPECT_NEAR(n.overhead_seconds, double(want[node].sent + want[node].received) * kOverheadPerMessage,
                1e-12) << "node " << node;
    EXPECT_EQ(r.render.nodes[std::size_t(node)].rows, 4) << "node " << node;
  }
  // Time from counted work, at the values of platforms/cost_model.json's rendering
  // parameters (counted flops: vertex 19, clip vertex 21, projection 10, triangle 26 + 6 = 32,
  // sample tested 26, inside 7, written 19; exposure sample 6, bucket 1, pixel 180) on a
  // 2.5 Mflop/s node (paper section 5).
  for (const RenderNodeStats& n : r.render.nodes) {
    const RenderCounts& c = n.counts;
    const double rasterise = (19.0 * c.vertices + 21.0 * c.clip_vertices + 10.0 * c.projected_vertices +
                              32.0 * c.triangles + 26.0 * c.samples_tested + 7.0 * c.samples_inside +
                              19.0 * c.samples_written) / 2.5e6;
    const double rest = (6.0 * c.exposure_samples + 1.0 * c.histogram_buckets + 180.0 * c.pixels_resolved) / 2.5e6;
    EXPECT_NEAR(n.rasterise_seconds, rasterise, 1e-12) << n.stats.node;
    EXPECT_NEAR(n.stats.compute_seconds, rasterise + rest, 1e-12) << n.stats.node;
    EXPECT_EQ(c.pixels_resolved, 4u * 16u) << n.stats.node;
    EXPECT_EQ(c.vertices, 11u * 4u) << n.stats.node;  // every node sees all 11 quads
  }
  std::uint64_t tested = 0;
  for (const RenderNodeStats& n : r.render.nodes) tested += n.counts.samples_tested;
  ASSERT_GT(tested, 0u) << "the camera must see the scene for the time check to mean anything";
  // Histograms added: node 0 gets 2 children per round, node 2 one: 512 buckets each.
  EXPECT_EQ(r.render.nodes[0].counts.histogram_buckets, 8u * 2u * 512u);
  EXPECT_EQ(r.render.nodes[2].counts.histogram_buckets, 8u * 512u);
  // The radiosity run's statistics are kept apart: there visibility processor 1 sent one
  // answer (rank 0's 5 points are one block of the default 100).
  EXPECT_EQ(r.nodes[1].messages_sent, 1);
}

// Hypercube, log2 4 = 2 steps: step 0 pairs 0-1 and 2-3, step 1 pairs 0-2 and 1-3; each
// sends all it holds. Node 0: own 6, then {0, 1} = 6; node 1: 0, then {1, 0} = 6; node 2:
// 5, then {2, 3} = 5; node 3: 0, then {3, 2} = 5. No credits.
TEST(RenderPhaseMessages, HypercubeOfFourNodes) {
  const SimulationResult r = run(hand_counted_scene(),
                                 render_config(2, 1, RowPartition::kScanlines,
                                               RenderDistribution::kHypercube, 16, 16, 1));
  ASSERT_EQ(r.status, RunStatus::kOk) << r.failure;
  const double records[4][2] = {{6, 6}, {0, 6}, {5, 5}, {0, 5}};
  const double exposure[4] = {16 * kSelection, 8 * kHistogram, 8 * kHistogram + 8 * kSelection,
                              8 * kHistogram};
  const long exposure_messages[4] = {16, 8, 16, 8};
  for (int node = 0; node < 4; ++node) {
    const NodeStats& n = r.render.nodes[std::size_t(node)].stats;
    const double piece = node == 0 ? 0.0 : kPiece;  // scanlines: 4 rows each too
    EXPECT_EQ(n.messages_sent, 2 + exposure_messages[node] + (node == 0 ? 0 : 1)) << node;
    EXPECT_DOUBLE_EQ(n.bytes_sent, (records[node][0] + records[node][1]) * kRecord + 2 * kHeader +
                                       exposure[node] + piece) << node;
  }
}

// Memory (R = 4, V = 0 on the hand-counted scene: the ranks own 5 (floor), 3 (table), 2
// (wall) and 1 (light) elements; 4 nodes, a 16 x 16 picture, blocks of 4 rows).
// Frame share: 4 rows x 16 x 9 samples x 20 bytes = 11,520. Ring 0 -> 1 -> 3 -> 2 -> 0: node
// 0 holds at most its own 5 with node 2's 2 arriving (7 records); node 1 its own 3 with node
// 0's 5 (8). Hypercube: in the end all 11. Reserve 786,432 bytes.
TEST(RenderPhaseMemory, RingHoldsTwoSharesHypercubeAll) {
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const std::vector<PatchSolution> solution =
      uniform_solution(scene, std::vector<Rgb>(std::size_t(scene.element_total()), Rgb(0.0)));
  RenderOptions options{true, RowPartition::kBlocks, RenderDistribution::kRing, 16, 16};
  const double base = 786432 + 11520;
  const std::vector<double> ring = render_memory(scene, options, 4, 0, solution, costs);
  ASSERT_EQ(ring.size(), 4u);
  EXPECT_DOUBLE_EQ(ring[0], base + 7 * 104);
  EXPECT_DOUBLE_EQ(ring[1], base + 8 * 104);
  options.distribution = RenderDistribution::kHypercube;
  for (double bytes : render_memory(scene, options, 4, 0, solution, costs)) EXPECT_DOUBLE_EQ(bytes, base + 11 * 104);
  // 800 x 600 in 4 parts: resolving, a node holds its frame share (150 rows x 800 x 9 x 20
  // bytes = 21.6 MB) and its finished rows (150 x 800 x 3 = 360,000 bytes), more than the
  // frame share and the 11 records while distributing.
  options = {true, RowPartition::kScanlines, RenderDistribution::kHypercube, 800, 600};
  EXPECT_DOUBLE_EQ(render_memory(scene, options, 4, 0, solution, costs)[1], 786432 + 21600000 + 360000);
}

TEST(RenderPhaseMemory, FrameBeyondTheNodeIsOutOfMemory) {
  const Scene scene = hand_counted_scene();
  SimulationConfig config = render_config(1, 0, RowPartition::kBlocks,
                                          RenderDistribution::kHypercube, 800, 600, 1);
  const OutOfMemory oom = first_node_out_of_memory(
      scene, config, load_platform_config(repo("platforms/ncube2.json")),
      load_cost_model(repo("platforms/cost_model.json")));
  EXPECT_EQ(oom.node, 0);
  EXPECT_EQ(oom.role, NodeRole::kRendering);
  // The whole frame (86.4 MB) and the whole picture's pixels (1.44 MB) while resolving.
  EXPECT_DOUBLE_EQ(oom.needed_bytes, 786432 + 600 * 800 * 9 * 20.0 + 600 * 800 * 3);
  config.render.enabled = false;
  EXPECT_EQ(first_node_out_of_memory(scene, config, load_platform_config(repo("platforms/ncube2.json")),
                                     load_cost_model(repo("platforms/cost_model.json"))).node, -1);
}

// ------------------------------------------------ the adaptive mesh (section 4.1)

// Replaces element k of patch p's solution by its four children, with radiosities `b` + 0.1 c
// for child c.
void subdivide(std::vector<PatchSolution>& solution, int p, std::size_t k, const Rgb& b) {
  PatchSolution& s = solution[std::size_t(p)];
  const std::array<ElementCell, 4> children = s.cells[k].children();
  s.cells.erase(s.cells.begin() + long(k));
  s.radiosity.erase(s.radiosity.begin() + long(k));
  for (int c = 3; c >= 0; --c) {
    s.cells.insert(s.cells.begin() + long(k), children[std::size_t(c)]);
    s.radiosity.insert(s.radiosity.begin() + long(k), b + Rgb(0.1 * c));
  }
}

// The hand-counted scene's wall (patch 3, 1 x 2 elements) with its first element cut in four:
// 5 records, and the wall's second element carries the children's shared corner on its edge
// (1 T-vertex). A record is 104 bytes, a T-vertex 24 more (platforms/cost_model.json).
std::vector<PatchSolution> hand_counted_with_a_cut_wall(const Scene& scene) {
  std::vector<PatchSolution> solution =
      uniform_solution(scene, std::vector<Rgb>(std::size_t(scene.element_total()), Rgb(0.3)));
  subdivide(solution, 3, 0, Rgb(0.5));
  return solution;
}
constexpr double kTVertex = 24;

// Memory with the cut wall, R = 4, V = 0 as above: node 2 (the wall's rank) starts with 5
// records and 1 T-vertex, 544 bytes. Ring 0 -> 1 -> 3 -> 2 -> 0: node 0 holds its own 5 with
// node 2's arriving, node 1 node 0's 5 with node 2's passing on (both 10 records and the
// T-vertex); hypercube: all 14 records and the T-vertex.
TEST(RenderPhaseMemory, TVerticesAddTheirBytes) {
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const std::vector<PatchSolution> solution = hand_counted_with_a_cut_wall(scene);
  RenderOptions options{true, RowPartition::kBlocks, RenderDistribution::kRing, 16, 16};
  const double base = 786432 + 11520;
  const std::vector<double> ring = render_memory(scene, options, 4, 0, solution, costs);
  EXPECT_DOUBLE_EQ(ring[0], base + 10 * kRecord + kTVertex);
  EXPECT_DOUBLE_EQ(ring[1], base + 10 * kRecord + kTVertex);
  options.distribution = RenderDistribution::kHypercube;
  for (double bytes : render_memory(scene, options, 4, 0, solution, costs))
    EXPECT_DOUBLE_EQ(bytes, base + 14 * kRecord + kTVertex);
}

// The hypercube of four nodes above (R = 2, V = 1) with the cut wall: node 2's share (table
// and wall) is now 8 records and the T-vertex.
TEST(RenderPhaseMessages, TVerticesAreSent) {
  SimulatedMachine machine;
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const RenderOptions options{true, RowPartition::kScanlines, RenderDistribution::kHypercube, 16, 16};
  const RenderResult r = run_render_phase(scene, options, 2, 1, hand_counted_with_a_cut_wall(scene),
                                          machine.hosts, machine.platform, costs, true, nullptr);
  ASSERT_TRUE(r.ran) << r.failure;
  ASSERT_TRUE(r.failure.empty()) << r.failure;
  const double records[4][2] = {{6, 6}, {0, 6}, {8, 8}, {0, 8}};
  const double t_vertices[4][2] = {{0, 0}, {0, 0}, {1, 1}, {0, 1}};
  const double exposure[4] = {16 * kSelection, 8 * kHistogram, 8 * kHistogram + 8 * kSelection,
                              8 * kHistogram};
  for (int node = 0; node < 4; ++node) {
    const double piece = node == 0 ? 0.0 : kPiece;
    EXPECT_DOUBLE_EQ(r.nodes[std::size_t(node)].stats.bytes_sent,
                     (records[node][0] + records[node][1]) * kRecord +
                         (t_vertices[node][0] + t_vertices[node][1]) * kTVertex + 2 * kHeader +
                         exposure[node] + piece) << node;
  }
}

// Out of memory at render time, from the solution's records: a node that fits the
// level-0 records but not the subdivided ones stops the phase, naming the node.
TEST(RenderPhaseMemory, RecordsBeyondTheNodeStopThePhase) {
  SimulatedMachine machine;
  const Scene scene = hand_counted_scene();
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const RenderOptions options{true, RowPartition::kBlocks, RenderDistribution::kHypercube, 16, 16};
  const std::vector<PatchSolution> solution = hand_counted_with_a_cut_wall(scene);
  PlatformConfig platform = machine.platform;
  // Room for the level-0 records (11) but not for the cut wall's (14 and a T-vertex).
  platform.node_memory = 786432 + 11520 + 12 * kRecord;
  const RenderResult r = run_render_phase(scene, options, 2, 1, solution, machine.hosts, platform,
                                          costs, true, nullptr);
  EXPECT_FALSE(r.ran);
  EXPECT_EQ(r.out_of_memory_node, 0);
  EXPECT_DOUBLE_EQ(r.out_of_memory_bytes, 786432 + 11520 + 14 * kRecord + kTVertex);
}

// The picture of the rendering phase with a subdivided solution (T-vertices on many
// patches) is the sequential render pixel for pixel, for both partitions and distributions.
TEST(RenderPhaseAdaptiveMesh, ParallelIsTheSequentialPicture) {
  SimulatedMachine machine;
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  std::vector<Rgb> radiosity;
  for (long e = 0; e < scene.element_total(); ++e)
    radiosity.push_back(Rgb(0.2 + 0.05 * double(e % 7), 0.3, 0.1 + 0.02 * double(e % 11)));
  std::vector<PatchSolution> solution = uniform_solution(scene, radiosity);
  for (std::size_t p = 0; p < solution.size(); p += 2) {
    subdivide(solution, int(p), 0, Rgb(0.6, 0.2, 0.4));
    subdivide(solution, int(p), 1, Rgb(0.1, 0.5, 0.3));  // a child, next to its siblings
  }
  int t_vertices = 0;
  std::vector<int> all(scene.patches.size());
  for (std::size_t p = 0; p < all.size(); ++p) all[p] = int(p);
  for (const RenderElement& e : render_elements(scene, solution, all)) t_vertices += e.t_vertices();
  ASSERT_GT(t_vertices, 10);
  const Image sequential = render_solution(scene, scene.camera, solution, 61, 47);
  for (const RenderOptions& options :
       {RenderOptions{true, RowPartition::kBlocks, RenderDistribution::kRing, 61, 47},
        RenderOptions{true, RowPartition::kScanlines, RenderDistribution::kHypercube, 61, 47}}) {
    const RenderResult r = run_render_phase(scene, options, 4, 1, solution, machine.hosts,
                                            machine.platform, costs, true, nullptr);
    ASSERT_TRUE(r.ran && r.failure.empty()) << r.failure;
    EXPECT_EQ(encode_png(r.picture), encode_png(sequential));
    for (int y = 0; y < 47; ++y)
      for (int x = 0; x < 61; ++x)
        ASSERT_EQ(r.picture.at(x, y), sequential.at(x, y)) << "pixel " << x << ", " << y;
  }
}

// Two coplanar, overlapping patches, both subdivided, on different nodes: every sample where
// they overlap is a depth tie (or nearly), which the drawing key must settle as the
// sequential scene-order drawing does, whatever order the records arrive in.
TEST(RenderPhaseAdaptiveMesh, DepthTiesOfSubdividedPatchesResolveAsInSceneOrder) {
  SimulatedMachine machine;
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  Scene scene;
  for (const Vec3& centre : {Vec3(0, 0, -5), Vec3(0.5, 0.3, -5)})
    scene.patches.push_back(hand_counted_patch(centre - Vec3(1, 1, 0), Vec3(2, 0, 0), Vec3(0, 2, 0),
                                               centre.x > 0 ? 0.0 : 1.0, 3, 2));
  scene.build_elements();
  scene.camera.eye = Vec3(0.0);
  scene.camera.look_at = Vec3(0, 0, -1);
  scene.camera.up = Vec3(0, 1, 0);
  scene.camera.fov_deg = 90.0;
  std::vector<Rgb> radiosity;
  for (long e = 0; e < scene.element_total(); ++e)
    radiosity.push_back(e < 6 ? Rgb(1.0, 0.1 * double(e), 0.0) : Rgb(0.0, 0.1 * double(e), 1.0));
  std::vector<PatchSolution> solution = uniform_solution(scene, radiosity);
  subdivide(solution, 0, 4, Rgb(0.9, 0.2, 0.0));
  subdivide(solution, 1, 0, Rgb(0.0, 0.2, 0.9));
  subdivide(solution, 1, 3, Rgb(0.0, 0.7, 0.5));
  const Image sequential = render_solution(scene, scene.camera, solution, 40, 30);
  for (RenderDistribution distribution : {RenderDistribution::kRing, RenderDistribution::kHypercube}) {
    const RenderOptions options{true, RowPartition::kScanlines, distribution, 40, 30};
    const RenderResult r = run_render_phase(scene, options, 2, 0, solution, machine.hosts,
                                            machine.platform, costs, true, nullptr);
    ASSERT_TRUE(r.ran && r.failure.empty()) << r.failure;
    EXPECT_EQ(r.picture.pixels, sequential.pixels) << render_distribution_name(distribution);
  }
}

TEST(RenderPhaseConfiguration, HypercubeNeedsAPowerOfTwo) {
  const Scene scene = hand_counted_scene();
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  SimulationConfig config = render_config(3, 0, RowPartition::kBlocks,
                                          RenderDistribution::kHypercube, 16, 16, 1);
  EXPECT_THROW(check_configuration(scene, config, platform), InputError);
  config.render.distribution = RenderDistribution::kRing;
  EXPECT_NO_THROW(check_configuration(scene, config, platform));
}

}  // namespace
}  // namespace ncube

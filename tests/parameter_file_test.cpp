#include "machine/parameter_file.h"

#include <cstdio>
#include <unistd.h>
#include <fstream>
#include <gtest/gtest.h>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

std::string write_temp(const std::string& text) {
  // One file per test and process: ctest runs the tests of this file in parallel.
  const std::string path = ::testing::TempDir() + "params-" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                           "-" + std::to_string(::getpid()) + ".json";
  std::ofstream(path) << text;
  return path;
}

// The reader's own specs, a machine's seven as they were when this test was written (the
// platform loader's come from src/machine/machine_parameters.h: machine_parameters_test).
const std::vector<ParameterSpec> kSpecs = {
    {"dimension", 0, true, 13},      {"node_speed", 1e3, false, 1e15},
    {"node_memory", 1, true, 0x1p50}, {"link_bandwidth", 1e3, false, 1e15},
    {"hop_latency", 0, false, 1},    {"send_overhead", 0, false, 1},
    {"receive_overhead", 0, false, 1, "s"}};

std::string error_of(const std::string& text) {
  try {
    read_parameter_file(write_temp(text), kPlatformFile, kSpecs);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kValid = R"({"description": "x", "parameters": {
  "dimension": {"value": 3}, "node_speed": {"value": 1e6}, "node_memory": {"value": 1000},
  "link_bandwidth": {"value": 1e6}, "hop_latency": {"value": 1e-6},
  "send_overhead": {"value": 1e-5}, "receive_overhead": {"value": 1e-5}}})";

std::string with(const std::string& from, const std::string& to) {
  std::string text = kValid;
  text.replace(text.find(from), from.size(), to);
  return text;
}

TEST(ParameterFile, ReadsTheShippedPlatformAndCostModel) {
  const PlatformConfig p = load_platform_config(repo("platforms/ncube2.json"));
  EXPECT_EQ(p.node_count(), 64);
  EXPECT_DOUBLE_EQ(p.node_speed, 2.5e6);
  EXPECT_DOUBLE_EQ(p.node_memory, 4194304);
  const CostModel c = load_cost_model(repo("platforms/cost_model.json"));
  EXPECT_GT(c.flops_per_ray_patch_test, 0.0);
  EXPECT_GT(c.element_bytes, 0.0);
}

TEST(ParameterFile, ValidFileLoads) { EXPECT_EQ(error_of(kValid), ""); }

TEST(ParameterFile, NamesTheParameterThatIsWrong) {
  EXPECT_NE(error_of(with(R"("dimension": {"value": 3})", R"("dimension": {"value": 2.5})"))
                .find("\"dimension\": value 2.5 must be a whole number"),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("dimension": {"value": 3})", R"("dimension": {"value": 40})"))
                .find("\"dimension\": value 40 is above"),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("node_speed": {"value": 1e6})", R"("node_speed": {"value": -1})"))
                .find("\"node_speed\": value -1 is below"),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("node_speed": {"value": 1e6})", R"("node_sped": {"value": 1e6})"))
                .find("\"node_speed\": missing"),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("hop_latency": {"value": 1e-6})", R"("hop_latency": {"value": "fast"})"))
                .find("\"hop_latency\": expected"),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("description": "x",)", R"("description": "x", "extra": 1,)"))
                .find("unknown key \"extra\""),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("hop_latency": {"value": 1e-6})", R"("hop_latency": {"value": 1e-6, "units": "s"})"))
                .find("unknown key \"units\""),
            std::string::npos);
  EXPECT_NE(error_of(with(R"("receive_overhead": {"value": 1e-5})",
                          R"("receive_overhead": {"value": 1e-5, "unit": "ms"})"))
                .find("\"receive_overhead\": unit \"ms\" is not \"s\""),
            std::string::npos);
  EXPECT_EQ(error_of(with(R"("receive_overhead": {"value": 1e-5})",
                          R"("receive_overhead": {"value": 1e-5, "unit": "s"})")),
            "");
  EXPECT_NE(error_of("{ not json").find("malformed JSON"), std::string::npos);
  EXPECT_NE(error_of(std::string(kValid).substr(0, std::string(kValid).size() - 2) +
                     R"(, "turbo": {"value": 1}}})")
                .find("unknown parameter \"turbo\""),
            std::string::npos);
}

TEST(ParameterFile, MissingFileIsNamed) {
  try {
    load_cost_model("/nonexistent/cost.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/cost.json: cannot open cost model: No such file or directory"), std::string::npos);
  }
}

}  // namespace
}  // namespace ncube

namespace ncube {
namespace {

// Octree visibility (section 6): its work is charged at parameters counted from the code
// (docs/model.md, "Octree visibility"), none fitted: a slab test 3 x 8 flops, an overlap
// test 6 compares, a cell's share of its parent's centre 6 / 8.
TEST(ParameterFile, OctreeWorkIsChargedAtItsCountedParameters) {
  const CostModel c = load_cost_model(repo("platforms/cost_model.json"));
  WorkCounts work;
  work.octree_cells_visited = 2;
  work.octree_overlap_tests = 3;
  work.octree_cells_built = 8;
  EXPECT_DOUBLE_EQ(c.flops(work), 2 * 24 + 3 * 6 + 8 * 0.75);
}

}  // namespace
}  // namespace ncube

// The cost model and the counters' lists (counts/work_counts.h, counts/render_counts.h,
// machine/cost_model.h): every counter has its parameter, loaded, charged and reported.
#include "machine/cost_model.h"

#include <cstdio>
#include <fstream>
#include <set>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "simulation/result_file.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

nlohmann::json shipped() {
  std::ifstream in(repo("platforms/cost_model.json"));
  return nlohmann::json::parse(in);
}

// The error of loading the shipped cost model without `parameter` ("" if none).
std::string error_without(const std::string& parameter) {
  nlohmann::json file = shipped();
  file["parameters"].erase(parameter);
  const std::string path = ::testing::TempDir() + "cost-without-" + parameter + "-" +
                           std::to_string(::getpid()) + ".json";
  std::ofstream(path) << file.dump();
  std::string error;
  try {
    load_cost_model(path);
  } catch (const InputError& e) {
    error = e.what();
  }
  std::remove(path.c_str());  // the test leaves nothing behind in the temporary folder
  return error;
}

// Generated from the lists: every counter's flops parameter (and every data size) must be in
// the file, and its absence is named.
TEST(CostModel, RefusesAFileWithoutAnyOneParameter) {
  int flops_parameters = 0;
#define NCUBE_EXPECT_REFUSED(member, cost, doc)                                          \
  EXPECT_NE(error_without(#cost).find("\"" #cost "\""), std::string::npos) << #member; \
  ++flops_parameters;
  NCUBE_WORK_COUNTERS(NCUBE_EXPECT_REFUSED)
  NCUBE_RENDER_COUNTERS(NCUBE_EXPECT_REFUSED)
#undef NCUBE_EXPECT_REFUSED
  // As many as the shipped file has flops figures: a counter added to a list without its
  // figure, or a figure without its counter, fails here, and adding both needs no edit.
  int flops_in_file = 0;
  const nlohmann::json file = shipped();
  for (const auto& [name, entry] : file["parameters"].items())
    if (name.rfind("flops_per_", 0) == 0) ++flops_in_file;
  EXPECT_EQ(flops_parameters, flops_in_file);
#define NCUBE_EXPECT_SIZE_REFUSED(name, min, max, doc) \
  EXPECT_NE(error_without(#name).find("\"" #name "\""), std::string::npos);
  NCUBE_DATA_SIZES(NCUBE_EXPECT_SIZE_REFUSED)
#undef NCUBE_EXPECT_SIZE_REFUSED
}

// Every parameter of the file is loaded into its own field, at the file's value.
TEST(CostModel, LoadsEveryParameterOfTheFileIntoItsField) {
  const nlohmann::json file = shipped()["parameters"];
  const CostModel m = load_cost_model(repo("platforms/cost_model.json"));
  std::set<std::string> names;
  for (const CostParameter& p : cost_parameters()) {
    names.insert(p.name);
    EXPECT_EQ(m.*p.field, file.at(p.name).at("value").get<double>()) << p.name;
  }
  EXPECT_EQ(names.size(), file.size());
  EXPECT_EQ(cost_parameters().size(), file.size());
  // Spot checks against the file's documented values.
  EXPECT_EQ(m.flops_per_form_factor, 180);
  EXPECT_EQ(m.flops_per_pixel_resolved, 180);
  EXPECT_EQ(m.octree_cell_bytes, 64);
  EXPECT_EQ(m.node_reserve_bytes, 786432);
}

// Each counter is charged at its own parameter: one operation of each kind, each parameter
// a distinct power of two, so that a counter charged at another's parameter (or twice, or
// not at all) shows in the sum.
TEST(CostModel, ChargesEachCounterAtItsOwnParameter) {
  CostModel m;
  WorkCounts work;
  RenderCounts render;
  double weight = 1.0, expected_work = 0.0, expected_render = 0.0;
#define NCUBE_SET_WORK(member, cost, doc)                       \
  m.cost = weight;                                              \
  work.member = 3;                                              \
  if (!is_host_work_counter(#member)) expected_work += 3 * weight; \
  weight *= 2;
  NCUBE_WORK_COUNTERS(NCUBE_SET_WORK)
#undef NCUBE_SET_WORK
#define NCUBE_SET_RENDER(member, cost, doc) \
  m.cost = weight;                          \
  render.member = 5;                        \
  expected_render += 5 * weight;            \
  weight *= 2;
  NCUBE_RENDER_COUNTERS(NCUBE_SET_RENDER)
#undef NCUBE_SET_RENDER
  EXPECT_EQ(m.flops(work), expected_work);
  EXPECT_EQ(m.flops(render), expected_render);
  // Hand-worked: the first counter alone.
  WorkCounts one;
  one.shooter_candidates = 7;
  EXPECT_EQ(m.flops(one), 7.0);
  // The host work counters are charged only at their own rates (work_kinds.h), never here.
  one.blocked_rays = 5;
  one.form_factor_edge_terms = 9;
  EXPECT_EQ(m.flops(one), 7.0);
}

// One counter of a family: two structs that differ in it compare unequal, adding adds it.
template <typename Counts, typename Member>
void expect_adds_and_compares(Member Counts::*member, const char* name) {
  Counts a, b;
  b.*member = 2;
  EXPECT_FALSE(a == b) << name;
  a += b;
  a += b;
  EXPECT_EQ(a.*member, 4u) << name;
  b.*member = 4;
  EXPECT_TRUE(a == b) << name;
}

// The sum and the comparison cover every counter.
TEST(CostModel, CountsAddAndCompareEveryCounter) {
#define NCUBE_CHECK_WORK(member, cost, doc) expect_adds_and_compares(&WorkCounts::member, #member);
  NCUBE_WORK_COUNTERS(NCUBE_CHECK_WORK)
#undef NCUBE_CHECK_WORK
#define NCUBE_CHECK_RENDER(member, cost, doc) expect_adds_and_compares(&RenderCounts::member, #member);
  NCUBE_RENDER_COUNTERS(NCUBE_CHECK_RENDER)
#undef NCUBE_CHECK_RENDER
}

// The result file's names of the counters (docs/result-format.md), written out by hand.
TEST(CostModel, ResultFileNamesEveryCounterAsDocumented) {
  WorkCounts work;
  work.plane_crossings = 11;
  const nlohmann::json w = counts_to_json(work);
  std::set<std::string> work_names;
  for (auto it = w.begin(); it != w.end(); ++it) work_names.insert(it.key());
  EXPECT_EQ(work_names, (std::set<std::string>{
                            "shooter_candidates", "receivers", "rays", "ray_patch_tests",
                            "plane_crossings", "form_factors", "element_updates",
                            "subdivision_tests", "elements_created", "octree_cells_visited",
                            "octree_overlap_tests", "octree_cells_built"}));
  EXPECT_EQ(w.value("plane_crossings", -1), 11);
  // The shooter-centred scheme's counters, in its runs' files only.
  const nlohmann::json s = counts_to_json(work, "ray-traced", "shooters");
  std::set<std::string> shooter_names;
  for (auto it = s.begin(); it != s.end(); ++it) shooter_names.insert(it.key());
  std::set<std::string> expected_shooter_names = work_names;
  expected_shooter_names.insert({"increments_combined", "increments_applied"});
  EXPECT_EQ(shooter_names, expected_shooter_names);
  EXPECT_EQ(w.value("rays", -1), 0);
  RenderCounts render;
  render.samples_inside = 13;
  const nlohmann::json r = render_counts_to_json(render);
  std::set<std::string> render_names;
  for (auto it = r.begin(); it != r.end(); ++it) render_names.insert(it.key());
  EXPECT_EQ(render_names,
            (std::set<std::string>{"vertices", "clip_vertices", "projected_vertices", "triangles",
                                   "samples_tested", "samples_inside", "samples_written",
                                   "exposure_samples", "histogram_buckets", "pixels_resolved"}));
  EXPECT_EQ(r.value("samples_inside", -1), 13);
}

}  // namespace
}  // namespace ncube

// Rates per kind of work (src/machine/work_kinds.h): every counted operation has a kind whose
// rate is an optional machine parameter; a machine that gives no rate is charged exactly as
// with one flop rate; one that gives them is charged each kind at its rate (worked by hand).
#include "machine/work_kinds.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "machine/machine_parameters.h"

namespace ncube {
namespace {

const MachineParameter* parameter_named(const std::string& name) {
  for (const MachineParameter& p : machine_parameters())
    if (name == p.name) return &p;
  return nullptr;
}

TEST(WorkKinds, EveryCounterHasAKindWhoseRateIsAnOptionalMachineParameter) {
  std::set<std::string> listed;
#define NCUBE_CHECK_KIND(member, cost, doc)                                          \
  EXPECT_NE(work_rate_of(#cost), "") << #cost << " has no kind (work_kinds.h)";      \
  listed.insert(#cost);
  NCUBE_WORK_COUNTERS(NCUBE_CHECK_KIND)
  NCUBE_RENDER_COUNTERS(NCUBE_CHECK_KIND)
#undef NCUBE_CHECK_KIND
  std::set<std::string> kinds;
#define NCUBE_KIND_LISTED(cost, rate)                                                 \
  EXPECT_TRUE(listed.count(#cost)) << #cost << ": no such counter's parameter";       \
  EXPECT_TRUE(kinds.insert(#cost).second) << #cost << " listed twice";
  NCUBE_WORK_KINDS(NCUBE_KIND_LISTED)
#undef NCUBE_KIND_LISTED
  EXPECT_EQ(kinds, listed);
  ASSERT_EQ(work_rate_names(),
            (std::vector<std::string>{"test_speed", "ray_speed", "arithmetic_speed",
                                      "memory_speed", "projection_speed", "raster_speed",
                                      "blocked_ray_speed", "edge_term_speed"}));
  for (const std::string& rate : work_rate_names()) {
    const MachineParameter* p = parameter_named(rate);
    ASSERT_NE(p, nullptr) << rate;
    EXPECT_TRUE(p->optional) << rate;
    EXPECT_EQ(std::string(p->unit), "flop/s") << rate;
  }
}

CostModel hand_costs() {
  CostModel c;
  c.flops_per_ray = 9;
  c.flops_per_ray_patch_test = 17.3547;
  c.flops_per_plane_crossing = 27.2143;
  c.flops_per_form_factor = 180;
  c.flops_per_element_update = 15;
  c.flops_per_increment_combined = 3;
  c.flops_per_sample_tested = 26;
  c.flops_per_pixel_resolved = 180;
  c.flops_per_histogram_bucket = 1;
  return c;
}

WorkCounts hand_counts() {
  WorkCounts w;
  w.rays = 7;
  w.ray_patch_tests = 1000;
  w.plane_crossings = 130;
  w.form_factors = 5;
  w.element_updates = 4;
  w.increments_combined = 11;
  return w;
}

TEST(WorkKinds, AMachineWithoutRatesIsChargedAsWithOneFlopRateToTheLastBit) {
  PlatformConfig p;
  p.node_speed = 2.5e6;
  const CostModel c = hand_costs();
  EXPECT_FALSE(gives_work_rates(p));
  EXPECT_EQ(compute_seconds(c, p, hand_counts()), c.flops(hand_counts()) / 2.5e6);
  RenderCounts r;
  r.samples_tested = 100;
  r.pixels_resolved = 3;
  EXPECT_EQ(compute_seconds(c, p, r), c.flops(r) / 2.5e6);
}

TEST(WorkKinds, EachKindRunsAtItsOwnRate) {
  PlatformConfig p;
  p.node_speed = 1e6;
  p.test_speed = 4e8;
  p.arithmetic_speed = 2e8;
  p.memory_speed = 1e9;
  EXPECT_TRUE(gives_work_rates(p));
  // By hand: tests (7 x 9 + 1000 x 17.3547 + 130 x 27.2143) / 4e8, arithmetic
  // (5 x 180 + 4 x 15) / 2e8, memory 11 x 3 / 1e9.
  const double expected = (63 + 17354.7 + 3537.859) / 4e8 + 960 / 2e8 + 33 / 1e9;
  EXPECT_NEAR(compute_seconds(hand_costs(), p, hand_counts()), expected, expected * 1e-12);
  // A kind the machine leaves out runs at node_speed.
  p.memory_speed = 0;
  EXPECT_NEAR(compute_seconds(hand_costs(), p, hand_counts()),
              (63 + 17354.7 + 3537.859) / 4e8 + 960 / 2e8 + 33 / 1e6, expected * 1e-12);
  RenderCounts r;
  r.samples_tested = 100;
  r.pixels_resolved = 3;
  r.histogram_buckets = 512;
  EXPECT_NEAR(compute_seconds(hand_costs(), p, r), 2600 / 4e8 + 540 / 2e8 + 512 / 1e6, 1e-15);
}

TEST(WorkKinds, RaysRunAtRaySpeedAndWithoutItAtTestSpeedToTheLastBit) {
  EXPECT_EQ(work_rate_of("flops_per_ray"), "ray_speed");
  EXPECT_EQ(fallback_rate_of("ray_speed"), "test_speed");
  EXPECT_EQ(fallback_rate_of("test_speed"), "");
  PlatformConfig p;
  p.node_speed = 1e6;
  p.test_speed = 4e8;
  p.arithmetic_speed = 2e8;
  // No ray_speed: rays at test_speed, the sum in the counters' order with each counter's flops
  // over its rate, as compute_seconds summed it before ray_speed existed (written out here).
  const CostModel c = hand_costs();
  const WorkCounts w = hand_counts();
  double before = 0.0;
  before += c.flops_per_ray * double(w.rays) / 4e8;
  before += c.flops_per_ray_patch_test * double(w.ray_patch_tests) / 4e8;
  before += c.flops_per_plane_crossing * double(w.plane_crossings) / 4e8;
  before += c.flops_per_form_factor * double(w.form_factors) / 2e8;
  before += c.flops_per_element_update * double(w.element_updates) / 2e8;
  before += c.flops_per_increment_combined * double(w.increments_combined) / 1e6;
  EXPECT_EQ(compute_seconds(c, p, w), before);
  // With ray_speed, by hand: rays 7 x 9 / 1e8, the rest as before.
  p.ray_speed = 1e8;
  const double expected = 63 / 1e8 + (17354.7 + 3537.859) / 4e8 + 960 / 2e8 + 33 / 1e6;
  EXPECT_NEAR(compute_seconds(c, p, w), expected, expected * 1e-12);
  EXPECT_EQ(kind_flops(c, w, "ray_speed"), 63);
  EXPECT_NEAR(kind_flops(c, w, "test_speed"), 17354.7 + 3537.859, 1e-9);
  // ray_speed alone: rays at it, every other kind at node_speed (test_speed left out).
  p.test_speed = 0;
  p.arithmetic_speed = 0;
  EXPECT_NEAR(compute_seconds(c, p, w), 63 / 1e8 + (17354.7 + 3537.859 + 960 + 33) / 1e6,
              1e-15);
  // Neither: rays at node_speed.
  p.ray_speed = 0;
  EXPECT_FALSE(gives_work_rates(p));
}

// The host work counters (work_counts.h): charged only on a platform that gives their own rate
// (no fallback), and then the form factors they replace (NCUBE_HOST_REPLACES) are not.
TEST(WorkKinds, HostWorkIsChargedOnlyWhereItsRateIsGivenAndThenReplacesTheFormFactors) {
  const CostModel c = [] {
    CostModel m = hand_costs();
    m.flops_per_blocked_ray = 42;
    m.flops_per_form_factor_edge_term = 45;
    return m;
  }();
  const WorkCounts before = hand_counts();
  WorkCounts w = before;
  w.blocked_rays = 3;
  w.form_factor_edge_terms = 20;
  // Without rates, and with the rates of before the counters existed: to the last bit as
  // without the counters.
  PlatformConfig p;
  p.node_speed = 1e6;
  EXPECT_EQ(compute_seconds(c, p, w), compute_seconds(c, p, before));
  p.test_speed = 4e8;
  p.arithmetic_speed = 2e8;
  p.ray_speed = 1e8;
  EXPECT_EQ(compute_seconds(c, p, w), compute_seconds(c, p, before));
  EXPECT_FALSE(charges_counter(p, "blocked_rays"));
  EXPECT_FALSE(charges_counter(p, "form_factor_edge_terms"));
  EXPECT_TRUE(charges_counter(p, "form_factors"));
  EXPECT_TRUE(charges_counter(p, "rays"));
  // blocked_ray_speed given: blocked rays 3 x 42 at it, by hand.
  p.blocked_ray_speed = 5e8;
  const double without = 63 / 1e8 + (17354.7 + 3537.859) / 4e8 + 960 / 2e8 + 33 / 1e6;
  EXPECT_NEAR(compute_seconds(c, p, w), without + 126 / 5e8, without * 1e-12);
  EXPECT_TRUE(charges_counter(p, "blocked_rays"));
  // edge_term_speed given: 20 x 45 edge-term flops at it, and the 5 form factors' 900 flops
  // no more (the updates' 60 stay at arithmetic_speed).
  p.edge_term_speed = 3e8;
  const double host = 63 / 1e8 + (17354.7 + 3537.859) / 4e8 + 60 / 2e8 + 33 / 1e6 + 126 / 5e8 +
                      900 / 3e8;
  EXPECT_NEAR(compute_seconds(c, p, w), host, host * 1e-12);
  EXPECT_TRUE(charges_counter(p, "form_factor_edge_terms"));
  EXPECT_FALSE(charges_counter(p, "form_factors"));
  // What a probe divides by: as on a platform that gives every rate.
  EXPECT_EQ(kind_flops(c, w, "arithmetic_speed"), 60);
  EXPECT_EQ(kind_flops(c, w, "edge_term_speed"), 900);
  EXPECT_EQ(kind_flops(c, w, "blocked_ray_speed"), 126);
}

// The hemicube's kinds: given, each counter runs at its kind's rate; left out, each counter at
// the rate that ran it before the kinds existed (clip and depth tests test_speed, cells read
// memory_speed, the rest arithmetic_speed), to the last bit. Worked by hand.
TEST(WorkKinds, HemicubeCountersRunAtTheirKindsAndWithoutThemAsBeforeToTheLastBit) {
  CostModel c;
  c.flops_per_hemicube_vertex_transformed = 21;
  c.flops_per_hemicube_clip_test = 2;
  c.flops_per_hemicube_row_scanned = 10;
  c.flops_per_hemicube_depth_test = 2;
  c.flops_per_hemicube_cell_read = 3;
  WorkCounts w;
  w.hemicube_vertices_transformed = 40;
  w.hemicube_clip_tests = 300;
  w.hemicube_rows_scanned = 70;
  w.hemicube_depth_tests = 900;
  w.hemicube_cells_read = 1000;
  PlatformConfig p;
  p.node_speed = 1e6;
  p.test_speed = 4e8;
  p.arithmetic_speed = 2e8;
  p.memory_speed = 1e9;
  const double before = 840.0 / 2e8 + 600.0 / 4e8 + 700.0 / 2e8 + 1800.0 / 4e8 + 3000.0 / 1e9;
  EXPECT_EQ(compute_seconds(c, p, w), before);
  // memory_speed left out too: the cells read at node_speed, as before.
  p.memory_speed = 0;
  EXPECT_EQ(compute_seconds(c, p, w),
            840.0 / 2e8 + 600.0 / 4e8 + 700.0 / 2e8 + 1800.0 / 4e8 + 3000.0 / 1e6);
  p.memory_speed = 1e9;
  p.projection_speed = 5e8;
  EXPECT_NEAR(compute_seconds(c, p, w),
              (840.0 + 600.0) / 5e8 + 700.0 / 2e8 + 1800.0 / 4e8 + 3000.0 / 1e9, 1e-15);
  p.raster_speed = 3e8;
  EXPECT_NEAR(compute_seconds(c, p, w), (840.0 + 600.0) / 5e8 + (700.0 + 1800.0 + 3000.0) / 3e8,
              1e-15);
  EXPECT_EQ(kind_flops(c, w, "raster_speed"), 5500);
  EXPECT_EQ(kind_flops(c, w, "projection_speed"), 1440);
  EXPECT_EQ(kind_flops(c, w, "test_speed"), 0);
}

}  // namespace
}  // namespace ncube

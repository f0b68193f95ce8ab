// One registration per form-factor method (radiosity/form_factor_methods.h; docs/architecture.md,
// "How to add a method"): every consumer knows every registered name (the option, the result
// file, the host's version, the memory plan), a name with no registration is a bug, not a
// fallback; the hemicube's options are refused where they cannot be honoured (exit 2) or do
// not fit (exit 3); and a whole hemicube run on the hand-counted scene is charged its counted
// work through the cost model.
#include <gtest/gtest.h>

#include <algorithm>

#include "hand_counted_scene.h"
#include "simulate_arguments.h"
#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "nodes/memory_plan.h"
#include "nodes/placement.h"
#include "radiosity/form_factor_methods.h"
#include "scene/scene_loader.h"
#include "simulation/configuration_check.h"
#include "simulation/host_machinery.h"
#include "simulation/memory_check.h"
#include "simulation/result_file.h"
#include "simulation/simulation.h"
#include "tools/simulate_options.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

TEST(FormFactorMethods, ThePapersRaysAreTheDefault) {
  EXPECT_EQ(form_factor_methods().paper_default().name, "ray-traced");
  EXPECT_EQ(ProgressiveOptions{}.form_factors, "ray-traced");
  EXPECT_TRUE(form_factor_methods().contains("hemicube"));
}

TEST(FormFactorMethods, EveryMethodIsAValueOfTheOptionWithItsDoc) {
  SimulateOptions described;
  std::string text;
  ASSERT_EQ(parse({"--describe-options"}, described, &text), 0);
  const nlohmann::json options = nlohmann::json::parse(text);
  const auto entry = std::find_if(options.begin(), options.end(), [](const nlohmann::json& o) {
    return o.value("flag", "") == "--form-factors";
  });
  ASSERT_NE(entry, options.end());
  EXPECT_EQ((*entry)["values"].get<std::vector<std::string>>(), form_factor_methods().names());
  EXPECT_EQ((*entry)["default"], "ray-traced");
  for (const FormFactorMethod& method : form_factor_methods().all()) {
    EXPECT_NE((*entry)["help"].get<std::string>().find(method.name + " (" + method.doc + ")"),
              std::string::npos);
    SimulateOptions parsed;
    ASSERT_EQ(parse({"--form-factors", method.name}, parsed), -1) << method.name;
    EXPECT_EQ(parsed.config.options.form_factors, method.name);
  }
  SimulateOptions bad;
  EXPECT_EQ(parse({"--form-factors", "radiosity"}, bad), kExitBadInput);
  EXPECT_EQ(parse({"--hemicube-resolution", "101"}, bad), kExitBadInput);   // odd
  EXPECT_EQ(parse({"--hemicube-resolution", "2002"}, bad), kExitBadInput);  // beyond 2000
  EXPECT_EQ(parse({"--hemicube-resolution", "0"}, bad), kExitBadInput);
  EXPECT_EQ(parse({"--hemicube-placement", "corners"}, bad), kExitBadInput);
  SimulateOptions elements;
  ASSERT_EQ(parse({"--form-factors", "hemicube", "--hemicube-resolution", "2", "--hemicube-placement",
                   "elements"},
                  elements),
            -1);
  EXPECT_EQ(elements.config.options.hemicube.resolution, 2);
  EXPECT_EQ(elements.config.options.hemicube.placement, HemicubePlacement::kElements);
  // Back faces: block by default (every run before the option), pass on request.
  EXPECT_EQ(elements.config.options.hemicube.back_faces, HemicubeBackFaces::kBlock);
  EXPECT_EQ(parse({"--hemicube-back-faces", "transparent"}, bad), kExitBadInput);
  SimulateOptions pass;
  ASSERT_EQ(parse({"--form-factors", "hemicube", "--hemicube-back-faces", "pass"}, pass), -1);
  EXPECT_EQ(pass.config.options.hemicube.back_faces, HemicubeBackFaces::kPass);
}

TEST(FormFactorMethods, TheResultFileRecordsTheHemicubeOnlyForHemicubeRuns) {
  const Scene scene = hand_counted_scene();
  SimulationConfig config;
  nlohmann::json paper = result_to_json(scene, config, SimulationResult{});
  for (const char* field : {"form_factors", "hemicube_resolution", "hemicube_placement"})
    EXPECT_FALSE(paper["config"].contains(field)) << field;
  EXPECT_FALSE(paper["counts"].contains("hemicube_cells_read"));
  EXPECT_TRUE(paper["counts"].contains("rays"));
  config.options.form_factors = "hemicube";
  config.options.hemicube = {50, HemicubePlacement::kElements};
  const nlohmann::json hemicube = result_to_json(scene, config, SimulationResult{});
  EXPECT_EQ(hemicube["config"]["form_factors"], "hemicube");
  EXPECT_EQ(hemicube["config"]["hemicube_resolution"], 50);
  EXPECT_EQ(hemicube["config"]["hemicube_placement"], "elements");
  EXPECT_TRUE(hemicube["counts"].contains("hemicube_cells_read"));
  // The back faces only when they pass: a hemicube file without the field blocked, so every
  // hemicube file of the default keeps its bytes.
  EXPECT_FALSE(hemicube["config"].contains("hemicube_back_faces"));
  config.options.hemicube.back_faces = HemicubeBackFaces::kPass;
  EXPECT_EQ(result_to_json(scene, config, SimulationResult{})["config"]["hemicube_back_faces"], "pass");
  config.options.form_factors = "ray-traced";
  EXPECT_FALSE(result_to_json(scene, config, SimulationResult{})["config"].contains("hemicube_back_faces"));
  config.options.form_factors = "radiosity";
  EXPECT_THROW(result_to_json(scene, config, SimulationResult{}), std::logic_error);
}

// Each node program calls another of them (the paper's radiosity processor `shoot`, the
// shooter-centred scheme's `form_factors`): an empty one is a run failing with exit 7
// (docs/architecture.md, "Form-factor methods").
TEST(FormFactorMethods, EveryRegistrationHasItsFunctions) {
  const ProgressiveOptions defaults;
  for (const FormFactorMethod& method : form_factor_methods().all()) {
    EXPECT_TRUE(method.shoot) << method.name;
    EXPECT_TRUE(method.form_factors) << method.name;
    EXPECT_TRUE(method.setup_work) << method.name;
    EXPECT_TRUE(method.node_items) << method.name;
    EXPECT_TRUE(method.setting) << method.name;
    EXPECT_TRUE(method.counted) << method.name;
    // Without a V > 0 gather, the reason a V > 0 run is refused.
    EXPECT_EQ(!method.gather_visible, !method.without_visibility_processors.empty()) << method.name;
    // Own options: named when changed, and none changed at the defaults.
    EXPECT_EQ(method.own_options.empty(), !method.changed_options) << method.name;
    if (method.changed_options) {
      EXPECT_TRUE(method.changed_options(defaults).empty()) << method.name;
    }
    if (method.refused_options) {
      EXPECT_EQ(method.refused_options(defaults), "") << method.name;
    }
  }
  // The paper's method is defined with visibility processors (section 3).
  EXPECT_TRUE(form_factor_methods().paper_default().gather_visible);
}

// Registering after the registry has been read would leave consumers that have read it
// without the method: refused.
TEST(FormFactorMethods, NoMethodIsAddedAfterTheRegistryIsRead) {
  form_factor_methods();
  FormFactorMethod late;
  late.name = "late";
  EXPECT_THROW(add_form_factor_method(late), std::logic_error);
}

TEST(FormFactorMethods, EveryMethodHasAHostVersionAndNodeMemory) {
  const Scene scene = load_scene(repo("scenes/cornell-box.json"));
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  for (const FormFactorMethod& method : form_factor_methods().all()) {
    ProgressiveOptions options;
    options.form_factors = method.name;
    HostMachinery machinery;
    EXPECT_NO_THROW(build_host_machinery(machinery, scene, {visibility_share(scene, 1, 0)}, options, 0,
                                         2, 100, false))
        << method.name;
  }
  ProgressiveOptions unknown;
  unknown.form_factors = "radiosity";
  HostMachinery machinery;
  EXPECT_THROW(build_host_machinery(machinery, scene, {{0, 1}}, unknown, 0, 1, 100, false),
               std::logic_error);
  // The hemicube's table (1.5 N^2 floats) and one face's item and depth buffers (N^2 cells
  // of 8 bytes) on every radiosity processor: 60,000 + 80,000 bytes at N = 100.
  const auto plan = [&](const std::string& name) {
    ProgramOptions program;
    program.options.form_factors = name;
    return plan_memory(ProgramSetup{scene, Placement{2, 0}, program, 1.0},
                       partition_patches_by_elements(scene, 2), costs);
  };
  const std::vector<NodeMemory> rays = plan("ray-traced"), hemicube = plan("hemicube");
  ASSERT_EQ(rays.size(), 2u);
  for (std::size_t n = 0; n < rays.size(); ++n)
    EXPECT_DOUBLE_EQ(hemicube[n].bytes - rays[n].bytes, 140000.0);
}

SimulationConfig hemicube_config(int R, int V) {
  SimulationConfig config;
  config.radiosity_processors = R;
  config.visibility_processors = V;
  config.options.form_factors = "hemicube";
  return config;
}

TEST(FormFactorMethods, OptionsTheHemicubeCannotHonourAreRefused) {
  const Scene scene = hand_counted_scene();
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  EXPECT_NO_THROW(check_configuration(scene, hemicube_config(2, 0), platform));
  EXPECT_THROW(check_configuration(scene, hemicube_config(2, 1), platform), InputError);
  SimulationConfig octree = hemicube_config(1, 0);
  octree.options.visibility = "octree";
  EXPECT_THROW(check_configuration(scene, octree, platform), InputError);
  SimulationConfig first_blocker = hemicube_config(1, 0);
  first_blocker.options.ray_policy = RayTestPolicy::kStopAtFirstBlocker;
  EXPECT_THROW(check_configuration(scene, first_blocker, platform), InputError);
  SimulationConfig samples = hemicube_config(1, 0);
  samples.options.samples = 16;
  EXPECT_THROW(check_configuration(scene, samples, platform), InputError);
  SimulationConfig odd = hemicube_config(1, 0);
  odd.options.hemicube.resolution = 99;
  EXPECT_THROW(check_configuration(scene, odd, platform), InputError);
  // The hemicube's options without it would have no effect.
  SimulationConfig resolution;
  resolution.options.hemicube.resolution = 50;
  EXPECT_THROW(check_configuration(scene, resolution, platform), InputError);
  SimulationConfig placement;
  placement.options.hemicube.placement = HemicubePlacement::kElements;
  EXPECT_THROW(check_configuration(scene, placement, platform), InputError);
  SimulationConfig back_faces;
  back_faces.options.hemicube.back_faces = HemicubeBackFaces::kPass;
  EXPECT_THROW(check_configuration(scene, back_faces, platform), InputError);
  SimulationConfig passing = hemicube_config(1, 0);
  passing.options.hemicube.back_faces = HemicubeBackFaces::kPass;
  EXPECT_NO_THROW(check_configuration(scene, passing, platform));
  // Out of simulated memory (exit 3) where the buffers do not fit a 4 MB node: N = 1000
  // needs 1.5e6 x 4 + 1e6 x 8 = 14 MB.
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  SimulationConfig big = hemicube_config(1, 0);
  big.options.hemicube.resolution = 1000;
  EXPECT_EQ(first_node_out_of_memory(scene, big, platform, costs).node, 0);
  big.options.hemicube.resolution = 400;
  EXPECT_EQ(first_node_out_of_memory(scene, big, platform, costs).node, -1);
}

// One shot of the light on the hand-counted scene, R = 1, N = 10: the node renders the 10
// receiving elements (the light's own patch is in the eye's plane), 4 vertices each; it
// reads out 10 x 10 + 4 x 10 x 5 cells; it computed its table of 150 delta form factors when
// it started. Its compute time is the cost model's price of its counts.
TEST(FormFactorMethods, AHemicubeRunIsChargedItsCountedWork) {
  SimulationConfig config = hemicube_config(1, 0);
  config.options.hemicube.resolution = 10;
  config.options.max_iterations = 1;
  const CostModel costs = load_cost_model(repo("platforms/cost_model.json"));
  const PlatformConfig platform = load_platform_config(repo("platforms/ncube2.json"));
  const SimulationResult r = run_simulation(hand_counted_scene(), config, platform, costs);
  ASSERT_EQ(r.status, RunStatus::kOk);
  ASSERT_EQ(r.iterations, 1);
  const WorkCounts& c = r.counts;
  EXPECT_EQ(c.hemicube_delta_form_factors, 150u);
  EXPECT_EQ(c.hemicube_vertices_transformed, 40u);
  EXPECT_EQ(c.hemicube_polygons_set_up, 10u);
  EXPECT_EQ(c.hemicube_cells_read, 300u);
  EXPECT_EQ(c.element_updates, 10u);
  EXPECT_EQ(c.rays + c.ray_patch_tests + c.form_factors, 0u);
  EXPECT_GT(c.hemicube_depth_tests, 0u);
  ASSERT_EQ(r.nodes.size(), 1u);
  EXPECT_NEAR(r.nodes[0].compute_seconds, costs.flops(c) / platform.node_speed,
              1e-12 * r.nodes[0].compute_seconds);
  // Every receiver lit from the light's centre: the floor, the table top and the wall.
  for (int patch = 1; patch < 4; ++patch) EXPECT_GT(r.patch_radiosity[std::size_t(patch)].r, 0.0) << patch;
}

}  // namespace
}  // namespace ncube

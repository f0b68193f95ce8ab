#include "simulation/result_file.h"

#include <algorithm>

#include "simulation/iteration_time.h"
#include "simulation/parallelisations.h"
#include "radiosity/form_factor_methods.h"
#include "visibility/visibility_methods.h"

namespace ncube {

nlohmann::json counts_to_json(const WorkCounts& c, const std::string& form_factors,
                              const std::string& parallelisation,
                              const std::vector<std::string>& host_counters_charged) {
  nlohmann::json j;
  const auto charged = [&](const char* member) {
    return !is_host_work_counter(member) ||
           std::find(host_counters_charged.begin(), host_counters_charged.end(), member) !=
               host_counters_charged.end();
  };
#define NCUBE_WORK_COUNT_TO_JSON(member, cost, doc) \
  if (writes_counter(form_factors, #member) &&                  \
      parallelisation_writes_counter(parallelisation, #member) && charged(#member)) \
    j[#member] = c.member;
  NCUBE_WORK_COUNTERS(NCUBE_WORK_COUNT_TO_JSON)
#undef NCUBE_WORK_COUNT_TO_JSON
  return j;
}

nlohmann::json render_counts_to_json(const RenderCounts& c) {
  nlohmann::json j;
#define NCUBE_COUNT_TO_JSON(member, cost, doc) j[#member] = c.member;
  NCUBE_RENDER_COUNTERS(NCUBE_COUNT_TO_JSON)
#undef NCUBE_COUNT_TO_JSON
  return j;
}

namespace {

const char* ray_policy_name(RayTestPolicy policy) {
  return policy == RayTestPolicy::kTestAllPatches ? "all" : "first-blocker";
}

// The rendering phase (section 2.3, --render-parallel): docs/result-format.md.
nlohmann::json render_to_json(const SimulationConfig& config, const RenderResult& render) {
  nlohmann::json nodes = nlohmann::json::array();
  RenderCounts all;
  for (const RenderNodeStats& n : render.nodes) {
    all += n.counts;
    nodes.push_back({{"node", n.stats.node},
                     {"role", role_name(n.stats.role)},
                     {"rows", n.rows},
                     {"rasterise_seconds", n.rasterise_seconds},
                     {"compute_seconds", n.stats.compute_seconds},
                     {"overhead_seconds", n.stats.overhead_seconds},
                     {"waiting_seconds", n.stats.waiting_seconds},
                     {"messages_sent", n.stats.messages_sent},
                     {"bytes_sent", n.stats.bytes_sent},
                     {"messages_received", n.stats.messages_received},
                     {"peak_memory_bytes", n.stats.peak_memory_bytes},
                     {"counts", render_counts_to_json(n.counts)}});
  }
  return {{"partition", row_partition_name(config.render.partition)},
          {"distribution", render_distribution_name(config.render.distribution)},
          {"width", config.render.width},
          {"height", config.render.height},
          {"simulated_seconds", render.simulated_seconds},
          {"imbalance", render.imbalance},
          {"counts", render_counts_to_json(all)},
          {"nodes", nodes}};
}

}  // namespace

nlohmann::json result_to_json(const Scene& scene, const SimulationConfig& config,
                              const SimulationResult& result) {
  nlohmann::json j;
  j["schema_version"] = kResultSchemaVersion;
  j["scene"] = {{"name", scene.name},
                {"patches", scene.patches.size()},
                {"elements", scene.element_total()}};
  j["config"] = {{"R", config.radiosity_processors},
                 {"V", config.visibility_processors},
                 {"nodes", config.node_count()},
                 {"samples", config.options.samples},
                 {"ray_test", ray_policy_name(config.options.ray_policy)},
                 {"visibility", visibility_methods().at(config.options.visibility).name},
                 {"skip_facing_away", config.options.skip_facing_away},
                 {"form_factors", form_factor_methods().at(config.options.form_factors).name},
                 {"hemicube_resolution", config.options.hemicube.resolution},
                 {"hemicube_placement", hemicube_placement_name(config.options.hemicube.placement)},
                 {"hemicube_back_faces", hemicube_back_faces_name(config.options.hemicube.back_faces)},
                 {"hemicube_reciprocity", hemicube_reciprocity_name(config.options.hemicube.reciprocity)},
                 {"convergence_fraction", config.options.convergence_fraction},
                 {"max_iterations", config.options.max_iterations},
                 {"block_size", config.block_size},
                 {"pipelined", config.pipelined},
                 {"memory_cap", config.memory_cap},
                 {"subdivide", config.options.subdivision.enabled},
                 {"subdivide_contrast", config.options.subdivision.contrast},
                 {"subdivide_max_level", config.options.subdivision.max_level},
                 {"subdivide_min_area", config.options.subdivision.min_area},
                 {"balance", config.balancing.enabled},
                 {"balance_threshold", config.balancing.threshold},
                 {"render_parallel",
                  config.render.enabled ? row_partition_name(config.render.partition) : "off"},
                 {"render_distribution", render_distribution_name(config.render.distribution)},
                 {"image_width", config.render.width},
                 {"image_height", config.render.height},
                 {"outline_elements", config.render.outline_elements},
                 {"parallelisation", parallelisations().at(config.parallelisation).name},
                 {"shooters_per_iteration", config.shooters_per_iteration}};
  // The form-factor method for every run but the paper's, each method's own options for its
  // runs only (FormFactorMethod::own_options), the parallelisation's only for the
  // shooter-centred schemes: the paper's runs keep their files.
  const FormFactorMethod& method = form_factor_methods().at(config.options.form_factors);
  if (method.name == form_factor_methods().paper_default().name) j["config"].erase("form_factors");
  for (const FormFactorMethod& other : form_factor_methods().all())
    if (other.name != method.name)
      for (const std::string& field : other.own_options) j["config"].erase(field);
  // An own option at the value every run of the method had before the option existed is not
  // recorded (FormFactorMethod::recorded_unless): a hemicube run's file without
  // hemicube_back_faces blocked, as every hemicube run did before --hemicube-back-faces.
  for (const auto& [field, value] : method.recorded_unless) {
    const auto found = j["config"].find(field);
    if (found != j["config"].end() &&
        (found->is_string() ? found->get<std::string>() : found->dump()) == value)
      j["config"].erase(field);
  }
  if (parallelisations().at(config.parallelisation).name == parallelisations().paper_default().name)
    for (const char* field : {"parallelisation", "shooters_per_iteration"}) j["config"].erase(field);
  j["status"] = status_name(result.status);
  if (result.status == RunStatus::kOutOfMemory)
    j["out_of_memory"] = {{"node", result.out_of_memory.node},
                          {"role", role_name(result.out_of_memory.role)},
                          {"needed_bytes", result.out_of_memory.needed_bytes},
                          {"available_bytes", result.out_of_memory.available_bytes}};
  if (result.status == RunStatus::kFailed) j["failure"] = result.failure;
  j["iterations"] = result.iterations;
  j["converged"] = result.converged;
  j["simulated_seconds"] = result.simulated_seconds;
  j["iteration_seconds"] = result.iteration_seconds;
  const std::optional<double> per_iteration = seconds_per_iteration(result.iteration_seconds);
  j["seconds_per_iteration"] = per_iteration ? nlohmann::json(*per_iteration) : nlohmann::json();
  j["iterations_measured"] = iterations_measured(result.iteration_seconds);
  j["shooters"] = result.shooters;
  // Sections 4.1, 4.2: the elements each radiosity processor held at each shooter selection
  // (with subdivision or balancing on), the elements at the end, and the patches moved.
  j["elements_per_iteration"] = result.elements_per_iteration;
  j["elements_at_end"] = result.elements_at_end();
  j["patches_moved"] = result.patches_moved;
  j["transfers"] = {{"messages", result.transfer_messages}, {"payload_bytes", result.transfer_bytes}};
  nlohmann::json radiosity = nlohmann::json::array();
  for (const Rgb& b : result.patch_radiosity) radiosity.push_back({b.r, b.g, b.b});
  j["patch_radiosity"] = radiosity;
  j["counts"] = counts_to_json(result.counts, config.options.form_factors, config.parallelisation,
                               result.host_counters_charged);
  nlohmann::json nodes = nlohmann::json::array();
  for (const NodeStats& n : result.nodes)
    nodes.push_back({{"node", n.node},
                     {"role", role_name(n.role)},
                     {"rank", n.rank},
                     {"compute_seconds", n.compute_seconds},
                     {"overhead_seconds", n.overhead_seconds},
                     {"waiting_seconds", n.waiting_seconds},
                     {"messages_sent", n.messages_sent},
                     {"bytes_sent", n.bytes_sent},
                     {"messages_received", n.messages_received},
                     {"peak_memory_bytes", n.peak_memory_bytes},
                     {"memory_bytes_at_end", n.memory_bytes_at_end},
                     {"counts", counts_to_json(n.counts, config.options.form_factors, config.parallelisation,
                                                   result.host_counters_charged)}});
  j["nodes"] = nodes;
  if (result.render.ran) j["render"] = render_to_json(config, result.render);
  j["host_seconds"] = result.host_seconds;
  return j;
}

}  // namespace ncube

#include "simulation/provenance.h"

#include "simulation/result_file.h"
#include "util/file_hash.h"
#include "util/version.h"

namespace ncube {

nlohmann::json platform_values(const PlatformConfig& p) {
  if (p.format == "simgrid-xml")  // the interconnect is the file's (its hash names it)
    return {{"nodes", p.node_count()},          {"node_speed", p.node_speed},
            {"node_memory", p.node_memory},     {"send_overhead", p.send_overhead},
            {"receive_overhead", p.receive_overhead}};
  return {{"dimension", p.dimension},         {"nodes", p.node_count()},
          {"node_speed", p.node_speed},       {"node_memory", p.node_memory},
          {"link_bandwidth", p.link_bandwidth}, {"hop_latency", p.hop_latency},
          {"send_overhead", p.send_overhead}, {"receive_overhead", p.receive_overhead}};
}

nlohmann::json cost_model_values(const CostModel& c) {
  return {{"flops_per_shooter_candidate", c.flops_per_shooter_candidate},
          {"flops_per_receiver", c.flops_per_receiver},
          {"flops_per_ray", c.flops_per_ray},
          {"flops_per_ray_patch_test", c.flops_per_ray_patch_test},
          {"flops_per_plane_crossing", c.flops_per_plane_crossing},
          {"flops_per_form_factor", c.flops_per_form_factor},
          {"flops_per_element_update", c.flops_per_element_update},
          {"message_header_bytes", c.message_header_bytes},
          {"shooter_record_bytes", c.shooter_record_bytes},
          {"point_bytes", c.point_bytes},
          {"patch_geometry_bytes", c.patch_geometry_bytes},
          {"patch_radiosity_bytes", c.patch_radiosity_bytes},
          {"element_bytes", c.element_bytes},
          {"flops_per_render_vertex", c.flops_per_render_vertex},
          {"flops_per_clip_vertex", c.flops_per_clip_vertex},
          {"flops_per_projected_vertex", c.flops_per_projected_vertex},
          {"flops_per_triangle", c.flops_per_triangle},
          {"flops_per_sample_tested", c.flops_per_sample_tested},
          {"flops_per_sample_inside", c.flops_per_sample_inside},
          {"flops_per_sample_written", c.flops_per_sample_written},
          {"flops_per_exposure_sample", c.flops_per_exposure_sample},
          {"flops_per_histogram_bucket", c.flops_per_histogram_bucket},
          {"flops_per_pixel_resolved", c.flops_per_pixel_resolved},
          {"render_element_bytes", c.render_element_bytes},
          {"render_vertex_bytes", c.render_vertex_bytes},
          {"frame_sample_bytes", c.frame_sample_bytes},
          {"pixel_bytes", c.pixel_bytes},
          {"exposure_histogram_bytes", c.exposure_histogram_bytes},
          {"exposure_selection_bytes", c.exposure_selection_bytes},
          {"node_reserve_bytes", c.node_reserve_bytes}};
}

nlohmann::json provenance_to_json(const RunInputs& inputs, const Scene& scene,
                                  const PlatformConfig& platform, const CostModel& costs,
                                  const SimulationResult& result) {
  nlohmann::json platform_json = {{"file", inputs.platform_file},
                                  {"sha256", file_sha256(inputs.platform_file)},
                                  {"format", platform.format},
                                  {"values", platform_values(platform)},
                                  {"simgrid_config", result.simgrid_config}};
  return {{"schema_version", kResultSchemaVersion},
          {"command_line", inputs.command_line},
          {"code_version", code_version()},
          {"simgrid_version", simgrid_version()},
          {"scene", {{"name", scene.name},
                     {"file", inputs.scene_file},
                     {"sha256", file_sha256(inputs.scene_file)}}},
          {"platform", platform_json},
          {"cost_model", {{"file", inputs.cost_model_file},
                          {"sha256", file_sha256(inputs.cost_model_file)},
                          {"values", cost_model_values(costs)}}}};
}

}  // namespace ncube

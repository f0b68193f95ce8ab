#include "machine/cost_model.h"

#include "machine/parameter_file.h"

namespace ncube {

double CostModel::flops(const WorkCounts& c) const {
  return flops_per_shooter_candidate * double(c.shooter_candidates) +
         flops_per_receiver * double(c.receivers) + flops_per_ray * double(c.rays) +
         flops_per_ray_patch_test * double(c.ray_patch_tests) +
         flops_per_plane_crossing * double(c.plane_crossings) +
         flops_per_form_factor * double(c.form_factors) +
         flops_per_element_update * double(c.element_updates);
}

CostModel load_cost_model(const std::string& path) {
  // Sanity bounds (a typo, not a model, beyond them): flops per operation up to 1e9, data
  // sizes up to 1e9 bytes, the reserve up to 2^50 bytes.
  constexpr double kFlops = 1e9, kBytes = 1e9;
  const auto v = read_parameter_file(path, {{"flops_per_shooter_candidate", 0, false, kFlops},
                                            {"flops_per_receiver", 0, false, kFlops},
                                            {"flops_per_ray", 0, false, kFlops},
                                            {"flops_per_ray_patch_test", 0, false, kFlops},
                                            {"flops_per_plane_crossing", 0, false, kFlops},
                                            {"flops_per_form_factor", 0, false, kFlops},
                                            {"flops_per_element_update", 0, false, kFlops},
                                            {"message_header_bytes", 0, true, kBytes},
                                            {"shooter_record_bytes", 1, true, kBytes},
                                            {"point_bytes", 1, true, kBytes},
                                            {"patch_geometry_bytes", 1, true, kBytes},
                                            {"patch_radiosity_bytes", 1, true, kBytes},
                                            {"element_bytes", 1, true, kBytes},
                                            {"node_reserve_bytes", 0, true, 0x1p50}});
  CostModel m;
  m.flops_per_shooter_candidate = v.at("flops_per_shooter_candidate");
  m.flops_per_receiver = v.at("flops_per_receiver");
  m.flops_per_ray = v.at("flops_per_ray");
  m.flops_per_ray_patch_test = v.at("flops_per_ray_patch_test");
  m.flops_per_plane_crossing = v.at("flops_per_plane_crossing");
  m.flops_per_form_factor = v.at("flops_per_form_factor");
  m.flops_per_element_update = v.at("flops_per_element_update");
  m.message_header_bytes = v.at("message_header_bytes");
  m.shooter_record_bytes = v.at("shooter_record_bytes");
  m.point_bytes = v.at("point_bytes");
  m.patch_geometry_bytes = v.at("patch_geometry_bytes");
  m.patch_radiosity_bytes = v.at("patch_radiosity_bytes");
  m.element_bytes = v.at("element_bytes");
  m.node_reserve_bytes = v.at("node_reserve_bytes");
  return m;
}

}  // namespace ncube

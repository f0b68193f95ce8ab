#include "machine/cost_model.h"

#include "machine/parameter_file.h"

namespace ncube {

double CostModel::flops(const WorkCounts& c) const {
  return flops_per_shooter_candidate * double(c.shooter_candidates) +
         flops_per_receiver * double(c.receivers) + flops_per_ray * double(c.rays) +
         flops_per_ray_patch_test * double(c.ray_patch_tests) +
         flops_per_plane_crossing * double(c.plane_crossings) +
         flops_per_form_factor * double(c.form_factors) +
         flops_per_element_update * double(c.element_updates) +
         flops_per_subdivision_test * double(c.subdivision_tests) +
         flops_per_element_created * double(c.elements_created) +
         flops_per_octree_cell_visited * double(c.octree_cells_visited) +
         flops_per_octree_overlap_test * double(c.octree_overlap_tests) +
         flops_per_octree_cell_built * double(c.octree_cells_built);
}

double CostModel::flops(const RenderCounts& c) const {
  return flops_per_render_vertex * double(c.vertices) +
         flops_per_clip_vertex * double(c.clip_vertices) +
         flops_per_projected_vertex * double(c.projected_vertices) +
         flops_per_triangle * double(c.triangles) +
         flops_per_sample_tested * double(c.samples_tested) +
         flops_per_sample_inside * double(c.samples_inside) +
         flops_per_sample_written * double(c.samples_written) +
         flops_per_exposure_sample * double(c.exposure_samples) +
         flops_per_histogram_bucket * double(c.histogram_buckets) +
         flops_per_pixel_resolved * double(c.pixels_resolved);
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
                                            {"flops_per_subdivision_test", 0, false, kFlops},
                                            {"flops_per_element_created", 0, false, kFlops},
                                            {"flops_per_octree_cell_visited", 0, false, kFlops},
                                            {"flops_per_octree_overlap_test", 0, false, kFlops},
                                            {"flops_per_octree_cell_built", 0, false, kFlops},
                                            {"octree_cell_bytes", 1, true, kBytes},
                                            {"octree_reference_bytes", 1, true, kBytes},
                                            {"message_header_bytes", 0, true, kBytes},
                                            {"shooter_record_bytes", 1, true, kBytes},
                                            {"point_bytes", 1, true, kBytes},
                                            {"patch_geometry_bytes", 1, true, kBytes},
                                            {"patch_radiosity_bytes", 1, true, kBytes},
                                            {"element_bytes", 1, true, kBytes},
                                            {"load_record_bytes", 1, true, kBytes},
                                            {"transfer_order_bytes", 1, true, kBytes},
                                            {"flops_per_render_vertex", 0, false, kFlops},
                                            {"flops_per_clip_vertex", 0, false, kFlops},
                                            {"flops_per_projected_vertex", 0, false, kFlops},
                                            {"flops_per_triangle", 0, false, kFlops},
                                            {"flops_per_sample_tested", 0, false, kFlops},
                                            {"flops_per_sample_inside", 0, false, kFlops},
                                            {"flops_per_sample_written", 0, false, kFlops},
                                            {"flops_per_exposure_sample", 0, false, kFlops},
                                            {"flops_per_histogram_bucket", 0, false, kFlops},
                                            {"flops_per_pixel_resolved", 0, false, kFlops},
                                            {"render_element_bytes", 1, true, kBytes},
                                            {"render_vertex_bytes", 1, true, kBytes},
                                            {"frame_sample_bytes", 1, true, kBytes},
                                            {"pixel_bytes", 1, true, kBytes},
                                            {"exposure_histogram_bytes", 1, true, kBytes},
                                            {"exposure_selection_bytes", 1, true, kBytes},
                                            {"node_reserve_bytes", 0, true, 0x1p50}});
  CostModel m;
  m.flops_per_shooter_candidate = v.at("flops_per_shooter_candidate");
  m.flops_per_receiver = v.at("flops_per_receiver");
  m.flops_per_ray = v.at("flops_per_ray");
  m.flops_per_ray_patch_test = v.at("flops_per_ray_patch_test");
  m.flops_per_plane_crossing = v.at("flops_per_plane_crossing");
  m.flops_per_form_factor = v.at("flops_per_form_factor");
  m.flops_per_element_update = v.at("flops_per_element_update");
  m.flops_per_subdivision_test = v.at("flops_per_subdivision_test");
  m.flops_per_element_created = v.at("flops_per_element_created");
  m.flops_per_octree_cell_visited = v.at("flops_per_octree_cell_visited");
  m.flops_per_octree_overlap_test = v.at("flops_per_octree_overlap_test");
  m.flops_per_octree_cell_built = v.at("flops_per_octree_cell_built");
  m.octree_cell_bytes = v.at("octree_cell_bytes");
  m.octree_reference_bytes = v.at("octree_reference_bytes");
  m.message_header_bytes = v.at("message_header_bytes");
  m.shooter_record_bytes = v.at("shooter_record_bytes");
  m.point_bytes = v.at("point_bytes");
  m.patch_geometry_bytes = v.at("patch_geometry_bytes");
  m.patch_radiosity_bytes = v.at("patch_radiosity_bytes");
  m.element_bytes = v.at("element_bytes");
  m.load_record_bytes = v.at("load_record_bytes");
  m.transfer_order_bytes = v.at("transfer_order_bytes");
  m.node_reserve_bytes = v.at("node_reserve_bytes");
  m.flops_per_render_vertex = v.at("flops_per_render_vertex");
  m.flops_per_clip_vertex = v.at("flops_per_clip_vertex");
  m.flops_per_projected_vertex = v.at("flops_per_projected_vertex");
  m.flops_per_triangle = v.at("flops_per_triangle");
  m.flops_per_sample_tested = v.at("flops_per_sample_tested");
  m.flops_per_sample_inside = v.at("flops_per_sample_inside");
  m.flops_per_sample_written = v.at("flops_per_sample_written");
  m.flops_per_exposure_sample = v.at("flops_per_exposure_sample");
  m.flops_per_histogram_bucket = v.at("flops_per_histogram_bucket");
  m.flops_per_pixel_resolved = v.at("flops_per_pixel_resolved");
  m.render_element_bytes = v.at("render_element_bytes");
  m.render_vertex_bytes = v.at("render_vertex_bytes");
  m.frame_sample_bytes = v.at("frame_sample_bytes");
  m.pixel_bytes = v.at("pixel_bytes");
  m.exposure_histogram_bytes = v.at("exposure_histogram_bytes");
  m.exposure_selection_bytes = v.at("exposure_selection_bytes");
  return m;
}

}  // namespace ncube

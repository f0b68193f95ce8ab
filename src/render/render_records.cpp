#include "render/render_records.h"

#include <string>

#include "util/input_error.h"

namespace ncube {

std::vector<PatchSolution> uniform_solution(const Scene& scene,
                                            const std::vector<Rgb>& element_radiosity) {
  if (long(element_radiosity.size()) != scene.element_total())
    throw InputError("render: " + std::to_string(element_radiosity.size()) +
                     " radiosities for " + std::to_string(scene.element_total()) + " elements");
  std::vector<PatchSolution> solution(scene.patches.size());
  for (std::size_t p = 0; p < scene.patches.size(); ++p) {
    const Patch& patch = scene.patches[p];
    PatchSolution& s = solution[p];
    s.patch = int(p);
    for (int j = 0; j < patch.nv; ++j)
      for (int i = 0; i < patch.nu; ++i) {
        s.cells.push_back({0, i, j});
        s.radiosity.push_back(element_radiosity[std::size_t(patch.first_element) + j * patch.nu + i]);
      }
  }
  return solution;
}

namespace {

void check_solution(const Scene& scene, const std::vector<PatchSolution>& solution) {
  if (solution.size() != scene.patches.size())
    throw InputError("render: a solution of " + std::to_string(solution.size()) +
                     " patches for a scene of " + std::to_string(scene.patches.size()));
  for (std::size_t p = 0; p < solution.size(); ++p) {
    const PatchSolution& s = solution[p];
    const std::string where = "render: solution of patch " + std::to_string(p);
    if (s.patch != int(p)) throw InputError(where + ": names patch " + std::to_string(s.patch));
    if (s.cells.empty() || s.cells.size() != s.radiosity.size())
      throw InputError(where + ": " + std::to_string(s.radiosity.size()) + " radiosities for " +
                       std::to_string(s.cells.size()) + " elements");
    for (const ElementCell& c : s.cells)
      if (!cell_in_patch(scene.patches[p], c)) throw InputError(where + ": an element is outside it");
  }
}

}  // namespace

std::vector<RenderElement> render_elements(const Scene& scene,
                                           const std::vector<PatchSolution>& solution,
                                           const std::vector<int>& patches) {
  check_solution(scene, solution);
  // The running index of each patch's first element.
  std::vector<int> first(solution.size() + 1, 0);
  for (std::size_t p = 0; p < solution.size(); ++p)
    first[p + 1] = first[p] + int(solution[p].cells.size());
  std::vector<RenderElement> records;
  for (int p : patches) {
    const Patch& patch = scene.patches[std::size_t(p)];
    const PatchSolution& s = solution[std::size_t(p)];
    const PatchMesh mesh(patch, s.cells);
    const bool emitter = patch.emission.r > 0.0 || patch.emission.g > 0.0 || patch.emission.b > 0.0;
    for (std::size_t k = 0; k < s.cells.size(); ++k) {
      RenderElement r;
      r.element = first[std::size_t(p)] + int(k);
      r.corners = mesh.corner_count(k);
      r.boundary = mesh.boundary(s.radiosity, k);
      r.emitter = emitter;
      records.push_back(std::move(r));
    }
  }
  return records;
}

}  // namespace ncube

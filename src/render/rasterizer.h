// Renders a radiosity solution as a picture a person can judge: perspective camera,
// z-buffer, Gouraud shading of vertex radiosities, 3x3 supersampling, tone mapping.
#pragma once

#include <optional>
#include <vector>

#include <glm/vec2.hpp>

#include "render/image.h"
#include "render/render_records.h"
#include "scene/scene.h"

namespace ncube {
class FrameShare;
}

namespace ncube {

// Where a world point lands in a width x height picture seen by `camera`, in continuous
// pixel coordinates (x right, y down; pixel (i, j) covers [i, i+1) x [j, j+1)), or nothing
// if the point is not in front of the eye. Throws InputError for a degenerate camera.
std::optional<glm::dvec2> project(const Camera& camera, int width, int height, const Vec3& point);

// The scene seen by `camera`, each element of `solution` (one entry per scene patch, in
// order; see render_records.h) drawn with its whole boundary and Gouraud-shaded with its
// nodal radiosities. Both sides of every polygon are drawn; the background is black.
// Tone mapping: exposure so that the 95th percentile of the luminance of the visible
// non-emitting surface (all visible surface if no such) maps to 0.9, then clamp to [0, 1]
// and sRGB encode. With `outline_elements`, each element's edges are thin black lines (the
// exposure is that of the picture without them). The output is a deterministic function of
// the inputs.
Image render_solution(const Scene& scene, const Camera& camera,
                      const std::vector<PatchSolution>& solution, int width, int height,
                      bool outline_elements = false);

// The exposure scale of that picture (render_solution's tone mapping), for colouring the
// solution mesh as the picture is coloured.
double solution_exposure(const Scene& scene, const Camera& camera,
                         const std::vector<PatchSolution>& solution, int width, int height);

// The exposure scale of a frame that holds the whole picture (the tone mapping above).
double frame_exposure(const FrameShare& frame);

}  // namespace ncube

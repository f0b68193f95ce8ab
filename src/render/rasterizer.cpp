#include "render/rasterizer.h"

#include <algorithm>
#include <numeric>

#include "render/exposure.h"
#include "render/frame_share.h"

namespace ncube {

std::optional<glm::dvec2> project(const Camera& camera, int width, int height,
                                  const Vec3& point) {
  const CameraView view(camera, width, height);
  const Vec3 c = view.to_camera(point);
  if (!(c.z > 0.0)) return std::nullopt;
  return view.to_screen(c);
}

// Exposure of a frame held in one place: its visible samples' luminances, sorted in part.
double frame_exposure(const FrameShare& frame) {
  std::vector<double> lum[2];  // [0]: non-emitters, [1]: all visible
  frame.for_each_visible([&lum](const Rgb& radiosity, bool emitter) {
    const double l = luminance(radiosity);
    if (!emitter) lum[0].push_back(l);
    lum[1].push_back(l);
  });
  return exposure_scale(select_locally(lum[0]), select_locally(lum[1]));
}

namespace {

// The scene's elements drawn into one frame that holds the whole picture.
void draw_all(const Scene& scene, const std::vector<PatchSolution>& solution, FrameShare& frame,
              RenderCounts& counts) {
  std::vector<int> all_patches(scene.patches.size());
  std::iota(all_patches.begin(), all_patches.end(), 0);
  for (const RenderElement& element : render_elements(scene, solution, all_patches))
    frame.draw(element, counts);
}

}  // namespace

Image render_solution(const Scene& scene, const Camera& camera,
                      const std::vector<PatchSolution>& solution, int width, int height,
                      bool outline_elements) {
  FrameShare frame(scene, camera, width, height, RowShare::whole(height), outline_elements);
  RenderCounts counts;
  draw_all(scene, solution, frame, counts);
  return frame.resolve(frame_exposure(frame), counts);
}

double solution_exposure(const Scene& scene, const Camera& camera,
                         const std::vector<PatchSolution>& solution, int width, int height) {
  // Drawn in bands of rows, not as one frame: the whole frame of an 800 x 600 picture is
  // 4.3 M samples, about 180 MB written for one number (a second of CPU, most of it page
  // faults, in every --mesh run). A picture's parts are the whole picture sample for sample
  // (frame_share.h), so the visible samples' luminances, and the percentile, are the same.
  constexpr int kBandRows = 64;
  std::vector<int> all_patches(scene.patches.size());
  std::iota(all_patches.begin(), all_patches.end(), 0);
  const std::vector<RenderElement> elements = render_elements(scene, solution, all_patches);
  const int bands = std::max(1, (height + kBandRows - 1) / kBandRows);
  // The non-emitters' luminances and the emitters': the selection over all visible samples
  // is used only when no non-emitter shows (exposure_scale), and is then the emitters'.
  std::vector<double> lit, emitting;
  lit.reserve(std::size_t(width) * std::size_t(height) * kSamplesPerAxis * kSamplesPerAxis);
  for (int part = 0; part < bands; ++part) {
    FrameShare frame(scene, camera, width, height,
                     RowShare{height, bands, part, RowPartition::kBlocks}, false);
    RenderCounts counts;
    for (const RenderElement& element : elements) frame.draw(element, counts);
    frame.for_each_visible([&lit, &emitting](const Rgb& radiosity, bool emitter) {
      (emitter ? emitting : lit).push_back(luminance(radiosity));
    });
  }
  const LuminanceSelection non_emitters = select_locally(lit);
  return exposure_scale(non_emitters,
                        non_emitters.count > 0 ? non_emitters : select_locally(emitting));
}

}  // namespace ncube

// The z-buffered, 3 x 3 supersampled frame of the rows one renderer owns (paper section
// 2.3: each processor renders its part of the picture). The sequential render is the
// special case of one part holding every row; both draw with the same code, so a picture
// assembled from parts is the sequential picture pixel for pixel.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "counts/render_counts.h"
#include "render/image.h"
#include "render/render_records.h"
#include "render/row_share.h"
#include "scene/scene.h"

namespace ncube {

constexpr int kSamplesPerAxis = 3;  // supersampling per axis, for smooth edges

// World -> camera space (x right, y up, z depth along the view) -> pixels.
struct CameraView {
  Vec3 eye, right, up, forward;
  double focal = 0.0;  // pixels per unit of x/z
  double cx = 0.0, cy = 0.0;

  // Throws InputError for a bad picture size or a degenerate camera.
  CameraView(const Camera& camera, int width, int height);
  Vec3 to_camera(const Vec3& p) const;
  glm::dvec2 to_screen(const Vec3& c) const;
};

class FrameShare {
 public:
  // Throws InputError for a bad picture size or a degenerate camera. With
  // `outline_elements`, the resolved picture shows each element's edges as dark lines.
  FrameShare(const Scene& scene, const Camera& camera, int width, int height, RowShare rows,
             bool outline_elements = false);

  // Draws one element into the owned rows, in any order: the nearest surface wins, a depth
  // tie the lower (element, triangle) drawing key, as when drawn in scene order. An element
  // without T-vertices is a fan from its first (clipped) vertex; one with T-vertices a fan
  // from its centre, so that every piece of its boundary is a triangle's edge and the
  // shading along it is the neighbours' (docs/model.md, "Rendering").
  void draw(const RenderElement& element, RenderCounts& counts);

  // Calls f(radiosity, emitter) for every sample that shows a surface.
  template <class F>
  void for_each_visible(F f) const;
  std::uint64_t visible_samples() const;

  // The owned rows, in order, tone mapped with exposure `scale`: clamp per sample, average
  // 3 x 3, sRGB encode (width x rows().count() pixels). Outline samples are black.
  Image resolve(double scale, RenderCounts& counts) const;

  const RowShare& rows() const { return rows_; }
  std::size_t samples() const { return inv_depth_.size(); }

 private:
  struct CameraVertex {
    Vec3 position;  // camera space
    Rgb radiosity;
  };
  // Perspective-correct interpolation: 1/z and radiosity/z are linear in screen space.
  struct ScreenVertex {
    glm::dvec2 p;
    double w;  // 1/z
    Rgb rw;    // radiosity/z
  };
  // `element_edges`: which of the edges ab (1), bc (2), ca (4) lie on the element's boundary
  // (for outlines).
  void draw_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, std::int64_t key,
                     bool emitter, unsigned element_edges, RenderCounts& counts);

  CameraView view_;
  double near_ = 0.0;
  int width_ = 0, height_ = 0;  // in samples
  RowShare rows_;               // in picture rows
  std::vector<double> inv_depth_;  // 0 = background
  std::vector<Rgb> radiosity_;
  std::vector<std::int64_t> key_;  // drawing key of the nearest surface
  std::vector<char> emitter_;
  bool outline_elements_ = false;
  std::vector<char> outline_;  // the sample lies on an edge of its element (when outlining)
  // Scratch space of draw(), kept to spare an allocation per element.
  std::vector<CameraVertex> in_, out_;
  std::vector<char> out_on_boundary_;  // the edge from out_[k] to out_[k + 1] is the element's
  std::vector<ScreenVertex> screen_;
};

template <class F>
void FrameShare::for_each_visible(F f) const {
  for (std::size_t k = 0; k < inv_depth_.size(); ++k)
    if (inv_depth_[k] != 0.0) f(radiosity_[k], emitter_[k] != 0);
}

}  // namespace ncube

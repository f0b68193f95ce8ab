#include "render/frame_share.h"

#include "render/exposure.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "util/input_error.h"

namespace ncube {

CameraView::CameraView(const Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0)
    throw InputError("render: image size " + std::to_string(width) + "x" +
                     std::to_string(height) + " must be positive");
  const Vec3 view = camera.look_at - camera.eye;
  const Vec3 side = glm::cross(view, camera.up);
  if (!(glm::length(view) > 0.0) || !(glm::length(side) > 0.0))
    throw InputError("camera: look_at must differ from eye and up must not be along the view");
  if (!(camera.fov_deg > 0.0 && camera.fov_deg < 180.0))
    throw InputError("camera: fov_deg must be in (0, 180)");
  eye = camera.eye;
  forward = glm::normalize(view);
  right = glm::normalize(side);
  up = glm::cross(right, forward);
  focal = 0.5 * height / std::tan(0.5 * glm::radians(camera.fov_deg));
  cx = 0.5 * width;
  cy = 0.5 * height;
}

Vec3 CameraView::to_camera(const Vec3& p) const {
  const Vec3 d = p - eye;
  return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
}

glm::dvec2 CameraView::to_screen(const Vec3& c) const {
  return {cx + focal * c.x / c.z, cy - focal * c.y / c.z};
}

namespace {

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Outlines: a sample within half a sample of its element's edge (a line one sample wide, in
// screen space whatever the distance) is drawn black.
constexpr double kOutlineHalfWidth = 0.5;

}  // namespace

FrameShare::FrameShare(const Scene& scene, const Camera& camera, int width, int height,
                       RowShare rows, bool outline_elements)
    : view_(camera, width * kSamplesPerAxis, height * kSamplesPerAxis),
      width_(width * kSamplesPerAxis),
      height_(height * kSamplesPerAxis),
      rows_(rows),
      outline_elements_(outline_elements) {
  // The near plane scales with the scene so that any unit of length works.
  const double extent = scene_bounds(scene).diagonal();
  near_ = extent > 0.0 ? 1e-6 * extent : 1e-9;
  const std::size_t n = std::size_t(width_) * kSamplesPerAxis * std::size_t(rows_.count());
  inv_depth_.assign(n, 0.0);
  radiosity_.assign(n, Rgb(0.0));
  key_.assign(n, 0);
  emitter_.assign(n, 0);
  if (outline_elements_) outline_.assign(n, 0);
}

// Samples are at sample centres; the inclusive edge test leaves no cracks between
// neighbours (a shared edge is drawn twice with the same values). Only the sample rows of
// the owned picture rows are visited.
void FrameShare::draw_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, std::int64_t key,
                               bool emitter, unsigned element_edges, RenderCounts& counts) {
  ++counts.triangles;
  double area = edge(a.p, b.p, c.p);
  if (!std::isfinite(area) || area == 0.0) return;
  if (area < 0.0) {  // back side: both sides are drawn
    std::swap(b, c);
    area = -area;
    element_edges = (element_edges & 2u) | ((element_edges & 1u) << 2) | ((element_edges & 4u) >> 2);
  }
  // Outlines: the edge function over an edge's length is the distance to it, in samples.
  const bool outline_ab = outline_elements_ && (element_edges & 1u),
             outline_bc = outline_elements_ && (element_edges & 2u),
             outline_ca = outline_elements_ && (element_edges & 4u);
  const double half_ab = outline_ab ? kOutlineHalfWidth * glm::length(b.p - a.p) : 0.0,
               half_bc = outline_bc ? kOutlineHalfWidth * glm::length(c.p - b.p) : 0.0,
               half_ca = outline_ca ? kOutlineHalfWidth * glm::length(a.p - c.p) : 0.0;
  const auto range = [](double lo, double hi, int size, int& first, int& last) {
    first = int(std::clamp(std::ceil(lo - 0.5), 0.0, double(size)));
    last = int(std::clamp(std::floor(hi - 0.5), -1.0, double(size - 1)));
  };
  int x0, x1, y0, y1;
  range(std::min({a.p.x, b.p.x, c.p.x}), std::max({a.p.x, b.p.x, c.p.x}), width_, x0, x1);
  range(std::min({a.p.y, b.p.y, c.p.y}), std::max({a.p.y, b.p.y, c.p.y}), height_, y0, y1);
  if (y0 > y1 || x0 > x1) return;
  const int last_row = y1 / kSamplesPerAxis;
  for (int row = rows_.first_owned_from(y0 / kSamplesPerAxis); row <= last_row && row < rows_.height;
       row = rows_.next_owned(row)) {
    const int local = rows_.local_index(row);
    const int sy0 = std::max(y0, row * kSamplesPerAxis);
    const int sy1 = std::min(y1, row * kSamplesPerAxis + kSamplesPerAxis - 1);
    for (int y = sy0; y <= sy1; ++y) {
      const std::size_t line =
          (std::size_t(local) * kSamplesPerAxis + std::size_t(y - row * kSamplesPerAxis)) * width_;
      counts.samples_tested += std::uint64_t(x1 - x0 + 1);
      for (int x = x0; x <= x1; ++x) {
        const glm::dvec2 p(x + 0.5, y + 0.5);
        const double ea = edge(b.p, c.p, p), eb = edge(c.p, a.p, p), ec = edge(a.p, b.p, p);
        if (ea < 0.0 || eb < 0.0 || ec < 0.0) continue;
        ++counts.samples_inside;
        const double w = (ea * a.w + eb * b.w + ec * c.w) / area;
        const std::size_t k = line + std::size_t(x);
        if (!(w > inv_depth_[k] || (w == inv_depth_[k] && key < key_[k]))) continue;
        ++counts.samples_written;
        inv_depth_[k] = w;
        key_[k] = key;
        radiosity_[k] = (ea * a.rw + eb * b.rw + ec * c.rw) / (area * w);
        emitter_[k] = emitter;
        if (outline_elements_)
          outline_[k] = (outline_ab && ec <= half_ab) || (outline_bc && ea <= half_bc) ||
                        (outline_ca && eb <= half_ca);
      }
    }
  }
}

// Clips against the near plane z = near (Sutherland-Hodgman), projects, draws as a fan.
void FrameShare::draw(const RenderElement& element, RenderCounts& counts) {
  const std::size_t n = element.boundary.size();
  in_.clear();
  for (const MeshVertex& v : element.boundary)
    in_.push_back({view_.to_camera(v.position), v.radiosity});
  counts.vertices += std::uint64_t(n);
  out_.clear();
  out_on_boundary_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const CameraVertex& s = in_[i];
    const CameraVertex& e = in_[(i + 1) % n];
    const bool s_in = s.position.z >= near_, e_in = e.position.z >= near_;
    if (s_in) {
      out_.push_back(s);
      out_on_boundary_.push_back(1);
    }
    if (s_in != e_in) {
      const double t = (near_ - s.position.z) / (e.position.z - s.position.z);
      out_.push_back({s.position + t * (e.position - s.position),
                      s.radiosity + t * (e.radiosity - s.radiosity)});
      // Leaving the near side, the next edge runs along the near plane, not the element's.
      out_on_boundary_.push_back(!e_in ? 0 : 1);
      ++counts.clip_vertices;
    }
  }
  const std::size_t m = out_.size();
  if (m < 3) return;
  // A T-vertex lies on the line of its edge: in a fan from a corner the pieces of that
  // corner's own edges would be degenerate triangles, their T-vertices' radiosities lost.
  // The centre (mean of the boundary points, position and radiosity: exact for a radiosity
  // linear over the element) sees every piece of the boundary. It is taken unclipped; when
  // it is behind the near plane the clipped polygon is fanned from its first vertex.
  CameraVertex centre{Vec3(0.0), Rgb(0.0)};
  bool centre_fan = element.t_vertices() > 0;
  if (centre_fan) {
    for (const CameraVertex& v : in_) {
      centre.position += v.position;
      centre.radiosity += v.radiosity;
    }
    centre.position /= double(n);
    centre.radiosity /= double(n);
    centre_fan = centre.position.z >= near_;
    counts.vertices += 1;
  }
  screen_.clear();
  const auto project = [this](const CameraVertex& v) {
    const double w = 1.0 / v.position.z;
    return ScreenVertex{view_.to_screen(v.position), w, v.radiosity * w};
  };
  for (const CameraVertex& v : out_) screen_.push_back(project(v));
  counts.projected_vertices += std::uint64_t(m);
  // Drawing key: element, then triangle of its fan, so ties resolve as in scene order.
  const std::int64_t element_key = std::int64_t(element.element) << 32;
  if (centre_fan) {
    const ScreenVertex c = project(centre);
    ++counts.projected_vertices;
    for (std::size_t i = 0; i < m; ++i)
      draw_triangle(c, screen_[i], screen_[(i + 1) % m], element_key + std::int64_t(i),
                    element.emitter, out_on_boundary_[i] ? 2u : 0u, counts);
    return;
  }
  for (std::size_t i = 1; i + 1 < m; ++i) {
    const unsigned edges = (i == 1 && out_on_boundary_[0] ? 1u : 0u) |
                           (out_on_boundary_[i] ? 2u : 0u) |
                           (i + 2 == m && out_on_boundary_[m - 1] ? 4u : 0u);
    draw_triangle(screen_[0], screen_[i], screen_[i + 1], element_key + std::int64_t(i),
                  element.emitter, edges, counts);
  }
}

std::uint64_t FrameShare::visible_samples() const {
  return std::uint64_t(std::count_if(inv_depth_.begin(), inv_depth_.end(),
                                     [](double w) { return w != 0.0; }));
}

// Clamp per sample before averaging so edges of over-exposed emitters stay smooth.
Image FrameShare::resolve(double scale, RenderCounts& counts) const {
  const int width = width_ / kSamplesPerAxis;
  Image image(width, rows_.count());
  for (int local = 0; local < rows_.count(); ++local) {
    for (int x = 0; x < width; ++x) {
      Rgb sum(0.0);
      for (int sy = 0; sy < kSamplesPerAxis; ++sy)
        for (int sx = 0; sx < kSamplesPerAxis; ++sx) {
          const std::size_t k = (std::size_t(local) * kSamplesPerAxis + sy) * width_ +
                                std::size_t(x) * kSamplesPerAxis + sx;
          if (!outline_elements_ || !outline_[k]) sum += glm::clamp(radiosity_[k] * scale, 0.0, 1.0);
        }
      sum /= double(kSamplesPerAxis * kSamplesPerAxis);
      image.at(x, local) = glm::vec3(float(srgb_encode(sum.r)), float(srgb_encode(sum.g)),
                                 float(srgb_encode(sum.b)));
    }
    counts.pixels_resolved += std::uint64_t(width);
  }
  return image;
}

}  // namespace ncube

#include "render/frame_share.h"

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

struct CameraVertex {
  Vec3 position;  // camera space
  Rgb radiosity;
};

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Index of grid vertex (i, j) of a patch. A triangle's top row of grid vertices is one
// point (v2), so they all share the index of (0, nv).
int grid_vertex(const Patch& patch, int i, int j) {
  return patch.polygon.count == 3 && j == patch.nv ? patch.nv * (patch.nu + 1)
                                                   : j * (patch.nu + 1) + i;
}

// The corners of element (i, j) in grid_cell's vertex order; a last-row triangle has 3.
int cell_corners(const Patch& patch, int i, int j, int corners[4]) {
  corners[0] = grid_vertex(patch, i, j);
  corners[1] = grid_vertex(patch, i + 1, j);
  corners[2] = grid_vertex(patch, i + 1, j + 1);
  corners[3] = grid_vertex(patch, i, j + 1);
  return patch.polygon.count == 3 && j == patch.nv - 1 ? 3 : 4;
}

// Radiosity at each grid vertex: the mean of the patch's elements sharing it.
std::vector<Rgb> vertex_radiosity(const Patch& patch, const std::vector<Rgb>& element_radiosity) {
  std::vector<Rgb> sum(std::size_t(patch.nu + 1) * (patch.nv + 1), Rgb(0.0));
  std::vector<int> count(sum.size(), 0);
  for (int j = 0; j < patch.nv; ++j)
    for (int i = 0; i < patch.nu; ++i) {
      const Rgb& b = element_radiosity[std::size_t(patch.first_element) + j * patch.nu + i];
      int corners[4];
      const int n = cell_corners(patch, i, j, corners);
      for (int c = 0; c < n; ++c) {
        sum[corners[c]] += b;
        ++count[corners[c]];
      }
    }
  for (std::size_t k = 0; k < sum.size(); ++k)
    if (count[k] > 0) sum[k] /= double(count[k]);
  return sum;
}

double srgb_encode(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

constexpr int kMaxFanVertices = 8;  // a quad clipped by one plane has at most 5

}  // namespace

std::vector<RenderElement> render_elements(const Scene& scene,
                                           const std::vector<Rgb>& element_radiosity,
                                           const std::vector<int>& patches) {
  if (element_radiosity.size() != scene.elements.size())
    throw InputError("render: " + std::to_string(element_radiosity.size()) +
                     " radiosities for " + std::to_string(scene.elements.size()) + " elements");
  std::vector<RenderElement> records;
  for (int p : patches) {
    const Patch& patch = scene.patches[std::size_t(p)];
    const std::vector<Rgb> corner = vertex_radiosity(patch, element_radiosity);
    const bool emitter = patch.emission.r > 0.0 || patch.emission.g > 0.0 || patch.emission.b > 0.0;
    for (int j = 0; j < patch.nv; ++j)
      for (int i = 0; i < patch.nu; ++i) {
        RenderElement r;
        r.element = patch.first_element + j * patch.nu + i;
        const Element& element = scene.elements[std::size_t(r.element)];
        int corners[4];
        r.corners = cell_corners(patch, i, j, corners);
        for (int c = 0; c < r.corners; ++c) {
          r.position[c] = element.polygon[c];
          r.radiosity[c] = corner[corners[c]];
        }
        r.emitter = emitter;
        records.push_back(r);
      }
  }
  return records;
}

// Perspective-correct interpolation: 1/z and radiosity/z are linear in screen space.
struct FrameShare::ScreenVertex {
  glm::dvec2 p;
  double w;  // 1/z
  Rgb rw;    // radiosity/z
};

FrameShare::FrameShare(const Scene& scene, const Camera& camera, int width, int height,
                       RowShare rows)
    : view_(camera, width * kSamplesPerAxis, height * kSamplesPerAxis),
      width_(width * kSamplesPerAxis),
      height_(height * kSamplesPerAxis),
      rows_(rows) {
  // The near plane scales with the scene so that any unit of length works.
  const double extent = scene_bounds(scene).diagonal();
  near_ = extent > 0.0 ? 1e-6 * extent : 1e-9;
  const std::size_t n = std::size_t(width_) * kSamplesPerAxis * std::size_t(rows_.count());
  inv_depth_.assign(n, 0.0);
  radiosity_.assign(n, Rgb(0.0));
  key_.assign(n, 0);
  emitter_.assign(n, 0);
}

// Samples are at sample centres; the inclusive edge test leaves no cracks between
// neighbours (a shared edge is drawn twice with the same values). Only the sample rows of
// the owned picture rows are visited.
void FrameShare::draw_triangle(ScreenVertex a, ScreenVertex b, ScreenVertex c, std::int64_t key,
                               bool emitter, RenderCounts& counts) {
  ++counts.triangles;
  double area = edge(a.p, b.p, c.p);
  if (!std::isfinite(area) || area == 0.0) return;
  if (area < 0.0) {  // back side: both sides are drawn
    std::swap(b, c);
    area = -area;
  }
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
      }
    }
  }
}

// Clips against the near plane z = near (Sutherland-Hodgman), projects, draws as a fan.
void FrameShare::draw(const RenderElement& element, RenderCounts& counts) {
  CameraVertex in[4];
  for (int c = 0; c < element.corners; ++c)
    in[c] = {view_.to_camera(element.position[c]), element.radiosity[c]};
  counts.vertices += std::uint64_t(element.corners);
  CameraVertex out[kMaxFanVertices];
  int m = 0;
  const int n = element.corners;
  for (int i = 0; i < n; ++i) {
    const CameraVertex& s = in[i];
    const CameraVertex& e = in[(i + 1) % n];
    const bool s_in = s.position.z >= near_, e_in = e.position.z >= near_;
    if (s_in) out[m++] = s;
    if (s_in != e_in) {
      const double t = (near_ - s.position.z) / (e.position.z - s.position.z);
      out[m++] = {s.position + t * (e.position - s.position),
                  s.radiosity + t * (e.radiosity - s.radiosity)};
      ++counts.clip_vertices;
    }
  }
  if (m < 3) return;
  ScreenVertex sv[kMaxFanVertices];
  for (int i = 0; i < m; ++i) {
    const double w = 1.0 / out[i].position.z;
    sv[i] = {view_.to_screen(out[i].position), w, out[i].radiosity * w};
  }
  counts.projected_vertices += std::uint64_t(m);
  // Drawing key: element, then triangle of its fan, so ties resolve as in scene order.
  for (int i = 1; i + 1 < m; ++i)
    draw_triangle(sv[0], sv[i], sv[i + 1], std::int64_t(element.element) * kMaxFanVertices + i,
                  element.emitter, counts);
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
          sum += glm::clamp(radiosity_[k] * scale, 0.0, 1.0);
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

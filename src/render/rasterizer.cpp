#include "render/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "util/input_error.h"

namespace ncube {
namespace {

constexpr int kSamples = 3;               // supersampling per axis, for smooth edges
constexpr double kPercentile = 0.95;      // this percentile of visible luminance ...
constexpr double kPercentileValue = 0.9;  // ... maps to this linear value (before sRGB)

// World -> camera space (x right, y up, z depth along the view) -> pixels.
struct View {
  Vec3 eye, right, up, forward;
  double focal = 0.0;  // pixels per unit of x/z
  double cx = 0.0, cy = 0.0;

  Vec3 to_camera(const Vec3& p) const {
    const Vec3 d = p - eye;
    return {glm::dot(d, right), glm::dot(d, up), glm::dot(d, forward)};
  }
  glm::dvec2 to_screen(const Vec3& c) const {
    return {cx + focal * c.x / c.z, cy - focal * c.y / c.z};
  }
};

View make_view(const Camera& camera, int width, int height) {
  if (width <= 0 || height <= 0)
    throw InputError("render: image size " + std::to_string(width) + "x" +
                     std::to_string(height) + " must be positive");
  const Vec3 forward = camera.look_at - camera.eye;
  const Vec3 side = glm::cross(forward, camera.up);
  if (!(glm::length(forward) > 0.0) || !(glm::length(side) > 0.0))
    throw InputError("camera: look_at must differ from eye and up must not be along the view");
  if (!(camera.fov_deg > 0.0 && camera.fov_deg < 180.0))
    throw InputError("camera: fov_deg must be in (0, 180)");
  View v;
  v.eye = camera.eye;
  v.forward = glm::normalize(forward);
  v.right = glm::normalize(side);
  v.up = glm::cross(v.right, v.forward);
  v.focal = 0.5 * height / std::tan(0.5 * glm::radians(camera.fov_deg));
  v.cx = 0.5 * width;
  v.cy = 0.5 * height;
  return v;
}

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

// The supersampled frame: nearest surface per sample.
struct Frame {
  int width, height;
  std::vector<double> inv_depth;  // 0 = background
  std::vector<Rgb> radiosity;
  std::vector<char> emitter;

  Frame(int w, int h)
      : width(w), height(h), inv_depth(std::size_t(w) * h, 0.0),
        radiosity(std::size_t(w) * h, Rgb(0.0)), emitter(std::size_t(w) * h, 0) {}
};

double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
  return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Samples are at pixel centres; the inclusive edge test leaves no cracks between
// neighbours (a shared edge is drawn twice with the same values).
void draw_triangle(Frame& frame, ScreenVertex a, ScreenVertex b, ScreenVertex c, bool emitter) {
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
  range(std::min({a.p.x, b.p.x, c.p.x}), std::max({a.p.x, b.p.x, c.p.x}), frame.width, x0, x1);
  range(std::min({a.p.y, b.p.y, c.p.y}), std::max({a.p.y, b.p.y, c.p.y}), frame.height, y0, y1);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5);
      const double ea = edge(b.p, c.p, p), eb = edge(c.p, a.p, p), ec = edge(a.p, b.p, p);
      if (ea < 0.0 || eb < 0.0 || ec < 0.0) continue;
      const double w = (ea * a.w + eb * b.w + ec * c.w) / area;
      const std::size_t k = std::size_t(y) * frame.width + x;
      if (!(w > frame.inv_depth[k])) continue;
      frame.inv_depth[k] = w;
      frame.radiosity[k] = (ea * a.rw + eb * b.rw + ec * c.rw) / (area * w);
      frame.emitter[k] = emitter;
    }
}

// Clips against the near plane z = near (Sutherland-Hodgman), projects, draws as a fan.
void draw_polygon(Frame& frame, const View& view, double near, const CameraVertex* in, int n,
                  bool emitter) {
  CameraVertex out[8];
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const CameraVertex& s = in[i];
    const CameraVertex& e = in[(i + 1) % n];
    const bool s_in = s.position.z >= near, e_in = e.position.z >= near;
    if (s_in) out[m++] = s;
    if (s_in != e_in) {
      const double t = (near - s.position.z) / (e.position.z - s.position.z);
      out[m++] = {s.position + t * (e.position - s.position),
                  s.radiosity + t * (e.radiosity - s.radiosity)};
    }
  }
  if (m < 3) return;
  ScreenVertex sv[8];
  for (int i = 0; i < m; ++i) {
    const double w = 1.0 / out[i].position.z;
    sv[i] = {view.to_screen(out[i].position), w, out[i].radiosity * w};
  }
  for (int i = 1; i + 1 < m; ++i) draw_triangle(frame, sv[0], sv[i], sv[i + 1], emitter);
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

// Radiosity at each grid vertex: the mean of the patch's elements sharing it (the apex of
// a triangle is shared by its whole last row).
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

double luminance(const Rgb& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; }

double srgb_encode(double c) {
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

// Exposure that maps the kPercentile luminance of visible non-emitting samples (of all
// visible samples if no non-emitter shows) to kPercentileValue.
double exposure(const Frame& frame) {
  std::vector<double> lum[2];  // [0]: non-emitters, [1]: all visible
  for (std::size_t k = 0; k < frame.inv_depth.size(); ++k) {
    if (frame.inv_depth[k] == 0.0) continue;
    const double l = luminance(frame.radiosity[k]);
    if (!frame.emitter[k]) lum[0].push_back(l);
    lum[1].push_back(l);
  }
  std::vector<double>& v = lum[0].empty() ? lum[1] : lum[0];
  if (v.empty()) return 1.0;
  auto nth = v.begin() + std::ptrdiff_t(kPercentile * double(v.size() - 1));
  std::nth_element(v.begin(), nth, v.end());
  double reference = *nth;
  if (!(reference > 0.0)) reference = *std::max_element(v.begin(), v.end());
  return reference > 0.0 ? kPercentileValue / reference : 1.0;
}

}  // namespace

std::optional<glm::dvec2> project(const Camera& camera, int width, int height,
                                  const Vec3& point) {
  const View view = make_view(camera, width, height);
  const Vec3 c = view.to_camera(point);
  if (!(c.z > 0.0)) return std::nullopt;
  return view.to_screen(c);
}

Image render_solution(const Scene& scene, const Camera& camera,
                      const std::vector<Rgb>& element_radiosity, int width, int height) {
  if (element_radiosity.size() != scene.elements.size())
    throw InputError("render: " + std::to_string(element_radiosity.size()) +
                     " radiosities for " + std::to_string(scene.elements.size()) + " elements");
  const View view = make_view(camera, width * kSamples, height * kSamples);

  // The near plane scales with the scene so that any unit of length works.
  const double extent = scene_bounds(scene).diagonal();
  const double near = extent > 0.0 ? 1e-6 * extent : 1e-9;

  Frame frame(width * kSamples, height * kSamples);
  for (const Patch& patch : scene.patches) {
    const std::vector<Rgb> corner = vertex_radiosity(patch, element_radiosity);
    const bool emitter = patch.emission.r > 0.0 || patch.emission.g > 0.0 || patch.emission.b > 0.0;
    for (int j = 0; j < patch.nv; ++j)
      for (int i = 0; i < patch.nu; ++i) {
        const Element& element =
            scene.elements[std::size_t(patch.first_element) + j * patch.nu + i];
        int corners[4];
        const int n = cell_corners(patch, i, j, corners);
        CameraVertex v[4];
        for (int c = 0; c < n; ++c)
          v[c] = {view.to_camera(element.polygon[c]), corner[corners[c]]};
        draw_polygon(frame, view, near, v, n, emitter);
      }
  }

  // Clamp per sample before averaging so edges of over-exposed emitters stay smooth.
  const double scale = exposure(frame);
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      Rgb sum(0.0);
      for (int sy = 0; sy < kSamples; ++sy)
        for (int sx = 0; sx < kSamples; ++sx) {
          const std::size_t k = std::size_t(y * kSamples + sy) * frame.width + x * kSamples + sx;
          sum += glm::clamp(frame.radiosity[k] * scale, 0.0, 1.0);
        }
      sum /= double(kSamples * kSamples);
      image.at(x, y) = glm::vec3(float(srgb_encode(sum.r)), float(srgb_encode(sum.g)),
                                 float(srgb_encode(sum.b)));
    }
  return image;
}

}  // namespace ncube

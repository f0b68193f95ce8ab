#include "reference/area_form_factors.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <glm/geometric.hpp>

#include "reference/point_polygon_factor.h"
#include "reference/ray_visibility.h"
#include "reference/stratified_points.h"

namespace ncube::reference {
namespace {

// Whether any corner of `polygon` lies strictly in front of the plane through `point`.
bool some_in_front(const Polygon& polygon, const Vec3& point, const Vec3& normal) {
  for (int c = 0; c < polygon.count; ++c)
    if (glm::dot(polygon[c] - point, normal) > 0.0) return true;
  return false;
}

double radius(const Element& e) {
  double r = 0.0;
  for (int c = 0; c < e.polygon.count; ++c) r = std::max(r, glm::length(e.polygon[c] - e.centre));
  return r;
}

// The kernel cos cos / (pi r^2) times the two points' weights, 0 where either faces away.
double kernel(const AreaSample& x, const Vec3& nx, const AreaSample& y, const Vec3& ny) {
  const Vec3 d = y.point - x.point;
  const double r2 = glm::dot(d, d);
  if (r2 <= 0.0) return 0.0;
  const double cos_x = glm::dot(nx, d);
  const double cos_y = -glm::dot(ny, d);
  if (cos_x <= 0.0 || cos_y <= 0.0) return 0.0;
  return x.weight * y.weight * cos_x * cos_y / (M_PI * r2 * r2);
}

// The kernel, 0 also where the segment is blocked.
double pair_term(const AreaSample& x, const Vec3& nx, const AreaSample& y, const Vec3& ny,
                 const RayVisibility& rays, long long& ray_count) {
  const double term = kernel(x, nx, y, ny);
  if (term <= 0.0) return 0.0;
  ++ray_count;
  return rays.visible(x.point, nx, y.point, ny) ? term : 0.0;
}

// The weighted share of `points` (on a surface of normal `normal`) that are open: from which
// some ray of a stratified cosine-weighted spread of kEnclosureSide^2 directions meets a
// patch's front or leaves the scene. A point whose every ray meets a back (the floor inside
// a bottomless box standing on it) is enclosed: it receives nothing and sends nothing to any
// front, so its radiosity is its emission, and it must not dilute what the rest of its
// element sends (the element's radiosity is constant: without this, the floor elements
// partly under the Cornell box's blocks sent the blocks' faces their mean over the dark part
// too, several per cent too little).
double open_fraction_of(const std::vector<AreaSample>& points, const Vec3& normal,
                        const RayVisibility& rays, std::uint64_t seed) {
  constexpr int side = FormFactorOptions::kEnclosureSide;
  const Vec3 tangent = glm::normalize(
      glm::cross(normal, std::fabs(normal.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  const Vec3 bitangent = glm::cross(normal, tangent);
  SampleStream stream(seed);
  double open = 0.0, all = 0.0;
  for (const AreaSample& x : points) {
    bool is_open = false;
    for (int a = 0; a < side && !is_open; ++a)
      for (int b = 0; b < side && !is_open; ++b) {
        const double u = (a + stream.next_unit()) / side, v = (b + stream.next_unit()) / side;
        const double r = std::sqrt(u), phi = 2.0 * M_PI * v;
        const Vec3 direction = r * std::cos(phi) * tangent + r * std::sin(phi) * bitangent +
                               std::sqrt(std::max(0.0, 1.0 - u)) * normal;
        is_open = rays.first_hit(x.point, normal, direction) != RayVisibility::Hit::kBack;
      }
    all += x.weight;
    if (is_open) open += x.weight;
  }
  return all > 0.0 ? open / all : 0.0;
}

}  // namespace

FormFactors::FormFactors(std::vector<double> open_area, std::vector<Row> rows)
    : open_area_(std::move(open_area)), rows_(std::move(rows)) {
  rows_.resize(open_area_.size());
}

double FormFactors::factor(int i, int j) const {
  if (i == j || open_area(i) <= 0.0) return 0.0;
  const Row& row = rows_[std::size_t(std::min(i, j))];
  const auto at = std::lower_bound(row.column.begin(), row.column.end(), std::max(i, j));
  if (at == row.column.end() || *at != std::max(i, j)) return 0.0;
  return row.exchange[std::size_t(at - row.column.begin())] / open_area(i);
}

std::vector<FormFactorEntry> FormFactors::row(int i) const {
  std::vector<FormFactorEntry> entries;
  if (open_area(i) <= 0.0) return entries;
  for (int j = 0; j < i; ++j)
    if (const double f = factor(i, j); f > 0.0) entries.push_back({j, f});
  const Row& own = rows_[std::size_t(i)];
  for (std::size_t k = 0; k < own.column.size(); ++k)
    entries.push_back({own.column[k], own.exchange[k] / open_area(i)});
  return entries;
}

long long FormFactors::pairs() const {
  long long count = 0;
  for (const Row& row : rows_) count += static_cast<long long>(row.column.size());
  return count;
}

double FormFactors::bytes() const {
  return double(pairs()) * double(sizeof(std::int32_t) + sizeof(double)) +
         double(rows_.size()) * double(sizeof(Row) + sizeof(double));
}

FormFactors area_form_factors(const Scene& scene, const FormFactorOptions& options,
                                 FormFactorStats* stats, std::vector<double>* open_fraction) {
  const int n = int(scene.elements.size());
  const int k = options.side * options.side;
  const RayVisibility rays(scene);
  std::vector<std::vector<AreaSample>> points(static_cast<std::size_t>(n));
  std::vector<double> radii(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    points[std::size_t(i)] = stratified_points(scene.elements[std::size_t(i)].polygon, options.side,
                                               mix_seed(options.seed, std::uint64_t(i), 1));
    radii[std::size_t(i)] = radius(scene.elements[std::size_t(i)]);
  }
  // The share of each element's area that is open (open_fraction_of above).
  std::vector<double> open_share(static_cast<std::size_t>(n));
  const int threads = options.threads > 0 ? options.threads : omp_get_num_procs();
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
  for (int i = 0; i < n; ++i)
    open_share[std::size_t(i)] = open_fraction_of(points[std::size_t(i)],
                                            scene.patches[std::size_t(scene.elements[std::size_t(i)].patch)].normal,
                                            rays, mix_seed(options.seed, std::uint64_t(i), 0));
  // upper[i]: (j, I_ij) for j > i, the double integral, each row held at its exact size (a
  // thread's scratch row grows; the kept one is a copy without the growth's slack).
  std::vector<FormFactors::Row> upper(static_cast<std::size_t>(n));
  long long ray_total = 0, near_total = 0, pair_total = 0;
#pragma omp parallel num_threads(threads) reduction(+ : ray_total, near_total, pair_total)
  {
  FormFactors::Row scratch;
#pragma omp for schedule(dynamic, 4)
  for (int i = 0; i < n; ++i) {
    const Element& ei = scene.elements[std::size_t(i)];
    const Vec3& ni = scene.patches[std::size_t(ei.patch)].normal;
    std::vector<int> order(static_cast<std::size_t>(k));
    scratch.column.clear();
    scratch.exchange.clear();
    for (int j = i + 1; j < n; ++j) {
      const Element& ej = scene.elements[std::size_t(j)];
      if (ej.patch == ei.patch) continue;
      const Vec3& nj = scene.patches[std::size_t(ej.patch)].normal;
      if (!some_in_front(ej.polygon, ei.centre, ni) || !some_in_front(ei.polygon, ej.centre, nj))
        continue;
      ++pair_total;
      const auto& pi = points[std::size_t(i)];
      const auto& pj = points[std::size_t(j)];
      const bool near = glm::length(ej.centre - ei.centre) <
                        FormFactorOptions::kNearFactor * (radii[std::size_t(i)] + radii[std::size_t(j)]);
      double sum = 0.0;
      double count = 0.0;
      if (near) {
        ++near_total;
        // The inner integral over j in closed form, visibility from every point pair.
        for (const AreaSample& x : pi) {
          // One-sided: a point on or behind j's plane sees only j's back, which sends nothing.
          // (The closed form below is the same magnitude from either side, and no kernel term
          // of such a point is positive, so it must not reach the ratio's fallback.)
          if (glm::dot(x.point - ej.centre, nj) <= 0.0) continue;
          const double unoccluded = point_polygon_factor(x.point, ni, ej.polygon);
          if (unoccluded <= 0.0) continue;
          double seen = 0.0, all = 0.0;
          for (const AreaSample& y : pj) {
            const double term = kernel(x, ni, y, nj);
            if (term <= 0.0) continue;
            all += term;
            ++ray_total;
            if (rays.visible(x.point, ni, y.point, nj)) seen += term;
          }
          // No point of j in front of x (a sliver of j seen edge-on): taken as unblocked.
          sum += x.weight * unoccluded * (all > 0.0 ? seen / all : 1.0);
        }
        count = double(k);
      } else {
        std::iota(order.begin(), order.end(), 0);
        SampleStream shuffle(mix_seed(options.seed, std::uint64_t(i), std::uint64_t(j) + 2));
        for (int a = k - 1; a > 0; --a)
          std::swap(order[std::size_t(a)], order[shuffle.next_bits() % std::uint64_t(a + 1)]);
        for (int a = 0; a < k; ++a)
          sum += pair_term(pi[std::size_t(a)], ni, pj[std::size_t(order[std::size_t(a)])], nj, rays,
                           ray_total);
        count = double(k);
      }
      if (sum > 0.0) {
        scratch.column.push_back(std::int32_t(j));
        scratch.exchange.push_back(sum / count);
      }
    }
    upper[std::size_t(i)].column.assign(scratch.column.begin(), scratch.column.end());
    upper[std::size_t(i)].exchange.assign(scratch.exchange.begin(), scratch.exchange.end());
  }
  }
  // F_ij = I_ij / (A_i times i's open share): the exchange of i's open part, whose radiosity
  // is what i sends (its enclosed part sees no front, so I_ij holds nothing of it).
  std::vector<double> open_area(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    open_area[std::size_t(i)] = scene.elements[std::size_t(i)].area * open_share[std::size_t(i)];
  if (stats) *stats = {ray_total, near_total, pair_total};
  if (open_fraction) *open_fraction = std::move(open_share);
  return FormFactors(std::move(open_area), std::move(upper));
}

}  // namespace ncube::reference

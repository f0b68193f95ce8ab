// Host time of importing large models (a reported figure, not a test; docs/scene-format.md,
// "Importing models"): an OBJ grid of bumpy triangles (no two make a planar quad, so every
// triangle looks for a partner) with and without --merge-coplanar, and the merge alone, by
// size, to show the merge O(n log n) in the triangles (it was quadratic: 40,000 triangles 58 s); one face of n corners
// (a convex ring and a comb, ear clipping's easy and hard cases) up to the limit of 32,767, whose
// cost grows between n log n and n^2 (docs/scene-format.md; the quadratic versions took 20 ms
// for 1,024 corners, 8.8 s for 20,000);
// and 15 faces of 20,000 corners (5 rings, 5 combs, 5 stars of random radii) in one OBJ. The
// models are written to a temporary folder, not kept.
// Run: build/benchmarks --benchmark_filter='Import|MergeCoplanar'
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <unistd.h>

#include "models/coplanar_merge.h"
#include "models/face_shapes.h"
#include "models/model_import.h"

namespace {

namespace fs = std::filesystem;

// The models' folder, removed when the benchmarks end.
struct Folder {
  fs::path dir = fs::temp_directory_path() / ("ncube_import_bench_" + std::to_string(::getpid()));
  Folder() {
    fs::create_directories(dir);
    std::ofstream(dir / "m.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
  }
  ~Folder() { fs::remove_all(dir); }
};

const fs::path& bench_folder() {
  static const Folder folder;
  return folder.dir;
}

// An n x n grid of quads, each cut into two triangles, with random heights: 2 n^2 triangles.
std::string bumpy_grid(int n) {
  const fs::path path = bench_folder() / ("grid" + std::to_string(n) + ".obj");
  if (fs::exists(path)) return path.string();
  std::ofstream out(path);
  std::mt19937 random(1);
  std::uniform_real_distribution<double> height(0.0, 1.0);
  out << "mtllib m.mtl\n";
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) out << "v " << x << " " << height(random) << " " << y << "\n";
  out << "usemtl lamp\n";
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const int a = y * (n + 1) + x + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
      out << "f " << a << " " << d << " " << c << "\nf " << a << " " << c << " " << b << "\n";
    }
  return path.string();
}

void ImportGrid(benchmark::State& state, bool merge) {
  const int n = int(state.range(0));
  const std::string path = bumpy_grid(n);
  ncube::ImportOptions options;
  options.merge_coplanar = merge;
  for (auto _ : state) {
    ncube::ImportSummary summary;
    benchmark::DoNotOptimize(ncube::import_model(path, options, summary));
  }
  state.counters["triangles"] = 2.0 * n * n;
}
BENCHMARK_CAPTURE(ImportGrid, merge, true)->Arg(100)->Arg(141)->Arg(245)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ImportGrid, no_merge, false)->Arg(100)->Arg(141)->Arg(245)->Unit(benchmark::kMillisecond);

// One face of n corners: a convex ring, or a comb of n / 4 teeth (ears found late).
void ImportFace(benchmark::State& state, bool comb) {
  const int n = int(state.range(0));
  const fs::path path = bench_folder() / ((comb ? "comb" : "ring") + std::to_string(n) + ".obj");
  {
    std::ofstream out(path);
    out << "mtllib m.mtl\n";
    if (comb) {
      const int teeth = n / 4;
      for (int t = 0; t < teeth; ++t)  // up a tooth and down, along the top
        out << "v " << 2 * t << " 0 10\nv " << 2 * t << " 0 1\nv " << 2 * t + 1 << " 0 1\nv " << 2 * t + 1
            << " 0 10\n";
      // The comb's back: the last tooth's corner down to y = 0 and back to the first.
      out << "v " << 2 * teeth << " 0 0\nv -1 0 0\n";
    } else {
      for (int k = 0; k < n; ++k)
        out << "v " << std::cos(2 * M_PI * k / n) << " 0 " << -std::sin(2 * M_PI * k / n) << "\n";
    }
    out << "usemtl lamp\nf";
    const int corners = comb ? n / 4 * 4 + 2 : n;
    for (int k = corners; k >= 1; --k) out << " " << k;
    out << "\n";
  }
  for (auto _ : state) {
    ncube::ImportSummary summary;
    benchmark::DoNotOptimize(ncube::import_model(path.string(), {}, summary));
  }
}
BENCHMARK_CAPTURE(ImportFace, ring, false)->RangeMultiplier(4)->Range(128, 32767)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(ImportFace, comb, true)->RangeMultiplier(4)->Range(128, 32764)->Unit(benchmark::kMillisecond);

// 15 faces of 20,000 corners each, side by side in planes y = 0, 3, 6, ...: rings, combs of
// 5,000 teeth (19,998 corners and the comb's back) and stars whose radius alternates between 1
// and a random 0.3 to 0.8 (concave at every other corner).
void ImportBigFaces(benchmark::State& state) {
  const fs::path path = bench_folder() / "big_faces.obj";
  constexpr int kCorners = 20000, kFaces = 15;
  {
    std::ofstream out(path);
    std::mt19937 random(1);
    std::uniform_real_distribution<double> inner(0.3, 0.8);
    out << "mtllib m.mtl\n";
    for (int f = 0; f < kFaces; ++f) {
      const double y = 3.0 * f;
      for (int k = 0; k < kCorners; ++k) {
        const double a = 2 * M_PI * k / kCorners;
        if (f % 3 == 1) {  // a comb: up a tooth and down, then the back
          const int t = k / 4;
          const double x[] = {2.0 * t, 2.0 * t, 2.0 * t + 1, 2.0 * t + 1}, z[] = {10, 1, 1, 10};
          if (k < kCorners - 2) out << "v " << x[k % 4] / 5000 << " " << y << " " << z[k % 4] / 10 << "\n";
          else out << "v " << (k == kCorners - 2 ? 2.0 * (kCorners / 4 - 1) / 5000 : -1.0 / 5000) << " " << y << " 0\n";
        } else {
          const double r = f % 3 == 2 && k % 2 == 1 ? inner(random) : 1.0;
          out << "v " << r * std::cos(a) << " " << y << " " << -r * std::sin(a) << "\n";
        }
      }
    }
    out << "usemtl lamp\n";
    for (int f = 0; f < kFaces; ++f) {
      out << "f";
      // The combs' corners run clockwise as written: turned so that every face faces +y.
      for (int k = 0; k < kCorners; ++k)
        out << " " << f * kCorners + (f % 3 == 1 ? kCorners - k : k + 1);
      out << "\n";
    }
  }
  for (auto _ : state) {
    ncube::ImportSummary summary;
    benchmark::DoNotOptimize(ncube::import_model(path.string(), {}, summary));
    state.counters["patches"] = double(summary.patches);
  }
}
BENCHMARK(ImportBigFaces)->Unit(benchmark::kMillisecond);

}  // namespace

namespace {

// The merge alone on the bumpy grid's triangles (no file, no Assimp): linear in the triangles.
void MergeCoplanar(benchmark::State& state) {
  const int n = int(state.range(0));
  std::mt19937 random(1);
  std::uniform_real_distribution<double> height(0.0, 1.0);
  std::vector<ncube::models::Point> corner;
  for (int y = 0; y <= n; ++y)
    for (int x = 0; x <= n; ++x) corner.emplace_back(x, height(random), y);
  std::vector<ncube::models::ImportedPatch> patches;
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const auto a = corner[std::size_t(y * (n + 1) + x)], b = corner[std::size_t(y * (n + 1) + x + 1)],
                 c = corner[std::size_t((y + 1) * (n + 1) + x + 1)], d = corner[std::size_t((y + 1) * (n + 1) + x)];
      patches.push_back({{a, d, c}, {}});
      patches.push_back({{a, c, b}, {}});
    }
  for (auto _ : state) {
    long pairs = 0;
    benchmark::DoNotOptimize(ncube::models::merge_coplanar(patches, pairs));
  }
  state.counters["triangles"] = double(patches.size());
  state.counters["ns_per_triangle"] =
      benchmark::Counter(double(patches.size()), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(MergeCoplanar)->Arg(100)->Arg(141)->Arg(245)->Arg(490)->Unit(benchmark::kMillisecond);

}  // namespace

// What the hemicube costs the host in each scene the prediction table runs it on
// (build/machine_probe --hemicube-scenes ROUNDS; a reported figure, not a rate written
// anywhere): render_hemicube, the code the node programs run with --form-factors hemicube and
// the probe fits projection_speed and raster_speed on, timed on the scenes as a one-node run
// draws them and in the probe's own hemicube rooms, every run round by round in one process so
// that the host's other work falls on all of them alike (docs/machines/probe.md, "What a
// hemicube costs").
//
// A scene's run: its four shooters (scene_shooter_patches), each one hemicube at its centre
// (or, with the Cornell box's row, one at each of its elements, every k-th of them kept so that
// a pass stays short), drawing every element of every other patch, the delta form factors'
// table made once beforehand (a node's from its start). A timed unit is as many passes as make
// about kSecondsAUnit of host time, from a pass timed after a warming one.
#include "tools/scene_hemicube_cost.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "geometry/polygon.h"
#include "radiosity/hemicube.h"
#include "scene/scene_loader.h"
#include "tools/simulate_options.h"
#include "tools/thread_clock.h"

namespace ncube {
namespace {

constexpr double kSecondsAUnit = 0.024;
// Hemicubes a pass at the most (the Cornell box's elements: 6 to 144 a shooter).
constexpr std::size_t kMostHemicubes = 24;

struct Eye {
  Vec3 point, normal, tangent;
  double weight;
  std::size_t drawn;  // index into SceneHemicubes::drawn
};

struct SceneHemicubes {
  Scene scene;
  std::vector<Eye> eyes;
  std::vector<std::vector<HemicubePolygon>> drawn;  // a shooter's: every other patch's elements
  std::unique_ptr<DeltaFormFactors> deltas;
  void pass(WorkCounts& counts) const {
    static const std::vector<HemicubePolygon> no_occluders;
    for (const Eye& eye : eyes) {
      std::vector<double> sums(drawn[eye.drawn].size(), 0.0);
      render_hemicube(eye.point, eye.normal, eye.tangent, drawn[eye.drawn], no_occluders, *deltas,
                      eye.weight, sums, counts);
    }
  }
};

std::shared_ptr<SceneHemicubes> scene_hemicubes(const std::string& scene_name,
                                                const HemicubeOptions& options) {
  auto v = std::make_shared<SceneHemicubes>();
  v->scene = load_scene(repository_root() + "/scenes/" + scene_name + ".json");
  std::vector<Eye> eyes;
  for (int shooter : scene_shooter_patches(v->scene)) {
    const Patch& p = v->scene.patches[std::size_t(shooter)];
    std::vector<HemicubePolygon> drawn;
    for (std::size_t e = 0; e < v->scene.elements.size(); ++e)
      if (v->scene.elements[e].patch != shooter)
        drawn.push_back(hemicube_polygon(v->scene, v->scene.elements[e].patch,
                                         v->scene.elements[e].polygon, v->scene.elements[e].area));
    v->drawn.push_back(std::move(drawn));
    const Vec3 tangent = glm::normalize(p.polygon[1] - p.polygon[0]);
    if (options.placement == HemicubePlacement::kCentre) {
      eyes.push_back({p.polygon.centroid(), p.normal, tangent, p.area, v->drawn.size() - 1});
      continue;
    }
    for (int j = 0; j < p.nv; ++j)
      for (int i = 0; i < p.nu; ++i) {
        const Polygon element = grid_cell(p.polygon, p.nu, p.nv, i, j);
        eyes.push_back({element.centroid(), p.normal, tangent, element.area(), v->drawn.size() - 1});
      }
  }
  const std::size_t stride = (eyes.size() + kMostHemicubes - 1) / kMostHemicubes;
  for (std::size_t k = 0; k < eyes.size(); k += stride) v->eyes.push_back(eyes[k]);
  v->deltas = std::make_unique<DeltaFormFactors>(options.resolution);
  WorkCounts warm;
  v->pass(warm);  // warms the caches
  return v;
}

void print_counters(const WorkCounts& c, int passes) {
  const auto per_pass = [passes](std::uint64_t n) {
    return (unsigned long long)(n / std::uint64_t(std::max(passes, 1)));
  };
#define NCUBE_PRINT_COUNTER(member, cost, doc) std::printf(" | %s %llu", #member, per_pass(c.member));
  NCUBE_HEMICUBE_COUNTERS(NCUBE_PRINT_COUNTER)
#undef NCUBE_PRINT_COUNTER
  std::printf("\n");
}

std::vector<LoopRun> with_scenes(const std::vector<LoopRun>& rooms) {
  std::vector<LoopRun> all = rooms;
  for (LoopRun& run : scene_hemicube_runs()) all.push_back(std::move(run));
  return all;
}

}  // namespace

std::vector<LoopRun> scene_hemicube_runs() {
  struct Case {
    std::string name, scene;
    HemicubeOptions options;
  };
  HemicubeOptions at_elements, at_400, standard;
  at_elements.placement = HemicubePlacement::kElements;
  at_400.resolution = 400;
  std::vector<LoopRun> runs;
  for (const Case& c : {Case{"cornell-box, hemicube at elements", "cornell-box", at_elements},
                        Case{"scene0, hemicube at 400", "scene0", at_400},
                        Case{"scene1, hemicube", "scene1", standard}})
    runs.push_back({c.name, [c] {
                      std::shared_ptr<SceneHemicubes> v = scene_hemicubes(c.scene, c.options);
                      return std::function<void(WorkCounts&)>([v](WorkCounts& w) { v->pass(w); });
                    }});
  return runs;
}

int print_hemicube_costs(int rounds, const std::vector<LoopRun>& rooms) {
  std::vector<TimedPasses> prepared;
  for (const LoopRun& run : with_scenes(rooms)) {
    TimedPasses p;
    p.name = run.name;
    p.pass = run.prepare();
    const double start = thread_seconds();
    p.pass(p.counts);
    p.passes = std::max(1, int(std::lround(kSecondsAUnit / std::max(thread_seconds() - start, 1e-6))));
    prepared.push_back(std::move(p));
  }
  time_round_by_round(prepared, rounds);
  for (const TimedPasses& p : prepared) {
    const auto [lo, hi] = std::minmax_element(p.seconds.begin(), p.seconds.end());
    std::printf("%s | passes %d | median_s %.6f | spread_percent %.1f", p.name.c_str(), p.passes,
                median(p.seconds), 100 * (*hi - *lo) / median(p.seconds));
    print_counters(p.counts, 1);
  }
  return 0;
}

int run_hemicube_passes(const std::string& name, int passes, const std::vector<LoopRun>& rooms) {
  const std::vector<LoopRun> all = with_scenes(rooms);
  const std::function<void(WorkCounts&)> pass = named_run("--hemicube-only", name, all).prepare();
  WorkCounts c;
  for (int k = 0; k < passes; ++k) pass(c);
  std::printf("%s | passes %d", name.c_str(), passes);
  print_counters(c, passes);
  return 0;
}

}  // namespace ncube

// ./machine_probe --out FILE [--network FILE] [--repeats N] — measures this computer's rates
// per kind of work (src/machine/work_kinds.h) on the project's own counted kernels, on one
// thread, and writes a SimGrid platform file of 64 such nodes with the 2024 cluster's network
// (platforms/machines/cluster-2024.xml by default), each rate's measurement in the file.
// docs/machines/probe.md.
//
// The kernels are the very code the simulated node programs charge for (the readable
// definitions, not the host's fast machinery): the paper's brute-force visibility loop
// (BruteForceOccluders through visible_parts) and the engine's gather (point-to-part form
// factors and radiosity updates), on scenes of the probe's own (rooms of boxes drawn from a
// fixed seed, never one of the scenes the simulator is held against). The loop does three
// kinds of work: a ray's own (ray_speed: its set-up, its loop's start and exit), its tests
// (test_speed: ray-patch tests, plane crossings) and what a blocked ray costs more
// (blocked_ray_speed: the edge tests of the patch that stops it, a branch no predictor
// foretells); the gather two: each receiver's update (arithmetic_speed) and the contour
// integrals' edge terms (edge_term_speed). Each rate is measured where its kind dominates, so
// that the fits are well-conditioned: the loop in 6 rooms of 19 to 985 patches (tests), the
// rays of one room against no patch at all (rays), and a room against a screen of 2 cells (2
// tests a ray, a third of the rays blocked); the gather in the same rooms, and with no part
// visible (the updates alone). The rates are the relative least squares fits of time = sum
// over kinds of flops / rate (src/machine/rate_fit.h), each run's residual written with them.
// The hemicube (render_hemicube, --form-factors hemicube) is timed on the probe's rooms too,
// in 6 runs from 985 patches on hemicubes of 8 x 8 cells (its polygons' work dominates:
// projection_speed) to 49 on 400 x 400 (its cells': raster_speed), and fitted the same way.
// Each kernel is timed `repeats` times in the thread's CPU time (a shared host's other
// processes do not count), the median kept; flops are counted with platforms/cost_model.json.
// memory_speed has no kernel reachable outside a node program (the increments' sum is the
// increment exchange's own): it is left out, so that kind runs at node_speed, which is the
// measured test_speed.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <functional>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <memory>
#include <new>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "machine/cost_model.h"
#include "machine/simgrid_platform_file.h"
#include "machine/rate_fit.h"
#include "machine/work_kinds.h"
#include "radiosity/hemicube.h"
#include "radiosity/radiosity_engine.h"
#include "scene/scene.h"
#include "tools/option_table.h"
#include "tools/output_files.h"
#include "tools/scene_hemicube_cost.h"
#include "tools/scene_test_cost.h"
#include "tools/simulate_options.h"
#include "tools/thread_clock.h"
#include "tools/tool_exits.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "util/version.h"
#include "visibility/brute_force_occluders.h"
#include "visibility/shooter.h"

namespace {

using ncube::median;
using ncube::Polygon;
using ncube::Rgb;
using ncube::thread_seconds;
using ncube::Vec3;

// A room of the probe's own: a room 4 x 3 x 4 (walls, floor and ceiling each cut x cut patches
// of 2 x 2 elements), a light in the ceiling, and `boxes` boxes of random size and place (seed
// 1994, the same first boxes in every room; five faces each, the top as two triangles, a third
// of them floating like shelves): 6 cut^2 + 1 + 6 boxes patches, quads and triangles both;
// with `screen` > 0, a screen across the room at mid-height besides. kRooms below are the
// rooms timed.
ncube::Scene probe_room(int cut, int boxes, int screen) {
  ncube::Scene scene;
  scene.name = "machine probe room";
  auto add = [&](const Polygon& polygon, const Rgb& emission, int n) {
    ncube::Patch p;
    p.polygon = polygon;
    p.reflectance = Rgb(0.6);
    p.emission = emission;
    p.nu = p.nv = n;
    scene.patches.push_back(p);
  };
  const double X = 4, Y = 3, Z = 4;
  // Each wall as cut x cut quads facing into the room: corner o, edges u and v (u x v inward).
  auto wall = [&](Vec3 o, Vec3 u, Vec3 v) {
    for (int i = 0; i < cut; ++i)
      for (int j = 0; j < cut; ++j) {
        const Vec3 a = o + u * (double(i) / cut) + v * (double(j) / cut);
        add(Polygon::quad(a, a + u / double(cut), a + u / double(cut) + v / double(cut), a + v / double(cut)),
            Rgb(0.0), 2);
      }
  };
  wall({0, 0, 0}, {0, 0, Z}, {X, 0, 0});  // floor, facing +y
  wall({0, Y, 0}, {X, 0, 0}, {0, 0, Z});  // ceiling, facing -y
  wall({0, 0, 0}, {X, 0, 0}, {0, Y, 0});  // z = 0, facing +z
  wall({0, 0, Z}, {0, Y, 0}, {X, 0, 0});  // z = Z, facing -z
  wall({0, 0, 0}, {0, Y, 0}, {0, 0, Z});  // x = 0, facing +x
  wall({X, 0, 0}, {0, 0, Z}, {0, Y, 0});  // x = X, facing -x
  add(Polygon::quad({1.5, Y - 0.01, 1.5}, {2.5, Y - 0.01, 1.5}, {2.5, Y - 0.01, 2.5}, {1.5, Y - 0.01, 2.5}),
      Rgb(10.0), 2);
  std::mt19937 random(1994);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int b = 0; b < boxes; ++b) {
    const double w = 0.2 + 0.6 * unit(random), d = 0.2 + 0.6 * unit(random),
                 h = 0.2 + 1.2 * unit(random);
    const double x = 0.1 + (X - 0.2 - w) * unit(random), z = 0.1 + (Z - 0.2 - d) * unit(random);
    const double y = b % 3 == 0 ? 0.3 + 1.0 * unit(random) : 0.0;  // a third float (shelves)
    const Vec3 p000{x, y, z}, p100{x + w, y, z}, p010{x, y + h, z}, p110{x + w, y + h, z},
        p001{x, y, z + d}, p101{x + w, y, z + d}, p011{x, y + h, z + d}, p111{x + w, y + h, z + d};
    add(Polygon::quad(p000, p010, p110, p100), Rgb(0.0), 1);  // facing -z
    add(Polygon::quad(p001, p101, p111, p011), Rgb(0.0), 1);  // facing +z
    add(Polygon::quad(p000, p001, p011, p010), Rgb(0.0), 1);  // facing -x
    add(Polygon::quad(p100, p110, p111, p101), Rgb(0.0), 1);  // facing +x
    add(Polygon::triangle(p010, p011, p111), Rgb(0.0), 1);    // top, facing +y
    add(Polygon::triangle(p010, p111, p110), Rgb(0.0), 1);
  }
  // A screen: a checkerboard of screen x screen cells across the room at mid-height, every
  // other cell a patch (facing down), so that about half the rays from below are blocked, by
  // which cell no branch foretells.
  for (int i = 0; i < screen; ++i)
    for (int j = 0; j < screen; ++j) {
      if ((i + j) % 2) continue;
      const double x0 = X * i / screen, x1 = X * (i + 1) / screen, z0 = Z * j / screen,
                   z1 = Z * (j + 1) / screen, y = 0.5 * Y;
      add(Polygon::quad({x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}), Rgb(0.0), 1);
    }
  scene.build_elements();
  return scene;
}

// The rooms the loop and the gather are timed on, (cut, boxes): 19, 49, 103, 241, 505 and 985
// patches, so that a ray meets from 17 to 983 patches (the range of the rooms a radiosity
// program is run on, from a box with two blocks in it to the paper's largest scenes); how they
// were chosen, and what else was tried: docs/machines/probe.md. Every room has boxes: in an
// empty convex room no ray ever crosses a patch's plane, every test's branch goes the same
// way, and its tests run faster than in any room with something in it (bare rooms: 3.1-4.0 ns
// a test against 5.2-6.2 in these) — not the work a visibility computation does.
//
// Two more runs make the fits well-conditioned, each where one kind dominates (in the rooms a
// ray's own work is 1-2 % of its time and a blocked ray's 3 %, which a 2 % noise decides):
// the shots of the room of 241 patches against no patch at all (`nothing_to_test`: a ray's
// own work alone, ray_speed; its gather with no part visible: each receiver's update alone,
// arithmetic_speed), and the shots of a room against a screen across it, a checkerboard of 2
// x 2 cells with two of them patches (`screen`: 2 tests a ray, a third of the rays blocked,
// by which cell no branch foretells: blocked_ray_speed).
struct Room {
  int cut, boxes;
  bool nothing_to_test = false;
  int screen = 0;  // > 0: the loop runs against the screen's patches alone
};
const std::vector<Room> kRooms = {{1, 2},  {2, 4},  {3, 8},           {4, 24},
                                  {6, 48}, {8, 100}, {4, 24, true, 0}, {2, 0, false, 2}};
// Counted flops of one timed repeat of the rays with nothing to test (about 0.01 s).
constexpr double kRayFlopsARepeat = 6e7;
// Counted flops of one timed repeat of the loop in each room (about 0.07 s on a core of 2024):
// a small room's shots are run several times over to reach it.
constexpr double kLoopFlopsARepeat = 3e8;
// The same for the gather (its flops as a probed machine is charged them; about 0.02 s).
constexpr double kGatherFlopsARepeat = 3e7;

// The time a run is fitted on: the median of its repeats, or with --least the least of them
// (a disturbance only ever adds thread CPU time, and docs/machines/prediction_table.py takes
// the least of its processes: docs/machines/probe.md, "The probe under load").
bool fit_least = false;
double typical(const std::vector<double>& s) {
  return fit_least ? *std::min_element(s.begin(), s.end()) : median(s);
}

// (fastest - slowest) / median of a kernel's repeats, as a share.
double spread(const std::vector<double>& seconds) {
  const auto [least, most] = std::minmax_element(seconds.begin(), seconds.end());
  return (1.0 / *least - 1.0 / *most) * median(seconds);
}

// What a fit can leave: a rate of no time or less, when the rooms' times do not grow with
// the work as the two kinds say (a host disturbed beyond what the median removes).
struct MeasurementFailed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One kernel timed: the counts and the thread CPU time of each repeat.
struct Timing {
  std::string what;              // the kernel and its input
  ncube::WorkCounts counts;      // of one repeat
  std::vector<double> seconds;   // each repeat's thread CPU time
  std::size_t patches = 0;
  int passes = 1;                // times the shots are run in one repeat
};

std::string number(double v, int digits = 4) {
  std::ostringstream out;
  out << std::setprecision(digits) << v;
  return out.str();
}

// A share as a percentage of two significant digits, never in exponent form: a residual or a
// spread near zero (a run that pins its rate) reads "0.0001", which the file's readers (and
// tests/machine_probe_test.sh) parse as a number, where "1.2e-05" would not.
std::string percent(double share) {
  const double value = 100 * share;
  if (std::fabs(value) >= 0.01) return number(value, 2);
  std::ostringstream out;
  out << std::fixed << std::setprecision(4) << value;
  return out.str();
}

std::string counts_text(const ncube::WorkCounts& c) {
  std::string out;
#define NCUBE_COUNT_TEXT(member, cost, doc) \
  if (c.member) out += std::string(out.empty() ? "" : ", ") + #member + " " + std::to_string(c.member);
  NCUBE_WORK_COUNTERS(NCUBE_COUNT_TEXT)
#undef NCUBE_COUNT_TEXT
  return out;
}

std::string cpu_model() {
  try {
    const std::string text = ncube::read_input_file("/proc/cpuinfo", ncube::kPlatformFile);
    const std::size_t at = text.find("model name");
    if (at == std::string::npos) return "unknown";
    const std::size_t colon = text.find(':', at), end = text.find('\n', at);
    std::string name = text.substr(colon + 2, end - colon - 2);
    return name;
  } catch (const ncube::InputError&) {
    return "unknown (/proc/cpuinfo not readable)";
  }
}

// `text` as an XML comment's content: a comment may hold no "--" and no control character
// but tab and newline (XML 1.0, section 2.5), and the network's path and the CPU's name are
// the user's and the host's. A "--" becomes "- -"; a control character "?".
std::string comment_text(const std::string& text) {
  std::string safe;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '-' && !safe.empty() && safe.back() == '-') safe += ' ';
    safe += (byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7f ? '?' : c;
  }
  if (!safe.empty() && safe.back() == '-') safe += ' ';  // "--->" would close with "--"
  return safe;
}

// The network file with the probe's node figures: every node's speed the measured
// test_speed, the rates as <prop>s beside node_memory, and the measurements in a comment.
// `rates`: (machine parameter, flop/s), node_speed's first.
std::string probed_platform(const std::string& network_file, const std::string& network,
                            const std::vector<std::pair<std::string, double>>& rates,
                            const std::string& about) {
  std::string text = network;
  // Rates the network file gives already (platforms/machines/cluster-2024.xml does), with
  // their comment, make way for the measured ones.
  const auto erase_line_with = [&text](const std::string& what, const std::string& until) {
    const std::size_t at = text.find(what);
    if (at == std::string::npos) return false;
    const std::size_t begin = text.rfind('\n', at) + 1, end = text.find(until, at);
    text.erase(begin, text.find('\n', end) + 1 - begin);
    return true;
  };
  erase_line_with("<!-- Rates per kind of work", "-->");
  for (const std::string& rate : ncube::work_rate_names())
    while (erase_line_with("<prop id=\"" + rate + "\"", "/>")) {
    }
  const double node_speed = rates.at(0).second;
  std::size_t changed = 0;
  for (std::size_t at = text.find(" speed=\""); at != std::string::npos;
       at = text.find(" speed=\"", at + 1)) {
    const std::size_t begin = at + 8, end = text.find('"', begin);
    text.replace(begin, end - begin, number(node_speed, 6) + "f");
    ++changed;
  }
  const std::size_t memory = text.find("<prop id=\"node_memory\"");
  if (changed == 0 || memory == std::string::npos)
    throw ncube::InputError(network_file + ": no node speed or node_memory <prop> to replace "
                            "(expected a platform of platforms/machines/)");
  const std::size_t line_start = text.rfind('\n', memory) + 1;
  const std::string indent = text.substr(line_start, memory - line_start);
  std::string props;
  for (const auto& [rate, value] : rates)
    props += "<prop id=\"" + rate + "\" value=\"" + number(value, 6) + "\"/>\n" + indent;
  text.insert(memory, props);
  // The header comment (the first after the DOCTYPE) becomes the probe's.
  const std::size_t open = text.find("<!--"), close = text.find("-->", open);
  if (open == std::string::npos || close == std::string::npos)
    throw ncube::InputError(network_file + ": no header comment to replace");
  text.replace(open, close + 3 - open, "<!--" + comment_text(about) + "-->");
  return text;
}

// The kinds of work of the visibility loop, each a rate the fit gives: a ray's own, and its
// tests (ray-patch tests and their plane crossings, in the cost model's proportion of flops:
// src/machine/work_kinds.h).
const std::vector<std::string> kLoopKinds = {"ray_speed", "test_speed", "blocked_ray_speed"};
// The gather's: the counted form factors and updates (arithmetic_speed), and the edge terms
// the host sums for them (edge_term_speed).
const std::vector<std::string> kGatherKinds = {"arithmetic_speed", "edge_term_speed"};

double loop_flops(const ncube::CostModel& costs, const ncube::WorkCounts& counts) {
  double flops = 0;
  for (const std::string& kind : kLoopKinds) flops += ncube::kind_flops(costs, counts, kind);
  return flops;
}

// A room's shots: kShooters shooters of 64 parts (M = 64), the light and patches spread
// evenly through the room's list, with the elements that receive from each.
constexpr int kShooters = 4;
struct Shots {
  ncube::Scene scene;
  std::vector<int> all;
  std::vector<ncube::Shooter> shooters;
  std::vector<std::vector<ncube::ElementRef>> receivers;
  std::vector<std::vector<ncube::PartMask>> masks;
};

void aim(Shots& shots, const ncube::RadiosityEngine& engine, const Room& room) {
  const int patches = int(shots.scene.patches.size()), light = 6 * room.cut * room.cut;
  std::vector<int> chosen = {light};
  const int spread_over = std::min(kShooters - 1, patches - 1);
  for (int k = 0; k < spread_over; ++k) {
    int patch = int(std::lround((k + 0.5) * patches / spread_over - 0.5));
    while (std::find(chosen.begin(), chosen.end(), patch) != chosen.end()) patch = (patch + 1) % patches;
    chosen.push_back(patch);
  }
  for (int patch : chosen) {
    shots.shooters.push_back(ncube::make_shooter(shots.scene, patch, Rgb(1.0), 64));
    ncube::WorkCounts ignored;
    shots.receivers.push_back(engine.receivers(shots.shooters.back(), false, ignored));
  }
  shots.masks.resize(shots.shooters.size());
}

// The brute-force visibility loop in one room, then the engine's gather for the masks it
// found: set up, with one run of each that warms the caches and counts a pass; then timed by
// time_rooms.
struct PreparedRoom {
  Shots shots;
  std::unique_ptr<ncube::RadiosityEngine> engine;
  std::unique_ptr<ncube::BruteForceOccluders> occluders;
  std::vector<std::vector<ncube::PartMask>> gather_masks;  // the masks the gather is timed on
  Timing loop, gather;
  void loop_pass(ncube::WorkCounts& counts) {
    for (std::size_t s = 0; s < shots.shooters.size(); ++s)
      shots.masks[s] = ncube::visible_parts(*engine, *occluders, shots.receivers[s],
                                            shots.shooters[s], counts);
  }
  void gather_pass(ncube::WorkCounts& counts) {
    for (std::size_t s = 0; s < shots.shooters.size(); ++s)
      engine->gather(shots.shooters[s], shots.receivers[s], gather_masks[s], counts);
  }
};

std::unique_ptr<PreparedRoom> prepare_room(const Room& room, const ncube::CostModel& costs) {
  auto prepared = std::make_unique<PreparedRoom>();
  Shots& shots = prepared->shots;
  shots.scene = probe_room(room.cut, room.boxes, room.screen);
  shots.all.resize(shots.scene.patches.size());
  for (std::size_t k = 0; k < shots.all.size(); ++k) shots.all[k] = int(k);
  prepared->engine = std::make_unique<ncube::RadiosityEngine>(shots.scene, shots.all);
  ncube::RadiosityEngine& engine = *prepared->engine;
  std::vector<int> tested = shots.all;
  if (room.nothing_to_test) tested.clear();
  if (room.screen > 0)  // the screen's cells, the last patches
    tested.assign(shots.all.end() - (room.screen * room.screen + 1) / 2, shots.all.end());
  prepared->occluders = std::make_unique<ncube::BruteForceOccluders>(
      shots.scene, tested, ncube::RayTestPolicy::kTestAllPatches);
  aim(shots, engine, room);
  Timing& loop = prepared->loop;
  loop.patches = shots.scene.patches.size();
  // A large room's shots are more than a repeat: every k-th receiver of each shot, in store
  // order (the rays still cross the whole room), k from the shots' size before they are run
  // (a ray tests every patch but its two, each test the counted flops of a test and, a
  // guess for this estimate only, a quarter of a crossing's).
  double rays = 0;
  for (std::size_t s = 0; s < shots.shooters.size(); ++s)
    rays += double(shots.receivers[s].size()) * shots.shooters[s].part_count;
  const double estimate = rays * double(loop.patches - 2) *
                          (costs.flops_per_ray_patch_test + 0.25 * costs.flops_per_plane_crossing);
  std::size_t stride = 1;
  if (!room.nothing_to_test && estimate > kLoopFlopsARepeat) {
    stride = std::size_t(std::ceil(estimate / kLoopFlopsARepeat));
    for (auto& receivers : shots.receivers) {
      std::vector<ncube::ElementRef> kept;
      for (std::size_t k = 0; k < receivers.size(); k += stride) kept.push_back(receivers[k]);
      receivers = kept;
    }
  }
  ncube::WorkCounts once;
  prepared->loop_pass(once);
  loop.passes = std::max(1, int(std::lround((room.nothing_to_test ? kRayFlopsARepeat
                                                                     : kLoopFlopsARepeat) /
                                              loop_flops(costs, once))));
  loop.what = std::to_string(loop.patches) + " patches (cut " + std::to_string(room.cut) + ", " +
              std::to_string(room.boxes) + " boxes" +
              (room.screen ? ", a screen of " + std::to_string(room.screen) + " x " +
                                 std::to_string(room.screen) + " cells" : "") +
              "), the shots " + (room.nothing_to_test ? "against no patch, " :
                                 room.screen ? "against the screen alone, " : "") +
              (stride > 1 ? "to 1 receiver in " + std::to_string(stride) + ", " : "") +
              std::to_string(loop.passes) + (loop.passes == 1 ? " time" : " times");
  // With nothing to test every part is visible, not a gather a scene asks for; there the
  // gather is timed with no part visible instead: each receiver's own work alone (the light
  // test, the update: element_updates, arithmetic_speed), where that kind dominates.
  prepared->gather_masks = shots.masks;
  if (room.nothing_to_test)
    for (auto& masks : prepared->gather_masks)
      std::fill(masks.begin(), masks.end(), ncube::PartMask(0));
  // The gather of the masks found: its cost a counted form factor depends on which parts are
  // visible (the host sums a visible region's contour, not each part: docs/machines/probe.md),
  // so it is timed in every room, as the loop is.
  Timing& gather = prepared->gather;
  gather.patches = loop.patches;
  ncube::WorkCounts gathered_once;
  prepared->gather_pass(gathered_once);
  double gather_flops = 0;
  for (const std::string& kind : kGatherKinds)
    gather_flops += ncube::kind_flops(costs, gathered_once, kind);
  gather.passes = std::max(1, int(std::lround(kGatherFlopsARepeat / gather_flops)));
  gather.what = std::to_string(gather.patches) + " patches, the shots' gather" +
                (room.nothing_to_test ? " with no part visible " : " ") +
                std::to_string(gather.passes) + " times";
  return prepared;
}

// The hemicube's runs, (cut, boxes, resolution): its two kinds of work, a polygon's way into a
// face (projection_speed: moved, clipped, projected, its scan set up; per polygon and face)
// and the scan conversion's rows and cells with the item buffer's read-out (raster_speed; per
// cell), each dominating at one end: 985 patches on a hemicube of 8 x 8 cells (the polygons'
// work 96 % of the flops), 49 patches on one of 400 x 400 (the cells' 99 %), and
// between them the rooms and resolutions of the scenes' runs (100, the default, and 400).
struct HemicubeRoom {
  int cut, boxes, resolution;
};
const std::vector<HemicubeRoom> kHemicubeRooms = {
    {8, 100, 8}, {6, 48, 20}, {4, 24, 100}, {3, 8, 100}, {2, 4, 400}, {1, 2, 200}};
// Host seconds of one timed repeat of a hemicube run (its passes chosen from a warming pass):
// short, so that the probe stays about 2.5 s of CPU at --repeats 3.
constexpr double kHemicubeSecondsARepeat = 0.012;
const std::vector<std::string> kHemicubeKinds = {"projection_speed", "raster_speed"};

// One hemicube run: kShooters eyes (the light and patches spread through the room, as the
// loop's shooters), each rendering every other patch of the room (render_hemicube, the code
// the node programs run with --form-factors hemicube).
struct PreparedHemicube {
  ncube::Scene scene;
  std::vector<int> eyes;
  std::vector<std::vector<ncube::HemicubePolygon>> receivers;
  std::unique_ptr<ncube::DeltaFormFactors> deltas;
  Timing timing;
  void pass(ncube::WorkCounts& counts) {
    static const std::vector<ncube::HemicubePolygon> no_occluders;
    for (std::size_t e = 0; e < eyes.size(); ++e) {
      const ncube::Patch& eye = scene.patches[std::size_t(eyes[e])];
      std::vector<double> sums(receivers[e].size(), 0.0);
      ncube::render_hemicube(eye.polygon.centroid(), eye.normal,
                             glm::normalize(eye.polygon[1] - eye.polygon[0]), receivers[e],
                             no_occluders, *deltas, eye.area, sums, counts);
    }
  }
};

std::unique_ptr<PreparedHemicube> prepare_hemicube(const HemicubeRoom& room) {
  auto prepared = std::make_unique<PreparedHemicube>();
  prepared->scene = probe_room(room.cut, room.boxes, 0);
  const int patches = int(prepared->scene.patches.size()), light = 6 * room.cut * room.cut;
  prepared->eyes = {light};
  for (int k = 0; k < kShooters - 1; ++k) {
    int patch = int(std::lround((k + 0.5) * patches / (kShooters - 1) - 0.5));
    while (std::find(prepared->eyes.begin(), prepared->eyes.end(), patch) != prepared->eyes.end())
      patch = (patch + 1) % patches;
    prepared->eyes.push_back(patch);
  }
  for (int eye : prepared->eyes) {
    std::vector<ncube::HemicubePolygon> receivers;
    for (int k = 0; k < patches; ++k)
      if (k != eye)
        receivers.push_back(ncube::hemicube_polygon(prepared->scene, k,
                                                    prepared->scene.patches[std::size_t(k)].polygon,
                                                    prepared->scene.patches[std::size_t(k)].area));
    prepared->receivers.push_back(std::move(receivers));
  }
  prepared->deltas = std::make_unique<ncube::DeltaFormFactors>(room.resolution);
  ncube::WorkCounts once;
  const double start = thread_seconds();
  prepared->pass(once);
  const double warming = thread_seconds() - start;
  Timing& t = prepared->timing;
  t.patches = std::size_t(patches);
  t.passes = std::max(1, int(std::lround(kHemicubeSecondsARepeat / std::max(warming, 1e-6))));
  t.what = std::to_string(patches) + " patches, " + std::to_string(prepared->eyes.size()) +
           " hemicubes of " + std::to_string(room.resolution) + " x " +
           std::to_string(room.resolution) + " cells, " + std::to_string(t.passes) +
           (t.passes == 1 ? " time" : " times");
  return prepared;
}

// Every room's loop and gather timed `repeats` times, round by round: one repeat of each in
// turn, so that a few seconds in which another process disturbs the host fall on one repeat
// of several runs, which their medians leave out, rather than on every repeat of one run.
void time_rooms(std::vector<std::unique_ptr<PreparedRoom>>& rooms,
                std::vector<std::unique_ptr<PreparedHemicube>>& hemicubes, int repeats) {
  const auto time = [](Timing& timing, auto&& pass) {
    ncube::WorkCounts counts;
    const double start = thread_seconds();
    for (int p = 0; p < timing.passes; ++p) pass(counts);
    timing.seconds.push_back(thread_seconds() - start);
    timing.counts = counts;
  };
  for (int r = 0; r < repeats; ++r) {
    for (auto& room : rooms) {
      time(room->loop, [&](ncube::WorkCounts& c) { room->loop_pass(c); });
      time(room->gather, [&](ncube::WorkCounts& c) { room->gather_pass(c); });
    }
    for (auto& hemicube : hemicubes)
      time(hemicube->timing, [&](ncube::WorkCounts& c) { hemicube->pass(c); });
  }
}


// The probe's rooms whose shots test patches (the six test_speed is fitted on), as runs of
// --scenes and --loop-only: one pass of a room's shots as the probe times it (every k-th
// receiver in the largest rooms).
std::vector<ncube::LoopRun> room_loop_runs(const ncube::CostModel& costs) {
  std::vector<ncube::LoopRun> runs;
  for (const Room& room : kRooms) {
    if (room.nothing_to_test || room.screen > 0) continue;
    const std::string name = "room of " + std::to_string(6 * room.cut * room.cut + 1 + 6 * room.boxes) +
                             " patches";
    runs.push_back({name, [room, &costs] {
                      std::shared_ptr<PreparedRoom> prepared = prepare_room(room, costs);
                      return std::function<void(ncube::WorkCounts&)>(
                          [prepared](ncube::WorkCounts& c) { prepared->loop_pass(c); });
                    }});
  }
  return runs;
}

// The probe's hemicube runs, as runs of --hemicube-scenes and --hemicube-only: one pass of a
// room's hemicubes as the probe times it.
std::vector<ncube::LoopRun> room_hemicube_runs() {
  std::vector<ncube::LoopRun> runs;
  for (const HemicubeRoom& room : kHemicubeRooms) {
    const std::string name = "room of " + std::to_string(6 * room.cut * room.cut + 1 + 6 * room.boxes) +
                             " patches, " + std::to_string(room.resolution) + " x " +
                             std::to_string(room.resolution) + " cells";
    runs.push_back({name, [room] {
                      std::shared_ptr<PreparedHemicube> prepared = prepare_hemicube(room);
                      return std::function<void(ncube::WorkCounts&)>(
                          [prepared](ncube::WorkCounts& c) { prepared->pass(c); });
                    }});
  }
  return runs;
}

int machine_probe(int argc, char** argv) {
  const std::string root = ncube::repository_root();
  std::string out_file, network_file = root + "/platforms/machines/cluster-2024.xml",
                        cost_model_file = root + "/platforms/cost_model.json";
  int repeats = 7;
  CLI::App app{"Times the project's own counted kernels on this computer (one thread) and writes "
               "a platform file of 64 such nodes with its rates per kind of work.",
               "machine_probe"};
  int scene_rounds = 0;
  app.add_option("--out", out_file, "the platform file to write (SimGrid XML)");
  app.add_option("--network", network_file,
                 "a platform of platforms/machines/ whose network and other figures are kept")
      ->capture_default_str();
  app.add_option("--cost-model", cost_model_file, "flops per counted operation")
      ->capture_default_str();
  app.add_option("--repeats", repeats, "times each kernel is timed (the median is the rate)")
      ->capture_default_str()->check(ncube::decimal_count(3, 101));
  app.add_option("--scenes", scene_rounds,
                 "instead of probing: the loop's cost a test in each scene of scenes/, timed "
                 "round by round this many rounds (against --network's rates), no file written")
      ->check(ncube::decimal_count(1, 1001));
  std::string loop_only;
  int loop_passes = 1;
  app.add_option("--loop-only", loop_only,
                 "instead of probing: set up the one run of --scenes so named (\"room of 241 "
                 "patches\", \"scene2 shuffled\") and run its shots --passes times, for a "
                 "simulator of the caches (docs/machines/loop_profile.py)");
  int hemicube_rounds = 0;
  app.add_option("--hemicube-scenes", hemicube_rounds,
                 "instead of probing: the hemicube's work in the probe's hemicube rooms and the "
                 "prediction table's three hemicube scenes, timed round by round this many rounds, "
                 "no file written")
      ->check(ncube::decimal_count(1, 1001));
  std::string hemicube_only;
  app.add_option("--hemicube-only", hemicube_only,
                 "instead of probing: set up the one run of --hemicube-scenes so named (\"scene0, "
                 "hemicube at 400\") and run its hemicubes --passes times, for a simulator of the "
                 "caches (docs/machines/hemicube_profile.py)");
  app.add_option("--passes", loop_passes, "passes of --loop-only's shots or --hemicube-only's hemicubes")
      ->capture_default_str()->check(ncube::decimal_count(0, 1000));
  app.add_flag("--least", fit_least,
               "fit each run's least time over its repeats instead of their median");
  app.set_version_flag("--version", [] { return "machine_probe " + ncube::code_version(); });
  if (const auto ended = ncube::parse_command_line(app, "machine_probe", argc, argv)) return *ended;
  if (hemicube_rounds > 0 || !hemicube_only.empty()) {
    if (!hemicube_only.empty())
      return ncube::run_hemicube_passes(hemicube_only, loop_passes, room_hemicube_runs());
    return ncube::print_hemicube_costs(hemicube_rounds, room_hemicube_runs());
  }
  if (scene_rounds > 0 || !loop_only.empty()) {
    const ncube::CostModel costs = ncube::load_cost_model(cost_model_file);
    const std::vector<ncube::LoopRun> rooms = room_loop_runs(costs);
    if (!loop_only.empty()) return ncube::run_loop_passes(loop_only, loop_passes, rooms);
    return ncube::print_scene_test_costs(scene_rounds, network_file, rooms);
  }
  if (out_file.empty()) {
    std::cerr << "machine_probe: --out is required (the platform file to write)\n";
    return 2;
  }
  ncube::OutputFiles outputs({{"--out", out_file}}, {network_file, cost_model_file});
  const ncube::CostModel costs = ncube::load_cost_model(cost_model_file);
  const std::string network = ncube::read_input_file(network_file, ncube::kSimgridPlatformFile);
  // The network file is kept in the platform it writes: held to what ./simulate holds a
  // platform's text to (depth, hosts, topology strings, no DTD or entity of its own, <config>
  // settings in range and none naming a file, no attribute naming a file) before any time is
  // spent.
  ncube::check_simgrid_platform_text(network_file, network);
  // And it must take the rates (a node speed, node_memory, a header comment): tried with
  // placeholders here, so that a file that cannot is refused before the seconds of timing.
  probed_platform(network_file, network, {{"test_speed", 1.0}}, "");

  // The loop and the gather in every room, timed round by round; the loop's three rates
  // fitted, the gather's two.
  std::vector<Timing> loops, gathers;
  std::vector<ncube::TimedRun> runs, gather_runs;
  std::vector<std::unique_ptr<PreparedRoom>> prepared;
  for (const Room& room : kRooms) prepared.push_back(prepare_room(room, costs));
  std::vector<std::unique_ptr<PreparedHemicube>> hemicubes;
  for (const HemicubeRoom& room : kHemicubeRooms) hemicubes.push_back(prepare_hemicube(room));
  time_rooms(prepared, hemicubes, repeats);
  std::vector<ncube::TimedRun> hemicube_runs;
  for (const auto& timed : hemicubes) {
    ncube::TimedRun run{{}, typical(timed->timing.seconds)};
    for (const std::string& kind : kHemicubeKinds)
      run.flops.push_back(ncube::kind_flops(costs, timed->timing.counts, kind));
    hemicube_runs.push_back(run);
  }
  for (const auto& timed : prepared) {
    loops.push_back(timed->loop);
    gathers.push_back(timed->gather);
    const Timing& t = loops.back();
    ncube::TimedRun run{{}, typical(t.seconds)};
    for (const std::string& kind : kLoopKinds)
      run.flops.push_back(ncube::kind_flops(costs, t.counts, kind));
    runs.push_back(run);
    ncube::TimedRun gather_run{{}, typical(timed->gather.seconds)};
    for (const std::string& kind : kGatherKinds)
      gather_run.flops.push_back(ncube::kind_flops(costs, timed->gather.counts, kind));
    gather_runs.push_back(gather_run);
  }
  const ncube::RateFit fit = ncube::fit_seconds_per_flop(runs);
  for (std::size_t k = 0; k < loops.size(); ++k)
    std::cout << "room of " << loops[k].patches << " patches"
              << (loops[k].counts.ray_patch_tests ? "" : ", nothing to test") << ": "
              << number(double(loops[k].counts.ray_patch_tests) / double(loops[k].counts.rays), 4)
              << " tests a ray, "
              << number(100.0 * double(loops[k].counts.blocked_rays) / double(loops[k].counts.rays), 3)
              << " % blocked, " << number(median(loops[k].seconds), 4) << " s, "
              << number(1e9 * median(loops[k].seconds) / double(loops[k].counts.rays), 4)
              << " ns a ray, fit " << (fit.relative_residuals[k] >= 0 ? "+" : "")
              << percent(fit.relative_residuals[k]) << " %\n";
  const ncube::RateFit gather_fit = ncube::fit_seconds_per_flop(gather_runs);
  const ncube::RateFit hemicube_fit = ncube::fit_seconds_per_flop(hemicube_runs);
  // (rate, flop/s), node_speed's (test_speed) first: the rates of the two fits.
  std::vector<std::pair<std::string, double>> rates;
  const auto take = [&rates](const ncube::RateFit& f, const std::vector<std::string>& kinds,
                             const std::string& kernel) {
    for (std::size_t k = 0; k < kinds.size(); ++k) {
      if (!(f.seconds_per_flop[k] > 0))
        throw MeasurementFailed("the fit of the " + kernel + "'s times gave " + kinds[k] +
                                " no time or less (" + number(f.seconds_per_flop[k], 4) +
                                " s a flop): the host was too disturbed; probe again, or with "
                                "more --repeats");
      rates.push_back({kinds[k], 1 / f.seconds_per_flop[k]});
    }
  };
  take(fit, kLoopKinds, "visibility loop");
  take(gather_fit, kGatherKinds, "gather");
  take(hemicube_fit, kHemicubeKinds, "hemicube");
  // node_speed (and so memory_speed's kind) is the test rate: the first of the file's rates.
  std::swap(rates[0], rates[1]);
  const auto rate_of = [&rates](const std::string& name) {
    for (const auto& [rate, value] : rates)
      if (rate == name) return value;
    throw std::logic_error("machine_probe: no rate " + name);
  };
  const double test_speed = rate_of("test_speed"), ray_speed = rate_of("ray_speed"),
               blocked_ray_speed = rate_of("blocked_ray_speed"),
               arithmetic_speed = rate_of("arithmetic_speed"),
               edge_term_speed = rate_of("edge_term_speed"),
               projection_speed = rate_of("projection_speed"),
               raster_speed = rate_of("raster_speed");

  const auto now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char date[32];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  std::ostringstream about;
  about << " 64 nodes of this computer's CPU (" << cpu_model() << "), one process a node on one\n"
        << "     core, with every other figure (network, memory, message overheads) of\n"
        << "     " << network_file.substr(network_file.rfind("platforms/") == std::string::npos
                                              ? 0 : network_file.rfind("platforms/"))
        << ".\n     Written by build/machine_probe (" << ncube::code_version() << ") on " << date
        << "; docs/machines/probe.md.\n"
        << "     Node rates measured on one thread, in the thread's CPU time, on the probe's own\n"
        << "     rooms (not scenes of scenes/), flops counted with platforms/cost_model.json.\n"
        << "     node_speed is test_speed; memory_speed is not measured (no counted kernel of\n"
        << "     that kind outside a node program) and so runs at node_speed.\n"
        << "     test_speed = " << number(test_speed, 6) << " flop/s ("
        << number(1e9 * costs.flops_per_ray_patch_test / test_speed, 3)
        << " ns a ray-patch test), ray_speed = " << number(ray_speed, 6) << " flop/s\n       ("
        << number(1e9 * costs.flops_per_ray / ray_speed, 3) << " ns a ray's own work besides "
        << "its tests) and blocked_ray_speed = " << number(blocked_ray_speed, 6)
        << " flop/s\n       (" << number(1e9 * costs.flops_per_blocked_ray / blocked_ray_speed, 3)
        << " ns a blocked ray's more): the brute-force visibility loop (visible_parts over\n"
        << "       BruteForceOccluders, " << kShooters << " shooters of 64 parts) in " << loops.size()
        << " runs, the relative least squares fit of the median\n       time = ray flops / "
        << "ray_speed + test flops / test_speed + blocked flops / blocked_ray_speed\n       "
        << "(src/machine/rate_fit.h; test flops: the ray-patch tests' and their plane crossings'),"
        << "\n       root mean square residual " << percent(fit.rms_relative_residual)
        << " %. Each run: its counts a repeat, median of " << repeats << " repeats"
        << (fit_least ? " (the fits: the least of them)" : "") << ",\n       spread "
        << "(fastest - slowest over the median), fitted - measured:\n";
  for (std::size_t k = 0; k < loops.size(); ++k) {
    const Timing& t = loops[k];
    about << "       " << t.what << ": "
          << number(double(t.counts.ray_patch_tests) / double(t.counts.rays), 4)
          << " tests a ray, " << number(100.0 * double(t.counts.blocked_rays) /
                                        double(t.counts.rays), 3)
          << " % of the rays blocked; " << counts_text(t.counts) << "; "
          << number(median(t.seconds), 4) << " s, spread " << percent(spread(t.seconds))
          << " %, residual " << (fit.relative_residuals[k] >= 0 ? "+" : "")
          << percent(fit.relative_residuals[k]) << " %.\n";
  }
  about << "     arithmetic_speed = " << number(arithmetic_speed, 6) << " flop/s and edge_term_speed = "
        << number(edge_term_speed, 6) << " flop/s (" << number(1e9 * costs.flops_per_element_update /
                                                              arithmetic_speed, 3)
        << " ns a radiosity update,\n       "
        << number(1e9 * costs.flops_per_form_factor_edge_term / edge_term_speed, 3)
        << " ns an edge term; the counted form factors are their edge terms here, not charged\n"
        << "       apart): the engine's gather (point-to-part form factors, radiosity updates) of the\n"
        << "       same shots in the same rooms, the relative least squares fit of the median time =\n"
        << "       arithmetic flops / arithmetic_speed + edge-term flops / edge_term_speed,\n"
        << "       root mean square residual "
        << percent(gather_fit.rms_relative_residual) << " %:\n";
  for (std::size_t k = 0; k < gathers.size(); ++k) {
    const Timing& t = gathers[k];
    about << "       " << t.what << ": " << counts_text(t.counts) << "; "
          << number(median(t.seconds), 4) << " s, spread " << percent(spread(t.seconds))
          << " %, residual " << (gather_fit.relative_residuals[k] >= 0 ? "+" : "")
          << percent(gather_fit.relative_residuals[k]) << " %.\n";
  }
  about << "     projection_speed = " << number(projection_speed, 6) << " flop/s ("
        << number(1e9 * costs.flops_per_hemicube_vertex_transformed / projection_speed, 3)
        << " ns a vertex moved into a hemicube's frame) and raster_speed = "
        << number(raster_speed, 6) << " flop/s\n       ("
        << number(1e9 * costs.flops_per_hemicube_depth_test / raster_speed, 3)
        << " ns a cell depth-tested): the hemicube (render_hemicube, every other patch of a\n"
        << "       room from " << kShooters << " eyes) in " << hemicubes.size()
        << " runs, the relative least squares fit of the median time = projection\n"
        << "       flops / projection_speed + raster flops / raster_speed, root mean square "
        << "residual " << percent(hemicube_fit.rms_relative_residual) << " %:\n";
  for (std::size_t k = 0; k < hemicubes.size(); ++k) {
    const Timing& t = hemicubes[k]->timing;
    about << "       " << t.what << ": " << counts_text(t.counts) << "; "
          << number(median(t.seconds), 4) << " s, spread " << percent(spread(t.seconds))
          << " %, residual " << (hemicube_fit.relative_residuals[k] >= 0 ? "+" : "")
          << percent(hemicube_fit.relative_residuals[k]) << " %.\n";
  }
  about << "     ";
  const std::string text = probed_platform(network_file, network, rates, about.str());
  outputs.write("--out", text);
  outputs.commit();
  for (const auto& [rate, value] : rates) std::cout << rate << " " << number(value, 6) << " flop/s\n";
  std::cout << "visibility loop fit over " << loops.size() << " runs: root mean square residual "
            << percent(fit.rms_relative_residual) << " %\n";
  for (std::size_t k = 0; k < gathers.size(); ++k)
    std::cout << "room of " << gathers[k].patches << " patches: gather "
              << number(1e9 * median(gathers[k].seconds) /
                        double(std::max<std::uint64_t>(1, gathers[k].counts.element_updates)), 4)
              << " ns a receiver, "
              << number(double(gathers[k].counts.form_factor_edge_terms) /
                        double(std::max<std::uint64_t>(1, gathers[k].counts.element_updates)), 3)
              << " edge terms a receiver, fit " << (gather_fit.relative_residuals[k] >= 0 ? "+" : "")
              << percent(gather_fit.relative_residuals[k]) << " %\n";
  std::cout << "gather fit over " << gathers.size() << " runs: root mean square residual "
            << percent(gather_fit.rms_relative_residual) << " %\n";
  for (std::size_t k = 0; k < hemicubes.size(); ++k) {
    const Timing& t = hemicubes[k]->timing;
    std::cout << "hemicube, " << t.what << ": " << number(median(t.seconds), 4) << " s, "
              << number(100 * kind_flops(costs, t.counts, "raster_speed") /
                            (kind_flops(costs, t.counts, "raster_speed") +
                             kind_flops(costs, t.counts, "projection_speed")), 3)
              << " % raster flops, fit " << (hemicube_fit.relative_residuals[k] >= 0 ? "+" : "")
              << percent(hemicube_fit.relative_residuals[k]) << " %\n";
  }
  std::cout << "hemicube fit over " << hemicubes.size() << " runs: root mean square residual "
            << percent(hemicube_fit.rms_relative_residual) << " %\n";
  return ncube::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // The one catch ladder (tool_exits.h); a fit that gives no rate is a failed measurement (4).
  return ncube::run_tool("machine_probe", [&] {
    try {
      return machine_probe(argc, argv);
    } catch (const MeasurementFailed& e) {
      std::cerr << "machine_probe: " << e.what() << " (no output file was written)\n";
      return ncube::kExitSimulationFailed;
    }
  });
}

// ./machine_probe --out FILE [--network FILE] [--repeats N] — measures this computer's rates
// per kind of work (src/machine/work_kinds.h) on the project's own counted kernels, on one
// thread, and writes a SimGrid platform file of 64 such nodes with the 2024 cluster's network
// (platforms/machines/cluster-2024.xml by default), each rate's measurement in the file.
// docs/machines/probe.md.
//
// The kernels are the very code the simulated node programs charge for (the readable
// definitions, not the host's fast machinery): the paper's brute-force visibility loop
// (BruteForceOccluders through visible_parts: rays, ray-patch tests, plane crossings, kind
// test_speed) and the engine's gather (point-to-part form factors and radiosity updates, kind
// arithmetic_speed), on a scene of the probe's own (a room of boxes drawn from a fixed seed,
// never one of the scenes the simulator is held against). Each kernel is timed `repeats` times
// in the thread's CPU time (a shared host's other processes do not count); a rate is its
// counted flops (platforms/cost_model.json) over the median time. memory_speed has no kernel
// reachable outside a node program (the increments' sum is the increment exchange's own): it
// is left out, so that kind runs at node_speed, which is the measured test_speed.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <iomanip>
#include <iostream>
#include <new>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "machine/cost_model.h"
#include "machine/work_kinds.h"
#include "radiosity/radiosity_engine.h"
#include "radiosity/shooter.h"
#include "scene/scene.h"
#include "tools/output_files.h"
#include "tools/simulate_options.h"
#include "tools/tool_exits.h"
#include "util/input_error.h"
#include "util/input_file.h"
#include "util/version.h"
#include "visibility/brute_force_occluders.h"

namespace {

using ncube::Polygon;
using ncube::Rgb;
using ncube::Vec3;

// The probe's own scene: a room 4 x 3 x 4 (walls, floor and ceiling each 4 x 4 patches of
// 2 x 2 elements), a light in the ceiling, and 24 boxes of random size and place (seed 1994;
// five faces each, the top as two triangles), about 240 patches: rays meet a few hundred
// patches each, as in the paper's scenes, with quads and triangles both.
ncube::Scene probe_scene() {
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
  const int cut = 4;
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
  for (int b = 0; b < 24; ++b) {
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
  scene.build_elements();
  return scene;
}

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct Measurement {
  std::string rate;          // the machine parameter
  std::string kernel;        // what was timed
  double flops = 0;          // counted flops of one repeat
  std::vector<double> seconds;  // each repeat's thread CPU time
  ncube::WorkCounts counts;  // of one repeat

  double median() const {
    std::vector<double> s = seconds;
    std::sort(s.begin(), s.end());
    const std::size_t n = s.size();
    return n % 2 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
  }
  double value() const { return flops / median(); }
  double fastest() const { return flops / *std::min_element(seconds.begin(), seconds.end()); }
  double slowest() const { return flops / *std::max_element(seconds.begin(), seconds.end()); }
};

std::string number(double v, int digits = 4) {
  std::ostringstream out;
  out << std::setprecision(digits) << v;
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

// The network file with the probe's node figures: every node's speed the measured
// test_speed, the rates as <prop>s beside node_memory, and the measurements in a comment.
std::string probed_platform(const std::string& network_file, const std::string& network,
                            const std::vector<Measurement>& measured, const std::string& about) {
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
  const double node_speed = measured[0].value();
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
  for (const Measurement& m : measured)
    props += "<prop id=\"" + m.rate + "\" value=\"" + number(m.value(), 6) + "\"/>\n" + indent;
  text.insert(memory, props);
  // The header comment (the first after the DOCTYPE) becomes the probe's.
  const std::size_t open = text.find("<!--"), close = text.find("-->", open);
  if (open == std::string::npos || close == std::string::npos)
    throw ncube::InputError(network_file + ": no header comment to replace");
  text.replace(open, close + 3 - open, "<!--" + about + "-->");
  return text;
}

int machine_probe(int argc, char** argv) {
  const std::string root = ncube::repository_root();
  std::string out_file, network_file = root + "/platforms/machines/cluster-2024.xml",
                        cost_model_file = root + "/platforms/cost_model.json";
  int repeats = 7;
  CLI::App app{"Times the project's own counted kernels on this computer (one thread) and writes "
               "a platform file of 64 such nodes with its rates per kind of work.",
               "machine_probe"};
  app.add_option("--out", out_file, "the platform file to write (SimGrid XML)")->required();
  app.add_option("--network", network_file,
                 "a platform of platforms/machines/ whose network and other figures are kept")
      ->capture_default_str();
  app.add_option("--cost-model", cost_model_file, "flops per counted operation")
      ->capture_default_str();
  app.add_option("--repeats", repeats, "times each kernel is timed (the median is the rate)")
      ->capture_default_str()->check(CLI::Range(3, 101));
  app.set_version_flag("--version", [] { return "machine_probe " + ncube::code_version(); });
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return ncube::kExitOk;
  } catch (const CLI::CallForVersion& e) {
    std::cout << e.what() << "\n";
    return ncube::kExitOk;
  } catch (const CLI::ParseError& e) {
    std::cerr << "machine_probe: " << e.what() << "\n(see machine_probe --help)\n";
    return ncube::kExitBadInput;
  }
  ncube::OutputFiles outputs({{"--out", out_file}}, {network_file, cost_model_file});
  const ncube::CostModel costs = ncube::load_cost_model(cost_model_file);
  const std::string network = ncube::read_input_file(network_file, ncube::kSimgridPlatformFile);

  const ncube::Scene scene = probe_scene();
  std::vector<int> all(scene.patches.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = int(k);
  ncube::RadiosityEngine engine(scene, all);
  const ncube::BruteForceOccluders occluders(scene, all, ncube::RayTestPolicy::kTestAllPatches);
  // Shooters: the light, a ceiling patch, a wall patch and a box's side (64 parts, M = 64).
  const int light = 6 * 16;
  std::vector<ncube::Shooter> shooters;
  for (int patch : {light, 16 + 5, 32 + 6, light + 1 + 6 * 7 + 3})
    shooters.push_back(ncube::make_shooter(scene, patch, Rgb(1.0), 64));
  std::vector<std::vector<ncube::ElementRef>> receivers;
  for (const ncube::Shooter& s : shooters) {
    ncube::WorkCounts ignored;
    receivers.push_back(engine.receivers(s, false, ignored));
  }

  Measurement tests, arithmetic;
  tests.rate = "test_speed";
  tests.kernel = "the brute-force visibility loop (visible_parts over BruteForceOccluders) for 4 "
                 "shooters of 64 parts";
  arithmetic.rate = "arithmetic_speed";
  arithmetic.kernel = "the engine's gather (point-to-part form factors, radiosity updates) for "
                      "the same shots, 32 times";
  std::vector<std::vector<ncube::PartMask>> masks(shooters.size());
  for (int r = 0; r < repeats + 1; ++r) {  // the first repeat warms the caches, not counted
    ncube::WorkCounts counts;
    double start = thread_seconds();
    for (std::size_t s = 0; s < shooters.size(); ++s)
      masks[s] = ncube::visible_parts(engine, occluders, receivers[s], shooters[s], counts);
    const double test_seconds = thread_seconds() - start;
    ncube::WorkCounts gathered;
    start = thread_seconds();
    for (int again = 0; again < 32; ++again)
      for (std::size_t s = 0; s < shooters.size(); ++s)
        engine.gather(shooters[s], receivers[s], masks[s], gathered);
    const double gather_seconds = thread_seconds() - start;
    if (r == 0) continue;
    tests.seconds.push_back(test_seconds);
    tests.counts = counts;
    arithmetic.seconds.push_back(gather_seconds);
    arithmetic.counts = gathered;
  }
  tests.flops = ncube::kind_flops(costs, tests.counts, tests.rate);
  arithmetic.flops = ncube::kind_flops(costs, arithmetic.counts, arithmetic.rate);
  const std::vector<Measurement> measured = {tests, arithmetic};

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
        << "     scene (" << scene.patches.size() << " patches, " << scene.elements.size()
        << " elements; not a scene of scenes/), flops counted with platforms/cost_model.json.\n"
        << "     node_speed is test_speed; memory_speed is not measured (no counted kernel of\n"
        << "     that kind outside a node program) and so runs at node_speed.\n";
  for (const Measurement& m : measured) {
    about << "     " << m.rate << " = " << number(m.value(), 6) << " flop/s: " << m.kernel
          << ";\n       " << number(m.flops, 6) << " flops a repeat (" << counts_text(m.counts)
          << ");\n       median of " << m.seconds.size() << " repeats " << number(m.median(), 4)
          << " s; fastest " << number(m.fastest(), 4) << " flop/s, slowest "
          << number(m.slowest(), 4) << " flop/s (spread "
          << number(100.0 * (m.fastest() - m.slowest()) / m.value(), 3) << " % of the median).\n";
  }
  about << "     ";
  const std::string text = probed_platform(network_file, network, measured, about.str());
  outputs.write("--out", text);
  outputs.commit();
  for (const Measurement& m : measured)
    std::cout << m.rate << " " << number(m.value(), 6) << " flop/s (median of " << m.seconds.size()
              << "; fastest " << number(m.fastest(), 4) << ", slowest " << number(m.slowest(), 4)
              << ")\n";
  return ncube::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return ncube::run_tool("machine_probe", [&] { return machine_probe(argc, argv); });
}

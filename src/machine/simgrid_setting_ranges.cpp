#include "machine/simgrid_setting_ranges.h"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <sstream>

namespace ncube {
namespace {

using K = SettingKind;
constexpr double kIntMax = INT_MAX;

// What "survives" means and how each row was judged: docs/cli.md, "SimGrid settings". The
// failures quoted were measured with SimGrid 3.32 on scene0 R=2 V=1 (tests/simgrid_settings_test
// runs each range's ends). Settings whose value no code of a run reads (SMPI's own, ns-3's,
// the chaos monkey's without its plugin) take any value SimGrid's type check takes.
const std::vector<SimgridSettingRange> kRanges = {
    {"bmf/max-iterations", K::kInteger, 1, kIntMax, {},
     "with network/solver:bmf, 0 or less aborts (bmf.cpp: invalid number of iterations)"},
    {"bmf/precision", K::kReal, 1e-15, 1e-2, {},
     "the BMF solver's tolerance, as maxmin/precision"},
    {"cmonkey/host", K::kAny, 0, 0, {}, "read only by the chaos monkey, whose plugin is refused"},
    {"cmonkey/link", K::kAny, 0, 0, {}, "read only by the chaos monkey, whose plugin is refused"},
    {"cmonkey/tell", K::kAny, 0, 0, {}, "read only by the chaos monkey, whose plugin is refused"},
    {"cmonkey/time", K::kAny, 0, 0, {}, "read only by the chaos monkey, whose plugin is refused"},
    {"contexts/factory", K::kChoice, 0, 0, "raw,ucontext,boost,thread",
     "each runs scene0 (SimGrid checks the name)"},
    {"contexts/guard-size", K::kInteger, 0, 1024, {},
     "pages protected below each actor's stack: -1 or 2^31-1 abort (failed to protect stack)"},
    {"contexts/nthreads", K::kInteger, 1, 1, {},
     "the node programs share the host's state (answer cache, lookahead, host threads) and are "
     "not written to run in SimGrid's parallel contexts (it crashed with SIGSEGV there; 2^31-1 hangs)"},
    {"contexts/stack-size", K::kInteger, 1024, 65536, {},
     "KiB per actor: 64 KiB or less is SIGSEGV (the node programs run host code on it); 1024 "
     "runs octree, subdivision, balancing and rendering; 2^31-1 is SIGSEGV"},
    {"contexts/synchro", K::kChoice, 0, 0, "futex,posix,busy_wait",
     "used only with contexts/nthreads above 1"},
    {"cpu/maxmin-selective-update", K::kBoolean, 0, 0, {},
     "SimGrid refuses 0 with cpu/optim:Lazy itself"},
    {"cpu/model", K::kChoice, 0, 0, "Cas01", "the only CPU model"},
    {"cpu/optim", K::kChoice, 0, 0, "Lazy,TI,Full", "each runs scene0"},
    {"cpu/solver", K::kChoice, 0, 0, "maxmin,fairbottleneck,bmf", "each runs scene0"},
    {"debug/breakpoint", K::kAny, 0, 0, {},
     "a debugging aid by design: raises SIGTRAP at that simulated time (docs/cli.md)"},
    {"debug/clean-atexit", K::kBoolean, 0, 0, {}, "both values run scene0"},
    {"debug/verbose-exit", K::kBoolean, 0, 0, {}, "both values run scene0"},
    {"disk/model", K::kChoice, 0, 0, "default", "the only disk model (the nodes have no disks)"},
    {"disk/solver", K::kChoice, 0, 0, "maxmin,fairbottleneck,bmf", "the nodes have no disks"},
    {"exception/cutpath", K::kBoolean, 0, 0, {}, "both values run scene0"},
    {"help-nostop", K::kBoolean, 0, 0, {}, "both values run scene0"},
    {"host/model", K::kChoice, 0, 0, "default,compound,ptask_L07", "each runs scene0"},
    {"host/solver", K::kChoice, 0, 0, "maxmin,fairbottleneck,bmf", "each runs scene0"},
    {"maxmin/concurrency-limit", K::kIntegerOrNone, 1, kIntMax, {},
     "0 lets no activity run: SimGrid stops on a deadlock"},
    {"maxmin/precision", K::kReal, 1e-15, 1e-2, {},
     "the sharing system's tolerance: NaN, infinite, 1 or more abort (The Impossible Did "
     "Happen), a negative one is SIGSEGV; below 1e-15 it is under a double's resolution"},
    {"model-check/replay", K::kEmpty, 0, 0, {},
     "replays a model checker's path, which a run is not: any path aborts or is exit 7"},
    {"model-check/timeout", K::kBoolean, 0, 0, {}, "SimGrid refuses it outside the model checker"},
    {"network/TCP-gamma", K::kReal, 0, 1e15, {}, "a TCP window in bytes (any value ran scene0)"},
    {"network/bandwidth-factor", K::kReal, 1e-6, 1e6, {},
     "scales every link's bandwidth: 0 aborts (bandwidth factor cannot be 0), NaN or negative "
     "abort (The Impossible Did Happen)"},
    {"network/crosstraffic", K::kBoolean, 0, 0, {}, "both values run scene0"},
    {"network/latency-factor", K::kReal, 0, 1e6, {},
     "scales every latency: infinite makes SimGrid stop on a deadlock"},
    {"network/loopback-bw", K::kReal, 1e3, 1e15, {},
     "a zone's default loopback, within the platform file's bandwidth bounds"},
    {"network/loopback-lat", K::kReal, 0, 1, {},
     "a zone's default loopback, within the platform file's latency bounds"},
    {"network/maxmin-selective-update", K::kBoolean, 0, 0, {},
     "SimGrid refuses 0 with network/optim:Lazy itself"},
    {"network/model", K::kChoice, 0, 0, "LV08,CM02,SMPI,IB",
     "Constant aborts (no link allowed, and every platform has loopbacks); ns-3 aborts (it "
     "knows only hosts on one-hop links)"},
    {"network/optim", K::kChoice, 0, 0, "Lazy,TI,Full", "each runs scene0"},
    {"network/solver", K::kChoice, 0, 0, "maxmin,fairbottleneck,bmf", "each runs scene0"},
    {"network/weight-S", K::kReal, 0, 1e15, {}, "bytes added to RTT weights (any value ran)"},
    {"ns3/TcpModel", K::kAny, 0, 0, {}, "read only by the ns-3 model, which is refused"},
    {"ns3/seed", K::kAny, 0, 0, {}, "read only by the ns-3 model, which is refused"},
    {"path", K::kAny, 0, 0, {}, "where SimGrid looks for the files a platform names"},
    {"plugin", K::kChoice, 0, 0, "link_load,link_energy_wifi,link_energy,host_load,host_energy,"
                                 "host_dvfs",
     "each runs scene0; cmonkey (the chaos monkey) kills hosts and links, which the node "
     "programs do not survive (SimGrid asserts)"},
    {"plugin/dvfs/governor", K::kChoice, 0, 0, "performance,powersave,ondemand,conservative,adagio",
     "each runs scene0 with plugin:host_dvfs"},
    {"plugin/dvfs/max-pstate", K::kInteger, -1, 0, {},
     "the nodes have one speed (pstate 0; -1 is the last): 5 aborts (max_pstate too large)"},
    {"plugin/dvfs/min-pstate", K::kInteger, 0, 0, {},
     "the nodes have one speed (pstate 0): above max-pstate aborts"},
    {"plugin/dvfs/sampling-rate", K::kReal, 0.1, 1e9, {},
     "seconds between samples, one actor wake-up per host each: NaN or infinite abort, 1e-5 "
     "or less made scene0 R=2 V=1 (2 iterations) run past 30 s"},
    {"smpi/IB-penalty-factors", K::kThreeFactors, 0, 0, {},
     "read by network/model:IB: anything else aborts (should contain 3 elements)"},
    {"smpi/async-small-thresh", K::kAny, 0, 0, {}, "SMPI's own: the nodes are not MPI processes"},
    {"smpi/auto-shared-malloc-thresh", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/bw-factor", K::kFactorList, 0, 0, {},
     "read by network/model:SMPI: unparsable aborts (Invalid factor), NaN aborts"},
    {"smpi/comp-adjustment-file", K::kAny, 0, 0, {}, "SMPI's own (SimGrid opens it to check)"},
    {"smpi/cpu-threshold", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/display-allocs", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/errors-are-fatal", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/grow-injected-times", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/host-speed", K::kAny, 0, 0, {}, "SMPI's own (SimGrid parses it)"},
    {"smpi/hostfile", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/init", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/iprobe", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/iprobe-cpu-usage", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/lat-factor", K::kFactorList, 0, 0, {},
     "read by network/model:SMPI: unparsable aborts (Invalid factor), NaN aborts"},
    {"smpi/list-leaks", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/map", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/np", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/pedantic", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/replay", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/send-is-detached-thresh", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/shared-malloc", K::kAny, 0, 0, {}, "SMPI's own (SimGrid checks the name)"},
    {"smpi/simulate-computation", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/test", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/trace-call-location", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/trace-call-use-absolute-path", K::kAny, 0, 0, {}, "SMPI's own"},
    {"smpi/wtime", K::kAny, 0, 0, {}, "SMPI's own"},
    {"surf/precision", K::kReal, 1e-15, 1e-3, {},
     "the time step's tolerance in seconds: NaN, 0 or negative make the run never end"},
    {"tracing", K::kBoolean, 0, 0, {}, "traced runs are read by pajeng (tests)"},
    {"tracing/actor", K::kBoolean, 0, 0, {}, "traced runs are read by pajeng (tests)"},
    {"tracing/basic", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/categorized", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/comment", K::kAny, 0, 0, {}, "a line of text at the top of the trace"},
    {"tracing/comment-file", K::kEmpty, 0, 0, {},
     "SimGrid reads it without the checks the project gives its inputs, and a missing one is "
     "SIGSEGV: use tracing/comment"},
    {"tracing/disable-destroy", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/disable_link", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/disable_power", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/filename", K::kOutputFile, 0, 0, {},
     "the trace's path, which only the command line names (docs/cli.md, \"Output files\")"},
    {"tracing/platform", K::kBoolean, 0, 0, {}, "traced runs are read by pajeng (tests)"},
    {"tracing/platform/topology", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/precision", K::kInteger, 0, 17, {},
     "digits after the decimal point of the trace's times (17 hold any double)"},
    {"tracing/smpi", K::kBoolean, 0, 0, {}, "both values run scene0 traced"},
    {"tracing/smpi/computing", K::kBoolean, 0, 0, {}, "SMPI's own"},
    {"tracing/smpi/display-sizes", K::kBoolean, 0, 0, {}, "SMPI's own"},
    {"tracing/smpi/format", K::kChoice, 0, 0, "Paje,TI", "SMPI's own"},
    {"tracing/smpi/format/ti-one-file", K::kBoolean, 0, 0, {}, "SMPI's own"},
    {"tracing/smpi/group", K::kBoolean, 0, 0, {}, "SMPI's own"},
    {"tracing/smpi/internals", K::kBoolean, 0, 0, {}, "SMPI's own"},
    {"tracing/smpi/sleeping", K::kBoolean, 0, 0, {}, "SMPI's own"},
    {"tracing/uncategorized", K::kBoolean, 0, 0, {}, "traced runs are read by pajeng (tests)"},
    {"tracing/vm", K::kChoice, 0, 0, "no,0,off,false",
     "SimGrid 3.32 gives every host a second trace container with it (exit 7: container "
     "node-0 already present); the nodes have no virtual machines"},
};

std::string number_text(double value) {
  std::ostringstream out;
  out << std::setprecision(15) << value;
  return out.str();
}

// A whole number or a finite one, as strtol / strtod read the whole text; nullopt-like false.
bool read_number(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno == 0 && std::isfinite(value);
}

bool read_integer(const std::string& text, double& value) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text[0]))) return false;
  char* end = nullptr;
  errno = 0;
  const long long whole = std::strtoll(text.c_str(), &end, 10);
  value = double(whole);
  return end == text.c_str() + text.size() && errno == 0;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t at; (at = text.find(separator, start)) != std::string::npos; start = at + 1)
    parts.push_back(text.substr(start, at - start));
  parts.push_back(text.substr(start));
  return parts;
}

bool positive_factor(const std::string& text) {
  double value = 0;
  return read_number(text, value) && value > 0;
}

bool factor_list(const std::string& text) {
  for (const std::string& entry : split(text, ';')) {
    const std::vector<std::string> pair = split(entry, ':');
    double size = 0;
    if (pair.size() != 2 || !read_integer(pair[0], size) || size < 0 || !positive_factor(pair[1]))
      return false;
  }
  return true;
}

bool within(const SimgridSettingRange& range, const std::string& value) {
  double number = 0;
  switch (range.kind) {
    case K::kAny:
    case K::kBoolean:
    case K::kOutputFile:  // where a platform gives it, platform_setting_problem refuses it
      return true;  // SimGrid's own check tells its type
    case K::kInteger:
      return read_integer(value, number) && number >= range.low && number <= range.high;
    case K::kIntegerOrNone:
      return read_integer(value, number) &&
             (number == -1 || (number >= range.low && number <= range.high));
    case K::kReal:
      return read_number(value, number) && number >= range.low && number <= range.high;
    case K::kChoice:
      for (const std::string& choice : split(std::string(range.choices), ','))
        if (value == choice) return true;
      return false;
    case K::kEmpty:
      return value.empty();
    case K::kFactorList:
      return factor_list(value);
    case K::kThreeFactors: {
      const std::vector<std::string> parts = split(value, ';');
      return parts.size() == 3 && positive_factor(parts[0]) && positive_factor(parts[1]) &&
             positive_factor(parts[2]);
    }
  }
  return false;
}

}  // namespace

const std::vector<SimgridSettingRange>& simgrid_setting_ranges() { return kRanges; }

const SimgridSettingRange* simgrid_setting_range(std::string_view name) {
  for (const SimgridSettingRange& range : kRanges)
    if (range.name == name) return &range;
  return nullptr;
}

std::string describe_range(const SimgridSettingRange& range) {
  const std::string interval = "[" + number_text(range.low) + ", " + number_text(range.high) + "]";
  std::string choices(range.choices);
  for (std::size_t at = 0; (at = choices.find(',', at)) != std::string::npos; at += 2)
    choices.replace(at, 1, ", ");
  switch (range.kind) {
    case K::kAny: return "any value SimGrid takes";
    case K::kBoolean: return "yes or no";
    case K::kInteger: return "a whole number in " + interval;
    case K::kIntegerOrNone: return "-1 (none) or a whole number in " + interval;
    case K::kReal: return "a finite number in " + interval;
    case K::kChoice: return "one of " + choices;
    case K::kEmpty: return "empty (not available in ./simulate)";
    case K::kFactorList: return "SIZE:FACTOR;SIZE:FACTOR... with sizes >= 0 and finite factors > 0";
    case K::kThreeFactors: return "A;B;C, three finite numbers > 0";
    case K::kOutputFile: return "a path, named on ./simulate's command line";
  }
  return "";
}

std::string setting_range_problem(const SimgridSettingRange& range, const std::string& value) {
  if (within(range, value)) return "";
  return std::string(range.name) + " must be " + describe_range(range) + " (" +
         std::string(range.why) + ")";
}

std::string platform_setting_problem(std::string_view name, const std::string& value) {
  const SimgridSettingRange* range = simgrid_setting_range(name);
  if (!range) return "";  // SimGrid names what it does not know
  if (range->kind == K::kOutputFile)
    return std::string(name) + " names a file SimGrid would write, and a platform file never "
           "chooses where anything is written: name it on the command line (--cfg=" +
           std::string(name) + ":PATH), where the output rule applies";
  return setting_range_problem(*range, value);
}

}  // namespace ncube

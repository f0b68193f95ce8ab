// ./network_bench --platform FILE [--json OUT] — ping-pong and streaming bandwidth between
// node 0 and its nearest node and between the platform's farthest pair, through the node
// programs' runtime (tools/network_benchmark.h); prints a table, optionally writes JSON.
// docs/network-benchmark.md.
#include <CLI/CLI.hpp>

#include <iostream>
#include <new>

#include <simgrid/s4u/Engine.hpp>

#include "machine/cost_model.h"
#include "machine/platform_config.h"
#include "machine/simgrid_outputs.h"
#include "machine/simgrid_session.h"
#include "machine/simgrid_settings.h"
#include "simulation/simulated_platform.h"
#include "tools/input_lookup.h"
#include "tools/network_benchmark.h"
#include "tools/network_report.h"
#include "tools/network_routes.h"
#include "tools/output_files.h"
#include "tools/simulate_options.h"
#include "tools/tool_exits.h"
#include "util/input_error.h"
#include "util/version.h"

namespace {

int network_bench(int argc, char** argv) {
  const std::string root = ncube::repository_root();
  std::string platform_file, json_file, cost_model_file = root + "/platforms/cost_model.json";
  long min_bytes = 8, max_bytes = 1 << 20;
  ncube::NetworkBenchmarkSettings settings;
  std::vector<std::string> cfg;
  bool quiet = false;
  CLI::App app{"Ping-pong and streaming bandwidth between node 0 and its nearest node and "
               "between the farthest pair of a platform, through the node programs' runtime "
               "(their message overheads and byte counts).",
               "network_bench"};
  // The values are named as simulate's are (N, FILE: docs/cli.md), not by CLI11's C++ types;
  // files are found by simulate's rule (tools/input_lookup.h).
  app.add_option("--platform", platform_file,
                 "platform file (JSON parameters or SimGrid XML): a path, or a name in platforms/ "
                 "or platforms/machines/ (cm5)")
      ->required()->option_text("FILE (required)");
  app.add_option("--cost-model", cost_model_file, "cost model (its message header size)")
      ->option_text("FILE (default platforms/cost_model.json)");
  app.add_option("--json", json_file, "write the results here as JSON")->option_text("FILE");
  // A message holds its payload on the host (bytes / 8 part masks): 2^30 bytes at most, where
  // 2^40 ended in an uncaught bad_alloc.
  app.add_option("--min-bytes", min_bytes, "smallest payload, a multiple of 8 (8 to 2^30)")
      ->check(CLI::Range(8L, 1L << 30))->option_text("N (default " + std::to_string(min_bytes) + ")");
  app.add_option("--max-bytes", max_bytes,
                 "largest payload; sizes double from the smallest (8 to 2^30: a message holds its "
                 "payload on the host)")
      ->check(CLI::Range(8L, 1L << 30))->option_text("N (default " + std::to_string(max_bytes) + ")");
  app.add_option("--round-trips", settings.round_trips, "ping-pong round trips timed (1 to 1000)")
      ->check(CLI::Range(1, 1000))->option_text("N (default " + std::to_string(settings.round_trips) + ")");
  app.add_option("--stream-messages", settings.stream_messages,
                 "messages streamed back to back (1 to 1000)")
      ->check(CLI::Range(1, 1000))
      ->option_text("N (default " + std::to_string(settings.stream_messages) + ")");
  app.add_option("--cfg", cfg, "a SimGrid setting, NAME:VALUE; overrides the platform's")
      ->allow_extra_args(false)->option_text("NAME:VALUE (repeatable)");
  app.add_flag("--quiet", quiet, "print no table");
  app.set_version_flag("--version", [] {
    return "network_bench " + ncube::code_version() + " (SimGrid " + ncube::simgrid_version() + ")";
  });
  if (const auto ended = ncube::parse_command_line(app, "network_bench", argc, argv)) return *ended;
  platform_file = ncube::find_input(platform_file, ncube::InputRole::kPlatform, root);
  cost_model_file = ncube::find_input(cost_model_file, ncube::InputRole::kCostModel, root);
  if (min_bytes % 8 != 0)
    throw ncube::InputError("--min-bytes " + std::to_string(min_bytes) + ": not a multiple of 8");
  if (max_bytes < min_bytes)
    throw ncube::InputError("--max-bytes " + std::to_string(max_bytes) + ": below --min-bytes");
  for (long bytes = min_bytes; bytes <= max_bytes; bytes *= 2) settings.sizes.push_back(double(bytes));

  std::vector<std::string> simgrid_arguments;
  for (const std::string& setting : cfg) simgrid_arguments.push_back("--cfg=" + setting);
  ncube::check_simgrid_settings(simgrid_arguments);  // SimGrid would end the process
  // The files SimGrid's settings write (a Paje trace, a log) are outputs under the one rule,
  // as ./simulate's: never onto an input, written to temporary files and committed at the end.
  const ncube::SimgridOutputs simgrid_outputs(simgrid_arguments);
  std::vector<ncube::OutputFiles::Output> wanted = {{"--json", json_file}};
  for (const ncube::SimgridOutput& output : simgrid_outputs.outputs())
    wanted.push_back({output.setting, output.path});
  std::vector<std::string> read_files = {platform_file, cost_model_file};
  read_files.insert(read_files.end(), simgrid_outputs.inputs().begin(), simgrid_outputs.inputs().end());
  ncube::OutputFiles outputs(wanted, read_files);
  ncube::simgrid_engine(simgrid_outputs.engine_arguments(
      [&outputs](const std::string& setting) { return outputs.writer_path(setting); }));
  const ncube::CostModel costs = ncube::load_cost_model(cost_model_file);
  const ncube::PlatformConfig platform = ncube::load_platform_config(platform_file, simgrid_arguments);
  if (platform.node_count() < 2)
    throw ncube::InputError(platform_file + ": one node, no pair to measure");
  const std::vector<simgrid::s4u::Host*> nodes =
      ncube::build_simulated_platform(platform, simgrid_arguments);
  // Routes are read before the first run: the platform is sealed first, as run() would
  // (a DijkstraCache zone builds its graph then).
  simgrid::s4u::Engine::get_instance()->seal_platform();

  ncube::NetworkReport report;
  report.platform_file = platform_file;
  report.platform = platform;
  report.message_header_bytes = costs.message_header_bytes;
  report.simgrid_settings = ncube::simgrid_settings_used(simgrid_arguments);
  report.settings = settings;
  report.pairs.push_back(ncube::measure_pair("neighbours", ncube::nearest_to_node0(nodes), nodes,
                                             platform, costs, settings));
  report.pairs.push_back(ncube::measure_pair("farthest", ncube::farthest_pair(nodes), nodes,
                                             platform, costs, settings));
  if (!quiet) std::cout << ncube::network_report_table(report);
  if (!json_file.empty()) outputs.write("--json", ncube::network_report_json(report).dump(1) + "\n");
  outputs.commit();
  return ncube::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  return ncube::run_tool("network_bench", [&] { return network_bench(argc, argv); },
                         ncube::OtherRuntimeErrors::kSimulationFailed);
}

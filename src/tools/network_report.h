// The network benchmark's results (tools/network_benchmark.h) as a table for people and as
// JSON for scripts (docs/network-benchmark.md gives the fields).
#pragma once

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "machine/platform_config.h"
#include "tools/network_benchmark.h"

namespace ncube {

struct NetworkReport {
  std::string platform_file;
  PlatformConfig platform;
  double message_header_bytes = 0.0;
  std::map<std::string, std::string> simgrid_settings;  // in force (network model and --cfg)
  NetworkBenchmarkSettings settings;
  std::vector<PairMeasure> pairs;
};

nlohmann::json network_report_json(const NetworkReport& report);

// A header naming the platform, the overheads and each pair's route, then one row per size:
// one-way time (microseconds) and streaming bandwidth (MB/s, 10^6 bytes) of every pair.
std::string network_report_table(const NetworkReport& report);

}  // namespace ncube

#include "tools/network_report.h"

#include <cstdio>

namespace ncube {
namespace {

std::string printed(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

// `text` right-aligned in `width` columns, after two spaces.
std::string column(const std::string& text, std::size_t width = 18) {
  return "  " + (text.size() < width ? std::string(width - text.size(), ' ') : "") + text;
}

}  // namespace

nlohmann::json network_report_json(const NetworkReport& report) {
  nlohmann::json pairs = nlohmann::json::array();
  for (const PairMeasure& pair : report.pairs) {
    nlohmann::json sizes = nlohmann::json::array();
    for (const SizeMeasure& size : pair.sizes)
      sizes.push_back({{"bytes", size.bytes},
                       {"wire_bytes", size.wire_bytes},
                       {"one_way_seconds", size.one_way_seconds},
                       {"stream_seconds", size.stream_seconds},
                       {"stream_bandwidth_bytes_per_second", size.stream_bandwidth}});
    pairs.push_back({{"pair", pair.name},
                     {"from", pair.route.from},
                     {"to", pair.route.to},
                     {"links", pair.route.links},
                     {"route_latency_seconds", pair.route.latency},
                     {"bottleneck_bandwidth_bytes_per_second", pair.route.bottleneck_bandwidth},
                     {"sizes", sizes}});
  }
  return {{"platform_file", report.platform_file},
          {"nodes", report.platform.node_count()},
          {"send_overhead_seconds", report.platform.send_overhead},
          {"receive_overhead_seconds", report.platform.receive_overhead},
          {"message_header_bytes", report.message_header_bytes},
          {"simgrid_settings", report.simgrid_settings},
          {"round_trips", report.settings.round_trips},
          {"stream_messages", report.settings.stream_messages},
          {"pairs", pairs}};
}

std::string network_report_table(const NetworkReport& report) {
  std::string text = "platform " + report.platform_file + ": " +
                     std::to_string(report.platform.node_count()) + " nodes";
  for (const auto& [name, value] : report.simgrid_settings) text += ", " + name + " " + value;
  text += "\nper message: send overhead " + printed("%g", report.platform.send_overhead * 1e6) +
          " us, receive overhead " + printed("%g", report.platform.receive_overhead * 1e6) +
          " us, header " + printed("%g", report.message_header_bytes) + " bytes\n";
  text += "one-way: half the round trip of a ping-pong (" +
          std::to_string(report.settings.round_trips) + " round trips); stream: " +
          std::to_string(report.settings.stream_messages) +
          " messages back to back, payload bytes per second\n";
  for (const PairMeasure& pair : report.pairs)
    text += pair.name + ": node-" + std::to_string(pair.route.from) + " -> node-" +
            std::to_string(pair.route.to) + ", " + std::to_string(pair.route.links) +
            (pair.route.links == 1 ? " link" : " links") + ", route latency " +
            printed("%g", pair.route.latency * 1e6) + " us, bottleneck " +
            printed("%g", pair.route.bottleneck_bandwidth / 1e6) + " MB/s\n";
  text += "\n" + column("payload", 9).substr(2);
  for (const PairMeasure& pair : report.pairs) text += column("one-way " + pair.name);
  for (const PairMeasure& pair : report.pairs) text += column("stream " + pair.name);
  text += "\n" + column("(bytes)", 9).substr(2);
  for (std::size_t p = 0; p < report.pairs.size(); ++p) text += column("(us)");
  for (std::size_t p = 0; p < report.pairs.size(); ++p) text += column("(MB/s)");
  text += "\n";
  const std::size_t rows = report.pairs.empty() ? 0 : report.pairs.front().sizes.size();
  for (std::size_t row = 0; row < rows; ++row) {
    text += printed("%9.0f", report.pairs.front().sizes[row].bytes);
    for (const PairMeasure& pair : report.pairs)
      text += column(printed("%.3f", pair.sizes[row].one_way_seconds * 1e6));
    for (const PairMeasure& pair : report.pairs)
      text += column(printed("%.4f", pair.sizes[row].stream_bandwidth / 1e6));
    text += "\n";
  }
  return text;
}

}  // namespace ncube

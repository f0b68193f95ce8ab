#include "simulation/trace_file.h"

#include <nlohmann/json.hpp>

namespace ncube {

std::string trace_to_json(const SimulationResult& result) {
  nlohmann::json events = nlohmann::json::array();
  for (const NodeStats& n : result.nodes)
    events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 0}, {"tid", n.node},
                      {"args", {{"name", "node " + std::to_string(n.node) + " " + role_name(n.role) + " " +
                                             std::to_string(n.rank)}}}});
  for (const TraceEvent& e : result.trace)
    events.push_back({{"name", e.what}, {"cat", e.what}, {"ph", "X"}, {"pid", 0},
                      {"tid", e.node}, {"ts", e.start * 1e6}, {"dur", (e.end - e.start) * 1e6}});
  return nlohmann::json{{"traceEvents", events}, {"displayTimeUnit", "ms"}}.dump() + "\n";
}

}  // namespace ncube

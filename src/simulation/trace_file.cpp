#include "simulation/trace_file.h"

#include <algorithm>
#include <cmath>
#include <regex>

#include <nlohmann/json.hpp>

namespace ncube {

namespace {

// A decimal count of at most 9 digits (no sign, no leading zeros): stays an int.
bool read_count(const std::string& text, int& value) {
  static const std::regex decimal("0|[1-9][0-9]{0,8}");
  if (!std::regex_match(text, decimal)) return false;
  value = std::stoi(text);
  return true;
}

// Seconds as the trace's microseconds, to the nanosecond: the file keeps "3.2", not
// "3.1999999999999997" (a third of a large trace's bytes), and a viewer shows no finer.
double microseconds(double seconds) { return std::round(seconds * 1e9) / 1e3; }

// The event's name and arguments (docs/result-format.md, "The trace").
nlohmann::json event_json(const TraceEvent& e) {
  nlohmann::json args = nlohmann::json::object();
  if (e.render) {
    args["phase"] = "render";
  } else {
    args["iteration"] = e.iteration;
    if (e.shooter >= 0) args["shooter"] = e.shooter;
  }
  std::string name = e.what;
  if (e.has_message) {
    const char* kind = message_kind_name(e.kind);
    args["message"] = kind;
    args[e.sent ? "to" : "from"] = e.peer;
    // Modeled bytes are whole but for a fraction of a mask: whole ones are written as integers.
    if (e.bytes == std::floor(e.bytes) && e.bytes < 0x1p53)
      args["bytes"] = static_cast<long long>(e.bytes);
    else
      args["bytes"] = e.bytes;
    if (std::string(e.what) == "overhead") name = std::string(e.sent ? "send " : "receive ") + kind;
  }
  return {{"name", name}, {"cat", e.what}, {"ph", "X"}, {"pid", 0}, {"tid", e.node},
          {"ts", microseconds(e.start)}, {"dur", microseconds(e.end - e.start)}, {"args", args}};
}

}  // namespace

bool TraceWindow::keeps_node(int node) const {
  return nodes.empty() || std::binary_search(nodes.begin(), nodes.end(), node);
}

bool TraceWindow::keeps(const TraceEvent& event) const {
  if (!keeps_node(event.node)) return false;
  if (!iterations_limited) return true;
  return !event.render && event.iteration >= first_iteration && event.iteration <= last_iteration;
}

std::string parse_trace_iterations(const std::string& text, TraceWindow& window) {
  const std::string::size_type colon = text.find(':');
  int first = 0, last = INT_MAX;
  const bool ok = colon == std::string::npos
                      ? read_count(text, first) && (last = first, true)
                      : read_count(text.substr(0, colon), first) &&
                            (colon + 1 == text.size() || read_count(text.substr(colon + 1), last));
  if (!ok) return "'" + text + "' is not A:B, A: or A (iterations, decimal, from 0)";
  if (last < first) return "'" + text + "': the last iteration is before the first";
  window.iterations_limited = true;
  window.first_iteration = first;
  window.last_iteration = last;
  return "";
}

std::string parse_trace_nodes(const std::string& text, TraceWindow& window) {
  std::vector<int> nodes;
  std::string::size_type at = 0;
  while (at <= text.size()) {
    const std::string::size_type comma = std::min(text.find(',', at), text.size());
    const std::string item = text.substr(at, comma - at);
    const std::string::size_type dash = item.find('-');
    int low = 0, high = 0;
    const bool ok = dash == std::string::npos
                        ? read_count(item, low) && (high = low, true)
                        : read_count(item.substr(0, dash), low) && read_count(item.substr(dash + 1), high);
    if (!ok || high < low)
      return "'" + text + "' is not a list of nodes such as 0,3,8-15 (at '" + item + "')";
    // A range is at most the largest machine's nodes: a typo does not fill the host's memory.
    if (high - low > (1 << 24)) return "'" + text + "': the range " + item + " is too long";
    for (int node = low; node <= high; ++node) nodes.push_back(node);
    at = comma + 1;
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  window.nodes = nodes;
  return "";
}

std::string trace_window_problem(const TraceWindow& window, int node_count, int max_iterations) {
  if (!window.nodes.empty() && window.nodes.back() >= node_count)
    return "--trace-nodes names node " + std::to_string(window.nodes.back()) + ", but the run has " +
           std::to_string(node_count) + (node_count == 1 ? " node (0)" : " nodes (0-" +
           std::to_string(node_count - 1) + ")");
  if (window.iterations_limited && max_iterations >= 0) {
    const int named = window.last_iteration == INT_MAX ? window.first_iteration : window.last_iteration;
    if (named > max_iterations)
      return "--trace-iterations names iteration " + std::to_string(named) + ", but the run stops after " +
             std::to_string(max_iterations) + " (--iterations " + std::to_string(max_iterations) + ")";
  }
  return "";
}

std::string trace_window_problem_after(const TraceWindow& window, int iterations, bool converged) {
  if (!window.iterations_limited || window.first_iteration <= iterations) return "";
  return "--trace-iterations starts at iteration " + std::to_string(window.first_iteration) +
         ", but the run had " + std::to_string(iterations) + (iterations == 1 ? " iteration" : " iterations") +
         (converged ? " (it converged)" : "") +
         ": the trace would hold none of its iterations";
}

std::string trace_to_json(const SimulationResult& result, const TraceWindow& window) {
  nlohmann::json events = nlohmann::json::array();
  for (const NodeStats& n : result.nodes)
    if (window.keeps_node(n.node))
      events.push_back({{"name", "thread_name"}, {"ph", "M"}, {"pid", 0}, {"tid", n.node},
                        {"args", {{"name", "node " + std::to_string(n.node) + " " + role_name(n.role) +
                                               " " + std::to_string(n.rank)}}}});
  for (const TraceEvent& e : result.trace)
    if (window.keeps(e)) events.push_back(event_json(e));
  return nlohmann::json{{"traceEvents", events}, {"displayTimeUnit", "ms"}}.dump() + "\n";
}

}  // namespace ncube

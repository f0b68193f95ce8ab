#include "machine/platform_shape.h"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <simgrid/s4u/Engine.hpp>
#include <simgrid/s4u/Link.hpp>
#include <vector>

#include "machine/machine_parameters.h"
#include "machine/parameter_file.h"
#include "util/input_error.h"

namespace ncube {
namespace {

// The deepest nesting of elements in `text`, stopping as soon as it passes `limit` (a plain
// scan: comments, processing instructions, declarations and quoted attribute values skipped).
int nesting_depth(const std::string& text, int limit) {
  int depth = 0, deepest = 0;
  std::size_t at = 0;
  const auto skip_to = [&](const char* end) {
    const std::size_t found = text.find(end, at);
    at = found == std::string::npos ? text.size() : found + std::char_traits<char>::length(end);
  };
  while ((at = text.find('<', at)) != std::string::npos) {
    if (text.compare(at, 4, "<!--") == 0) {
      skip_to("-->");
    } else if (text.compare(at, 9, "<![CDATA[") == 0) {
      skip_to("]]>");
    } else if (text.compare(at, 2, "<?") == 0) {
      skip_to("?>");
    } else if (text.compare(at, 2, "<!") == 0) {
      skip_to(">");
    } else if (text.compare(at, 2, "</") == 0) {
      --depth;
      skip_to(">");
    } else {
      char quote = 0;
      std::size_t end = at + 1;
      for (; end < text.size(); ++end) {
        const char c = text[end];
        if (quote) {
          if (c == quote) quote = 0;
        } else if (c == '"' || c == '\'') {
          quote = c;
        } else if (c == '>') {
          break;
        }
      }
      if (end >= text.size() || text[end - 1] != '/') deepest = std::max(deepest, ++depth);
      if (deepest > limit) return deepest;
      at = end;
    }
  }
  return deepest;
}

std::string attribute(const xmlNode* node, const char* name) {
  xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (!value) return "";
  std::string text(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return text;
}

bool has_attribute(const xmlNode* node, const char* name) {
  return xmlHasProp(node, reinterpret_cast<const xmlChar*>(name)) != nullptr;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t begin = 0;
  for (std::size_t at; (at = text.find(separator, begin)) != std::string::npos; begin = at + 1)
    parts.push_back(text.substr(begin, at - begin));
  parts.push_back(text.substr(begin));
  return parts;
}

// A whole number in [low, high] written in decimal digits alone; -1 when it is not.
long whole(const std::string& text, long low, long high) {
  if (text.empty() || text.size() > 12) return -1;
  for (char c : text)
    if (c < '0' || c > '9') return -1;
  const long value = std::stol(text);
  return value < low || value > high ? -1 : value;
}

class ShapeCheck {
 public:
  explicit ShapeCheck(const std::string& path) : path_(path) {}

  void visit(const xmlNode* node) {
    for (; node; node = node->next) {
      if (node->type != XML_ELEMENT_NODE) continue;
      const std::string name(reinterpret_cast<const char*>(node->name));
      if (name == "trace" || name == "trace_connect")
        fail(node, "<" + name + ">: a trace changes a node's or a link's values during the run "
                   "(a node turned off or to speed 0 ends SimGrid in an abort); not supported");
      check_numbers(node);
      if (name == "host" || name == "peer") add(node, 1);
      if (name == "cluster" || name == "cabinet") add(node, cluster_hosts(node));
      visit(node->children);
    }
  }

  long hosts() const { return hosts_; }

 private:
  [[noreturn]] void fail(const xmlNode* node, const std::string& what) const {
    throw InputError(path_ + ": line " + std::to_string(xmlGetLineNo(node)) + ": " + what);
  }

  void add(const xmlNode* node, long count) {
    hosts_ += count;
    if (hosts_ > kMaxPlatformHosts)
      fail(node, "the file builds more than " + std::to_string(kMaxPlatformHosts) +
                     " hosts, the limit of a platform file (docs/platforms.md)");
  }

  // Hosts a radical names ("0-63", "0-3,8,10-12"), at most one more than the limit.
  long radical_hosts(const xmlNode* node) const {
    const std::string radical = attribute(node, "radical");
    long count = 0;
    for (const std::string& part : split(radical, ',')) {
      const std::vector<std::string> range = split(part, '-');
      const long low = whole(range[0], 0, 1L << 40);
      const long high = range.size() == 2 ? whole(range[1], 0, 1L << 40) : low;
      if (range.size() > 2 || low < 0 || high < low)
        fail(node, "radical=\"" + radical + "\": expected ranges of whole numbers, e.g. 0-63");
      count += high - low + 1;
      if (count > kMaxPlatformHosts) return kMaxPlatformHosts + 1;
    }
    return count;
  }

  // The positive whole numbers of a comma-separated list, or a failure naming the attribute.
  std::vector<long> numbers(const xmlNode* node, const std::string& list,
                            const std::string& what) const {
    std::vector<long> values;
    for (const std::string& part : split(list, ',')) {
      const long value = whole(part, 1, kMaxPlatformHosts);
      if (value < 0) fail(node, what);
      values.push_back(value);
    }
    return values;
  }

  static long product(const std::vector<long>& values) {
    long result = 1;
    for (long v : values) result = std::min(result * v, kMaxPlatformHosts + 1);
    return result;
  }

  // A cluster's hosts: its topology's count, which must equal the radical's.
  long cluster_hosts(const xmlNode* node) const {
    const long named = radical_hosts(node);
    const std::string topology = attribute(node, "topology");
    const std::string parameters = attribute(node, "topo_parameters");
    const std::string given = "topology=\"" + topology + "\" topo_parameters=\"" + parameters + "\": ";
    long built = named;
    if (topology == "TORUS") {
      built = product(numbers(node, parameters, given + "expected the torus's extents, e.g. 4,4,4"));
    } else if (topology == "FAT_TREE") {
      const std::vector<std::string> groups = split(parameters, ';');
      const std::string expected = given + "expected LEVELS;DOWN,...;UP,...;LINKS,... with LEVELS "
                                           "numbers in each list, e.g. 2;4,16;1,4;1,1";
      const long levels = groups.size() == 4 ? whole(groups[0], 1, 16) : -1;
      if (levels < 0) fail(node, expected);
      std::vector<long> down;
      for (int g = 1; g < 4; ++g) {
        const std::vector<long> list = numbers(node, groups[g], expected);
        if (long(list.size()) != levels) fail(node, expected);
        if (g == 1) down = list;
      }
      built = product(down);
    } else if (topology == "DRAGONFLY") {
      const std::vector<std::string> groups = split(parameters, ';');
      const std::string expected = given + "expected GROUPS,LINKS;CHASSIS,LINKS;ROUTERS,LINKS;NODES, "
                                           "e.g. 3,4;4,3;5,1;2";
      if (groups.size() != 4) fail(node, expected);
      std::vector<long> counts;
      for (int g = 0; g < 4; ++g) {
        const std::vector<long> list = numbers(node, groups[g], expected);
        if (list.size() != (g < 3 ? 2u : 1u)) fail(node, expected);
        counts.push_back(list[0]);
      }
      built = product(counts);
    } else if (!topology.empty() && topology != "FLAT") {
      fail(node, given + "the topology must be FLAT, TORUS, FAT_TREE or DRAGONFLY");
    }
    if (built > kMaxPlatformHosts || named > kMaxPlatformHosts)
      fail(node, "the cluster builds more than " + std::to_string(kMaxPlatformHosts) +
                     " hosts, the limit of a platform file (docs/platforms.md)");
    if (built != named)
      fail(node, given + "builds " + std::to_string(built) + " hosts, but radical=\"" +
                     attribute(node, "radical") + "\" names " + std::to_string(named));
    return built;
  }

  // Every rate, delay and speed attribute: a finite number, not negative, before its unit
  // (SimGrid aborts on "nanBps" or "infBps"); a speed may list power states, "1Gf,500Mf".
  void check_numbers(const xmlNode* node) const {
    static const char* const kNumbers[] = {"speed",  "bandwidth",   "latency",      "bw",
                                           "lat",    "bb_bw",       "bb_lat",       "loopback_bw",
                                           "loopback_lat", "limiter_link", "bw_in", "bw_out"};
    for (const char* name : kNumbers) {
      if (!has_attribute(node, name)) continue;
      const std::string value = attribute(node, name);
      for (const std::string& part : split(value, ',')) {
        const char* begin = part.c_str();
        char* end = nullptr;
        const double number = std::strtod(begin, &end);
        if (end == begin || !std::isfinite(number) || number < 0)
          fail(node, std::string(name) + "=\"" + value +
                         "\": expected a finite number of at least 0 before its unit");
      }
    }
  }

  std::string path_;
  long hosts_ = 0;
};

const MachineParameter& parameter(const char* name) {
  for (const MachineParameter& p : machine_parameters())
    if (std::string(p.name) == name) return p;
  throw std::logic_error(std::string("no machine parameter ") + name);
}

void within(const std::string& where, const MachineParameter& p, double value) {
  char written[32];
  std::snprintf(written, sizeof written, "%.6g", value);
  const std::string problem = value_problem(parameter_spec(p), value, written);
  if (!problem.empty()) throw InputError(where + " (held to " + p.name + "'s range): " + problem);
}

}  // namespace

long check_platform_shape(const std::string& path, const std::string& text) {
  if (nesting_depth(text, kMaxPlatformDepth) > kMaxPlatformDepth)
    throw InputError(path + ": elements nested more than " + std::to_string(kMaxPlatformDepth) +
                     " levels deep, the limit of a platform file (docs/platforms.md)");
  const std::unique_ptr<xmlDoc, void (*)(xmlDoc*)> document(
      xmlReadMemory(text.data(), int(text.size()), path.c_str(), nullptr,
                    XML_PARSE_NONET | XML_PARSE_RECOVER | XML_PARSE_NOERROR | XML_PARSE_NOWARNING),
      xmlFreeDoc);
  if (!document) return 0;  // SimGrid's own reader names what is wrong with the file
  ShapeCheck check(path);
  check.visit(xmlDocGetRootElement(document.get()));
  return check.hosts();
}

void check_platform_values(const std::string& path, simgrid::s4u::Engine& engine) {
  const MachineParameter& bandwidth = parameter("link_bandwidth");
  const MachineParameter& latency = parameter("hop_latency");
  for (simgrid::s4u::Link* link : engine.get_all_links()) {
    const std::string where = path + ": link \"" + link->get_name() + "\": ";
    within(where + "bandwidth", bandwidth, link->get_bandwidth());
    within(where + "latency", latency, link->get_latency());
  }
  // Every host is a node (node-0 ... node-(n-1), no other): their speeds are held to
  // node_speed's range with the other node values (read_simgrid_platform_file).
}

}  // namespace ncube

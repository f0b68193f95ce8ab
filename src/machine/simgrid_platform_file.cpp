#include "machine/simgrid_platform_file.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <simgrid/s4u/Engine.hpp>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <simgrid/s4u/NetZone.hpp>

#include "machine/machine_parameters.h"
#include "machine/parameter_file.h"
#include "machine/platform_shape.h"
#include "machine/simgrid_session.h"
#include "machine/simgrid_setting_ranges.h"
#include "util/input_error.h"
#include "util/input_file.h"

namespace ncube {
namespace {

// How a node's value is named in an error: the speed attribute or the property.
std::string xml_name(const MachineParameter& p) {
  return p.xml == XmlForm::kHostSpeed ? std::string("speed (") + p.name + ")"
                                      : std::string("property \"") + p.name + "\"";
}

// A node's value of a parameter the file carries (XmlForm::kHostSpeed or kProperty), held
// to the parameter's range. A property is the host's, else its zone's (a <cluster>'s <prop>
// belongs to the zone).
double node_value(const std::string& path, simgrid::s4u::Host* host, const MachineParameter& p) {
  const std::string host_name = path + ": host \"" + host->get_name() + "\": ";
  const ParameterSpec spec = parameter_spec(p);
  if (p.xml == XmlForm::kHostSpeed) {
    const double speed = host->get_speed();
    const std::string problem = value_problem(spec, speed, nlohmann::json(speed).dump());
    if (!problem.empty()) throw InputError(host_name + xml_name(p) + ": " + problem);
    return speed;
  }
  const char* text = host->get_property(p.name);
  if (!text) text = host->get_englobing_zone()->get_property(p.name);
  const std::string where = host_name + xml_name(p);
  if (!text && p.optional) return 0;  // left out: the kind of work runs at node_speed
  if (!text) throw InputError(where + ": missing");
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0')
    throw InputError(where + ": \"" + text + "\" is not a number");
  const std::string problem = value_problem(spec, value, text);
  if (!problem.empty()) throw InputError(where + ": " + problem);
  return value;
}

// "line <n>: <name>=" of the first attribute named `file` or `*_file` with a value, or "".
// A plain scan, not std::regex: its recursion would overflow the stack on a large file.
std::string file_attribute(const std::string& text) {
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  for (std::size_t at = text.find("file"); at != std::string::npos;
       at = text.find("file", at + 1)) {
    std::size_t begin = at;
    while (begin > 0 && word(text[begin - 1])) --begin;
    const bool named = begin == at || text[at - 1] == '_';  // "file" or "..._file"
    if (!named || begin == 0 ||
        !(std::isspace(static_cast<unsigned char>(text[begin - 1])) || text[begin - 1] == '<'))
      continue;
    std::size_t after = at + 4;
    while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
    if (after >= text.size() || text[after] != '=') continue;
    ++after;
    while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
    if (after >= text.size() || (text[after] != '"' && text[after] != '\'')) continue;
    const long line = long(std::count(text.begin(), text.begin() + long(at), '\n')) + 1;
    return "line " + std::to_string(line) + ": " + text.substr(begin, at + 4 - begin) + "=";
  }
  return "";
}

// An attribute's text ("" when absent).
std::string attribute(xmlNode* node, const char* name) {
  xmlChar* value = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (!value) return "";
  std::string text(reinterpret_cast<const char*>(value));
  xmlFree(value);
  return text;
}

bool named(const xmlNode* node, const char* name) {
  return node && node->type == XML_ELEMENT_NODE &&
         xmlStrEqual(node->name, reinterpret_cast<const xmlChar*>(name));
}

// The file's <config><prop id= value=/></config> settings are SimGrid settings like --cfg, and
// SimGrid applies them while it loads the file (a network model that cannot build the
// platform aborts there): each is held to src/machine/simgrid_setting_ranges.h first. Read
// with libxml2, without the network (the DOCTYPE's DTD is not fetched), without entities, and
// recovering as far as it can from what SimGrid's lenient reader takes (a "--" in a comment).
// `text` is the file as the input gate read it (libxml2 never opens the path itself).
void check_config_tags(const std::string& path, const std::string& text) {
  const std::unique_ptr<xmlDoc, void (*)(xmlDoc*)> document(
      xmlReadMemory(text.data(), int(text.size()), path.c_str(), nullptr,
                  XML_PARSE_NONET | XML_PARSE_RECOVER | XML_PARSE_NOERROR | XML_PARSE_NOWARNING),
      xmlFreeDoc);
  if (!document) return;  // SimGrid's own reader names what is wrong with the file
  const xmlNode* platform = xmlDocGetRootElement(document.get());
  for (xmlNode* config = platform ? platform->children : nullptr; config; config = config->next) {
    if (!named(config, "config")) continue;
    for (xmlNode* prop = config->children; prop; prop = prop->next) {
      if (!named(prop, "prop")) continue;
      const std::string name = attribute(prop, "id"), value = attribute(prop, "value");
      const std::string problem = platform_setting_problem(name, value);
      if (!problem.empty())
        throw InputError(path + ": <config> <prop id=\"" + name + "\" value=\"" + value +
                         "\">: " + problem);
    }
  }
}

// SimGrid's reader takes neither an internal DTD subset nor an entity declaration; refused
// here by name, so that a file is never judged by what an entity would expand to.
void check_document_type(const std::string& path, const std::string& text) {
  const auto line_of = [&text](std::size_t at) {
    return std::to_string(std::count(text.begin(), text.begin() + long(at), '\n') + 1);
  };
  const std::size_t entity = text.find("<!ENTITY");
  if (entity != std::string::npos)
    throw InputError(path + ": line " + line_of(entity) +
                     ": <!ENTITY: a platform file declares no entities (plain SimGrid XML)");
  const std::size_t doctype = text.find("<!DOCTYPE");
  if (doctype == std::string::npos) return;
  const std::size_t end = text.find('>', doctype), subset = text.find('[', doctype);
  if (subset != std::string::npos && (end == std::string::npos || subset < end))
    throw InputError(path + ": line " + line_of(doctype) +
                     ": <!DOCTYPE with a DTD of its own ([...]): a platform file names SimGrid's "
                     "DTD only");
}

}  // namespace

void check_simgrid_platform_text(const std::string& path, const std::string& text) {
  check_platform_shape(path, text);  // before SimGrid or libxml2 builds anything of it
  check_document_type(path, text);
  check_config_tags(path, text);
  // SimGrid would open the files an XML platform names (a host's speed_file, a link's
  // bandwidth_file, <trace file>, ...) itself, outside the gate: they are refused.
  const std::string attribute = file_attribute(text);
  if (!attribute.empty())
    throw InputError(path + ": " + attribute +
                     ": names a file, which SimGrid would read outside the input gate (files "
                     "a platform names are not read: docs/cli.md, \"Input files\")");
}

bool is_simgrid_platform_file(const std::string& path) {
  // Either kind of platform file, up to the larger limit: only its first character is read.
  InputStream in(path, InputKind{kPlatformFile.what, kSimgridPlatformFile.max_bytes});
  char c = 0;
  while (in.get(c) && std::isspace(static_cast<unsigned char>(c))) {
  }
  return in && c == '<';
}

PlatformConfig read_simgrid_platform_file(const std::string& path,
                                          const std::vector<std::string>& simgrid_arguments) {
  // SimGrid reads the descriptor the gate opened and checked, not the path again.
  InputFile file(path, kSimgridPlatformFile);
  const std::string text = file.read_all();
  check_simgrid_platform_text(path, text);
  simgrid::s4u::Engine& engine = simgrid_engine(simgrid_arguments);
  try {
    engine.load_platform(file.descriptor_path());
  } catch (const std::exception& e) {
    throw InputError(path + ": not a SimGrid platform file: " + e.what());
  }
  check_platform_values(path, engine);
  PlatformConfig c;
  c.format = "simgrid-xml";
  c.simgrid_config.clear();  // the file's own <config> tags are the defaults
  while (engine.host_by_name_or_null("node-" + std::to_string(c.xml_nodes))) ++c.xml_nodes;
  if (c.xml_nodes == 0) throw InputError(path + ": no host \"node-0\" (nodes are named node-0 ... node-(n-1))");
  if (std::size_t(c.xml_nodes) != engine.get_host_count())
    throw InputError(path + ": " + std::to_string(engine.get_host_count()) + " hosts, but only node-0 ... node-" +
                     std::to_string(c.xml_nodes - 1) + " are numbered without a gap");
  // Every node has node-0's values: the node programs see one machine (docs/platforms.md).
  for (simgrid::s4u::Host* host : simgrid_platform_nodes(c))
    for (const MachineParameter& p : machine_parameters()) {
      if (!carried_by(p, c.format)) continue;
      const double value = node_value(path, host, p);
      if (host->get_name() == "node-0")
        p.set(c, value);
      else if (value != p.get(c))
        throw InputError(path + ": host \"" + host->get_name() + "\": " + xml_name(p) + ": " +
                         nlohmann::json(value).dump() + " differs from node-0's " +
                         nlohmann::json(p.get(c)).dump() + " (every node must be the same)");
    }
  return c;
}

std::vector<simgrid::s4u::Host*> simgrid_platform_nodes(const PlatformConfig& platform) {
  std::vector<simgrid::s4u::Host*> hosts;
  for (int k = 0; k < platform.xml_nodes; ++k)
    hosts.push_back(simgrid::s4u::Engine::get_instance()->host_by_name("node-" + std::to_string(k)));
  return hosts;
}

}  // namespace ncube

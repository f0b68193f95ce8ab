// The one list of machine parameters (src/machine/machine_parameters.h): every consumer
// enumerates it, so each test here iterates the list and a parameter some consumer forgets
// fails it by name. The JSON loader (range, whole number, unit, missing), the SimGrid XML
// reader and its per-node check (each node's speed and properties), the result file's
// provenance, and the network model's one place. The docs tables: tests/platform_tables_test.sh;
// the robustness bounds: tests/robustness/cases.py (machine_cases).
#include "machine/machine_parameters.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <functional>
#include <fstream>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>

#include "machine/platform_config.h"
#include "machine/simgrid_platform_file.h"
#include "simulation/provenance.h"
#include "util/input_error.h"

namespace ncube {
namespace {

std::string repo(const std::string& path) { return std::string(NCUBE_SOURCE_DIR) + "/" + path; }

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A file of its own per test, case and process (ctest runs this file's tests in parallel).
std::string write_temp(const std::string& text, const std::string& suffix) {
  static int count = 0;
  const std::string path = ::testing::TempDir() + "machine-parameters-" +
                           ::testing::UnitTest::GetInstance()->current_test_info()->name() + "-" +
                           std::to_string(::getpid()) + "-" + std::to_string(count++) + suffix;
  std::ofstream(path) << text;
  return path;
}

std::string text(double value) {
  std::ostringstream out;
  out << std::setprecision(17) << value;
  return out.str();
}

// The nCube2 of the paper, worked out by hand from docs/ncube2-sources.md (not from the list):
// 64 nodes, 2.5 MFLOPS, 4 MB, 2.2 MB/s links, 1 us per hop, 80 us of CPU each side.
TEST(MachineParameters, TheNcube2FileGivesThePapersMachine) {
  const PlatformConfig p = load_platform_config(repo("platforms/ncube2.json"));
  EXPECT_EQ(p.dimension, 6);
  EXPECT_EQ(p.node_count(), 64);
  EXPECT_EQ(p.node_speed, 2.5e6);
  EXPECT_EQ(p.node_memory, 4194304.0);
  EXPECT_EQ(p.link_bandwidth, 2.2e6);
  EXPECT_EQ(p.hop_latency, 1e-6);
  EXPECT_EQ(p.send_overhead, 80e-6);
  EXPECT_EQ(p.receive_overhead, 80e-6);
}

TEST(MachineParameters, EveryEntryIsComplete) {
  std::set<std::string> names;
  for (const MachineParameter& p : machine_parameters()) {
    EXPECT_TRUE(names.insert(p.name).second) << p.name << " listed twice";
    EXPECT_LT(p.low, p.high) << p.name;
    EXPECT_GT(std::string(p.doc).size(), 20u) << p.name;
    PlatformConfig c;
    p.set(c, p.high);
    EXPECT_EQ(p.get(c), p.high) << p.name << ": get and set are not one field";
  }
  EXPECT_EQ(names.size(), 15u);  // update with the list when a parameter is added
}

// platforms/ncube2.json as a JSON object, each parameter set by `change`.
std::string ncube2_with(const std::function<void(nlohmann::json&)>& change) {
  nlohmann::json doc = nlohmann::json::parse(read_text(repo("platforms/ncube2.json")));
  change(doc["parameters"]);
  return doc.dump();
}

std::string json_error(const std::string& text) {
  try {
    load_platform_config(write_temp(text, ".json"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Each parameter is read from its entry, at both ends of its range, and refused just past
// them, fractional when it must be whole, missing, or in another unit, by name.
TEST(MachineParameters, TheJsonLoaderReadsAndChecksEveryParameter) {
  for (const MachineParameter& p : machine_parameters()) {
    const std::string named = "parameter \"" + std::string(p.name) + "\": ";
    for (const double end : {p.low, p.high}) {
      const std::string file =
          write_temp(ncube2_with([&](nlohmann::json& ps) { ps[p.name]["value"] = end; }), ".json");
      EXPECT_EQ(p.get(load_platform_config(file)), end) << p.name;
    }
    const double below = p.whole ? p.low - 1 : std::nextafter(p.low, -HUGE_VAL);
    const double above = p.whole ? p.high + 1 : std::nextafter(p.high, HUGE_VAL);
    EXPECT_NE(json_error(ncube2_with([&](nlohmann::json& ps) { ps[p.name]["value"] = below; }))
                  .find(named + "value " + nlohmann::json(below).dump() + " is below"),
              std::string::npos)
        << p.name;
    EXPECT_NE(json_error(ncube2_with([&](nlohmann::json& ps) { ps[p.name]["value"] = above; }))
                  .find(named + "value " + nlohmann::json(above).dump() + " is above"),
              std::string::npos)
        << p.name;
    if (p.whole) {
      EXPECT_NE(json_error(ncube2_with([&](nlohmann::json& ps) { ps[p.name]["value"] = p.low + 0.5; }))
                    .find(named + "value " + nlohmann::json(p.low + 0.5).dump() + " must be a whole number"),
                std::string::npos)
          << p.name;
    }
    if (p.optional) {  // left out: 0, the kind of work at node_speed
      const std::string file =
          write_temp(ncube2_with([&](nlohmann::json& ps) { ps.erase(p.name); }), ".json");
      EXPECT_EQ(p.get(load_platform_config(file)), 0) << p.name;
    } else {
      EXPECT_NE(json_error(ncube2_with([&](nlohmann::json& ps) { ps.erase(p.name); }))
                    .find(named + "missing"),
                std::string::npos)
          << p.name;
    }
    EXPECT_NE(json_error(ncube2_with([&](nlohmann::json& ps) { if (!ps.contains(p.name)) ps[p.name]["value"] = p.low;
                    ps[p.name]["unit"] = "furlong"; }))
                  .find(named + "unit \"furlong\" is not \"" + p.unit + "\""),
              std::string::npos)
        << p.name;
  }
}

// A platform's settings are asked of SimGrid together, in one child: the one it refuses is
// still the one named, wherever it sorts among them, and an earlier one SimGrid refuses is
// named before a later one of bad form.
TEST(MachineParameters, TheSettingSimgridRefusesIsNamedAmongThePlatformsOthers) {
  const nlohmann::json parameters =
      nlohmann::json::parse(read_text(repo("platforms/ncube2.json")))["parameters"];
  const auto error_with = [&](const nlohmann::json& settings) {
    return json_error(nlohmann::json{{"simgrid_config", settings}, {"parameters", parameters}}.dump());
  };
  const std::string last = error_with({{"network/model", "CM02"}, {"network/solver", "fairbottleneck"},
                                       {"network/crosstraffic", "0"}, {"tracing/actor", "maybe"}});
  EXPECT_NE(last.find("\"simgrid_config\": \"tracing/actor\": "), std::string::npos) << last;
  EXPECT_NE(last.find("boolean"), std::string::npos) << last;
  const std::string first = error_with({{"network/crosstraffic", "maybe"}, {"network/model", "bogus"}});
  EXPECT_NE(first.find("\"network/crosstraffic\": "), std::string::npos) << first;
  EXPECT_NE(error_with({{"network/crosstraffic", "0"}, {"network/model", "bogus"}})
                .find("\"network/model\": network/model must be one of"),
            std::string::npos);
}

TEST(MachineParameters, AJsonFileWithoutSimgridConfigGetsTheNetworkModel) {
  const PlatformConfig p = load_platform_config(
      write_temp(nlohmann::json{{"parameters", nlohmann::json::parse(read_text(repo(
                                                   "platforms/ncube2.json")))["parameters"]}}
                     .dump(),
                 ".json"));
  EXPECT_EQ(p.simgrid_config, default_network_model());
  EXPECT_EQ(default_network_model(),
            (std::map<std::string, std::string>{{"network/model", "CM02"},
                                                {"network/crosstraffic", "0"},
                                                {"network/solver", "fairbottleneck"}}));
}

// The network model's one place is NCUBE_NETWORK_MODEL: the two nCube2 files that repeat it
// (their bytes are hashed into every result file, so they keep their copy) must say the same.
TEST(MachineParameters, TheNcube2FilesStateTheListsNetworkModel) {
  EXPECT_EQ(load_platform_config(repo("platforms/ncube2.json")).simgrid_config,
            default_network_model());
  // The fat-tree example keeps the nCube2's network model too (docs/platforms.md).
  for (const char* file : {"platforms/ncube2.xml", "docs/examples/fat-tree-64.xml"}) {
    const std::string xml = read_text(repo(file));
    const std::size_t begin = xml.find("<config>"), end = xml.find("</config>");
    ASSERT_NE(begin, std::string::npos) << file;
    std::map<std::string, std::string> settings;
    for (std::size_t at = xml.find("<prop id=\"", begin); at < end;
         at = xml.find("<prop id=\"", at + 1)) {
      const std::size_t name = at + 10, name_end = xml.find('"', name);
      const std::size_t value = xml.find("value=\"", name_end) + 7;
      settings[xml.substr(name, name_end - name)] = xml.substr(value, xml.find('"', value) - value);
    }
    EXPECT_EQ(settings, default_network_model()) << file;
  }
}

// provenance.platform.values: "nodes" and every parameter the form carries, as read.
TEST(MachineParameters, ProvenanceWritesEveryParameterTheFormCarries) {
  for (const std::string format : {"json", "simgrid-xml"}) {
    PlatformConfig c;
    c.format = format;
    c.xml_nodes = 2;
    double value = 1;
    for (const MachineParameter& p : machine_parameters()) p.set(c, value += 1);
    const nlohmann::json values = platform_values(c);
    std::set<std::string> expected = {"nodes"};
    for (const MachineParameter& p : machine_parameters()) {
      if (p.xml != XmlForm::kInterconnect || format == "json") expected.insert(p.name);
      if (!values.contains(p.name)) continue;
      EXPECT_EQ(values[p.name].get<double>(), p.get(c)) << p.name;
      EXPECT_EQ(values[p.name].is_number_integer(), p.integral) << p.name;
    }
    std::set<std::string> written;
    for (auto it = values.begin(); it != values.end(); ++it) written.insert(it.key());
    EXPECT_EQ(written, expected) << format;
    EXPECT_EQ(values["nodes"], c.node_count());
  }
  EXPECT_EQ(platform_values(load_platform_config(repo("platforms/ncube2.json"))).dump(),
            R"({"dimension":6,"hop_latency":1e-06,"link_bandwidth":2200000.0,)"
            R"("node_memory":4194304.0,"node_speed":2500000.0,"nodes":64,)"
            R"("receive_overhead":8e-05,"send_overhead":8e-05})");
}

// A two-node SimGrid platform: each node host's speed and <prop>s from `value(host, p)` ("" to
// leave the property out), a link between them.
std::string two_nodes(const std::function<std::string(int, const MachineParameter&)>& value) {
  std::string hosts;
  for (int k = 0; k < 2; ++k) {
    std::string speed = "1Gf", props;
    for (const MachineParameter& p : machine_parameters()) {
      const std::string v = value(k, p);
      if (p.xml == XmlForm::kHostSpeed) speed = v + "f";
      if (p.xml == XmlForm::kProperty && !v.empty())
        props += "      <prop id=\"" + std::string(p.name) + "\" value=\"" + v + "\"/>\n";
    }
    hosts += "    <host id=\"node-" + std::to_string(k) + "\" speed=\"" + speed + "\">\n" + props +
             "    </host>\n";
  }
  return "<?xml version='1.0'?>\n<!DOCTYPE platform SYSTEM \"https://simgrid.org/simgrid.dtd\">\n"
         "<platform version=\"4.1\">\n  <zone id=\"z\" routing=\"Full\">\n" +
         hosts +
         "    <link id=\"l\" bandwidth=\"1MBps\" latency=\"1us\"/>\n"
         "    <route src=\"node-0\" dst=\"node-1\"><link_ctn id=\"l\"/></route>\n"
         "  </zone>\n</platform>\n";
}

// A value inside the parameter's range, distinct per parameter.
std::string inside(const MachineParameter& p) {
  const double v = p.low > 0 ? p.low * 2 : p.high / 4;
  return text(p.whole ? std::floor(v) : v);
}

// What reading `xml` gives, in a child process (SimGrid allows one platform per process):
// the error, or "ok" followed by each carried parameter's value.
std::string xml_outcome(const std::string& xml) {
  const std::string path = write_temp(xml, ".xml");
  int ends[2];
  if (pipe(ends) != 0) return "pipe failed";
  const pid_t child = fork();
  if (child == 0) {
    close(ends[0]);
    std::string said;
    try {
      const PlatformConfig c = read_simgrid_platform_file(path, {"--log=root.thres:critical"});
      said = "ok nodes=" + std::to_string(c.node_count());
      for (const MachineParameter& p : machine_parameters()) said += std::string(" ") + p.name + "=" + text(p.get(c));
    } catch (const InputError& e) {
      said = e.what();
    }
    if (write(ends[1], said.data(), said.size()) < 0) _exit(1);
    _exit(0);
  }
  close(ends[1]);
  std::string said;
  char buffer[4096];
  for (ssize_t n; (n = read(ends[0], buffer, sizeof buffer)) > 0;) said.append(buffer, std::size_t(n));
  close(ends[0]);
  int status = 0;
  waitpid(child, &status, 0);
  return said;
}

TEST(MachineParameters, TheXmlReaderReadsEveryParameterItCarries) {
  const std::string said = xml_outcome(two_nodes([](int, const MachineParameter& p) { return inside(p); }));
  std::string expected = "ok nodes=2";
  for (const MachineParameter& p : machine_parameters())
    expected += std::string(" ") + p.name + "=" +
                (p.xml == XmlForm::kInterconnect ? "0" : text(std::stod(inside(p))));
  EXPECT_EQ(said, expected);
  // A <cluster>'s <prop>s are its zone's: platforms/ncube2.xml gives them so.
  const PlatformConfig json = load_platform_config(repo("platforms/ncube2.json"));
  std::string ncube2 = "ok nodes=64";
  for (const MachineParameter& p : machine_parameters())
    ncube2 += std::string(" ") + p.name + "=" + (p.xml == XmlForm::kInterconnect ? "0" : text(p.get(json)));
  EXPECT_EQ(xml_outcome(read_text(repo("platforms/ncube2.xml"))), ncube2);
}

TEST(MachineParameters, TheXmlReaderChecksEveryParameterOnEveryNode) {
  for (const MachineParameter& p : machine_parameters()) {
    if (p.xml == XmlForm::kInterconnect) continue;
    const std::string item = p.xml == XmlForm::kHostSpeed
                                 ? std::string("speed (") + p.name + "): "
                                 : std::string("property \"") + p.name + "\": ";
    const auto with = [&](int host, const std::string& v) {
      return xml_outcome(two_nodes([&](int k, const MachineParameter& q) {
        return k == host && q.name == p.name ? v : inside(q);
      }));
    };
    // node-1 unlike node-0
    const double other = std::stod(inside(p)) * 1.5;
    EXPECT_NE(with(1, text(other)).find("host \"node-1\": " + item + nlohmann::json(other).dump() +
                                        " differs from node-0's"),
              std::string::npos)
        << p.name;
    // out of the range, on node-0
    EXPECT_NE(with(0, text(p.high * 2)).find("host \"node-0\": " + item + "value "), std::string::npos)
        << p.name;
    EXPECT_NE(with(0, text(p.high * 2)).find(" is above " + nlohmann::json(p.high).dump()),
              std::string::npos)
        << p.name;
    if (p.xml != XmlForm::kProperty) continue;
    if (p.optional)  // left out on one node only: the nodes differ
      EXPECT_NE(with(1, "").find("host \"node-1\": " + item + nlohmann::json(0.0).dump() + " differs"),
                std::string::npos)
          << p.name;
    else
      EXPECT_NE(with(1, "").find("host \"node-1\": " + item + "missing"), std::string::npos)
          << p.name;
    EXPECT_NE(with(0, "fast").find("host \"node-0\": " + item + "\"fast\" is not a number"),
              std::string::npos)
        << p.name;
  }
}

}  // namespace
}  // namespace ncube

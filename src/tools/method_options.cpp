#include "tools/method_options.h"

#include <stdexcept>
#include <string>
#include <string_view>

#include "counts/work_counts.h"
#include "radiosity/form_factor_methods.h"

namespace ncube {

namespace {

// The flag of the option the result file records in `field`.
std::string flag_of(const OptionTable& table, const std::string& field) {
  for (const nlohmann::json& entry : table.describe())
    if (entry.contains("field") && entry["field"] == field) return entry["flag"];
  throw std::logic_error("no option records \"" + field + "\"");
}

// The values a choice option recording `field` takes (std::logic_error for any other option:
// a value recorded unless at one value needs the list of the others).
nlohmann::json values_of(const OptionTable& table, const std::string& field) {
  for (const nlohmann::json& entry : table.describe())
    if (entry.contains("field") && entry["field"] == field && entry.contains("values"))
      return entry["values"];
  throw std::logic_error("no choice option records \"" + field + "\"");
}

}  // namespace

void annotate_form_factor_methods(OptionTable& table) {
  const MethodRegistry<FormFactorMethod>& methods = form_factor_methods();
  nlohmann::json others = nlohmann::json::array();
  nlohmann::json rules = nlohmann::json::object();
  for (const FormFactorMethod& method : methods.all()) {
    if (method.name != methods.paper_default().name) others.push_back(method.name);
    nlohmann::json rule = {{"visibility_processors", bool(method.gather_visible)},
                           {"traces_rays", method.traces_rays},
                           {"options", method.own_options}};
    if (!method.gather_visible) rule["reason"] = method.without_visibility_processors;
    // The counters only this method's runs write (FormFactorMethod::counter_prefix), with
    // what each counts: docs/result-format.md's table of them is written from these.
    nlohmann::json counters = nlohmann::json::array();
#define NCUBE_METHOD_COUNTER(member, cost, doc)                                     \
  if (!method.counter_prefix.empty() && std::string_view(#member).rfind(method.counter_prefix, 0) == 0) \
    counters.push_back({{"counter", #member}, {"counts", doc}});
    NCUBE_WORK_COUNTERS(NCUBE_METHOD_COUNTER)
#undef NCUBE_METHOD_COUNTER
    if (!counters.empty()) rule["counters"] = counters;
    rules[method.name] = rule;
    for (const std::string& field : method.own_options) {
      nlohmann::json when = {{"form_factors", nlohmann::json::array({method.name})}};
      // Recorded unless at the value every run had before the option: when at any other.
      for (const auto& [unless_field, unless_value] : method.recorded_unless) {
        if (unless_field != field) continue;
        nlohmann::json others = nlohmann::json::array();
        for (const nlohmann::json& value : values_of(table, field))
          if (value != unless_value) others.push_back(value);
        when[field] = others.size() == 1 ? others[0] : others;
      }
      table.annotate(flag_of(table, field), "recorded_when", when);
    }
  }
  table.annotate("--form-factors", "recorded_when", {{"form_factors", others}});
  table.annotate("--form-factors", "methods", rules);
}

}  // namespace ncube

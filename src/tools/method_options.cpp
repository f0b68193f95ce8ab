#include "tools/method_options.h"

#include <stdexcept>
#include <string>

#include "radiosity/form_factor_methods.h"

namespace ncube {

namespace {

// The flag of the option the result file records in `field`.
std::string flag_of(const OptionTable& table, const std::string& field) {
  for (const nlohmann::json& entry : table.describe())
    if (entry.contains("field") && entry["field"] == field) return entry["flag"];
  throw std::logic_error("no option records \"" + field + "\"");
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
    rules[method.name] = rule;
    for (const std::string& field : method.own_options)
      table.annotate(flag_of(table, field), "recorded_when",
                     {{"form_factors", nlohmann::json::array({method.name})}});
  }
  table.annotate("--form-factors", "recorded_when", {{"form_factors", others}});
  table.annotate("--form-factors", "methods", rules);
}

}  // namespace ncube

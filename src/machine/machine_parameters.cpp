#include "machine/machine_parameters.h"

#include <type_traits>

#include "machine/platform_config.h"

namespace ncube {

const std::vector<MachineParameter>& machine_parameters() {
  static const std::vector<MachineParameter> parameters = {
#define NCUBE_MACHINE_PARAMETER(name, type, unit, low, high, whole, xml, optional, doc)          \
  {#name, unit, low, high, whole, XmlForm::xml, optional, doc, std::is_integral_v<type>,       \
   [](const PlatformConfig& p) { return double(p.name); },                                     \
   [](PlatformConfig& p, double value) { p.name = static_cast<type>(value); }},
      NCUBE_MACHINE_PARAMETERS(NCUBE_MACHINE_PARAMETER)
#undef NCUBE_MACHINE_PARAMETER
  };
  return parameters;
}

ParameterSpec parameter_spec(const MachineParameter& parameter) {
  return {parameter.name, parameter.low, parameter.whole, parameter.high, parameter.unit,
          parameter.optional};
}

bool carried_by(const MachineParameter& parameter, const std::string& format) {
  return format == "json" || parameter.xml != XmlForm::kInterconnect;
}

const std::map<std::string, std::string>& default_network_model() {
  static const std::map<std::string, std::string> settings = {
#define NCUBE_NETWORK_SETTING(name, value, why) {name, value},
      NCUBE_NETWORK_MODEL(NCUBE_NETWORK_SETTING)
#undef NCUBE_NETWORK_SETTING
  };
  return settings;
}

}  // namespace ncube

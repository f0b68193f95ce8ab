// The documented-parameter JSON files of platforms/ (machine and cost model). Each file is
//   {"description": "...", "parameters": {"<name>": {"value": <number>, "unit": "...",
//                                                    "doc": "...", "source": "..."}, ...}}
// so that every number carries its meaning and origin next to it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace ncube {

struct ParameterSpec {
  std::string name;
  double min_value;   // inclusive lower bound
  bool integer;       // must be a whole number
  double max_value = 1e300;  // inclusive upper bound
};

// Largest parameter file read, in bytes.
constexpr std::size_t kMaxParameterFileBytes = std::size_t(1) << 20;

// Reads `path` and returns the value of every parameter in `specs`. Throws InputError naming
// the file and the parameter when one is missing, unknown, not a finite number, out of range
// or (for integers) fractional.
// `sections` names further top-level keys the file may have (read by the caller).
std::map<std::string, double> read_parameter_file(const std::string& path,
                                                  const std::vector<ParameterSpec>& specs,
                                                  const std::vector<std::string>& sections = {});

}  // namespace ncube

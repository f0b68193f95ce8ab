// The documented-parameter JSON files of platforms/ (machine and cost model). Each file is
//   {"description": "...", "parameters": {"<name>": {"value": <number>, "unit": "...",
//                                                    "doc": "...", "source": "..."}, ...}}
// so that every number carries its meaning and origin next to it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "util/input_file.h"

namespace ncube {

struct ParameterSpec {
  std::string name;
  double min_value;   // inclusive lower bound
  bool integer;       // must be a whole number
  double max_value = 1e300;  // inclusive upper bound
  const char* unit = nullptr;  // the "unit" a file may give (any when nullptr)
  bool optional = false;       // may be left out (then absent from the values read)
};

// "" when `value` (as the file wrote it: `written`) is within the spec, else why not:
// "value 40 is above 13", "value 2.5 must be a whole number". The SimGrid XML reader holds a
// node's properties to the same specs.
std::string value_problem(const ParameterSpec& spec, double value, const std::string& written);

// Largest parameter file read, in bytes.
constexpr std::size_t kMaxParameterFileBytes = kPlatformFile.max_bytes;
static_assert(kCostModelFile.max_bytes == kMaxParameterFileBytes);

// Reads `path` as `kind` (kPlatformFile or kCostModelFile: util/input_file.h) and returns
// the value of every parameter in `specs` (an optional one only when the file gives it). Throws InputError naming the file and the
// parameter when one is missing, unknown, not a finite number, out of range, (for
// integers) fractional, or given in another unit than the spec's.
// `sections` names further top-level keys the file may have (read by the caller).
std::map<std::string, double> read_parameter_file(const std::string& path, const InputKind& kind,
                                                  const std::vector<ParameterSpec>& specs,
                                                  const std::vector<std::string>& sections = {});

}  // namespace ncube

// Species presets: JSON files in core/tree/presets/, compiled into the core for CLI and web alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "params/param_table.h"

namespace niwa {

struct Preset {
  std::string name, title, source;
  int years = 10;
  uint64_t seed = 1;
  ParamSet params;
};

const std::vector<Preset>& Presets();
const Preset* FindPreset(const std::string& name);
// "binary, sakura, ..." for error messages.
std::string PresetNames();

}  // namespace niwa

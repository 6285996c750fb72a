// Species presets: JSON files in core/tree/presets/, compiled into the core for CLI and web alike.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "tree/tree_params.h"

namespace niwa {

struct Preset {
  std::string name, title, source;
  int years = 10;
  uint64_t seed = 1;
  TreeParams params;
};

const std::vector<Preset>& Presets();
const Preset* FindPreset(const std::string& name);
// Top-level keys of a preset file beside its parameters (also allowed in a --params file).
const std::vector<std::string_view>& PresetFileFields();
// "binary, sakura, ..." for error messages.
std::string PresetNames();

}  // namespace niwa

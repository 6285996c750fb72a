// The tree state as JSON for the bindings (StateFromJson, StateObject, ParamsObject), defined in
// tree_bindings.cpp and shared with common_bindings.cpp's presets and hash codec.
// Does not: decide anything itself; every check is the core's (FindPreset, ParamSet::Set,
// ParsePrune).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "io/url_codec.h"
#include "params/param_table.h"

namespace niwa {

// {"key": value} for every parameter (full values), as a JSON object.
nlohmann::ordered_json ParamsObject(const ParamSet& params);

// {preset, seed, years, params, prunes, camera} of a state.
nlohmann::ordered_json StateObject(const TreeState& state);

// Reads {preset, seed, years, params:{key:value}, prunes:["12:b42"], camera} into a TreeState.
// Missing fields take the preset's values; params are applied on top of the preset's parameters.
// Returns "" or one error line; state is only meaningful on success.
std::string StateFromJson(const std::string& text, TreeState* state);

}  // namespace niwa

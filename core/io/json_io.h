// JSON reading and writing of parameters, presets and whole trees (nlohmann-json).
#pragma once

#include <string>

#include "params/param_table.h"
#include "tree/tree.h"

namespace niwa {

// Applies {"key": number, ...} (or {"params": {...}}) onto params. Returns "" or one error line
// naming the field and its allowed range; params is unchanged on error.
std::string ApplyParamsJson(const std::string& text, ParamSet* params);
// {"key": value, ...} for every parameter, in table order.
std::string ParamsToJson(const ParamSet& params, int indent = 2);
// The whole tree: settings, parameters and every branch with its internodes, buds, leaves and
// flowers.
std::string TreeToJson(const Tree& tree);
// The parameter table itself, for the web panel: [{key, symbol, unit, default, min, max, ...}].
std::string ParamTableJson();

}  // namespace niwa

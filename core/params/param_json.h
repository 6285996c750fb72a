// JSON of parameter values and of a parameter table itself, for any table (nlohmann-json).
// Does not: know any study's rows or other fields of a study's state (core/<study>/*_state).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "params/json_guard.h"  // CheckJsonKeys, which every reader here runs first
#include "params/param_table.h"

namespace niwa {

// Applies {"key": number, ...} (or {"params": {...}}) onto params. `ignored` lists top-level
// keys that may sit beside the values (a preset's "name", "years", ...); with a "params" object,
// any other top-level key that is not ignored is refused (not silently dropped), and so is a key
// given twice. Numeric strings go through the one strict parser. The error names the field and its
// allowed range; params is unchanged on error.
Status ApplyParamsJson(const std::string& text, ParamSet* params,
                       const std::vector<std::string_view>& ignored = {});
// {"key": value, ...} for every row, in table order (indent as nlohmann's dump: -1 one line).
std::string ParamsToJson(const ParamSet& params, int indent = 2);
// The table for the web panel: [{key, symbol, unit, default, min, max, integer, group,
// group_title, stage, help}], in row order.
std::string ParamTableJson(const ParamTable& table);

}  // namespace niwa

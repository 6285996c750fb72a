// JSON reading and writing of parameter values and tables with nlohmann-json.
#include "params/param_json.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "base/echo.h"
#include "params/param_text.h"

namespace niwa {

using nlohmann::json;
using nlohmann::ordered_json;

Status ApplyParamsJson(const std::string& text, ParamSet* params,
                       const std::vector<std::string_view>& ignored) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "params"));
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) return Status::Error("params", "malformed JSON");
  if (!document.is_object()) {
    return Status::Error("params", "the JSON must be an object of key: number");
  }
  const json& values = document.contains("params") ? document["params"] : document;
  if (!values.is_object()) {
    return Status::Error("params", "'params' must be an object of key: number");
  }
  if (&values != &document) {  // beside "params", only the ignored fields may stand
    for (auto it = document.begin(); it != document.end(); ++it) {
      if (it.key() == "params") continue;
      if (std::find(ignored.begin(), ignored.end(), it.key()) != ignored.end()) continue;
      return Status::Error(Echo(it.key()),
                           "beside a \"params\" object; put every parameter inside \"params\"");
    }
  }
  ParamSet result = *params;
  for (auto it = values.begin(); it != values.end(); ++it) {
    std::optional<std::size_t> row = params->table().Find(it.key());
    if (!row) {
      if (&values == &document &&
          std::find(ignored.begin(), ignored.end(), it.key()) != ignored.end()) {
        continue;
      }
      return Status::Error("", "unknown parameter '" + Echo(it.key()) + "'");
    }
    if (!it.value().is_number()) {
      return Status::Error(it.key(), "must be " + RangeText(params->table().row(*row)));
    }
    NIWA_RETURN_IF_ERROR(result.Set(*row, it.value().get<double>()));
  }
  *params = result;
  return Status::Ok();
}

std::string ParamsToJson(const ParamSet& params, int indent) {
  ordered_json out = ordered_json::object();
  for (std::size_t i = 0; i < params.size(); ++i) out[params.table().row(i).key] = params.Get(i);
  return out.dump(indent);
}

std::string ParamTableJson(const ParamTable& table) {
  ordered_json out = ordered_json::array();
  for (const ParamSpec& s : table) {
    out.push_back({{"key", s.key},
                   {"symbol", s.symbol},
                   {"unit", s.unit},
                   {"default", s.default_value},
                   {"min", s.min_value},
                   {"max", s.max_value},
                   {"integer", s.integer},
                   {"group", s.group},
                   {"group_title", table.GroupTitle(s.group)},
                   {"stage", StageName(s.stage)},
                   {"help", s.help}});
  }
  return out.dump();
}

}  // namespace niwa

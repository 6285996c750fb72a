// The garden's wind settings: its rows of the tree table's "wind" group (see garden_wind_rows.h).
#include "compose/garden_wind_rows.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "math/det_math.h"
#include "params/param_json.h"
#include "params/param_text.h"
#include "sway/sway.h"

namespace niwa::compose {

namespace {

bool IsWindGroupRow(const ParamSpec& row) { return std::string(row.group) == "wind"; }

}  // namespace

const std::vector<GardenWindValue>& GardenWindDefaults() {
  static const std::vector<GardenWindValue> kDefaults = {
      {"wind_speed", 8},       {"wind_dir", 0},         {"gust_off", 600},       {"duration", 600},
      {"gust_front_speed", 4}, {"wind_variation", 0.4}, {"wind_wavelength", 25}, {"wind_period", 5},
  };
  return kDefaults;
}

TreeParams GardenWindBase() {
  TreeParams wind;
  for (const GardenWindValue& v : GardenWindDefaults()) {
    const std::optional<std::size_t> row = wind.table().Find(v.key);
    if (row) (void)wind.Set(*row, v.value);
  }
  return wind;
}

bool IsGardenWindKey(std::string_view key) {
  const ParamTable& table = TreeParams().table();
  const std::optional<std::size_t> row = table.Find(key);
  return row && IsWindGroupRow(table.row(*row)) && key != "gust_on";
}

std::vector<std::string> GardenWindKeys() {
  const ParamTable& table = TreeParams().table();
  std::vector<std::string> keys;
  for (std::size_t r = 0; r < table.size(); ++r)
    if (IsGardenWindKey(table.row(r).key)) keys.emplace_back(table.row(r).key);
  return keys;
}

Result<ParamSet> GardenWindRows(double size, const ParamSet& base, const std::string& json) {
  ParamSet wind = TreeParams();
  for (std::size_t r = 0; r < wind.size() && r < base.size(); ++r)
    if (IsGardenWindKey(wind.table().row(r).key)) NIWA_RETURN_IF_ERROR(wind.Set(r, base.Get(r)));
  bool gust_on_given = false;
  if (!json.empty()) {
    const nlohmann::json j = nlohmann::json::parse(json, nullptr, false);
    if (j.is_discarded() || !j.is_object())
      return Status::Error("wind", "must be a JSON object of the wind rows");
    for (auto it = j.begin(); it != j.end(); ++it) {
      const std::optional<std::size_t> row = wind.table().Find(it.key());
      if (!row || !IsWindGroupRow(wind.table().row(*row)))
        return Status::Error("wind", "'" + it.key().substr(0, 40) +
                                         "' is not a wind row (niwa params tree, group wind)");
      gust_on_given = gust_on_given || it.key() == "gust_on";
    }
    NIWA_RETURN_IF_ERROR(ApplyParamsJson(json, &wind));
  }
  if (!gust_on_given) {
    // The upwind edge of the square: its corner farthest against the wind, |cos| + |sin| half
    // sides upwind of the origin.
    const double front = wind.Get(TreeParam::kGustFrontSpeed);
    double s = 0, c = 1;
    det::SinCos(wind.Get(TreeParam::kWindDir) * (det::kPi / 180.0), &s, &c);
    const double upwind = 0.5 * size * (std::abs(c) + std::abs(s));
    const double latest = wind.table().row(static_cast<std::size_t>(TreeParam::kGustOn)).max_value;
    if (front > 0 && upwind / front > latest)
      return Status::Error("gust_front_speed",
                           FormatNumber(front) + " m/s takes more than " + FormatNumber(latest) +
                               " s from the garden's edge to its centre; must be 0 or at least " +
                               FormatNumber(std::ceil(upwind / latest * 1000) / 1000) + " m/s");
    NIWA_RETURN_IF_ERROR(wind.Set(TreeParam::kGustOn, front > 0 ? upwind / front : 0.0));
  }
  NIWA_RETURN_IF_ERROR(CheckSwayParams(wind));
  return wind;
}

Result<ParamSet> GardenWindRows(double size, const std::string& json) {
  return GardenWindRows(size, GardenWindBase(), json);
}

}  // namespace niwa::compose

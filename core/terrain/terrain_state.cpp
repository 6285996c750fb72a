// Terrain state from JSON and share-link hashes, over params/param_json and io/hash_codec.
#include "terrain/terrain_state.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>

#include "io/hash_codec.h"
#include "params/param_json.h"
#include "params/param_text.h"
#include "terrain/seeds.h"

namespace niwa::terrain {
namespace {

const char* kPresetNames =
    "simple, midpoint, fourier, improved, fig9a-c, fig10a-b, fig13a-c, fig14a-c, fig15 or fig16";

std::string SeedNames() {
  std::string names;
  const std::vector<SeedInfo>& seeds = BuiltinSeeds();
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    if (i > 0) names += i + 1 == seeds.size() ? " or " : ", ";
    names += seeds[i].name;
  }
  return names;
}

// "x,y;x,y;..." -> points; nullopt when any item is not two finite numbers.
std::optional<Ring> ParsePointList(std::string_view text) {
  Ring ring;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(';', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view item = text.substr(start, end - start);
    if (!item.empty()) {
      const std::size_t comma = item.find(',');
      if (comma == std::string_view::npos) return std::nullopt;
      std::optional<double> x = ParseNumber(item.substr(0, comma));
      std::optional<double> y = ParseNumber(item.substr(comma + 1));
      if (!x || !y) return std::nullopt;
      ring.push_back({*x, *y});
      if (ring.size() > kMaxStatePoints) return ring;  // SetTerrainPoints names the limit
    }
    start = end + 1;
  }
  return ring;
}

}  // namespace

Result<TerrainParams> BaseParams(std::string_view preset, std::string_view builtin) {
  TerrainParams p;
  if (!builtin.empty()) {
    bool found = false;
    for (const SeedInfo& info : BuiltinSeeds()) {
      if (info.name != builtin) continue;
      found = true;
      NIWA_RETURN_IF_ERROR(p.Set(TerrainParam::kD, info.d));
      NIWA_RETURN_IF_ERROR(p.Set(TerrainParam::kDh, info.dh));
      NIWA_RETURN_IF_ERROR(p.Set(TerrainParam::kH0, info.h0));
    }
    if (!found) {
      return Status::Error("builtin",
                           "'" + Printable(builtin) + "' is unknown; must be " + SeedNames());
    }
  }
  if (!preset.empty()) {
    Status s = ApplyPreset(std::string(preset), &p);
    if (!s.ok()) {
      return Status::Error("preset",
                           "'" + Printable(preset) + "' is unknown; must be " + kPresetNames);
    }
  }
  return p;
}

Status SetTerrainPreset(std::string_view name, TerrainState* state) {
  Result<TerrainParams> p = BaseParams(name, state->builtin);
  if (!p.ok()) return p.status();
  state->preset = std::string(name);
  state->params = *p;
  return Status::Ok();
}

Status SetTerrainBuiltin(std::string_view name, TerrainState* state) {
  Result<TerrainParams> p = BaseParams("", name);
  if (!p.ok()) return p.status();
  state->builtin = std::string(name);
  state->points.clear();
  return Status::Ok();
}

Status SetTerrainSeed(double seed, TerrainState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("seed", seed, 0, kMaxTerrainSeed, true));
  state->seed = static_cast<uint64_t>(seed);
  return Status::Ok();
}

Status SetTerrainPoints(const Ring& points, TerrainState* state) {
  if (points.size() < 3 || points.size() > kMaxStatePoints) {
    return Status::Error("contour", std::to_string(points.size()) + " points; must be 3 to " +
                                        std::to_string(kMaxStatePoints) +
                                        " (a longer one goes in a contour file)");
  }
  for (const Vec2& v : points) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || std::fabs(v.x) > 1e6 ||
        std::fabs(v.y) > 1e6) {
      return Status::Error("contour",
                           "a point is not finite or beyond 1e6 m; must be numbers in "
                           "[-1000000, 1000000]");
    }
  }
  state->builtin.clear();
  state->points = points;
  return Status::Ok();
}

Result<Ring> StateSeed(const TerrainState& state) {
  if (!state.builtin.empty()) return BuiltinSeed(state.builtin);
  if (state.points.size() < 3)
    return Status::Error("contour", "no seed; must be a builtin or 3+ points");
  return state.points;
}

Status ApplyTerrainStateJson(const std::string& text, TerrainState* state) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "params"));
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    return Status::Error("params", "not a JSON object; must be {preset, builtin, contour, params}");
  }
  TerrainState next = *state;
  // The seed: a state field, or (a file of before) a row of "params"; it leaves the text the
  // parameters are read from.
  const bool params_seed =
      j.contains("params") && j["params"].is_object() && j["params"].contains("seed");
  if (params_seed && j.contains("seed")) {
    return Status::Error("seed", "given at the top and in params; must be given once");
  }
  if (j.contains("seed") || params_seed) {
    const nlohmann::json& v = params_seed ? j["params"]["seed"] : j["seed"];
    std::optional<double> x;
    if (v.is_number()) x = v.get<double>();
    if (v.is_string()) x = ParseNumber(v.get<std::string>());
    if (!x) return Status::Error("seed", "must be a whole number in [0, 4294967295]");
    NIWA_RETURN_IF_ERROR(SetTerrainSeed(*x, &next));
    if (params_seed) j["params"].erase("seed");
  }
  if (j.contains("builtin") && !j["builtin"].is_null()) {
    if (!j["builtin"].is_string()) return Status::Error("builtin", "must be a seed name");
    const std::string b = j["builtin"].get<std::string>();
    if (!b.empty()) NIWA_RETURN_IF_ERROR(SetTerrainBuiltin(b, &next));
  }
  if (j.contains("contour")) {
    const nlohmann::json& c = j["contour"];
    if (!c.is_array()) return Status::Error("contour", "must be [[x, y], ...] in metres");
    Ring ring;
    for (const nlohmann::json& p : c) {
      if (!p.is_array() || p.size() != 2 || !p[0].is_number() || !p[1].is_number())
        return Status::Error("contour", "a point is not [x, y] numbers; must be [[x, y], ...]");
      ring.push_back({p[0].get<double>(), p[1].get<double>()});
    }
    NIWA_RETURN_IF_ERROR(SetTerrainPoints(ring, &next));
  }
  if (j.contains("preset")) {
    if (!j["preset"].is_string()) return Status::Error("preset", "must be a preset name");
    NIWA_RETURN_IF_ERROR(SetTerrainPreset(j["preset"].get<std::string>(), &next));
  }
  NIWA_RETURN_IF_ERROR(ApplyParamsJson(params_seed ? j.dump() : text, &next.params,
                                       {"preset", "builtin", "contour", "seed"}));
  *state = next;
  return Status::Ok();
}

std::string TerrainStateJson(const TerrainState& state) {
  nlohmann::json j;
  j["preset"] = state.preset;
  j["builtin"] = state.builtin;
  j["seed"] = state.seed;
  if (state.builtin.empty()) {
    nlohmann::json pts = nlohmann::json::array();
    for (const Vec2& v : state.points) pts.push_back({v.x, v.y});
    j["contour"] = pts;
  }
  j["params"] = nlohmann::json::parse(ParamsToJson(state.params, -1));
  return j.dump();
}

void ApplyTerrainHash(std::string_view hash, std::string_view prefix, TerrainState* state,
                      std::vector<std::string>* notices) {
  const std::string pre(prefix);
  HashPairs pairs = SplitHash(hash, notices);  // too long or a repeated key: nothing, a notice
  // The seed and the preset first, so the parameters go on top of them whatever their order.
  for (const auto& [key, value] : pairs) {
    if (key == pre + "builtin") {
      Status s = SetTerrainBuiltin(value, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
    } else if (key == pre + "contour") {
      std::optional<Ring> ring = ParsePointList(value);
      Status s = ring ? SetTerrainPoints(*ring, state)
                      : Status::Error("contour", "not x,y;x,y;... numbers");
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
    } else if (key == pre + "seed") {
      std::optional<double> x = ParseNumber(value);
      Status s = x ? SetTerrainSeed(*x, state)
                   : Status::Error("seed", "'" + Printable(value) + "' is not a number");
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
    }
  }
  bool preset_given = false;
  for (const auto& [key, value] : pairs) {
    if (key != pre + "preset") continue;
    preset_given = true;
    Status s = SetTerrainPreset(value, state);
    if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
  }
  if (!preset_given) {
    Result<TerrainParams> base = BaseParams(state->preset, state->builtin);
    if (base.ok()) state->params = *base;
  }
  for (const auto& [key, value] : pairs) {
    if (key == pre + "preset" || key == pre + "builtin" || key == pre + "contour" ||
        key == pre + "seed")
      continue;
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    if (prefix.empty() || key.rfind(pre, 0) == 0)
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
  }
}

std::string EncodeContourPoints(const Ring& points) {
  std::string out;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) out += ';';
    out += FormatNumber(points[i].x) + "," + FormatNumber(points[i].y);
  }
  return out;
}

std::string EncodeTerrainHash(const TerrainState& state, std::string_view prefix) {
  const std::string pre(prefix);
  std::string out;
  if (!state.preset.empty()) out += pre + "preset=" + state.preset + "&";
  if (!state.builtin.empty()) {
    out += pre + "builtin=" + state.builtin;
  } else {
    out += pre + "contour=" + EncodeContourPoints(state.points);
  }
  Result<TerrainParams> found = BaseParams(state.preset, state.builtin);
  const TerrainParams base = found.ok() ? *found : TerrainParams();
  // The rows before max_levels, the seed where its row stood, then the rest.
  // (each base takes the state's values of the rows the other half writes).
  TerrainParams before = base, after = base;
  for (std::size_t row = 0; row < state.params.size(); ++row) {
    TerrainParams& same = row < static_cast<std::size_t>(TerrainParam::kMaxLevels) ? after : before;
    (void)same.Set(row, state.params.Get(row));
  }
  out += EncodeChangedParams(state.params, before, prefix);
  if (state.seed != kDefaultTerrainSeed)
    out += "&" + pre + "seed=" + FormatNumber(static_cast<double>(state.seed));
  out += EncodeChangedParams(state.params, after, prefix);
  return out;
}

}  // namespace niwa::terrain

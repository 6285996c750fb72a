// The tree state resolver: setters, state JSON and share-link hash over io/hash_codec.
#include "tree/tree_state.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <optional>

#include "io/hash_codec.h"
#include "params/param_json.h"
#include "tree/presets.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

const Preset& PresetOrAbort(const char* name) {
  const Preset* preset = FindPreset(name);
  if (!preset) std::abort();  // the default preset is embedded; tested by the preset tests
  return *preset;
}

void ResetTo(const Preset& preset, TreeState* state) {
  state->preset = preset.name;
  state->params = preset.params;
  state->seed = preset.seed;
  state->years = preset.years;
}

// "" or "yaw,pitch,distance,tx,ty,tz": six decimal numbers within the page camera's ranges
// (tree.h).
bool CameraText(std::string_view text) {
  if (text.empty()) return true;  // no camera: the page frames the tree
  if (text.size() >= 128) return false;
  double v[6];
  std::size_t start = 0;
  for (int i = 0; i < 6; ++i) {
    std::size_t comma = text.find(',', start);
    if ((i < 5) != (comma != std::string_view::npos)) return false;
    std::optional<double> x = ParseNumber(text.substr(start, comma - start));
    if (!x) return false;
    v[i] = *x;
    start = comma + 1;
  }
  auto within = [](double x, double lo, double hi) { return x >= lo && x <= hi; };
  return within(v[0], -kMaxYaw, kMaxYaw) && within(v[1], kMinPitch, kMaxPitch) &&
         within(v[2], kMinDistance, kMaxDistance) && within(v[3], -kMaxTarget, kMaxTarget) &&
         within(v[4], -kMaxTarget, kMaxTarget) && within(v[5], -kMaxTarget, kMaxTarget);
}

const char* const kCameraRule =
    "must be yaw,pitch,distance,tx,ty,tz: yaw in [-1000, 1000], pitch in [-0.1, 1.5], distance in "
    "[0.2, 400], each target coordinate in [-10000, 10000]";

// A number from a JSON number or a numeric string; nullopt otherwise.
std::optional<double> JsonNumber(const json& value) {
  if (value.is_number()) return value.get<double>();
  if (value.is_string()) return ParseNumber(value.get<std::string>());
  return std::nullopt;
}

Status SetWhole(const json& value, const char* field, double max, Status (*set)(double, TreeState*),
                TreeState* state) {
  std::optional<double> number = JsonNumber(value);
  if (!number) return Status::Error(field, "must be " + RangeText(0, max, true));
  return set(*number, state);
}

Status ApplyParamsObject(const json& params, ParamSet* values) {
  if (!params.is_object()) return Status::Error("params", "must be an object of key: value");
  for (auto it = params.begin(); it != params.end(); ++it) {
    std::optional<std::size_t> row = values->table().Find(it.key());
    if (!row) return Status::Error("", "unknown parameter '" + it.key().substr(0, 64) + "'");
    if (it.value().is_number()) {
      NIWA_RETURN_IF_ERROR(values->Set(*row, it.value().get<double>()));
    } else if (it.value().is_string()) {
      NIWA_RETURN_IF_ERROR(values->SetFromText(it.key(), it.value().get<std::string>()));
    } else if (it.value().is_boolean()) {
      NIWA_RETURN_IF_ERROR(values->Set(*row, it.value().get<bool>() ? 1.0 : 0.0));
    } else {
      return Status::Error(it.key(), "must be " + RangeText(values->table().row(*row)));
    }
  }
  return Status::Ok();
}

// seed or years from a hash: dropped when not a whole number, clamped into [0, max].
template <typename T>
void HashWhole(const std::string& key, const std::string& value, double max, T* out,
               std::vector<std::string>* notices) {
  std::optional<double> number = ParseNumber(value);
  if (!number || std::floor(*number) != *number) {
    notices->push_back(key + ": '" + Printable(value) +
                       "' dropped, must be a whole number in [0, " + FormatNumber(max) + "]");
    return;
  }
  double clamped = std::min(max, std::max(0.0, *number));
  if (clamped != *number) {
    notices->push_back(key + ": clamped to " + FormatNumber(clamped) + ", must be in [0, " +
                       FormatNumber(max) + "]");
  }
  *out = static_cast<T>(clamped);
}

}  // namespace

TreeState::TreeState() { ResetTo(PresetOrAbort(kDefaultPreset), this); }

Status SetStatePreset(std::string_view name, TreeState* state) {
  const Preset* preset = FindPreset(std::string(name));
  if (!preset) {
    return Status::Error("preset",
                         "unknown '" + Printable(name) + "', must be one of " + PresetNames());
  }
  ResetTo(*preset, state);
  return Status::Ok();
}

Status SetStateYears(double years, TreeState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("years", years, 0, kMaxYears, true));
  state->years = static_cast<int>(years);
  return Status::Ok();
}

Status SetStateSeed(double seed, TreeState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("seed", seed, 0, kMaxSeed, true));
  state->seed = static_cast<uint64_t>(seed);
  return Status::Ok();
}

Status AddStatePrune(std::string_view text, TreeState* state) {
  if (state->prunes.size() >= kMaxPrunes) {
    return Status::Error("prune", "at most " + std::to_string(kMaxPrunes) + " prunes");
  }
  Result<Prune> prune = ParsePrune(text);
  if (!prune.ok()) return prune.status();
  state->prunes.push_back(*prune);
  return Status::Ok();
}

Status SetStateCamera(std::string_view text, TreeState* state) {
  if (!CameraText(text)) return Status::Error("camera", kCameraRule);
  state->camera = std::string(text);
  return Status::Ok();
}

Status CheckGustOrder(const ParamSet& params) {
  const double on = params.Get(static_cast<std::size_t>(ParamId::kGustOn));
  const double off = params.Get(static_cast<std::size_t>(ParamId::kGustOff));
  if (off > on) return Status::Ok();
  return Status::Error(
      "gust_off", FormatNumber(off) + " must be greater than gust_on (" + FormatNumber(on) + ")");
}

Status ApplyStateJson(const std::string& text, TreeState* state) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "state"));
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) return Status::Error("state", "malformed JSON");
  if (!document.is_object()) return Status::Error("state", "must be a JSON object");
  for (auto it = document.begin(); it != document.end(); ++it) {
    static const char* const kKeys[] = {"preset", "seed", "years", "params", "prunes", "camera"};
    if (std::find(std::begin(kKeys), std::end(kKeys), it.key()) == std::end(kKeys)) {
      return Status::Error(Printable(it.key()),
                           "unknown state key; the keys are preset, seed, years, params, prunes, "
                           "camera");
    }
  }
  TreeState result = *state;
  if (document.contains("preset")) {
    const json& name = document["preset"];
    NIWA_RETURN_IF_ERROR(
        SetStatePreset(name.is_string() ? name.get<std::string>() : name.dump(), &result));
  }
  if (document.contains("seed")) {
    NIWA_RETURN_IF_ERROR(SetWhole(document["seed"], "seed", kMaxSeed, SetStateSeed, &result));
  }
  if (document.contains("years")) {
    NIWA_RETURN_IF_ERROR(SetWhole(document["years"], "years", kMaxYears, SetStateYears, &result));
  }
  if (document.contains("params")) {
    NIWA_RETURN_IF_ERROR(ApplyParamsObject(document["params"], &result.params));
  }
  if (document.contains("prunes")) {
    const json& prunes = document["prunes"];
    if (!prunes.is_array()) {
      return Status::Error("prunes", "must be an array of \"YEAR:bID\" or \"YEAR:sinceY\"");
    }
    if (prunes.size() > kMaxPrunes) return Status::Error("prunes", "at most 256");
    result.prunes.clear();
    for (const json& item : prunes) {
      if (!item.is_string()) {
        return Status::Error("prunes", "each must be a string \"YEAR:bID\" or \"YEAR:sinceY\"");
      }
      NIWA_RETURN_IF_ERROR(AddStatePrune(item.get<std::string>(), &result));
    }
  }
  if (document.contains("camera")) {
    const json& camera = document["camera"];
    NIWA_RETURN_IF_ERROR(
        SetStateCamera(camera.is_string() ? camera.get<std::string>() : "?", &result));
  }
  *state = std::move(result);
  return Status::Ok();
}

std::string TreeStateJson(const TreeState& state) {
  ordered_json out;
  out["preset"] = state.preset;
  out["seed"] = state.seed;
  out["years"] = state.years;
  out["params"] = ordered_json::parse(ParamsToJson(state.params, -1));
  ordered_json prunes = ordered_json::array();
  for (const Prune& prune : state.prunes) prunes.push_back(FormatPrune(prune));
  out["prunes"] = std::move(prunes);
  out["camera"] = state.camera;
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string TreeStateFileJson(const TreeState& state) {
  const Preset* preset = FindPreset(state.preset);
  const TreeParams base = preset ? preset->params : TreeParams();
  ordered_json out;
  out["preset"] = state.preset;
  out["seed"] = state.seed;
  out["years"] = state.years;
  ordered_json params = ordered_json::object();
  for (std::size_t row = 0; row < state.params.size(); ++row) {
    if (state.params.Get(row) != base.Get(row)) {
      params[state.params.table().row(row).key] = state.params.Get(row);
    }
  }
  out["params"] = std::move(params);
  ordered_json prunes = ordered_json::array();
  for (const Prune& prune : state.prunes) prunes.push_back(FormatPrune(prune));
  out["prunes"] = std::move(prunes);
  out["camera"] = state.camera;
  return out.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

Result<std::string> TreeHashOfLink(std::string_view url) {
  ShareLink link = SplitShareLink(url);
  if (!link.error.empty()) return Status::Error("url", link.error);
  if (link.is_link && !link.page.empty() && link.page != "index.html") {
    const std::string page = Printable(link.page);
    const std::string what =
        link.page == "grove.html" ? "is the grove page, not a tree link" : "is not the tree page";
    return Status::Error("url", "'" + page + "' " + what +
                                    "; give a link to index.html (the tree page) or its hash");
  }
  return link.hash;
}

TreeState DecodeTreeHash(std::string_view hash, std::vector<std::string>* notices,
                         std::string_view prefix) {
  TreeState state;
  HashPairs pairs;
  const std::string prune_key = std::string(prefix) + "prune";
  for (auto& [key, value] : SplitHash(hash, notices, {prune_key})) {
    if (key.compare(0, prefix.size(), prefix) != 0) continue;  // another study's key
    pairs.emplace_back(key.substr(prefix.size()), std::move(value));
  }
  const std::string p(prefix);
  // The preset first: the other values are relative to it.
  for (const auto& [key, value] : pairs) {
    if (key != "preset") continue;
    if (!SetStatePreset(value, &state).ok()) {
      notices->push_back(p + "preset: unknown '" + Printable(value) + "', must be one of " +
                         PresetNames());
    }
  }
  for (const auto& [key, value] : pairs) {
    if (key == "preset") continue;
    if (key == "seed") {
      HashWhole(p + key, value, kMaxSeed, &state.seed, notices);
    } else if (key == "years") {
      HashWhole(p + key, value, kMaxYears, &state.years, notices);
    } else if (key == "prune") {
      if (state.prunes.size() >= kMaxPrunes) {
        notices->push_back(p + "prune: more than 256 prunes, rest dropped");
        continue;
      }
      Result<Prune> prune = ParsePrune(value);
      if (prune.ok()) {
        state.prunes.push_back(*prune);
      } else {
        notices->push_back(p + prune.status().Line() + " (dropped)");
      }
    } else if (key == "cam") {
      if (!SetStateCamera(value, &state).ok()) {
        notices->push_back(p + "cam: '" + Printable(value) + "' dropped, " + kCameraRule);
      }
    } else if (!ApplyHashParam(p + key, value, p, &state.params, notices)) {
      notices->push_back("unknown key '" + Printable(p + key) + "' dropped");
    }
  }
  if (Status gust = CheckGustOrder(state.params); !gust.ok()) {
    const Preset* preset = FindPreset(state.preset);
    const TreeParams base = preset ? preset->params : TreeParams();
    (void)state.params.Set(ParamId::kGustOn, base.Get(ParamId::kGustOn));
    (void)state.params.Set(ParamId::kGustOff, base.Get(ParamId::kGustOff));
    notices->push_back(p + gust.field() + ": " + gust.message() + "; both put back to " +
                       FormatNumber(base.Get(ParamId::kGustOn)) + " and " +
                       FormatNumber(base.Get(ParamId::kGustOff)));
  }
  return state;
}

std::string EncodeTreeHash(const TreeState& state, std::string_view prefix) {
  const std::string p(prefix);
  std::string out = p + "preset=" + state.preset + "&" + p + "seed=" + std::to_string(state.seed) +
                    "&" + p + "years=" + std::to_string(state.years);
  const Preset* preset = FindPreset(state.preset);
  out += EncodeChangedParams(state.params, preset ? preset->params : TreeParams(), prefix);
  for (const Prune& prune : state.prunes) out += "&" + p + "prune=" + FormatPrune(prune);
  if (!state.camera.empty()) out += "&" + p + "cam=" + state.camera;
  return out;
}

}  // namespace niwa

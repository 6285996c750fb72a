// Ivy state from JSON and share-link hashes, over params/param_json and io/hash_codec.
#include "ivy/ivy_state.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/hash_codec.h"
#include "params/param_json.h"
#include "params/param_text.h"

namespace niwa::ivy {

Status SetIvyPreset(std::string_view name, IvyState* state) {
  Result<IvyParams> p = IvyPreset(name);
  if (!p.ok()) return p.status();
  state->preset = std::string(name);
  state->params = *p;
  return Status::Ok();
}

Status SetIvySeed(double seed, IvyState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("seed", seed, 0, kMaxIvySeed, true));
  state->seed = static_cast<uint64_t>(seed);
  return Status::Ok();
}

Status SetIvySteps(double steps, IvyState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("steps", steps, 0, 10000, true));
  state->steps = static_cast<int>(steps);
  return Status::Ok();
}

namespace {

Result<double> Number(const nlohmann::json& v, const std::string& field) {
  if (v.is_number()) return v.get<double>();
  if (v.is_string()) {
    std::optional<double> x = ParseNumber(v.get<std::string>());
    if (x) return *x;
  }
  return Status::Error(field, "must be a number");
}

}  // namespace

Status ApplyIvyStateJson(const std::string& text, IvyState* state) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "params"));
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    return Status::Error("params", "not a JSON object; must be {preset, seed, steps, params}");
  }
  IvyState next = *state;
  if (j.contains("preset")) {
    if (!j["preset"].is_string()) return Status::Error("preset", "must be a preset name");
    NIWA_RETURN_IF_ERROR(SetIvyPreset(j["preset"].get<std::string>(), &next));
  }
  if (j.contains("seed")) {
    Result<double> v = Number(j["seed"], "seed");
    if (!v.ok()) return v.status();
    NIWA_RETURN_IF_ERROR(SetIvySeed(*v, &next));
  }
  if (j.contains("steps")) {
    Result<double> v = Number(j["steps"], "steps");
    if (!v.ok()) return v.status();
    NIWA_RETURN_IF_ERROR(SetIvySteps(*v, &next));
  }
  NIWA_RETURN_IF_ERROR(
      ApplyParamsJson(text, &next.params, {"preset", "seed", "steps", "name", "scene"}));
  *state = next;
  return Status::Ok();
}

void ApplyIvyHash(std::string_view hash, std::string_view prefix, IvyState* state,
                  std::vector<std::string>* notices) {
  const std::string pre(prefix);
  HashPairs pairs = SplitHash(hash, notices);
  // The preset first, so the other keys go on top of it whatever their order.
  for (const auto& [key, value] : pairs) {
    if (key != pre + "preset") continue;
    Status s = SetIvyPreset(value, state);
    if (!s.ok())
      notices->push_back(Printable(key) + ": '" + Printable(value) +
                         "' is unknown; must be one of paper, literal, improved, "
                         "metric");
  }
  for (const auto& [key, value] : pairs) {
    if (key == pre + "preset") continue;
    if (key == pre + "seed" || key == pre + "steps") {
      std::optional<double> x = ParseNumber(value);
      Status s = !x ? Status::Error(key, "'" + Printable(value) + "' is not a number")
                 : key == pre + "seed" ? SetIvySeed(*x, state)
                                       : SetIvySteps(*x, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    if (prefix.empty() || key.rfind(pre, 0) == 0) {
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
    }
  }
}

std::string EncodeIvyHash(const IvyState& state, std::string_view prefix) {
  const std::string pre(prefix);
  std::string out = pre + "preset=" + state.preset + "&" + pre +
                    "seed=" + std::to_string(state.seed) + "&" + pre +
                    "steps=" + std::to_string(state.steps);
  Result<IvyParams> base = IvyPreset(state.preset);
  out += EncodeChangedParams(state.params, base.ok() ? *base : IvyParams(), prefix);
  return out;
}

}  // namespace niwa::ivy

// The bark state's species, model, seed and values, as JSON and as a share-link hash.
#include "bark/bark_state.h"

#include <nlohmann/json.hpp>
#include <optional>

#include "io/hash_codec.h"
#include "params/param_json.h"
#include "params/param_text.h"

namespace niwa::bark {

Status SetBarkSpecies(std::string_view name, BarkState* state) {
  Result<BarkParams> params = BarkPreset(name);
  if (!params.ok()) {
    return Status::Error("species",
                         "'" + Printable(name) + "' is unknown; must be " + BarkPresetList());
  }
  state->species = std::string(name);
  state->params = *params;
  return Status::Ok();
}

Status SetBarkModel(std::string_view name, BarkState* state) {
  if (name != "2layer" && name != "4layer") {
    return Status::Error("model", "'" + Printable(name) + "' is unknown; must be 2layer or 4layer");
  }
  state->model = std::string(name);
  return Status::Ok();
}

Status SetBarkSeed(double seed, BarkState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("seed", seed, 0, kMaxBarkSeed, true));
  state->seed = static_cast<uint64_t>(seed);
  return Status::Ok();
}

Status SetBarkSize(std::string_view text, BarkState* state) {
  const std::size_t x = text.find('x');
  std::optional<double> w, h;
  if (x != std::string_view::npos) {
    w = ParseNumber(text.substr(0, x));
    h = ParseNumber(text.substr(x + 1));
  }
  if (!w || !h) {
    return Status::Error(
        "N_R", "'" + Printable(text) + "' is not WxH; must be two whole numbers, e.g. 128x64");
  }
  BarkParams next = state->params;
  NIWA_RETURN_IF_ERROR(next.Set(BarkParam::kNR, *w));
  NIWA_RETURN_IF_ERROR(next.Set(BarkParam::kNH, *h));
  state->params = next;
  return Status::Ok();
}

Status CheckBarkState(const BarkState& state) { return CheckBarkParams(state.params); }

Status ApplyBarkStateJson(const std::string& text, BarkState* state) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "params"));
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    return Status::Error("params", "not a JSON object; must be {species, model, seed, params}");
  BarkState next = *state;
  if (j.contains("species")) {
    if (!j["species"].is_string())
      return Status::Error("species", "must be a name: " + BarkPresetList());
    NIWA_RETURN_IF_ERROR(SetBarkSpecies(j["species"].get<std::string>(), &next));
  }
  if (j.contains("model")) {
    if (!j["model"].is_string()) return Status::Error("model", "must be 2layer or 4layer");
    NIWA_RETURN_IF_ERROR(SetBarkModel(j["model"].get<std::string>(), &next));
  }
  if (j.contains("seed")) {
    const nlohmann::json& v = j["seed"];
    std::optional<double> x;
    if (v.is_number()) x = v.get<double>();
    if (v.is_string()) x = ParseNumber(v.get<std::string>());
    if (!x) return Status::Error("seed", "must be a whole number in [0, 4294967295]");
    NIWA_RETURN_IF_ERROR(SetBarkSeed(*x, &next));
  }
  NIWA_RETURN_IF_ERROR(ApplyParamsJson(text, &next.params, {"species", "model", "seed"}));
  NIWA_RETURN_IF_ERROR(CheckBarkState(next));
  *state = next;
  return Status::Ok();
}

std::string BarkStateJson(const BarkState& state) {
  nlohmann::ordered_json j;
  j["species"] = state.species;
  j["model"] = state.model;
  j["seed"] = state.seed;
  j["params"] = nlohmann::ordered_json::parse(ParamsToJson(state.params, -1));
  return j.dump();
}

void ApplyBarkHash(std::string_view hash, std::string_view prefix, BarkState* state,
                   std::vector<std::string>* notices) {
  const std::string pre(prefix);
  const HashPairs pairs = SplitHash(hash, notices);
  // The species first, so the rows go on top of it whatever their order.
  for (const auto& [key, value] : pairs) {
    if (key != pre + "species") continue;
    const Status s = SetBarkSpecies(value, state);
    if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
  }
  for (const auto& [key, value] : pairs) {
    if (key == pre + "species") continue;
    if (key == pre + "model") {
      const Status s = SetBarkModel(value, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (key == pre + "seed") {
      const std::optional<double> x = ParseNumber(value);
      const Status s = x ? SetBarkSeed(*x, state)
                         : Status::Error("seed", "'" + Printable(value) + "' is not a number");
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    if (prefix.empty() || key.rfind(pre, 0) == 0)
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
  }
  // An odd N_R from a link is made even (down) with a notice, as a clamped row is.
  const int n_r = state->params.GetInt(BarkParam::kNR);
  if (n_r % 2 != 0) {
    (void)state->params.Set(BarkParam::kNR, n_r - 1);
    notices->push_back(pre + "N_R: " + std::to_string(n_r) + " is odd; " + std::to_string(n_r - 1) +
                       " used");
  }
  const int size = state->params.GetInt(BarkParam::kMapSize);
  if ((size & (size - 1)) != 0) {
    int p = 256;
    while (p * 2 <= size) p *= 2;
    (void)state->params.Set(BarkParam::kMapSize, p);
    notices->push_back(pre + "map_size: " + std::to_string(size) + " is not a power of two; " +
                       std::to_string(p) + " used");
  }
  // A node count over the limit cannot be clamped row by row: N_H is lowered to fit.
  const int max_h = kMaxNodes / state->params.GetInt(BarkParam::kNR);
  if (state->params.GetInt(BarkParam::kNH) > max_h) {
    (void)state->params.Set(BarkParam::kNH, max_h);
    notices->push_back(pre + "N_H: over " + std::to_string(kMaxNodes) + " nodes; " +
                       std::to_string(max_h) + " used");
  }
}

std::string EncodeBarkHash(const BarkState& state, std::string_view prefix) {
  const std::string pre(prefix);
  Result<BarkParams> base = BarkPreset(state.species);
  return pre + "species=" + PercentEncode(state.species) + "&" + pre +
         "model=" + PercentEncode(state.model) + "&" + pre +
         "seed=" + FormatNumber(static_cast<double>(state.seed)) +
         EncodeChangedParams(state.params, base.ok() ? *base : BarkParams(), prefix);
}

}  // namespace niwa::bark

// Ivy state from JSON and share-link hashes, over params/param_json and io/hash_codec.
#include "ivy/ivy_state.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "io/hash_codec.h"
#include "ivy/growth.h"
#include "ivy/scenes.h"
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

Status SetIvyAccel(std::string_view name, IvyState* state) {
  if (name == "bvh" || name == "linear") {
    state->accel = name == "bvh" ? Accel::kBvh : Accel::kLinear;
    return Status::Ok();
  }
  return Status::Error("accel", "'" + Printable(name) + "' is unknown; must be bvh or linear");
}

Status SetIvySteps(double steps, IvyState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("steps", steps, 0, 10000, true));
  state->steps = static_cast<int>(steps);
  return Status::Ok();
}

Status SetIvyScene(std::string_view name, IvyState* state) {
  if (!name.empty()) {
    const std::vector<std::string>& names = IvySceneNames();
    bool known = name == kTreeScene;
    std::string list;
    for (const std::string& n : names) {
      known = known || n == name;
      list += (list.empty() ? "" : ", ") + n;
    }
    list += std::string(", ") + kTreeScene;
    if (!known) {
      return Status::Error("scene", "'" + Printable(name) + "' is unknown; must be one of " + list);
    }
  }
  state->scene = std::string(name);
  return Status::Ok();
}

Status SetIvyTree(std::string_view name, IvyState* state) {
  bool spelled = !name.empty() && name.size() <= 40;
  for (char c : name) {
    spelled = spelled && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_');
  }
  if (!spelled) {
    return Status::Error("tree", "'" + Printable(name) +
                                     "' is not a tree preset name; must be 1..40 of a-z 0-9 - _ "
                                     "('niwa presets tree')");
  }
  state->tree = std::string(name);
  return Status::Ok();
}

Status SetIvyTreeYears(double years, IvyState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("tree_years", years, 1, kMaxTreeYears, true));
  state->tree_years = static_cast<int>(years);
  return Status::Ok();
}

Status SetIvySeedPoints(std::string_view text, IvyState* state) {
  std::vector<glm::dvec3> points;
  const std::string range = "must be X,Y,Z;X,Y,Z... (at most " + std::to_string(kMaxSeedPoints) +
                            " points, each coordinate in [-1e30, 1e30])";
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t semi = text.find(';', start);
    std::string_view point =
        text.substr(start, semi == std::string_view::npos ? std::string_view::npos : semi - start);
    glm::dvec3 p;
    std::size_t at = 0;
    for (int i = 0; i < 3; ++i) {
      std::size_t comma = i < 2 ? point.find(',', at) : point.size();
      if (comma == std::string_view::npos ||
          (i == 2 && point.find(',', at) != std::string_view::npos)) {
        return Status::Error("at", "'" + Printable(point) + "' is not X,Y,Z; " + range);
      }
      std::optional<double> x = ParseNumber(point.substr(at, comma - at));
      if (!x || !(std::fabs(*x) <= 1e30)) {
        return Status::Error("at", "'" + Printable(point) + "' is out of range; " + range);
      }
      p[i] = *x;
      at = comma + 1;
    }
    points.push_back(p);
    if (points.size() > static_cast<std::size_t>(kMaxSeedPoints)) {
      return Status::Error("at",
                           "more than " + std::to_string(kMaxSeedPoints) + " points; " + range);
    }
    if (semi == std::string_view::npos) break;
    start = semi + 1;
  }
  state->seed_points = std::move(points);
  return Status::Ok();
}

std::string FormatSeedPoints(const std::vector<glm::dvec3>& points) {
  std::string out;
  for (const glm::dvec3& p : points) {
    if (!out.empty()) out += ";";
    out += FormatNumber(p.x) + "," + FormatNumber(p.y) + "," + FormatNumber(p.z);
  }
  return out;
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
  if (j.contains("scene")) {
    if (!j["scene"].is_string()) return Status::Error("scene", "must be a scene name");
    NIWA_RETURN_IF_ERROR(SetIvyScene(j["scene"].get<std::string>(), &next));
  }
  if (j.contains("tree")) {
    if (!j["tree"].is_string()) return Status::Error("tree", "must be a tree preset name");
    NIWA_RETURN_IF_ERROR(SetIvyTree(j["tree"].get<std::string>(), &next));
  }
  if (j.contains("tree_years")) {
    Result<double> v = Number(j["tree_years"], "tree_years");
    if (!v.ok()) return v.status();
    NIWA_RETURN_IF_ERROR(SetIvyTreeYears(*v, &next));
  }
  if (j.contains("accel")) {
    if (!j["accel"].is_string()) return Status::Error("accel", "must be bvh or linear");
    NIWA_RETURN_IF_ERROR(SetIvyAccel(j["accel"].get<std::string>(), &next));
  }
  if (j.contains("seed_points")) {
    if (!j["seed_points"].is_string()) {
      return Status::Error("seed_points", "must be text X,Y,Z;X,Y,Z...");
    }
    NIWA_RETURN_IF_ERROR(SetIvySeedPoints(j["seed_points"].get<std::string>(), &next));
  }
  NIWA_RETURN_IF_ERROR(ApplyParamsJson(
      text, &next.params,
      {"preset", "seed", "steps", "name", "scene", "seed_points", "tree", "tree_years", "accel"}));
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
    if (!s.ok()) {
      std::string names;
      for (const std::string& n : IvyPresetNames()) names += (names.empty() ? "" : ", ") + n;
      notices->push_back(Printable(key) + ": '" + Printable(value) +
                         "' is unknown; must be one of " + names);
    }
  }
  for (const auto& [key, value] : pairs) {
    if (key == pre + "preset") continue;
    if (key == pre + "seed" || key == pre + "steps" || key == pre + "tree_years") {
      std::optional<double> x = ParseNumber(value);
      Status s = !x ? Status::Error(key, "'" + Printable(value) + "' is not a number")
                 : key == pre + "seed"  ? SetIvySeed(*x, state)
                 : key == pre + "steps" ? SetIvySteps(*x, state)
                                        : SetIvyTreeYears(*x, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (key == pre + "scene" || key == pre + "at" || key == pre + "tree") {
      Status s = key == pre + "scene" ? SetIvyScene(value, state)
                 : key == pre + "at"  ? SetIvySeedPoints(value, state)
                                      : SetIvyTree(value, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    if (prefix.empty() || key.rfind(pre, 0) == 0) {
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
    }
  }
}

std::string IvyStateJson(const IvyState& state) {
  nlohmann::ordered_json j;
  j["preset"] = state.preset;
  j["seed"] = state.seed;
  j["steps"] = state.steps;
  j["scene"] = state.scene;
  j["seed_points"] = FormatSeedPoints(state.seed_points);
  j["tree"] = state.tree;
  j["tree_years"] = state.tree_years;
  if (state.accel == Accel::kLinear) j["accel"] = "linear";  // bvh, the default, as before
  j["params"] = nlohmann::ordered_json::parse(ParamsToJson(state.params, -1));
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string EncodeIvyHash(const IvyState& state, std::string_view prefix) {
  const std::string pre(prefix);
  std::string out = pre + "preset=" + state.preset + "&" + pre +
                    "seed=" + std::to_string(state.seed) + "&" + pre +
                    "steps=" + std::to_string(state.steps);
  if (!state.scene.empty()) out += "&" + pre + "scene=" + state.scene;
  if (state.scene == kTreeScene) {
    out += "&" + pre + "tree=" + state.tree + "&" + pre +
           "tree_years=" + std::to_string(state.tree_years);
  }
  if (!state.seed_points.empty()) out += "&" + pre + "at=" + FormatSeedPoints(state.seed_points);
  Result<IvyParams> base = IvyPreset(state.preset);
  out += EncodeChangedParams(state.params, base.ok() ? *base : IvyParams(), prefix);
  return out;
}

}  // namespace niwa::ivy

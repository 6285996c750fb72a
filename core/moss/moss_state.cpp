// The moss state's preset and values, and its share-link hash.
#include "moss/moss_state.h"

#include <nlohmann/json.hpp>
#include <optional>

#include "io/hash_codec.h"
#include "moss/scenes.h"
#include "params/param_json.h"
#include "params/param_text.h"

namespace niwa::moss {

Status SetMossPreset(std::string_view name, MossState* state) {
  Result<MossParams> params = MossPreset(name);
  if (!params.ok()) return params.status();
  state->preset = std::string(name);
  state->params = *params;
  return Status::Ok();
}

Status SetMossDays(double days, MossState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("days", days, 0, kMaxMossDays, true));
  state->days = static_cast<int>(days);
  return Status::Ok();
}

Status SetMossSeed(double seed, MossState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("seed", seed, 0, static_cast<double>(kMaxMossSeed), true));
  state->seed = static_cast<uint64_t>(seed);
  return Status::Ok();
}

Status SetMossScene(std::string_view scene, MossState* state) {
  for (const std::string& name : SceneNames()) {
    if (name != scene) continue;
    state->scene = name;
    return Status::Ok();
  }
  if (scene == kTreeLand || scene == kTerrainLand) {
    state->scene = std::string(scene);
    return Status::Ok();
  }
  return Status::Error("scene", "'" + Printable(scene) +
                                    "' is unknown; must be plane, thesis, walls, rocks, tree or "
                                    "terrain");
}

namespace {

// A preset name of another study: 1..40 of [a-z0-9_-] (whether it exists is that study's word).
Status CheckPresetSpelling(const char* field, const char* study, std::string_view name) {
  bool spelled = !name.empty() && name.size() <= 40;
  for (char c : name)
    spelled = spelled && ((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_');
  if (spelled) return Status::Ok();
  return Status::Error(field, "'" + Printable(name) + "' is not a " + study +
                                  " preset name; must be 1..40 of a-z 0-9 - _ ('niwa presets " +
                                  study + "')");
}

}  // namespace

Status SetMossTree(std::string_view name, MossState* state) {
  NIWA_RETURN_IF_ERROR(CheckPresetSpelling("tree", "tree", name));
  state->tree = std::string(name);
  return Status::Ok();
}

Status SetMossTreeYears(double years, MossState* state) {
  NIWA_RETURN_IF_ERROR(CheckValue("tree_years", years, 1, kMaxMossTreeYears, true));
  state->tree_years = static_cast<int>(years);
  return Status::Ok();
}

Status SetMossTerrain(std::string_view name, MossState* state) {
  NIWA_RETURN_IF_ERROR(CheckPresetSpelling("terrain", "terrain", name));
  state->terrain = std::string(name);
  return Status::Ok();
}

Status SetMossTerrainSeed(double seed, MossState* state) {
  NIWA_RETURN_IF_ERROR(
      CheckValue("terrain_seed", seed, 0, static_cast<double>(kMaxMossSeed), true));
  state->terrain_seed = static_cast<uint64_t>(seed);
  return Status::Ok();
}

Status SetMossRockTriangles(double triangles, MossState* state) {
  NIWA_RETURN_IF_ERROR(
      CheckValue("rock_triangles", triangles, kRockTrianglesMin, kRockTrianglesMax, true));
  state->rock_triangles = static_cast<int>(triangles);
  return Status::Ok();
}

void ApplyMossHash(std::string_view hash, std::string_view prefix, MossState* state,
                   std::vector<std::string>* notices) {
  const std::string pre(prefix);
  const HashPairs pairs = SplitHash(hash, notices);
  // The preset first, so the rows go on top of it whatever their order.
  for (const auto& [key, value] : pairs) {
    if (key != pre + "preset") continue;
    const Status s = SetMossPreset(value, state);
    if (s.ok()) continue;
    std::string names;
    for (const std::string& n : MossPresetNames()) names += (names.empty() ? "" : " or ") + n;
    notices->push_back(Printable(key) + ": '" + Printable(value) + "' is unknown; must be " +
                       names);
  }
  for (const auto& [key, value] : pairs) {
    if (key == pre + "preset") continue;
    if (key == pre + "days" || key == pre + "seed" || key == pre + "tree_years" ||
        key == pre + "terrain_seed" || key == pre + "rock_triangles") {
      const std::optional<double> x = ParseNumber(value);
      const Status s = !x ? Status::Error(key, "'" + Printable(value) + "' is not a number")
                       : key == pre + "days"           ? SetMossDays(*x, state)
                       : key == pre + "seed"           ? SetMossSeed(*x, state)
                       : key == pre + "tree_years"     ? SetMossTreeYears(*x, state)
                       : key == pre + "rock_triangles" ? SetMossRockTriangles(*x, state)
                                                       : SetMossTerrainSeed(*x, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (key == pre + "scene" || key == pre + "tree" || key == pre + "terrain") {
      const Status s = key == pre + "scene"  ? SetMossScene(value, state)
                       : key == pre + "tree" ? SetMossTree(value, state)
                                             : SetMossTerrain(value, state);
      if (!s.ok()) notices->push_back(Printable(key) + ": " + s.message() + "; dropped");
      continue;
    }
    if (ApplyHashParam(key, value, prefix, &state->params, notices)) continue;
    if (prefix.empty() || key.rfind(pre, 0) == 0)
      notices->push_back("unknown key '" + Printable(key) + "' dropped");
  }
}

std::string EncodeMossHash(const MossState& state, std::string_view prefix) {
  Result<MossParams> base = MossPreset(state.preset);
  const std::string pre(prefix);
  std::string out = pre + "preset=" + PercentEncode(state.preset);
  if (state.scene != "thesis") out += "&" + pre + "scene=" + PercentEncode(state.scene);
  if (state.days != 300) out += "&" + pre + "days=" + std::to_string(state.days);
  if (state.seed != 1) out += "&" + pre + "seed=" + std::to_string(state.seed);
  if (state.scene == kTreeLand) {
    out += "&" + pre + "tree=" + PercentEncode(state.tree) + "&" + pre +
           "tree_years=" + std::to_string(state.tree_years);
  } else if (state.scene == kTerrainLand) {
    out += "&" + pre + "terrain=" + PercentEncode(state.terrain) + "&" + pre +
           "terrain_seed=" + std::to_string(state.terrain_seed);
  } else if (state.scene == "rocks" && state.rock_triangles != kRockTrianglesDefault) {
    out += "&" + pre + "rock_triangles=" + std::to_string(state.rock_triangles);
  }
  return out + EncodeChangedParams(state.params, base.ok() ? *base : MossParams(), prefix);
}

Status ApplyMossStateJson(const std::string& text, MossState* state) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "params"));
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    return Status::Error("params",
                         "not a JSON object; must be {preset, scene, days, seed, params}");
  }
  MossState next = *state;
  if (j.contains("preset")) {
    if (!j["preset"].is_string()) return Status::Error("preset", "must be a preset name");
    NIWA_RETURN_IF_ERROR(SetMossPreset(j["preset"].get<std::string>(), &next));
  }
  if (j.contains("scene")) {
    if (!j["scene"].is_string()) return Status::Error("scene", "must be a scene name");
    NIWA_RETURN_IF_ERROR(SetMossScene(j["scene"].get<std::string>(), &next));
  }
  if (j.contains("days")) {
    if (!j["days"].is_number()) return Status::Error("days", "must be a whole number in [0, 3650]");
    NIWA_RETURN_IF_ERROR(SetMossDays(j["days"].get<double>(), &next));
  }
  if (j.contains("seed")) {
    if (!j["seed"].is_number())
      return Status::Error("seed", "must be a whole number in [0, 4294967295]");
    NIWA_RETURN_IF_ERROR(SetMossSeed(j["seed"].get<double>(), &next));
  }
  if (j.contains("tree")) {
    if (!j["tree"].is_string()) return Status::Error("tree", "must be a tree preset name");
    NIWA_RETURN_IF_ERROR(SetMossTree(j["tree"].get<std::string>(), &next));
  }
  if (j.contains("tree_years")) {
    if (!j["tree_years"].is_number())
      return Status::Error("tree_years", "must be a whole number in [1, 100]");
    NIWA_RETURN_IF_ERROR(SetMossTreeYears(j["tree_years"].get<double>(), &next));
  }
  if (j.contains("terrain")) {
    if (!j["terrain"].is_string()) return Status::Error("terrain", "must be a terrain preset name");
    NIWA_RETURN_IF_ERROR(SetMossTerrain(j["terrain"].get<std::string>(), &next));
  }
  if (j.contains("terrain_seed")) {
    if (!j["terrain_seed"].is_number())
      return Status::Error("terrain_seed", "must be a whole number in [0, 4294967295]");
    NIWA_RETURN_IF_ERROR(SetMossTerrainSeed(j["terrain_seed"].get<double>(), &next));
  }
  if (j.contains("rock_triangles")) {
    if (!j["rock_triangles"].is_number())
      return Status::Error("rock_triangles", "must be a whole number in [" +
                                                 std::to_string(kRockTrianglesMin) + ", " +
                                                 std::to_string(kRockTrianglesMax) + "]");
    NIWA_RETURN_IF_ERROR(SetMossRockTriangles(j["rock_triangles"].get<double>(), &next));
  }
  NIWA_RETURN_IF_ERROR(ApplyParamsJson(text, &next.params,
                                       {"preset", "scene", "days", "seed", "tree", "tree_years",
                                        "terrain", "terrain_seed", "rock_triangles"}));
  NIWA_RETURN_IF_ERROR(CheckMossParams(next.params));  // the cross-row checks at load
  *state = next;
  return Status::Ok();
}

std::string MossStateJson(const MossState& state) {
  nlohmann::json j;
  j["preset"] = state.preset;
  j["scene"] = state.scene;
  j["days"] = state.days;
  j["seed"] = state.seed;
  if (state.scene == kTreeLand) {
    j["tree"] = state.tree;
    j["tree_years"] = state.tree_years;
  } else if (state.scene == kTerrainLand) {
    j["terrain"] = state.terrain;
    j["terrain_seed"] = state.terrain_seed;
  } else if (state.scene == "rocks" && state.rock_triangles != kRockTrianglesDefault) {
    j["rock_triangles"] = state.rock_triangles;
  }
  j["params"] = nlohmann::json::parse(ParamsToJson(state.params, -1));
  return j.dump();
}

}  // namespace niwa::moss

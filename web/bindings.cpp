// The one embind file: exposes the Niwa core to the Web Worker (web/worker.js).
//
// Everything that crosses from JavaScript arrives as text (JSON or a URL hash) and is checked by
// the core itself (FindPreset, ParamSet::Set / SetFromText, ParsePrune). Nothing here throws or
// aborts on bad input: errors come back as strings, either as the "error" field of a JSON answer or
// from GrowSession::error().
//
// Exposed to JS:
//   paramTableJson()      -> the parameter table [{key, symbol, unit, default, min, max, integer,
//   group, help}] presetsJson()         -> [{name, title, years, seed, source, params:{key:value}}]
//   decodeHash(hash)      -> {state:{preset, seed, years, params, prunes, camera}, notices:[...]}
//   encodeHash(stateJson) -> {hash} or {error}
//   GrowSession(stateJson): error(), years(), year(), growYear(), done(), buildMesh(), statsJson(),
//                           barkPositions() ... flowersIndices() as typed-array views into WASM
//                           memory; barkBranchIds() (Uint32, one per bark vertex);
//                           branchParents() (Int32 parent id per branch, -1 at the root);
//                           buildGlb() -> "" or error, then glbBytes() (Uint8 view of the .glb);
//                           paramsJson() (ParamsToJson of the state's parameters).
//
// The mesh views (emscripten::typed_memory_view) point into the WASM heap: they stay valid only
// until the next call that may allocate. The worker copies each one ONCE into a fresh ArrayBuffer
// right away and transfers that buffer to the main thread (no second copy).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "io/gltf_export.h"
#include "io/json_io.h"
#include "io/url_codec.h"
#include "params/param_table.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr double kMaxSeed = 4294967295.0;

// {"key": value} for every parameter (full values), as a JSON object.
ordered_json ParamsObject(const ParamSet& params) {
  ordered_json out = ordered_json::object();
  for (const ParamSpec& spec : ParamTable()) out[spec.key] = params.Get(spec.id);
  return out;
}

ordered_json StateObject(const TreeState& state) {
  ordered_json out;
  out["preset"] = state.preset;
  out["seed"] = state.seed;
  out["years"] = state.years;
  out["params"] = ParamsObject(state.params);
  ordered_json prunes = ordered_json::array();
  for (const Prune& prune : state.prunes) prunes.push_back(FormatPrune(prune));
  out["prunes"] = std::move(prunes);
  out["camera"] = state.camera;
  return out;
}

// A whole number in [min, max] from a JSON number or a numeric string; error line or "".
std::string WholeNumber(const json& value, const char* key, double min, double max, double* out) {
  std::string range = std::string(key) + ": must be a whole number in [" + FormatNumber(min) +
                      ", " + FormatNumber(max) + "]";
  double number = 0;
  if (value.is_number()) {
    number = value.get<double>();
  } else if (value.is_string()) {
    std::optional<double> parsed = ParseNumber(value.get<std::string>());
    if (!parsed) return range;
    number = *parsed;
  } else {
    return range;
  }
  if (!std::isfinite(number) || std::floor(number) != number || number < min || number > max)
    return range;
  *out = number;
  return "";
}

// Reads {preset, seed, years, params:{key:value}, prunes:["12:b42"], camera} into a TreeState.
// Missing fields take the preset's values; params are applied on top of the preset's parameters.
// Returns "" or one error line; state is only meaningful on success.
std::string StateFromJson(const std::string& text, TreeState* state) {
  json document = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (document.is_discarded()) return "state: malformed JSON";
  if (!document.is_object()) return "state: must be a JSON object";

  TreeState result;
  if (document.contains("preset")) {
    const json& name = document["preset"];
    if (!name.is_string() || !FindPreset(name.get<std::string>())) {
      std::string shown =
          name.is_string() ? name.get<std::string>().substr(0, 40) : name.dump().substr(0, 40);
      return "preset: unknown '" + shown + "', must be one of " + PresetNames();
    }
    result.preset = name.get<std::string>();
  }
  const Preset* preset = FindPreset(result.preset);
  if (!preset) return "preset: unknown '" + result.preset + "', must be one of " + PresetNames();
  result.params = preset->params;
  result.seed = preset->seed;
  result.years = preset->years;

  if (document.contains("seed")) {
    double seed = 0;
    std::string error = WholeNumber(document["seed"], "seed", 0, kMaxSeed, &seed);
    if (!error.empty()) return error;
    result.seed = static_cast<uint64_t>(seed);
  }
  if (document.contains("years")) {
    double years = 0;
    std::string error = WholeNumber(document["years"], "years", 0, kMaxYears, &years);
    if (!error.empty()) return error;
    result.years = static_cast<int>(years);
  }
  if (document.contains("params")) {
    const json& params = document["params"];
    if (!params.is_object()) return "params: must be an object of key: value";
    for (auto it = params.begin(); it != params.end(); ++it) {
      std::string error;
      if (it.value().is_number()) {
        std::optional<ParamId> id = FindParam(it.key());
        if (!id) return "unknown parameter '" + it.key().substr(0, 64) + "'";
        error = result.params.Set(*id, it.value().get<double>());
      } else if (it.value().is_string()) {
        error = result.params.SetFromText(it.key(), it.value().get<std::string>());
      } else if (it.value().is_boolean()) {
        error = result.params.SetFromText(it.key(), it.value().get<bool>() ? "1" : "0");
      } else {
        std::optional<ParamId> id = FindParam(it.key());
        if (!id) return "unknown parameter '" + it.key().substr(0, 64) + "'";
        error = it.key() + ": must be " + RangeText(Spec(*id));
      }
      if (!error.empty()) return error;
    }
  }
  if (document.contains("prunes")) {
    const json& prunes = document["prunes"];
    if (!prunes.is_array()) return "prunes: must be an array of \"YEAR:bID\" or \"YEAR:sinceY\"";
    if (prunes.size() > 256) return "prunes: at most 256";
    for (const json& item : prunes) {
      if (!item.is_string()) return "prunes: each must be a string \"YEAR:bID\" or \"YEAR:sinceY\"";
      Prune prune;
      std::string error;
      if (!ParsePrune(item.get<std::string>(), &prune, &error)) return error;
      result.prunes.push_back(prune);
    }
  }
  if (document.contains("camera")) {
    const json& camera = document["camera"];
    // One copy of the text: begin() and end() must come from the same string.
    const std::string text = camera.is_string() ? camera.get<std::string>() : std::string("?");
    bool ok = text.size() < 128 && std::all_of(text.begin(), text.end(), [](char c) {
                return (c >= '0' && c <= '9') || c == '.' || c == ',' || c == '-' || c == 'e';
              });
    if (!ok) return "camera: must be numbers separated by commas";
    result.camera = text;
  }
  *state = std::move(result);
  return "";
}

}  // namespace

std::string ParamTableJsonForJs() { return ParamTableJson(); }

std::string PresetsJson() {
  ordered_json out = ordered_json::array();
  for (const Preset& p : Presets()) {
    ordered_json j;
    j["name"] = p.name;
    j["title"] = p.title;
    j["years"] = p.years;
    j["seed"] = p.seed;
    j["source"] = p.source;
    j["params"] = ParamsObject(p.params);
    out.push_back(std::move(j));
  }
  return out.dump();
}

std::string DecodeHashJson(const std::string& hash) {
  std::vector<std::string> notices;
  TreeState state = DecodeStateHash(hash, &notices);
  ordered_json out;
  out["state"] = StateObject(state);
  out["notices"] = notices;
  // Notices echo pieces of the (hostile) hash; replace bytes that are not valid UTF-8 for dump().
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string EncodeHashJson(const std::string& state_json) {
  TreeState state;
  ordered_json out;
  std::string error = StateFromJson(state_json, &state);
  if (error.empty()) {
    out["hash"] = EncodeStateHash(state);
  } else {
    out["error"] = error;
  }
  return out.dump(-1, ' ', false, json::error_handler_t::replace);
}

// One tree grown year by year for the worker, which yields to its event loop between years so a
// newer request can supersede this one.
class GrowSession {
 public:
  explicit GrowSession(const std::string& state_json) {
    error_ = StateFromJson(state_json, &state_);
    if (!error_.empty()) return;
    GrowRequest request;
    request.preset = state_.preset;
    request.params = state_.params;
    request.seed = state_.seed;
    request.years = state_.years;
    request.prunes = state_.prunes;
    grower_ = std::make_unique<Grower>(request);
  }

  std::string error() const { return error_; }
  int years() const { return state_.years; }
  int year() const { return grower_ ? grower_->year() : 0; }
  bool done() const { return !grower_ || grower_->year() >= state_.years; }
  std::string hash() const { return error_.empty() ? EncodeStateHash(state_) : ""; }

  // Grows one more year; false when the tree already has all its years (or the state was bad).
  bool growYear() {
    if (done()) return false;
    grower_->GrowYear();
    return true;
  }

  // Builds the triangle meshes of the tree as grown so far; call before the buffer views.
  void buildMesh() {
    if (!grower_) return;
    mesh_ = BuildTreeMesh(grower_->tree());
    parents_.clear();
    for (const Branch& branch : grower_->tree().branches) parents_.push_back(branch.parent);
  }

  // {internodes, branches, leaves, flowers, height (cm), years, seed, preset, truncated, ms,
  // bounds}
  std::string statsJson() const {
    ordered_json j;
    if (!grower_) {
      j["error"] = error_;
      return j.dump();
    }
    const Tree& tree = grower_->tree();
    TreeStats s = ComputeStats(tree);
    j["internodes"] = s.internodes;
    j["branches"] = s.branches;
    j["leaves"] = s.leaves;
    j["flowers"] = s.flowers;
    j["height"] = s.height;
    j["years"] = tree.years;
    j["seed"] = tree.seed;
    j["preset"] = tree.preset;
    j["truncated"] = tree.truncated;
    j["ms"] = grower_->timings().ms_total;
    // Axis-aligned bounds of every mesh vertex (metres), for framing the camera.
    float lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    bool any = false;
    for (const MeshBuffers* m : {&mesh_.bark, &mesh_.leaves, &mesh_.flowers}) {
      for (std::size_t i = 0; i + 2 < m->positions.size(); i += 3) {
        for (std::size_t k = 0; k < 3; ++k) {
          float v = m->positions[i + k];
          lo[k] = any ? std::min(lo[k], v) : v;
          hi[k] = any ? std::max(hi[k], v) : v;
        }
        any = true;
      }
    }
    j["bounds"] = {{"min", {lo[0], lo[1], lo[2]}}, {"max", {hi[0], hi[1], hi[2]}}};
    return j.dump();
  }

  // Typed-array views into WASM memory (valid until the next allocating call: copy at once).
  emscripten::val barkPositions() const { return View(mesh_.bark.positions); }
  emscripten::val barkNormals() const { return View(mesh_.bark.normals); }
  emscripten::val barkIndices() const { return View(mesh_.bark.indices); }
  emscripten::val leavesPositions() const { return View(mesh_.leaves.positions); }
  emscripten::val leavesNormals() const { return View(mesh_.leaves.normals); }
  emscripten::val leavesIndices() const { return View(mesh_.leaves.indices); }
  emscripten::val flowersPositions() const { return View(mesh_.flowers.positions); }
  emscripten::val flowersNormals() const { return View(mesh_.flowers.normals); }
  emscripten::val flowersIndices() const { return View(mesh_.flowers.indices); }
  // Branch id of each bark vertex (picking and the selection highlight).
  emscripten::val barkBranchIds() const { return View(mesh_.bark_branch_id); }
  // Parent branch id of every branch (-1 for the seedling shoot): what a cut takes with it.
  emscripten::val branchParents() const { return View(parents_); }

  // Binary glTF of the mesh last built (buildMesh); "" or one error line. Then glbBytes() views it.
  std::string buildGlb() {
    glb_.clear();
    if (!grower_) return error_.empty() ? "no tree" : error_;
    return WriteGlb(mesh_, &glb_);
  }
  emscripten::val glbBytes() const { return View(glb_); }

  // The state's full parameter set as JSON (ParamsToJson), for the "Download .json" button.
  std::string paramsJson() const { return ParamsToJson(state_.params); }

 private:
  template <typename T>
  static emscripten::val View(const std::vector<T>& data) {
    return emscripten::val(emscripten::typed_memory_view(data.size(), data.data()));
  }

  TreeState state_;
  std::string error_;
  std::unique_ptr<Grower> grower_;
  TreeMesh mesh_;
  std::vector<int32_t> parents_;
  std::vector<unsigned char> glb_;
};

}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa) {
  using namespace emscripten;
  function("paramTableJson", &niwa::ParamTableJsonForJs);
  function("presetsJson", &niwa::PresetsJson);
  function("decodeHash", &niwa::DecodeHashJson);
  function("encodeHash", &niwa::EncodeHashJson);
  class_<niwa::GrowSession>("GrowSession")
      .constructor<std::string>()
      .function("error", &niwa::GrowSession::error)
      .function("years", &niwa::GrowSession::years)
      .function("year", &niwa::GrowSession::year)
      .function("done", &niwa::GrowSession::done)
      .function("hash", &niwa::GrowSession::hash)
      .function("growYear", &niwa::GrowSession::growYear)
      .function("buildMesh", &niwa::GrowSession::buildMesh)
      .function("statsJson", &niwa::GrowSession::statsJson)
      .function("barkPositions", &niwa::GrowSession::barkPositions)
      .function("barkNormals", &niwa::GrowSession::barkNormals)
      .function("barkIndices", &niwa::GrowSession::barkIndices)
      .function("leavesPositions", &niwa::GrowSession::leavesPositions)
      .function("leavesNormals", &niwa::GrowSession::leavesNormals)
      .function("leavesIndices", &niwa::GrowSession::leavesIndices)
      .function("flowersPositions", &niwa::GrowSession::flowersPositions)
      .function("flowersNormals", &niwa::GrowSession::flowersNormals)
      .function("flowersIndices", &niwa::GrowSession::flowersIndices)
      .function("barkBranchIds", &niwa::GrowSession::barkBranchIds)
      .function("branchParents", &niwa::GrowSession::branchParents)
      .function("buildGlb", &niwa::GrowSession::buildGlb)
      .function("glbBytes", &niwa::GrowSession::glbBytes)
      .function("paramsJson", &niwa::GrowSession::paramsJson);
}

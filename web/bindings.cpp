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
//                           paramsJson() (ParamsToJson of the state's parameters);
//                           leavesUvs() (uv per leaf vertex: v = 0 at the petiole, 1 at the tip);
//                           sway skinning of the mesh (core/sway/skin.h): barkJoints() /
//                           barkWeights() (and leaves*, flowers*), one node point and one eq. 3.15
//                           weight per vertex; swayNodes() node points; swayStart() -> "" or error
//                           (rest pose, time 0, the state's wind); swayStep(n) advances n steps of
//                           dt and returns the time; swayPoses() (16 floats per node point, see
//                           WriteSwayPoses); swayDt(), swayDuration(), swayWindSpeed() (m/s now,
//                           at the world origin);
//                           swayStartAt(origins) -> "" or error: the same tree swayed as N
//                           instances (the grove page): origins = JS array of 3 N numbers, each
//                           instance's base in the world in METRES (x, y, z; converted to the
//                           model's cm), one SwaySimulator per instance, so each feels the wind
//                           field (travelling front and wave) at its own place; swayStep(n) then
//                           steps all N and swayPoses() holds N blocks of swayNodes() x 16 floats,
//                           instance k's node point j at floats (k swayNodes() + j) 16;
//                           swayInstances() -> N (1 after swayStart(), 0 before any start);
//                           hybrid rendering (thesis ch. 4, core/render): buildHybrid() -> "" or
//                           error (scene + atlas geometry: atlasSize(), atlasBarkPositions() ...
//                           atlasFlowersIndices(), clip-space triangles that paint the card atlas);
//                           hybridView(ex,ey,ez, tx,ty,tz, fovY, width, height) -> table 4.1 JSON
//                           and the draw list: card{Positions,Uvs,Indices,Joints,Weights}(),
//                           line{Positions,Colors,Widths,Joints,Weights}() (eq. 4.1 with
//                           hysteresis against the previous view, eq. 4.2 colours);
//                           hybridViewSlot(slot, ex,ey,ez, tx,ty,tz, fovY, width, height): the same
//                           with the hysteresis against the previous view OF THAT SLOT (0..255), so
//                           one tree can keep several draw lists (the grove page: one per distance
//                           band); the slots are cleared by buildHybrid().
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

#include "io/json_io.h"
#include "io/url_codec.h"
#include "params/param_table.h"
#include "render/atlas_mesh.h"
#include "render/hybrid.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree.h"
#include "tree/tree_gltf.h"

namespace niwa {
namespace {

using nlohmann::json;
using nlohmann::ordered_json;

constexpr double kMaxSeed = 4294967295.0;

// The sway and wind parameters of a state (rows of the one parameter table, groups "sway", "wind").
SwayParams SwayParamsOf(const ParamSet& params) { return SwayParams(params); }

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
    // The node points of this tree and the skin that ties every vertex to one of them (thesis
    // 3.3.1, eq. 3.15); the pose texture starts at rest.
    sways_.clear();
    sway_model_ = BuildSwayModel(grower_->tree(), SwayParams(state_.params));
    skin_ = BuildTreeSkin(mesh_, sway_model_);
    poses_.assign(sway_model_.nodes.size() * kSwayPoseFloats, 0.0f);
    RestSwayPoses(sway_model_.nodes.size(), poses_.data());
  }

  // ---- Sway (thesis chapter 3) of the tree last meshed ----
  int swayNodes() const { return static_cast<int>(sway_model_.nodes.size()); }

  // (Re)starts the sway from rest at time 0 with the state's sway and wind parameters.
  std::string swayStart() { return StartSway({glm::dvec3(0.0)}); }

  // The same with one simulator per instance; origins: 3 numbers per instance, metres.
  std::string swayStartAt(emscripten::val origins) {
    if (!origins.isArray()) return "sway: origins must be an array of 3 numbers per instance";
    const std::vector<double> o = emscripten::vecFromJSArray<double>(origins);
    if (o.empty() || o.size() % 3 != 0 || o.size() / 3 > kMaxSwayInstances)
      return "sway: origins must hold 3 numbers per instance, 1 to " +
             std::to_string(kMaxSwayInstances) + " instances";
    std::vector<glm::dvec3> at;
    for (std::size_t i = 0; i < o.size(); i += 3) {
      if (!std::isfinite(o[i]) || !std::isfinite(o[i + 1]) || !std::isfinite(o[i + 2]))
        return "sway: origins must be finite numbers";
      at.emplace_back(o[i] * 100.0, o[i + 1] * 100.0, o[i + 2] * 100.0);  // m -> cm
    }
    return StartSway(at);
  }
  int swayInstances() const { return static_cast<int>(sways_.size()); }

  // Advances every instance `steps` time steps (at most 64 per call) and writes the poses (one
  // block per instance); returns the time (s).
  double swayStep(int steps) {
    if (sways_.empty()) return 0;
    const std::size_t nodes = sway_model_.nodes.size();
    const int n = std::min(std::max(steps, 0), 64);
    for (std::size_t k = 0; k < sways_.size(); ++k) {
      for (int i = 0; i < n; ++i) sways_[k]->Step();
      if (poses_.size() == sways_.size() * nodes * kSwayPoseFloats)
        WriteSwayPoses(*sways_[k], MeshOptions{}.cm_to_units,
                       poses_.data() + k * nodes * kSwayPoseFloats);
    }
    return sways_[0]->time();
  }
  double swayDt() const { return sway_params_.dt; }
  double swayDuration() const { return sway_params_.duration; }
  // Wind speed (m/s) at the tree's root now: drives the leaf flutter in the shader.
  double swayWindSpeed() const {
    if (sways_.empty()) return 0;
    return glm::length(WindAt(sway_params_, glm::dvec3(0.0), sways_[0]->time())) / 100.0;
  }

  // {internodes, branches, leaves, flowers, height (cm), years, seed, preset, truncated, ms,
  // idle_prunes: ["prune 12:b40: why it cut nothing"], bounds}
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
    // Prunes that cut nothing (a URL may name a year or branch the tree does not have), one
    // notice each, once the tree has all its years.
    ordered_json idle = ordered_json::array();
    for (const Prune& prune : state_.prunes) {
      std::string reason = done() ? IdlePruneReason(prune, tree) : "";
      if (!reason.empty()) idle.push_back("prune " + FormatPrune(prune) + ": " + reason);
    }
    j["idle_prunes"] = std::move(idle);
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
    return WriteTreeGlb(mesh_, &glb_).Line();
  }
  emscripten::val glbBytes() const { return View(glb_); }

  emscripten::val leavesUvs() const { return View(mesh_.leaves.uvs); }
  emscripten::val barkJoints() const { return View(skin_.bark.joint); }
  emscripten::val barkWeights() const { return View(skin_.bark.weight); }
  emscripten::val leavesJoints() const { return View(skin_.leaves.joint); }
  emscripten::val leavesWeights() const { return View(skin_.leaves.weight); }
  emscripten::val flowersJoints() const { return View(skin_.flowers.joint); }
  emscripten::val flowersWeights() const { return View(skin_.flowers.weight); }
  emscripten::val swayPoses() const { return View(poses_); }

  // ---- Hybrid rendering (thesis chapter 4) of the tree last meshed ----
  std::string buildHybrid() {
    if (!grower_) return error_.empty() ? "no tree" : error_;
    RenderOptions options = RenderOptionsFromParams(state_.params);
    std::string error = CheckRenderOptions(options);
    if (!error.empty()) return error;
    hybrid_ = BuildHybridScene(grower_->tree(), options);
    atlas_ = BuildAtlasMesh(mesh_, hybrid_);
    has_selection_ = false;
    slots_.clear();
    return hybrid_.atlas_fits ? "" : "render: the card atlas does not fit; lower card_planes";
  }
  int atlasSize() const { return hybrid_.atlas_size; }
  int renderMode() const { return static_cast<int>(state_.params.Get(ParamId::kRenderMode)); }
  emscripten::val atlasBarkPositions() const { return View(atlas_.bark.positions); }
  emscripten::val atlasBarkNormals() const { return View(atlas_.bark.normals); }
  emscripten::val atlasBarkIndices() const { return View(atlas_.bark.indices); }
  emscripten::val atlasLeavesPositions() const { return View(atlas_.leaves.positions); }
  emscripten::val atlasLeavesNormals() const { return View(atlas_.leaves.normals); }
  emscripten::val atlasLeavesIndices() const { return View(atlas_.leaves.indices); }
  emscripten::val atlasFlowersPositions() const { return View(atlas_.flowers.positions); }
  emscripten::val atlasFlowersNormals() const { return View(atlas_.flowers.normals); }
  emscripten::val atlasFlowersIndices() const { return View(atlas_.flowers.indices); }

  // Card-or-line per branch for this camera (metres, radians, pixels), the draw list and its skin;
  // returns the table 4.1 counts as JSON (CountHybrid + CountFull), or {"error": ...}.
  std::string hybridView(double ex, double ey, double ez, double tx, double ty, double tz,
                         double fov_y, int width, int height) {
    ordered_json j;
    if (!grower_ || hybrid_.frames.empty()) {
      j["error"] = "no hybrid scene";
      return j.dump();
    }
    const Tree& tree = grower_->tree();
    RenderCamera camera;
    camera.eye = glm::vec3(static_cast<float>(ex), static_cast<float>(ey), static_cast<float>(ez));
    camera.target =
        glm::vec3(static_cast<float>(tx), static_cast<float>(ty), static_cast<float>(tz));
    camera.fov_y = static_cast<float>(fov_y);
    camera.width = std::max(1, width);
    camera.height = std::max(1, height);
    selection_ = SelectHybrid(tree, hybrid_, camera, has_selection_ ? &selection_ : nullptr);
    has_selection_ = true;
    LineShading shading;  // eq. 4.2 lit by the light model's sun (renderer.js setSun)
    const double el = state_.params.Get(ParamId::kSunElevation) * 3.14159265358979 / 180.0;
    const double az = state_.params.Get(ParamId::kSunAzimuth) * 3.14159265358979 / 180.0;
    shading.light_dir =
        glm::vec3(static_cast<float>(std::cos(el) * std::cos(az)), static_cast<float>(std::sin(el)),
                  static_cast<float>(std::cos(el) * std::sin(az)));
    draw_ = BuildDrawList(tree, hybrid_, selection_, camera, shading);
    draw_skin_ = BuildDrawListSkin(tree, hybrid_, draw_, sway_model_);
    RenderStats stats = CountHybrid(hybrid_, selection_);
    CountFull(mesh_, &stats);
    j["lines"] = stats.lines;
    j["line_branches"] = stats.line_branches;
    j["card_branches"] = stats.card_branches;
    j["branch_polygons"] = stats.branch_polygons;
    j["leaf_polygons"] = stats.leaf_polygons;
    j["total_polygons"] = stats.total_polygons;
    j["primitives"] = stats.primitives;
    j["textures"] = stats.textures;
    j["leaf_clusters"] = stats.leaf_clusters;
    j["full_polygons"] = stats.full_polygons;
    int alive = 0;
    for (const Branch& b : tree.branches) alive += b.alive ? 1 : 0;
    j["alive_branches"] = alive;
    return j.dump();
  }
  // hybridView with its own previous selection per slot (the default view keeps its own).
  std::string hybridViewSlot(int slot, double ex, double ey, double ez, double tx, double ty,
                             double tz, double fov_y, int width, int height) {
    if (slot < 0 || slot > 255)
      return R"({"error":"view: slot must be a whole number in [0, 255]"})";
    if (slots_.size() <= static_cast<size_t>(slot)) slots_.resize(slot + 1);
    Slot& s = slots_[slot];
    std::swap(selection_, s.selection);
    std::swap(has_selection_, s.has_selection);
    std::string out = hybridView(ex, ey, ez, tx, ty, tz, fov_y, width, height);
    std::swap(selection_, s.selection);
    std::swap(has_selection_, s.has_selection);
    return out;
  }
  emscripten::val cardPositions() const { return View(draw_.card_positions); }
  emscripten::val cardUvs() const { return View(draw_.card_uvs); }
  emscripten::val cardIndices() const { return View(draw_.card_indices); }
  emscripten::val cardJoints() const { return View(draw_skin_.cards.joint); }
  emscripten::val cardWeights() const { return View(draw_skin_.cards.weight); }
  emscripten::val linePositions() const { return View(draw_.line_positions); }
  emscripten::val lineColors() const { return View(draw_.line_colors); }
  emscripten::val lineWidths() const { return View(draw_.line_widths); }
  emscripten::val lineJoints() const { return View(draw_skin_.lines.joint); }
  emscripten::val lineWeights() const { return View(draw_skin_.lines.weight); }

  // The state's full parameter set as JSON (ParamsToJson), for the "Download .json" button.
  std::string paramsJson() const { return ParamsToJson(state_.params); }

 private:
  static constexpr std::size_t kMaxSwayInstances = 4096;

  // One simulator per origin (cm), from rest at time 0; the poses at rest.
  std::string StartSway(const std::vector<glm::dvec3>& origins) {
    if (!grower_) return error_.empty() ? "no tree" : error_;
    SwayParams params = SwayParamsOf(state_.params);
    std::string error = CheckSwayParams(state_.params);
    if (!error.empty()) return error;
    sways_.clear();
    for (const glm::dvec3& origin : origins)
      sways_.push_back(std::make_unique<SwaySimulator>(grower_->tree(), params, origin));
    sway_params_ = params;
    const std::size_t points = origins.size() * sway_model_.nodes.size();
    poses_.assign(points * kSwayPoseFloats, 0.0f);
    RestSwayPoses(points, poses_.data());
    return "";
  }

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
  SwayModel sway_model_;
  TreeSkin skin_;
  SwayParams sway_params_;
  std::vector<std::unique_ptr<SwaySimulator>> sways_;  // one per instance (swayStartAt)
  std::vector<float> poses_;  // sways_.size() blocks of nodes x 16 floats (one at rest before)
  HybridScene hybrid_;
  AtlasMesh atlas_;
  HybridSelection selection_;
  bool has_selection_ = false;
  HybridDrawList draw_;
  DrawListSkin draw_skin_;
  struct Slot {
    HybridSelection selection;
    bool has_selection = false;
  };
  std::vector<Slot> slots_;  // hybridViewSlot's previous selections
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
      .function("paramsJson", &niwa::GrowSession::paramsJson)
      .function("leavesUvs", &niwa::GrowSession::leavesUvs)
      .function("barkJoints", &niwa::GrowSession::barkJoints)
      .function("barkWeights", &niwa::GrowSession::barkWeights)
      .function("leavesJoints", &niwa::GrowSession::leavesJoints)
      .function("leavesWeights", &niwa::GrowSession::leavesWeights)
      .function("flowersJoints", &niwa::GrowSession::flowersJoints)
      .function("flowersWeights", &niwa::GrowSession::flowersWeights)
      .function("swayNodes", &niwa::GrowSession::swayNodes)
      .function("swayStart", &niwa::GrowSession::swayStart)
      .function("swayStartAt", &niwa::GrowSession::swayStartAt)
      .function("swayInstances", &niwa::GrowSession::swayInstances)
      .function("swayStep", &niwa::GrowSession::swayStep)
      .function("swayPoses", &niwa::GrowSession::swayPoses)
      .function("swayDt", &niwa::GrowSession::swayDt)
      .function("swayDuration", &niwa::GrowSession::swayDuration)
      .function("swayWindSpeed", &niwa::GrowSession::swayWindSpeed)
      .function("buildHybrid", &niwa::GrowSession::buildHybrid)
      .function("atlasSize", &niwa::GrowSession::atlasSize)
      .function("renderMode", &niwa::GrowSession::renderMode)
      .function("atlasBarkPositions", &niwa::GrowSession::atlasBarkPositions)
      .function("atlasBarkNormals", &niwa::GrowSession::atlasBarkNormals)
      .function("atlasBarkIndices", &niwa::GrowSession::atlasBarkIndices)
      .function("atlasLeavesPositions", &niwa::GrowSession::atlasLeavesPositions)
      .function("atlasLeavesNormals", &niwa::GrowSession::atlasLeavesNormals)
      .function("atlasLeavesIndices", &niwa::GrowSession::atlasLeavesIndices)
      .function("atlasFlowersPositions", &niwa::GrowSession::atlasFlowersPositions)
      .function("atlasFlowersNormals", &niwa::GrowSession::atlasFlowersNormals)
      .function("atlasFlowersIndices", &niwa::GrowSession::atlasFlowersIndices)
      .function("hybridView", &niwa::GrowSession::hybridView)
      .function("hybridViewSlot", &niwa::GrowSession::hybridViewSlot)
      .function("cardPositions", &niwa::GrowSession::cardPositions)
      .function("cardUvs", &niwa::GrowSession::cardUvs)
      .function("cardIndices", &niwa::GrowSession::cardIndices)
      .function("cardJoints", &niwa::GrowSession::cardJoints)
      .function("cardWeights", &niwa::GrowSession::cardWeights)
      .function("linePositions", &niwa::GrowSession::linePositions)
      .function("lineColors", &niwa::GrowSession::lineColors)
      .function("lineWidths", &niwa::GrowSession::lineWidths)
      .function("lineJoints", &niwa::GrowSession::lineJoints)
      .function("lineWeights", &niwa::GrowSession::lineWeights);
}

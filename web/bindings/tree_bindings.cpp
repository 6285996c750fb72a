// The tree study's bindings: TreeSession, an adapter over core/render/tree_run's TreeRun (one tree
// grown year by year, its mesh, skin, exports and table 4.1 counts) for the worker
// (web/worker/tree_handler.js), plus what only a page has: the running sway's simulators and
// poses, the card atlas and the per-view draw lists.
//
// JS BINDINGS DESIGN
// - One WASM module (niwa_web) holds every study: one EMSCRIPTEN_BINDINGS(niwa_<study>) block per
//   file (this one is niwa_tree; the table, presets and hash codec are common_bindings.cpp).
// - Everything that crosses from JavaScript arrives as text (JSON or a URL hash) and is checked by
//   the core itself (core/tree/tree_state: ApplyStateJson, DecodeTreeHash). Nothing here throws or
//   aborts on bad input: errors come back as an error record {ok: false, field, message}
//   (error_record.h): a returned string is "" or the record, a JSON answer is the record itself,
//   and TreeSession::error() says why a session has no tree.
// - Buffers leave through ONE generic accessor, buffers(group) -> {name: typed view} (buffers.h),
//   not one getter per buffer. The views point into the WASM heap and stay valid only until the
//   next call that may allocate: the worker copies each one ONCE right away and transfers that
//   copy to the main thread (web/worker/transfer.js). Groups:
//     "bark" | "leaves" | "flowers"   positions, normals (Float32 xyz), indices (Uint32), joints
//                                     (Uint32, node point per vertex) and weights (Float32,
//                                     eq. 3.15) of the sway skin (core/sway/skin.h); leaves also
//                                     uvs (Float32 uv: the texture coordinates of the .glb; leaves
//                                     v = 0 at the petiole); bark also branchIds (Uint32 per
//                                     vertex) and branchParents (Int32 per branch, -1 at the root);
//                                     each also occlusion (Float32 per vertex, 0-1: the crown's
//                                     ambient occlusion, core/tree/crown_occlusion.h, computed at
//                                     the first call after a mesh build, before any view is made)
//     "atlas.bark" | "atlas.leaves" | "atlas.flowers"   positions, normals, uvs, indices:
//                                     clip-space triangles that paint the card atlas (after
//                                     buildHybrid), uvs into the part's texture
//     "cards"                         positions, uvs, indices, joints, weights (after hybridView)
//     "lines"                         positions, colors, widths, joints, weights (after hybridView)
//     "sway"                          poses (16 floats per node point and instance, WriteSwayPoses)
//     "glb"                           bytes (Uint8, after buildGlb)
//   An unknown group gives null.
// - Calls, in order: TreeSession(stateJson) -> error(), hash(), years(); growYear() until done();
//   buildMesh(); statsJson(); buffers(...). update(stateJson) -> {ok, stages} hands a new state to
//   TreeRun::Update, which re-does only the earliest stage whose rows changed and the ones after
//   (grow: the run is reset, growYear() and buildMesh() again; mesh, sway, view: the tree stays,
//   the hybrid scene is cleared). swayStart() /
//   swayStartAt(origins in metres, 3 per instance) -> "" or error, swayStep(n) -> time, swayDt(),
//   swayStepsPerTick() (the worker's steps a tick, sway_budget), swaySpeed() (share of real time),
//   swayDuration(), swayWindSpeed(), swayInstances(). buildHybrid() -> "" or error, atlasSize(),
//   renderMode(), hybridView(ex,ey,ez, tx,ty,tz, fovY, width, height) -> table 4.1 JSON,
//   hybridViewSlot(slot, ...) with the hysteresis of that slot (0..255). buildGlb() -> "" or error;
//   paramsJson(). dressBark() -> "" or the error record: the bark the state's rows `bark` and
//   `bark_model` ask for on the tree as grown (core/compose/bark_on_tree's GrowTreeBark, the CLI's
//   run; 512 px maps, within the page budget; bark 0 the procedural bark again):
//   buffers("bark").uvs and the card atlas's "atlas.bark" uvs (buildHybrid) then wrap its maps,
//   barkTexture("bark" | "barkNormal") gives them ({width, height, pixels, digest}, null when not
//   dressed), barkJson() its summary, and buildGlb() writes them into the .glb (BarkTreeGlb).
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

#include "buffers.h"
#include "compose/bark_on_tree.h"
#include "error_record.h"
#include "image_val.h"
#include "light/sun.h"
#include "page_budget.h"
#include "params/param_json.h"
#include "params/param_table.h"
#include "params/param_text.h"
#include "render/atlas_mesh.h"
#include "render/hybrid.h"
#include "render/tree_lod.h"
#include "render/tree_run.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "sway/sway_budget.h"
#include "tree/crown_occlusion.h"
#include "tree/mesh.h"
#include "tree/tree.h"
#include "tree/tree_budget.h"
#include "tree/tree_params.h"
#include "tree/tree_state.h"
#include "tree/tree_textures.h"
#include "view_camera.h"

namespace niwa {
namespace {

using nlohmann::ordered_json;

const TreeMesh kNoMesh;
const TreeSkin kNoSkin;
const SwayModel kNoModel;
// The heights (m) the page reads the trunk at, the first the tree allows: breast height, then
// lower for a young or small tree (the page has no height control; the CLI's --bark-height).
constexpr double kPageBarkHeights[] = {compose::kDefaultBarkHeight, 0.5, 0.1, 0.02};
constexpr int kPageBarkMapSize = 512;

}  // namespace

// One tree grown year by year for the worker (web/worker/tree_handler.js), which yields to its
// event loop between years so a newer request can supersede this one.
class TreeSession {
 public:
  explicit TreeSession(const std::string& state_json) {
    error_ = ApplyStateJson(state_json, &state_);  // core/tree/tree_state
    if (!error_.ok()) return;
    SetPageLimits(&state_);
    Result<TreeRun> run = TreeRun::Start(state_, PageBudget());  // core/render/tree_run
    if (!run.ok()) {
      error_ = run.status();
      return;
    }
    run_ = std::make_unique<TreeRun>(std::move(run).value());
    ResetTrunks();
  }

  // The most internodes the page grows and draws: their mesh (about 150 MB of buffers) is built,
  // copied out of the heap and uploaded to the GPU without the page stalling for seconds.
  static constexpr long kPageInternodes = 400000;
  std::string error() const { return ErrorText(error_); }
  int years() const { return state_.years; }
  int year() const { return run_ ? run_->done() : 0; }
  bool done() const { return !run_ || run_->finished(); }
  std::string hash() const { return run_ ? run_->Hash("") : ""; }

  // A new state for the session's run (the page's edits): core/render/tree_run's TreeRun::Update
  // re-does only the earliest stage whose rows changed (the table's stage column) and the ones
  // after it. Returns {"ok": true, "stages": ["mesh", "sway", "view"]} (the stages re-done; none
  // when nothing changed) or the error record, the session unchanged on error. With "grow" the run
  // starts again from year 0 (growYear() and buildMesh() as after the constructor); otherwise the
  // tree stays, its mesh (stage mesh) and skin (mesh or sway) are rebuilt as the run says, and when
  // anything changed any sway stops and the hybrid scene is cleared (buildHybrid() rebuilds it with
  // the new render rows).
  std::string update(const std::string& state_json) {
    TreeState next;
    const Status error = ApplyStateJson(state_json, &next);
    if (!error.ok()) return ErrorRecordJson(error);
    if (!run_) return ErrorRecordJson(NoTree());
    SetPageLimits(&next);  // the growth's limits when it regrows (a later stage keeps the run's)
    const Result<run::StageMask> mask = run_->Update(next);
    if (!mask.ok()) return ErrorRecordJson(mask.status());
    ordered_json stages = ordered_json::array();
    for (Stage stage : {Stage::kGrow, Stage::kMesh, Stage::kSway, Stage::kView}) {
      if (*mask & (1u << static_cast<int>(stage))) stages.push_back(StageName(stage));
    }
    if (*mask & (1u << static_cast<int>(Stage::kGrow))) {
      ResetTrunks();
      bark_.reset();
    }
    if (*mask != 0) {
      state_ = run_->state();
      sways_.clear();
      RestPoses(model().nodes.size());
      hybrid_ = HybridScene{};
      atlas_ = AtlasMesh{};
      has_selection_ = false;
      slots_.clear();
      draw_ = HybridDrawList{};
      draw_skin_ = DrawListSkin{};
    }
    return JsonText(ordered_json{{"ok", true}, {"stages", stages}});
  }

  // The typed views of one buffer group (see JS BINDINGS DESIGN above), or null.
  emscripten::val buffers(const std::string& group) const {
    NamedBuffers out;
    const auto part = [&out](const MeshBuffers& mesh, const VertexSkin& skin) {
      out.Add("positions", mesh.positions)
          .Add("normals", mesh.normals)
          .Add("indices", mesh.indices)
          .Add("joints", skin.joint)
          .Add("weights", skin.weight);
    };
    const auto atlas = [&out](const MeshBuffers& mesh) {
      out.Add("positions", mesh.positions)
          .Add("normals", mesh.normals)
          .Add("uvs", mesh.uvs)
          .Add("indices", mesh.indices);
    };
    const TreeMesh& mesh = run_ ? run_->mesh() : kNoMesh;
    const TreeSkin& skin = run_ ? run_->skin() : kNoSkin;
    // The crown's ambient occlusion per vertex (core/tree/crown_occlusion.h), computed once per
    // mesh.
    const CrownOcclusion* occlusion = run_ && run_->has_mesh() ? &run_->occlusion() : nullptr;
    const auto occluded = [&out, occlusion](const std::vector<float> CrownOcclusion::*part) {
      if (occlusion) out.Add("occlusion", occlusion->*part);
    };
    if (group == "bark") {
      // Before the first view: WrapBarkUvs allocates, and a growth of the WASM memory would leave
      // the views already added pointing at the old buffer.
      if (bark_ && run_) bark_uvs_ = compose::WrapBarkUvs(run_->tree(), mesh, bark_->old_bark);
      part(mesh.bark, skin.bark);
      occluded(&CrownOcclusion::bark);
      out.Add("uvs", bark_ && run_ ? bark_uvs_ : mesh.bark.uvs)
          .Add("branchIds", mesh.bark_branch_id)
          .Add("branchParents", parents_);
    } else if (group == "leaves") {
      part(mesh.leaves, skin.leaves);
      out.Add("uvs", mesh.leaves.uvs);
      occluded(&CrownOcclusion::leaves);
    } else if (group == "flowers") {
      part(mesh.flowers, skin.flowers);
      out.Add("uvs", mesh.flowers.uvs);
      occluded(&CrownOcclusion::flowers);
    } else if (group == "atlas.bark") {
      atlas(atlas_.bark);
    } else if (group == "atlas.leaves") {
      atlas(atlas_.leaves);
    } else if (group == "atlas.flowers") {
      atlas(atlas_.flowers);
    } else if (group == "cards") {
      out.Add("positions", draw_.card_positions)
          .Add("uvs", draw_.card_uvs)
          .Add("indices", draw_.card_indices)
          .Add("joints", draw_skin_.cards.joint)
          .Add("weights", draw_skin_.cards.weight);
    } else if (group == "lines") {
      out.Add("positions", draw_.line_positions)
          .Add("colors", draw_.line_colors)
          .Add("widths", draw_.line_widths)
          .Add("joints", draw_skin_.lines.joint)
          .Add("weights", draw_skin_.lines.weight);
    } else if (group == "sway") {
      out.Add("poses", poses_);
    } else if (group == "glb") {
      out.Add("bytes", glb_);
    } else {
      return emscripten::val::null();
    }
    return out.ToJs();
  }

  // Grows one more year; false when the tree already has all its years (or the state was bad).
  bool growYear() {
    if (!run_ || !run_->GrowYear()) return false;
    for (compose::TrunkHistory& trunk : trunks_) compose::RecordTrunkYear(run_->tree(), &trunk);
    return true;
  }

  // The bark the state's rows ask for (the tree table's `bark`, `bark_model`; see JS BINDINGS
  // DESIGN): bark 0 takes any simulated bark off; bark 1 runs core/compose/bark_on_tree's
  // GrowTreeBark (the CLI's run) on the tree as grown at the first of kPageBarkHeights the trunk
  // allows, the tree's seed, camphor, 512 px maps, the tree's held estimate plus the bark's
  // checked against the page budget before any bark work (refused naming "bark"), unless the
  // bark on it is already that model's for this year. "" or the error record; on error the
  // session wears the procedural bark.
  std::string dressBark() {
    if (!run_) return ErrorRecordJson(NoTree());
    const ParamSet& rows = run_->state().params;
    if (!compose::TreeBarkSimulated(rows)) {
      undressBark();
      return "";
    }
    const Result<std::string> model = compose::TreeBarkModel(rows);
    if (!model.ok()) {
      undressBark();
      return ErrorRecordJson(model.status());
    }
    if (bark_ && bark_->plan.state.model == *model && bark_year_ == run_->done()) return "";
    undressBark();
    compose::BarkOnTreeOptions options;
    options.map_size = kPageBarkMapSize;
    options.seed = run_->state().seed;
    options.model = *model;
    Result<compose::BarkOnTree> bark = compose::GrowTreeBark(
        trunks_, options, run_->Held(), PageBudget(),
        *model == "4layer" ? "set bark_model 2 (the 2-layer model), or grow fewer years"
                           : "grow fewer years");
    if (!bark.ok()) return ErrorRecordJson(bark.status());
    bark_ = std::move(bark).value();
    bark_year_ = run_->done();
    return "";
  }
  void undressBark() {
    bark_.reset();
    bark_uvs_.clear();
  }
  bool barkDressed() const { return bark_.has_value(); }
  // {width, height, pixels: Uint8Array RGBA (a copy), digest} of the dressed bark's "bark" (base
  // colour) or "barkNormal" map; null when not dressed or another kind.
  emscripten::val barkTexture(const std::string& kind) const {
    if (!bark_ || (kind != "bark" && kind != "barkNormal")) return emscripten::val::null();
    const image::Rgba8Image& image =
        kind == "bark" ? bark_->old_bark.colour_pixels : bark_->old_bark.normal_pixels;
    emscripten::val out = ImageToJs(image);
    out.set("digest", "bark-sim-" + kind + "-" + ImageDigest(image));
    return out;
  }
  // compose::BarkOnTreeJson of the dressed bark, "" when not dressed.
  std::string barkJson() const { return bark_ ? compose::BarkOnTreeJson(*bark_) : ""; }

  // Builds the triangle meshes of the tree as grown so far; call before the buffer views. "" or
  // the line naming the page budget the mesh would cross (the mesh is then left empty).
  std::string buildMesh() {
    if (!run_) return "";
    // The mesh within the page's budget, its node points and skin (thesis 3.3.1, eq. 3.15).
    const Status error = run_->BuildMesh();
    if (!error.ok()) return ErrorText(error);
    parents_.clear();
    for (const Branch& branch : run_->tree().branches) parents_.push_back(branch.parent);
    sways_.clear();
    RestPoses(model().nodes.size());  // the pose texture starts at rest
    return "";
  }

  // ---- Sway (thesis chapter 3) of the tree last meshed ----
  int swayNodes() const { return static_cast<int>(model().nodes.size()); }

  // (Re)starts the sway from rest at time 0 with the state's sway and wind parameters.
  std::string swayStart() { return StartSway({glm::dvec3(0.0)}); }

  // The same with one simulator per instance; origins: 3 numbers per instance, metres.
  std::string swayStartAt(emscripten::val origins) {
    if (!origins.isArray()) {
      return ErrorText(Status::Error("sway", "origins must be an array of 3 numbers per instance"));
    }
    const std::vector<double> o = emscripten::vecFromJSArray<double>(origins);
    if (o.empty() || o.size() % 3 != 0 || o.size() / 3 > kMaxSwayInstances)
      return ErrorText(Status::Error("sway", "origins must hold 3 numbers per instance, 1 to " +
                                                 std::to_string(kMaxSwayInstances) + " instances"));
    std::vector<glm::dvec3> at;
    for (std::size_t i = 0; i < o.size(); i += 3) {
      if (!std::isfinite(o[i]) || !std::isfinite(o[i + 1]) || !std::isfinite(o[i + 2]))
        return ErrorText(Status::Error("sway", "origins must be finite numbers"));
      at.emplace_back(o[i] * 100.0, o[i + 1] * 100.0, o[i + 2] * 100.0);  // m -> cm
    }
    return StartSway(at);
  }
  int swayInstances() const { return static_cast<int>(sways_.size()); }

  // Advances every instance `steps` time steps (at most 64 per call) and writes the poses (one
  // block per instance); returns the time (s).
  double swayStep(int steps) {
    if (sways_.empty()) return 0;
    const std::size_t nodes = model().nodes.size();
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
  // Steps the worker may take in one tick (core/sway/sway_budget: within the page's tick, <= 8)
  // and the share of real time the sway is estimated to keep (1: real time; >= 1/4, else refused).
  int swayStepsPerTick() const { return sway_time_.steps_per_tick; }
  double swaySpeed() const { return sway_time_.speed; }
  double swayDuration() const { return sway_params_.duration; }
  // Wind speed (m/s) at the tree's root now: drives the leaf flutter in the shader.
  double swayWindSpeed() const {
    if (sways_.empty()) return 0;
    return glm::length(WindAt(sway_params_, glm::dvec3(0.0), sways_[0]->time())) / 100.0;
  }

  // The stats JSON of core/tree/tree_report (the CLI's --stats), plus idle_prunes (prunes that cut
  // nothing, once the tree has all its years) and bounds (of every mesh vertex, metres).
  std::string statsJson() const {
    if (!run_) return ErrorRecordJson(NoTree());
    return run_->PageStatsJson();
  }

  // The look of the mesh last built, for the textures (web/bindings/texture_bindings.cpp):
  // {"leaf_shape": 0..3, "season": 0..3, "autumn_colour": 0..4, "flower_colour": 0..4,
  // "flower_form": 0..1, "leaf_spray": 1..12} (core/tree/tree_look.h).
  std::string lookJson() const {
    const TreeLook& look = (run_ ? run_->mesh() : kNoMesh).look;
    ordered_json out;
    out["leaf_shape"] = static_cast<int>(look.leaf_shape);
    out["season"] = static_cast<int>(look.season);
    out["autumn_colour"] = static_cast<int>(look.autumn);
    out["flower_colour"] = static_cast<int>(look.flower_colour);
    out["flower_form"] = static_cast<int>(look.flower_form);
    out["leaf_spray"] = look.leaf_spray;
    return out.dump();
  }

  // Binary glTF of the mesh last built (buildMesh); "" or one error line. Then buffers("glb").
  // With the bark dressed (dressBark), the tree in its simulated bark: core/compose/bark_on_tree's
  // BarkTreeGlb, the bytes of `niwa tree grow --bark sim --out t.glb` for the same state, height
  // and map size (the old and the young shoots' maps: base colour, normal, occlusion), checked
  // first as the CLI checks it (the tree held, the .glb's work and the bark's, naming "bark").
  std::string buildGlb() {
    TreeExportRequest request;
    request.kind = TreeExportRequest::Kind::kGlb;
    if (!bark_ || !run_) return Export(request);
    glb_.clear();
    const Status fits =
        CheckEstimate(run_->Held() + run_->ExportWork(request) + bark_->plan.estimate, PageBudget(),
                      "set bark 0, or grow fewer years");
    if (!fits.ok()) return ErrorText(Status::Error("bark", fits.message()));
    Result<std::string> bytes = compose::BarkTreeGlb(run_->tree(), run_->mesh(), *bark_);
    if (!bytes.ok()) return ErrorText(bytes.status());
    glb_.assign(bytes->begin(), bytes->end());
    return "";
  }

  // Game-ready .glb (issue 17 item 4, core/render/tree_lod): within max_triangles (< 0: the full
  // mesh) and, with lod, the sibling nodes tree_LOD0..2. "" or one error line; then buffers("glb").
  std::string buildLodGlb(double max_triangles, bool lod) {
    glb_.clear();
    if (!run_) return ErrorText(NoTree());
    if (max_triangles >= 0) {
      const Status range = CheckValue("triangle budget", max_triangles,
                                      static_cast<double>(kMinLodTriangles), 1e8, true);
      if (!range.ok()) return ErrorText(range);
    }
    TreeExportRequest request;
    request.kind = TreeExportRequest::Kind::kLodGlb;
    request.max_triangles = max_triangles < 0 ? -1 : static_cast<long>(max_triangles);
    request.lod = lod;
    request.lod_field = "triangle budget";  // the export panel's field
    return Export(request);
  }

  // The wind sway as a skinned, animated .glb (core/sway/sway_gltf, as `niwa tree sway --out
  // x.glb`), its size estimated against the page budget first. "" or one error line.
  std::string buildSwayGlb(double fps) {
    glb_.clear();
    if (!run_) return ErrorText(NoTree());
    const Status range = CheckValue("sway fps", fps, 1, 240, false);
    if (!range.ok()) return ErrorText(range);
    TreeExportRequest request;
    request.kind = TreeExportRequest::Kind::kSwayGlb;
    request.fps = fps;
    return Export(request);
  }

  // ---- Hybrid rendering (thesis chapter 4) of the tree last meshed ----
  std::string buildHybrid() {
    if (!run_) return ErrorText(NoTree());
    RenderOptions options = RenderOptionsFromParams(state().params);
    const Status error = CheckRenderOptions(options);
    if (!error.ok()) return ErrorText(error);
    hybrid_ = BuildHybridScene(run_->tree(), options);
    // A dressed bark's cards wear its tile as the full view does (buffers("bark").uvs).
    if (bark_) {
      const std::vector<float> bark_uvs =
          compose::WrapBarkUvs(run_->tree(), run_->mesh(), bark_->old_bark);
      atlas_ = BuildAtlasMesh(run_->mesh(), hybrid_, &bark_uvs);
    } else {
      atlas_ = BuildAtlasMesh(run_->mesh(), hybrid_);
    }
    has_selection_ = false;
    slots_.clear();
    return hybrid_.atlas_fits ? ""
                              : ErrorText(Status::Error(
                                    "render", "the card atlas does not fit; lower card_planes"));
  }
  int atlasSize() const { return hybrid_.atlas_size; }
  int renderMode() const { return static_cast<int>(state().params.Get(ParamId::kRenderMode)); }

  // Card-or-line per branch for this camera (metres, radians, pixels), the draw list and its skin;
  // returns the table 4.1 counts as JSON (CountHybrid + CountFull), or an error record.
  std::string hybridView(double ex, double ey, double ez, double tx, double ty, double tz,
                         double fov_y, int width, int height) {
    ordered_json j;
    if (!run_ || hybrid_.frames.empty()) {
      return ErrorRecordJson(Status::Error("view", "no hybrid scene"));
    }
    const Tree& tree = run_->tree();
    const RenderCamera camera = ViewCamera(ex, ey, ez, tx, ty, tz, fov_y, width, height);
    selection_ = SelectHybrid(tree, hybrid_, camera, has_selection_ ? &selection_ : nullptr);
    has_selection_ = true;
    LineShading shading;  // eq. 4.2 lit by the light model's sun (renderer.js setSun)
    shading.light_dir =
        light::SunDirection(static_cast<float>(state().params.Get(ParamId::kSunElevation)),
                            static_cast<float>(state().params.Get(ParamId::kSunAzimuth)));
    draw_ = BuildDrawList(tree, hybrid_, selection_, camera, shading);
    draw_skin_ = BuildDrawListSkin(tree, hybrid_, draw_, model());
    return ViewCountsJson(run_->CountView(hybrid_, selection_));  // table 4.1, as render-stats
  }
  // hybridView with its own previous selection per slot (the default view keeps its own).
  std::string hybridViewSlot(int slot, double ex, double ey, double ez, double tx, double ty,
                             double tz, double fov_y, int width, int height) {
    if (slot < 0 || slot > 255)
      return ErrorRecordJson(Status::Error("view", "slot must be a whole number in [0, 255]"));
    if (slots_.size() <= static_cast<size_t>(slot)) slots_.resize(slot + 1);
    Slot& s = slots_[slot];
    std::swap(selection_, s.selection);
    std::swap(has_selection_, s.has_selection);
    std::string out = hybridView(ex, ey, ez, tx, ty, tz, fov_y, width, height);
    std::swap(selection_, s.selection);
    std::swap(has_selection_, s.has_selection);
    return out;
  }

  // The state's full parameter set as JSON (ParamsToJson), for the "Download .json" button.
  std::string paramsJson() const { return ParamsToJson(state().params); }

 private:
  // Why there is no tree: the state's or the start's error, else "tree: no tree".
  Status NoTree() const { return error_.ok() ? Status::Error("tree", "no tree") : error_; }

  // The page's growth limits on `state` (docs/budgets.md): what a laptop tab's WASM heap holds,
  // by estimate, and kPageInternodes.
  static void SetPageLimits(TreeState* state) {
    state->limits = TreeGrowLimits(state->params, PageBudget(), "years");
    state->limits.bytes_per_alive_internode = MeshBytesPerInternode(state->params);
    state->limits.max_internodes = kPageInternodes;
    state->limits.internode_limit = "page internode budget";
  }

  // The state of the run (after updates), or the one given when it was refused.
  const TreeState& state() const { return run_ ? run_->state() : state_; }
  const SwayModel& model() const { return run_ ? run_->sway_model() : kNoModel; }

  // One pose block at rest per node point of `points`.
  void RestPoses(std::size_t points) {
    poses_.assign(points * kSwayPoseFloats, 0.0f);
    RestSwayPoses(points, poses_.data());
  }

  // An export of the run into glb_, checked against the page's budget first: "" or one line.
  std::string Export(const TreeExportRequest& request) {
    glb_.clear();
    if (!run_) return ErrorText(NoTree());
    const Status fits = run_->CheckExport(request);
    if (!fits.ok()) return ErrorText(fits);
    Result<std::string> bytes = run_->Export(request);
    if (!bytes.ok()) return ErrorText(bytes.status());
    glb_.assign(bytes->begin(), bytes->end());
    return "";
  }

  static constexpr std::size_t kMaxSwayInstances = 4096;

  // One simulator per origin (cm), from rest at time 0; the poses at rest.
  std::string StartSway(const std::vector<glm::dvec3>& origins) {
    if (!run_) return ErrorText(NoTree());
    const SwayParams params = run_->sway_params();
    const Status error = CheckSwayParams(state().params);
    if (!error.ok()) return ErrorText(error);
    // The page's budget: the simulators and poses next to the tree and its mesh (docs/budgets.md).
    const SwayModel& sway_model = model();
    const Status fits = CheckEstimate(
        run_->grown() + EstimateTreeExport(CountTree(run_->tree()), TreeExport::kMesh) +
            EstimatePageSway(sway_model, static_cast<int>(origins.size())),
        PageBudget(), "lower years or the number of trees");
    if (!fits.ok()) return ErrorText(fits);
    // And its time: one worker tick of steps within the page's tick, at least 1/4 of real time.
    const int instances = static_cast<int>(origins.size());
    const PageSwayTime time = EstimatePageSwayTime(sway_model, params, instances);
    const Status in_time =
        CheckPageSwayTime(time, sway_model, params, instances, PageBudget().seconds_limit,
                          instances == 1 ? "raise dt, or lower years, N_high or B_l"
                                         : "raise dt, or lower years or the number of trees");
    if (!in_time.ok()) return ErrorText(in_time);
    sway_time_ = time;
    sways_.clear();
    for (const glm::dvec3& origin : origins)
      sways_.push_back(std::make_unique<SwaySimulator>(run_->tree(), params, origin));
    sway_params_ = params;
    RestPoses(origins.size() * sway_model.nodes.size());
    return "";
  }

  void ResetTrunks() {
    trunks_.clear();
    for (double height : kPageBarkHeights) {
      compose::TrunkHistory trunk;
      trunk.height_m = height;
      trunks_.push_back(std::move(trunk));
    }
  }

  std::vector<compose::TrunkHistory> trunks_;  // the trunk at kPageBarkHeights, year by year
  std::optional<compose::BarkOnTree> bark_;    // dressBark's bark
  int bark_year_ = 0;                          // the tree's year bark_ was grown on
  mutable std::vector<float> bark_uvs_;        // the mesh's bark UVs wrapping bark_'s tile
  TreeState state_;                            // as given (the run holds its own copy)
  Status error_;                  // why the session has no run (a bad state or a refused start)
  std::unique_ptr<TreeRun> run_;  // core/render/tree_run: growth, mesh, skin, exports, counts
  std::vector<int32_t> parents_;
  std::vector<unsigned char> glb_;
  SwayParams sway_params_;
  std::vector<std::unique_ptr<SwaySimulator>> sways_;  // one per instance (swayStartAt)
  PageSwayTime sway_time_;                             // of the sway started last
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

EMSCRIPTEN_BINDINGS(niwa_tree) {
  using namespace emscripten;
  class_<niwa::TreeSession>("TreeSession")
      .constructor<std::string>()
      .function("error", &niwa::TreeSession::error)
      .function("years", &niwa::TreeSession::years)
      .function("year", &niwa::TreeSession::year)
      .function("done", &niwa::TreeSession::done)
      .function("hash", &niwa::TreeSession::hash)
      .function("update", &niwa::TreeSession::update)
      .function("buffers", &niwa::TreeSession::buffers)
      .function("growYear", &niwa::TreeSession::growYear)
      .function("buildMesh", &niwa::TreeSession::buildMesh)
      .function("statsJson", &niwa::TreeSession::statsJson)
      .function("buildGlb", &niwa::TreeSession::buildGlb)
      .function("lookJson", &niwa::TreeSession::lookJson)
      .function("buildLodGlb", &niwa::TreeSession::buildLodGlb)
      .function("buildSwayGlb", &niwa::TreeSession::buildSwayGlb)
      .function("paramsJson", &niwa::TreeSession::paramsJson)
      .function("swayNodes", &niwa::TreeSession::swayNodes)
      .function("swayStart", &niwa::TreeSession::swayStart)
      .function("swayStartAt", &niwa::TreeSession::swayStartAt)
      .function("swayInstances", &niwa::TreeSession::swayInstances)
      .function("swayStep", &niwa::TreeSession::swayStep)
      .function("swayDt", &niwa::TreeSession::swayDt)
      .function("swayStepsPerTick", &niwa::TreeSession::swayStepsPerTick)
      .function("swaySpeed", &niwa::TreeSession::swaySpeed)
      .function("swayDuration", &niwa::TreeSession::swayDuration)
      .function("swayWindSpeed", &niwa::TreeSession::swayWindSpeed)
      .function("buildHybrid", &niwa::TreeSession::buildHybrid)
      .function("atlasSize", &niwa::TreeSession::atlasSize)
      .function("renderMode", &niwa::TreeSession::renderMode)
      .function("hybridView", &niwa::TreeSession::hybridView)
      .function("hybridViewSlot", &niwa::TreeSession::hybridViewSlot)
      .function("dressBark", &niwa::TreeSession::dressBark)
      .function("barkDressed", &niwa::TreeSession::barkDressed)
      .function("barkTexture", &niwa::TreeSession::barkTexture)
      .function("barkJson", &niwa::TreeSession::barkJson);
}

// The tree study's run over its three chapters: growth, mesh and sway skin, hybrid view counts and
// the exports.
#include "render/tree_run.h"

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <utility>

#include "math/rotation.h"
#include "params/param_table.h"
#include "params/param_text.h"
#include "render/lod_budget.h"
#include "sway/sway_budget.h"
#include "sway/sway_gltf.h"
#include "tree/prune.h"
#include "tree/tree_gltf.h"
#include "tree/tree_json.h"
#include "tree/tree_look.h"
#include "tree/tree_report.h"

namespace niwa {

Result<TreeExportRequest::Kind> TreeExportKind(const std::string& format) {
  using Kind = TreeExportRequest::Kind;
  if (format == "glb") return Kind::kGlb;
  if (format == "json") return Kind::kJson;
  if (format == "svg") return Kind::kSvg;
  if (format == "lod.glb") return Kind::kLodGlb;
  if (format == "sway.glb") return Kind::kSwayGlb;
  return Status::Error("format",
                       "'" + Echo(format) + "' must be glb, json, svg, lod.glb or sway.glb");
}

std::string ViewCountsJson(const TreeViewCounts& counts) {
  const RenderStats& stats = counts.stats;
  nlohmann::ordered_json j;
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
  j["alive_branches"] = counts.alive_branches;
  return j.dump();
}

std::string RenderStatsJson(const TreeViewCounts& counts, const RenderStatsHeader& header) {
  const RenderStats& stats = counts.stats;
  const bool full = header.full;
  nlohmann::ordered_json j;
  j["mode"] = full ? "full" : "hybrid";
  j["preset"] = header.preset;
  j["seed"] = header.seed;
  j["years"] = header.years;
  j["width"] = header.width;
  j["height"] = header.height;
  j["cam"] = header.cam;
  j["threshold"] = header.threshold;
  j["leaf_mode"] = header.leaf_mode;
  j["lines"] = full ? 0 : stats.lines;
  j["line_branches"] = full ? 0 : stats.line_branches;
  j["card_branches"] = full ? 0 : stats.card_branches;
  j["branch_polygons"] = full ? stats.full_bark : stats.branch_polygons;
  j["leaf_polygons"] = full ? stats.full_leaves + stats.full_flowers : stats.leaf_polygons;
  j["total_polygons"] = full ? stats.full_polygons : stats.total_polygons;
  j["primitives"] = full ? stats.full_polygons : stats.primitives;
  j["textures"] = full ? 0 : stats.textures;
  j["texture_groups"] = full ? 0 : stats.texture_groups;
  j["atlas_tiles"] = full ? 0 : stats.atlas_tiles;
  j["atlas_fits"] = counts.atlas_fits;
  j["leaf_clusters"] = full ? 0 : stats.leaf_clusters;
  j["leaf_branches"] = stats.leaf_branches;
  j["full_polygons"] = stats.full_polygons;
  j["full_bark"] = stats.full_bark;
  j["full_leaves"] = stats.full_leaves;
  j["full_flowers"] = stats.full_flowers;
  j["primitive_ratio"] =  // primitives drawn / full_polygons
      stats.full_polygons > 0 ? j["primitives"].get<double>() / stats.full_polygons : 0.0;
  j["ms_grow_mesh"] = header.ms_grow_mesh;
  j["ms_scene"] = header.ms_scene;
  j["ms_select"] = header.ms_select;
  return j.dump();
}

TreeRun::TreeRun(const TreeState& state, const Budget& budget)
    : state_(state), budget_(budget), grower_(std::make_unique<Grower>(state)) {}

Result<TreeRun> TreeRun::Start(const TreeState& state, const Budget& budget) {
  NIWA_RETURN_IF_ERROR(CheckValue("years", state.years, 0, kMaxYears, true));
  NIWA_RETURN_IF_ERROR(CheckGustOrder(state.params));
  return TreeRun(state, budget);
}

bool TreeRun::GrowYear() {
  if (finished()) return false;
  grower_->GrowYear();
  return true;
}

bool TreeRun::StartYear() {
  if (finished()) return false;
  const int before = grower_->year();
  grower_->StartYear();  // a limit may stop the growth instead
  return grower_->year() > before;
}

void TreeRun::FinishYear(const std::vector<LeafSphere>& foreign_shade) {
  grower_->FinishYear(foreign_shade);
}

Status TreeRun::Advance(const run::Observer& observer) {
  while (!finished()) {
    if (observer && !observer({"grow", static_cast<double>(done()), static_cast<double>(target())}))
      return run::CancelledStatus();
    grower_->GrowYear();
  }
  if (observer) observer({"grow", static_cast<double>(done()), static_cast<double>(target())});
  return Status::Ok();
}

MeshOptions TreeRun::LookOptions() const {
  // The look rows of the state (an Update of a mesh row changes them without regrowing the tree).
  MeshOptions options;
  options.look = LookFromParams(state_.params);
  return options;
}

Status TreeRun::BuildMesh() {
  const Status fits =
      CheckEstimate(grown() + EstimateTreeExport(CountTree(tree()), TreeExport::kMesh), budget_,
                    "lower " + state_.limits.years_name + ", N_high or B_l");
  if (!fits.ok()) {
    mesh_ = TreeMesh{};
    occlusion_.reset();
    has_mesh_ = true;
    return fits;
  }
  BuildBareMesh();
  BuildSkin();
  return Status::Ok();
}

void TreeRun::BuildBareMesh() {
  mesh_ = BuildTreeMesh(tree(), LookOptions());
  occlusion_.reset();
  has_mesh_ = true;
}

const CrownOcclusion& TreeRun::occlusion() {
  if (!occlusion_) occlusion_ = ComputeCrownOcclusion(mesh_);
  return *occlusion_;
}

void TreeRun::BuildSkin() {
  // The node points of this tree and the skin that ties every vertex to one of them (thesis
  // 3.3.1, eq. 3.15).
  sway_model_ = BuildSwayModel(tree(), sway_params());
  skin_ = BuildTreeSkin(mesh_, sway_model_);
}

Result<run::StageMask> TreeRun::Update(const TreeState& next) {
  NIWA_RETURN_IF_ERROR(CheckValue("years", next.years, 0, kMaxYears, true));
  NIWA_RETURN_IF_ERROR(CheckGustOrder(next.params));
  int earliest = static_cast<int>(Stage::kView) + 1;  // none
  std::vector<std::string> a, b;
  for (const Prune& prune : state_.prunes) a.push_back(FormatPrune(prune));
  for (const Prune& prune : next.prunes) b.push_back(FormatPrune(prune));
  if (next.preset != state_.preset || next.seed != state_.seed || next.years != state_.years ||
      a != b) {
    earliest = static_cast<int>(Stage::kGrow);
  }
  const ParamTable& table = state_.params.table();
  for (std::size_t row = 0; row < table.size(); ++row) {
    if (state_.params.Get(row) != next.params.Get(row)) {
      earliest = std::min(earliest, static_cast<int>(table.row(row).stage));
    }
  }
  // The look rows season, autumn_colour, flower_colour and flower_form are view rows of the table,
  // yet the mesh carries the look (a season drops leaves and flowers; the .glb paints its
  // textures): a changed look re-does the mesh.
  const TreeLook was = LookFromParams(state_.params), look = LookFromParams(next.params);
  if (was.leaf_shape != look.leaf_shape || was.season != look.season || was.autumn != look.autumn ||
      was.flower_colour != look.flower_colour || was.flower_form != look.flower_form ||
      was.leaf_spray != look.leaf_spray) {
    earliest = std::min(earliest, static_cast<int>(Stage::kMesh));
  }
  run::StageMask mask = 0;
  for (int stage = earliest; stage <= static_cast<int>(Stage::kView); ++stage) mask |= 1u << stage;
  if (mask == 0) return mask;
  if (earliest == static_cast<int>(Stage::kGrow)) {
    state_ = next;
    grower_ = std::make_unique<Grower>(state_);
    has_mesh_ = false;
    mesh_ = TreeMesh{};
    occlusion_.reset();
    sway_model_ = SwayModel{};
    skin_ = TreeSkin{};
    return mask;
  }
  const GrowLimits limits = state_.limits;  // the growth's, kept with the tree grown
  state_ = next;
  state_.limits = limits;
  if (has_mesh_ && earliest == static_cast<int>(Stage::kMesh)) BuildBareMesh();
  if (has_mesh_ && earliest <= static_cast<int>(Stage::kSway)) BuildSkin();
  return mask;
}

const TreeMesh& TreeRun::MeshOrBuilt(TreeMesh* scratch) const {
  if (has_mesh_) return mesh_;
  *scratch = BuildTreeMesh(tree(), LookOptions());
  return *scratch;
}

const SwayModel& TreeRun::ModelOrBuilt(SwayModel* scratch) const {
  if (has_mesh_ && !sway_model_.nodes.empty()) return sway_model_;
  *scratch = BuildSwayModel(tree(), sway_params());
  return *scratch;
}

Result<gltf::Document> TreeRun::Document() const {
  TreeMesh scratch;
  return TreeGltfDocument(MeshOrBuilt(&scratch));
}

std::vector<run::Part> TreeRun::Parts() const {
  std::vector<run::Part> parts;
  Result<gltf::Document> doc = Document();
  if (!doc.ok() || doc->meshes.empty()) return parts;
  for (const gltf::Primitive& primitive : doc->meshes[0].primitives) {
    run::Part part;
    part.mode = primitive.mode;
    part.mesh = primitive.mesh;
    if (primitive.material >= 0) {
      part.material = doc->materials[static_cast<std::size_t>(primitive.material)];
      part.name = part.material.name;  // "bark", "leaves", "flowers"
      // The part's own textures, its material's indices renumbered into them.
      for (int* texture :
           {&part.material.base_color_texture, &part.material.metallic_roughness_texture,
            &part.material.normal_texture, &part.material.occlusion_texture}) {
        if (*texture < 0) continue;
        part.textures.push_back(doc->textures[static_cast<std::size_t>(*texture)]);
        *texture = static_cast<int>(part.textures.size()) - 1;
      }
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

std::string TreeRun::StatsJson() const { return TreeStatsJson(tree(), timings()); }

std::string TreeRun::PageStatsJson() const {
  static const std::vector<Prune> kNone;
  TreeStatsExtras extras;
  extras.idle_prunes = finished() ? &state_.prunes : &kNone;
  extras.mesh = &mesh_;
  return TreeStatsJson(tree(), timings(), extras);
}

std::string TreeRun::Hash(const std::string& prefix) const {
  return EncodeTreeHash(state_, prefix);
}

Estimate TreeRun::Held() const {
  return has_mesh_ ? grown() + EstimateTreeExport(CountTree(tree()), TreeExport::kMesh) : grown();
}

Estimate TreeRun::ExportWork(const TreeExportRequest& request) const {
  using Kind = TreeExportRequest::Kind;
  const TreeCounts counts = CountTree(tree());
  switch (request.kind) {
    case Kind::kJson:
      return EstimateTreeExport(counts, TreeExport::kJson);
    case Kind::kSvg:
      return EstimateTreeExport(counts, TreeExport::kSvg);
    case Kind::kLodGlb:
      // The levels are built from the full mesh: core/render/lod_budget.
      return EstimateLodExport(counts, request.max_triangles, request.lod);
    case Kind::kSwayGlb: {
      SwayModel scratch;
      const Estimate clip = EstimateSwayGlb(ModelOrBuilt(&scratch), counts, sway_params(),
                                            request.fps, request.max_joints);
      // A budgeted mesh is built from the full one first (render/tree_lod_sway).
      if (request.sway_triangles < 0 ||
          static_cast<double>(request.sway_triangles) >= FullMeshTriangles(counts)) {
        return clip;
      }
      Estimate both = clip + EstimateLodExport(counts, request.sway_triangles, false);
      both.what = clip.what;  // the refusal names the clip, whose duration and fps the user sets
      return both;
    }
    case Kind::kGlb:
      break;
  }
  return EstimateTreeExport(counts, TreeExport::kGlb);
}

Result<Estimate> TreeRun::ExportEstimate(const std::string& format) const {
  Result<TreeExportRequest::Kind> kind = TreeExportKind(format);
  if (!kind.ok()) return kind.status();
  TreeExportRequest request;
  request.kind = *kind;
  return Held() + ExportWork(request);
}

Status TreeRun::CheckExport(const TreeExportRequest& request) const {
  const std::string& years = state_.limits.years_name;
  return CheckEstimate(Held() + ExportWork(request), budget_,
                       request.kind == TreeExportRequest::Kind::kSwayGlb
                           ? "lower duration or " + years
                           : "lower " + years + ", N_high or B_l");
}

Result<std::string> TreeRun::Export(const TreeExportRequest& request, SwayGlbInfo* sway,
                                    LodChoice* sway_choice) const {
  using Kind = TreeExportRequest::Kind;
  std::vector<unsigned char> glb;
  switch (request.kind) {
    case Kind::kJson:
      return TreeToJson(tree());
    case Kind::kSvg:
      return TreeToSvg(tree(), request.svg);
    case Kind::kGlb: {
      TreeMesh scratch;
      NIWA_RETURN_IF_ERROR(WriteTreeGlb(MeshOrBuilt(&scratch), &glb));
      break;
    }
    case Kind::kLodGlb: {
      // Game-ready export (issue 17 item 4): the budgeted level, or three LOD levels.
      std::vector<LodMesh> levels;
      if (request.lod) {
        Result<std::vector<LodMesh>> all =
            BuildLodLevels(tree(), request.max_triangles, LodOptions{}, request.lod_field);
        if (!all.ok()) return all.status();
        levels = std::move(all).value();
      } else {
        long budget = request.max_triangles;
        if (budget < 0) {
          TreeMesh scratch;
          budget = FullTriangles(MeshOrBuilt(&scratch));
        }
        Result<LodMesh> level = BuildLodMesh(tree(), budget, LodOptions{}, request.lod_field);
        if (!level.ok()) return level.status();
        levels.push_back(std::move(level).value());
      }
      NIWA_RETURN_IF_ERROR(WriteLodGlb(levels, &glb, "tree", request.layout));
      break;
    }
    case Kind::kSwayGlb: {
      // core/sway/sway_gltf's skin (exact or grouped), on the budgeted mesh when the full one
      // is over sway_triangles (render/tree_lod_sway).
      SwayGlbOptions options;
      options.fps = request.fps;
      options.max_joints = request.max_joints;
      options.key_error = request.key_error;
      NIWA_RETURN_IF_ERROR(WriteLodSwayGlb(tree(), sway_params(), options, request.sway_triangles,
                                           &glb, sway, sway_choice, request.lod_field));
      break;
    }
  }
  return std::string(glb.begin(), glb.end());
}

SwayRun TreeRun::Sway(int tips) const { return RunSway(tree(), sway_params(), tips); }

Estimate TreeRun::SwayEstimate(int tips) const {
  SwayModel scratch;
  return grown() + EstimateSwayRun(ModelOrBuilt(&scratch), sway_params(), tips);
}

OrbitView TreeRun::FrameView(float fov_y) const {
  TreeMesh scratch;
  return FrameOrbitView(MeshBounds(MeshOrBuilt(&scratch)), fov_y);
}

Status TreeRun::CheckPrunes() const {
  for (const Prune& prune : state_.prunes)
    NIWA_RETURN_IF_ERROR(IdlePruneReason(prune, tree()).Within("prune"));
  return Status::Ok();
}

Result<std::string> TreeRun::MappingsCsv(const TreeState& state, const Budget& budget) {
  if (!state.prunes.empty()) {  // a prune is checked against the tree it cuts
    Result<TreeRun> run = Start(state, budget);
    if (!run.ok()) return run.status();
    NIWA_RETURN_IF_ERROR(run->Advance(nullptr));
    NIWA_RETURN_IF_ERROR(run->CheckPrunes());
  }
  return TreeMappingsCsv(state.params);
}

Result<std::string> TreeRun::RenderStats(const TreeState& state, const Budget& budget,
                                         const RenderStatsRequest& request) {
  using Clock = std::chrono::steady_clock;
  const auto ms = [](Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  };
  RenderOptions render = RenderOptionsFromParams(state.params);
  render.line_segments = request.line_segments;
  NIWA_RETURN_IF_ERROR(CheckRenderOptions(render));
  const auto start = Clock::now();
  Result<TreeRun> started = Start(state, budget);
  if (!started.ok()) return started.status();
  TreeRun& run = *started;
  NIWA_RETURN_IF_ERROR(run.Advance(nullptr));
  NIWA_RETURN_IF_ERROR(run.CheckPrunes());
  run.BuildBareMesh();
  const float fov = request.fov_deg * (kPi / 180.0f);
  const OrbitView view = request.view ? *request.view : run.FrameView(fov);  // as the page frames
  const RenderCamera camera = CameraFromOrbit(view, request.width, request.height, fov);
  const auto select_start = Clock::now();
  const HybridScene scene = BuildHybridScene(run.tree(), render);
  const auto scene_end = Clock::now();
  const HybridSelection selection = SelectHybrid(run.tree(), scene, camera, nullptr);
  const TreeViewCounts counts = run.CountView(scene, selection);
  const auto select_end = Clock::now();
  RenderStatsHeader header;
  header.full = request.full;
  header.preset = run.tree().preset;
  header.seed = run.tree().seed;
  header.years = run.tree().years;
  header.width = request.width;
  header.height = request.height;
  header.cam = FormatOrbitView(view);
  header.threshold = render.threshold_px;
  header.leaf_mode = render.leaf_mode == LeafMode::kBranchCards ? "branch" : "cluster";
  header.ms_grow_mesh = ms(start, select_start);
  header.ms_scene = ms(select_start, scene_end);
  header.ms_select = ms(scene_end, select_end);
  return RenderStatsJson(counts, header);
}

TreeViewCounts TreeRun::CountView(const HybridScene& scene,
                                  const HybridSelection& selection) const {
  TreeViewCounts counts;
  counts.stats = CountHybrid(scene, selection);
  TreeMesh scratch;
  CountFull(MeshOrBuilt(&scratch), &counts.stats);
  counts.atlas_fits = scene.atlas_fits;
  for (const Branch& b : tree().branches) counts.alive_branches += b.alive ? 1 : 0;
  return counts;
}

}  // namespace niwa

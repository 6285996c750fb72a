// niwa CLI command of the render study: 'tree render-stats', what hybrid rendering (thesis ch. 4:
// cards and lines, core/render/hybrid) draws for a view, as JSON.
// cli-order: 30
#include <chrono>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "base/echo.h"
#include "cli_common.h"
#include "math/rotation.h"
#include "render/hybrid.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree_cli.h"

namespace niwa::cli {
namespace {

const FlagRange kViewport = {16, 16384, true};
const FlagRange kFov = {1, 170, false};
const FlagRange kPitch = {kMinPitch, kMaxPitch, false, " (radians)", true};
const FlagRange kDistance = {kMinDistance, kMaxDistance, false, " (metres)", true};
const FlagRange kYaw = {-kMaxYaw, kMaxYaw, false, " (radians)"};
const FlagRange kThreshold = {0.1, 1000, false, "", true};
const FlagRange kCardPlanes = {2, 8, true};
const FlagRange kLineSegments = {1, 64, true};

// ---- tree render-stats: thesis chapter 4 hybrid rendering counts (core/render/hybrid) ----
struct RenderStatsOptions {
  StateOptions state;
  int width = 512, height = 512;
  std::string cam, target, mode = "hybrid", leaf_mode = "cluster";
  float yaw = kDefaultYaw, pitch = kDefaultPitch, distance = 10, fov_deg = 45;
  RenderOptions render;
};

// The range of a render row of the tree table ("0.1..1000"): the flags that override a row take
// its range (checked by CheckRenderOptions).
std::string RowRange(ParamId id) { return RangeHelp(Spec(id)); }

void AddRenderStatsOptions(CLI::App* cmd, RenderStatsOptions* o) {
  AddNumberFlag(cmd, "--width", &o->width, kViewport,
                "Viewport width in pixels, " + RangeHelp(kViewport) + " (default 512)");
  AddNumberFlag(cmd, "--height", &o->height, kViewport,
                "Viewport height in pixels, " + RangeHelp(kViewport) + " (default 512)");
  cmd->add_option("--cam", o->cam,
                  "Camera as in the share link's cam=: yaw,pitch,distance,tx,ty,tz, yaw in "
                  "[-1000, 1000] rad, pitch and distance as below, each target coordinate in "
                  "[-10000, 10000] m (default: the page's framing of a new tree)");
  AddNumberFlag(cmd, "--yaw", &o->yaw, kYaw,
                "Camera yaw, radians, " + RangeHelp(kYaw) + " (overrides --cam)");
  AddNumberFlag(cmd, "--pitch", &o->pitch, kPitch,
                "Camera pitch, radians, " + RangeHelp(kPitch) + " (overrides --cam)");
  AddNumberFlag(
      cmd, "--distance", &o->distance, kDistance,
      "Camera distance to the target, metres, " + RangeHelp(kDistance) + " (overrides --cam)");
  cmd->add_option("--target", o->target,
                  "Camera target x,y,z in metres, each in [-10000, 10000] (overrides --cam)");
  AddNumberFlag(cmd, "--fov", &o->fov_deg, kFov,
                "Vertical field of view, degrees, " + RangeHelp(kFov) + " (default 45)");
  cmd->add_option("--mode", o->mode, "hybrid (thesis 4.2) or full (every polygon)");
  AddNumberFlag(cmd, "--threshold", &o->render.threshold_px, kThreshold,
                "Eq. 4.1 card/line threshold, pixels, " + RowRange(ParamId::kLineThreshold) +
                    " (overrides the line_threshold parameter, default " +
                    FormatNumber(Spec(ParamId::kLineThreshold).default_value) + ")");
  cmd->add_option("--leaf-mode", o->leaf_mode,
                  "cluster (leaf-cluster cards, thesis 5.2) or branch (thesis 4.2.1); overrides "
                  "the leaf_cluster_cards parameter (default 1: cluster)");
  AddNumberFlag(cmd, "--card-planes", &o->render.card_planes, kCardPlanes,
                "Card planes per branch, " + RowRange(ParamId::kCardPlanes) +
                    " (overrides the card_planes parameter, default " +
                    FormatNumber(Spec(ParamId::kCardPlanes).default_value) + ")");
  AddNumberFlag(cmd, "--line-segments", &o->render.line_segments, kLineSegments,
                "Most line segments per line branch, 1..64 (default 1)");
}

int RunRenderStats(RenderStatsOptions o, const CLI::App& cmd, std::ostream& out) {
  Check(CheckFlag("--width", o.width, kViewport));
  Check(CheckFlag("--height", o.height, kViewport));
  Check(CheckFlag("--fov", o.fov_deg, kFov));
  if (o.mode != "hybrid" && o.mode != "full") {
    throw BadInput{"--mode: '" + Echo(o.mode) + "' must be hybrid or full"};
  }
  if (o.leaf_mode != "cluster" && o.leaf_mode != "branch") {
    throw BadInput{"--leaf-mode: '" + Echo(o.leaf_mode) + "' must be cluster or branch"};
  }
  Status render_status = CheckRenderOptions(o.render);
  if (!render_status
           .ok()) {  // the options' fields are the flags' names: card_planes -> --card-planes
    std::string flag = render_status.field();
    for (char& c : flag) c = c == '_' ? '-' : c;
    Fail(Status::Error("--" + flag, render_status.message()));
  }
  std::string error;
  OrbitView view;
  if (!o.cam.empty() && !ParseOrbitView(o.cam, &view, &error)) throw BadInput{"--" + error};
  if (cmd.count("--yaw")) {
    if (!std::isfinite(o.yaw)) throw BadInput{"--yaw: must be a finite number (radians)"};
    view.yaw = o.yaw;
  }
  if (cmd.count("--pitch")) {
    Check(CheckFlag("--pitch", o.pitch, kPitch));
    view.pitch = o.pitch;
  }
  if (cmd.count("--distance")) {
    Check(CheckFlag("--distance", o.distance, kDistance));
    view.distance = o.distance;
  }
  if (cmd.count("--target")) {
    std::stringstream stream(o.target);
    std::string item;
    std::vector<double> xyz;
    while (std::getline(stream, item, ',')) {
      std::optional<double> v = ParseNumber(item);
      if (!v || !(std::fabs(*v) <= kMaxTarget)) break;
      xyz.push_back(*v);
    }
    if (xyz.size() != 3 || o.target.back() == ',') {
      throw BadInput{"--target: '" + Echo(o.target) +
                     "' must be three numbers x,y,z, each in [-10000, 10000] (metres)"};
    }
    view.target = glm::vec3(static_cast<float>(xyz[0]), static_cast<float>(xyz[1]),
                            static_cast<float>(xyz[2]));
  }
  TreeState request = ResolveTreeState(o.state, cmd);
  // The render rows of the parameter table (--set, --params, --url) give the options; the
  // --threshold, --leaf-mode and --card-planes flags override them.
  RenderOptions render = RenderOptionsFromParams(request.params);
  render.line_segments = o.render.line_segments;
  if (cmd.count("--threshold")) render.threshold_px = o.render.threshold_px;
  if (cmd.count("--card-planes")) render.card_planes = o.render.card_planes;
  if (cmd.count("--leaf-mode")) {
    render.leaf_mode = o.leaf_mode == "branch" ? LeafMode::kBranchCards : LeafMode::kClusterCards;
  }
  o.render = render;
  o.leaf_mode = render.leaf_mode == LeafMode::kBranchCards ? "branch" : "cluster";
  auto start = std::chrono::steady_clock::now();
  Tree tree = GrowTree(request);
  CheckPrunes(request, tree);
  TreeMesh mesh = BuildTreeMesh(tree);
  const float fov = o.fov_deg * (kPi / 180.0f);
  bool explicit_camera = !o.cam.empty();
  for (const char* flag : {"--yaw", "--pitch", "--distance", "--target"}) {
    explicit_camera = explicit_camera || cmd.count(flag) > 0;
  }
  if (!explicit_camera) view = FrameOrbitView(MeshBounds(mesh), fov);  // as the page frames it
  RenderCamera camera = CameraFromOrbit(view, o.width, o.height, fov);
  auto select_start = std::chrono::steady_clock::now();
  HybridScene scene = BuildHybridScene(tree, o.render);
  auto scene_end = std::chrono::steady_clock::now();
  HybridSelection selection = SelectHybrid(tree, scene, camera, nullptr);
  RenderStats stats = CountHybrid(scene, selection);
  auto select_end = std::chrono::steady_clock::now();
  CountFull(mesh, &stats);
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const bool full = o.mode == "full";
  nlohmann::ordered_json j;
  j["mode"] = o.mode;
  j["preset"] = tree.preset;
  j["seed"] = tree.seed;
  j["years"] = tree.years;
  j["width"] = o.width;
  j["height"] = o.height;
  j["cam"] = FormatOrbitView(view);
  j["threshold"] = o.render.threshold_px;
  j["leaf_mode"] = o.leaf_mode;
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
  j["atlas_fits"] = scene.atlas_fits;
  j["leaf_clusters"] = full ? 0 : stats.leaf_clusters;
  j["leaf_branches"] = stats.leaf_branches;
  j["full_polygons"] = stats.full_polygons;
  j["full_bark"] = stats.full_bark;
  j["full_leaves"] = stats.full_leaves;
  j["full_flowers"] = stats.full_flowers;
  j["primitive_ratio"] =  // primitives drawn / full_polygons
      stats.full_polygons > 0 ? j["primitives"].get<double>() / stats.full_polygons : 0.0;
  j["ms_grow_mesh"] = ms(start, select_start);
  j["ms_scene"] = ms(select_start, scene_end);
  j["ms_select"] = ms(scene_end, select_end);
  out << j.dump() << "\n";
  return 0;
}

}  // namespace

void AddRenderCommands(CLI::App& app, CommandList& commands) {
  CLI::App* tree = Subcommand(app, "tree", "Grow and export trees");
  CLI::App* render_stats = tree->add_subcommand(
      "render-stats",
      "Count what hybrid rendering (thesis ch. 4: cards and lines) draws for a view, as JSON");
  auto options = std::make_shared<RenderStatsOptions>();
  AddStateOptions(render_stats, TreeParamTable(), &options->state);
  AddRenderStatsOptions(render_stats, options.get());
  commands.push_back({render_stats, [render_stats, options](std::ostream& out) {
                        return RunRenderStats(*options, *render_stats, out);
                      }});
}

}  // namespace niwa::cli

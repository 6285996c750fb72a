// niwa CLI command of the render study: 'tree render-stats', what hybrid rendering (thesis ch. 4:
// cards and lines, core/render/hybrid) draws for a view, as JSON.
// cli-order: 30
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "base/echo.h"
#include "cli_common.h"
#include "math/rotation.h"
#include "render/hybrid.h"
#include "render/tree_run.h"
#include "run/field_names.h"
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
  // The options' fields are the flags' names (card_planes -> --card-planes): TreeFlagNames.
  Check(run::RenameField(CheckRenderOptions(o.render), TreeFlagNames()));
  OrbitView view;
  if (!o.cam.empty()) Check(run::RenameField(ParseOrbitView(o.cam, &view), TreeFlagNames()));
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
  // The flags into the state: --threshold, --card-planes and --leaf-mode override the render
  // rows of the table (--set, --params, --url); the run reads its options from the rows.
  TreeState state = ResolveTreeState(o.state, cmd);
  if (cmd.count("--threshold"))
    Check(AsFlag(state.params.Set(ParamId::kLineThreshold, o.render.threshold_px), "--threshold"));
  if (cmd.count("--card-planes"))
    Check(AsFlag(state.params.Set(ParamId::kCardPlanes, o.render.card_planes), "--card-planes"));
  if (cmd.count("--leaf-mode"))
    Check(AsFlag(state.params.Set(ParamId::kLeafClusterCards, o.leaf_mode == "branch" ? 0 : 1),
                 "--leaf-mode"));
  RenderStatsRequest request;
  request.full = o.mode == "full";
  request.width = o.width;
  request.height = o.height;
  request.fov_deg = o.fov_deg;
  request.line_segments = o.render.line_segments;
  bool explicit_camera = !o.cam.empty();
  for (const char* flag : {"--yaw", "--pitch", "--distance", "--target"})
    explicit_camera = explicit_camera || cmd.count(flag) > 0;
  if (explicit_camera) request.view = view;  // else the page's framing of the tree
  // core/render/tree_run: grow, prunes, mesh, the view's table 4.1.
  Result<std::string> stats = TreeRun::RenderStats(state, ResolveBudget(o.state.budget), request);
  Check(run::RenameField(stats.status(), TreeFlagNames()));
  out << *stats << "\n";
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
  commands.push_back({render_stats,
                      [render_stats, options](std::ostream& out) {
                        return RunRenderStats(*options, *render_stats, out);
                      },
                      {"--preset", "binary", "--years", "2"}});
}

}  // namespace niwa::cli

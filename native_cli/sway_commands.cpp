// niwa CLI command of the sway study: 'tree sway', the node-point wind sway of thesis chapter 3
// (core/sway, docs/sway-model.md) on a grown tree.
// cli-order: 20
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "base/echo.h"
#include "cli_common.h"
#include "render/tree_run.h"
#include "run/field_names.h"
#include "sway/sway.h"
#include "tree_cli.h"

namespace niwa::cli {
namespace {

const FlagRange kTips = {1, 50, true};
const FlagRange kFps = {1, 240, false};
const FlagRange kMaxJoints = {2, static_cast<double>(kMaxGltfJoints), true};
const FlagRange kSwayTriangles = {static_cast<double>(kMinLodTriangles), 100000000, true};
const FlagRange kKeyError = {0, 1, false, " (metres)"};

struct SwayOptions {
  StateOptions state;
  double wind = 0, wind_dir = 0, dt = 0, duration = 0;
  std::string gust, csv_path, svg_path;
  std::vector<std::string> sets;
  bool stats = false;
  int tips = 4;
  std::string out_path;  // .glb (skinned, animated), .csv or .svg
  double fps = 30;       // keys per second in the .glb
  double max_joints = static_cast<double>(kDefaultSwayJoints);        // the .glb skin's joints
  double max_triangles = static_cast<double>(kDefaultSwayTriangles);  // the .glb's mesh
  bool full_mesh = false;                                             // --full-mesh
  double key_error = kDefaultSwayKeyError;  // the clip's key reduction bound, metres
};

// "m/s, 0..100": a table row's unit and range for a flag's help.
std::string RowHelp(ParamId id) { return std::string(Spec(id).unit) + ", " + RangeHelp(Spec(id)); }

void AddSwayOptions(CLI::App* cmd, SwayOptions* o) {
  AddNumberFlag(cmd, "--wind", &o->wind, RowFlagRange(Spec(ParamId::kWindSpeed)),
                "Wind speed while the gust blows, " + RowHelp(ParamId::kWindSpeed) + " (default " +
                    FormatNumber(Spec(ParamId::kWindSpeed).default_value) + ")");
  AddNumberFlag(cmd, "--wind-dir", &o->wind_dir, RowFlagRange(Spec(ParamId::kWindDir)),
                "Wind azimuth, degrees, " + RangeHelp(Spec(ParamId::kWindDir)) +
                    ": 0 blows towards +x, 90 towards +z");
  cmd->add_option("--gust", o->gust,
                  "ON_S:OFF_S: the wind starts at ON and stops at OFF (default 1:6)");
  AddNumberFlag(cmd, "--dt", &o->dt, RowFlagRange(Spec(ParamId::kSwayDt)),
                "Time step, " + RowHelp(ParamId::kSwayDt) + " (default 1/30)");
  AddNumberFlag(cmd, "--duration", &o->duration, RowFlagRange(Spec(ParamId::kSwayDuration)),
                "Simulated time, " + RowHelp(ParamId::kSwayDuration) + " (default " +
                    FormatNumber(Spec(ParamId::kSwayDuration).default_value) + ")");
  cmd->add_option("--set-sway", o->sets,
                  "Same as --set (kept for old scripts): sway and wind parameters are rows of "
                  "the one table, see 'niwa params'");
  AddNumberFlag(cmd, "--tips", &o->tips, kTips,
                "Tips traced in --csv and --svg, " + RangeHelp(kTips) + " (default 4)");
  AddOutputFlag(cmd, "--csv", &o->csv_path, {".csv"},
                "Write tip trajectories: time,node,x,y,z (s, cm)");
  AddOutputFlag(cmd, "--svg", &o->svg_path, {".svg"},
                "Write a plot of tip displacement against time");
  cmd->add_flag("--stats", o->stats, "Print one JSON object of statistics on stdout");
  AddOutputFlag(cmd, "--out", &o->out_path, {".glb", ".csv", ".svg"},
                "Write the sway: .glb (tree mesh skinned to the node points, one animation clip "
                "of the run), .csv (as --csv) or .svg (as --svg)");
  OnlyWith(AddNumberFlag(cmd, "--fps", &o->fps, kFps,
                         "Animation keys per second of simulated time in --out .glb, " +
                             RangeHelp(kFps) +
                             " (default 30); each key is the state at the nearest time step"),
           "--out", {".glb"});
  OnlyWith(
      AddNumberFlag(cmd, "--max-joints", &o->max_joints, kMaxJoints,
                    "Joints of the --out .glb skin, the root included, " + RangeHelp(kMaxJoints) +
                        " (default " + std::to_string(kDefaultSwayJoints) +
                        "); a tree that needs more for the exact skin gets node points "
                        "grouped, each group turning with one rod"),
      "--out", {".glb"});
  OnlyWith(AddNumberFlag(cmd, "--max-triangles", &o->max_triangles, kSwayTriangles,
                         "Triangles of the --out .glb's mesh, " + RangeHelp(kSwayTriangles) +
                             " (default " + std::to_string(kDefaultSwayTriangles) +
                             "): a larger tree is skinned on its budgeted mesh (tubes, branch "
                             "and leaf-cluster cards, twig cones; docs/lod-export.md)"),
           "--out", {".glb"});
  OnlyWith(cmd->add_flag("--full-mesh", o->full_mesh,
                         "Skin the full mesh in --out .glb whatever its triangles"),
           "--out", {".glb"});
  OnlyWith(AddNumberFlag(cmd, "--key-error", &o->key_error, kKeyError,
                         "Keys of the --out .glb clip left out while their joints' interpolation "
                         "stays within this many metres at every vertex, " +
                             RangeHelp(kKeyError) + " (default " +
                             FormatNumber(kDefaultSwayKeyError) + "; 0 keeps every key)"),
           "--out", {".glb"});
}

// The flag whose values made CheckSwayParams fail: the last given of --gust, --set-sway, --set,
// --params and --url (in the order they apply: --url, --params, --set, --set-sway, --gust).
std::string SwayErrorSource(const SwayOptions& o, const CLI::App& cmd) {
  if (cmd.count("--gust")) return "--gust";
  if (!o.sets.empty()) return "--set-sway";
  if (!o.state.sets.empty()) return "--set";
  if (!o.state.params_file.empty()) return "--params";
  if (!o.state.url.empty()) return "--url";
  return "--set";
}

// Sway and wind parameters are rows of the tree table: --url, --params, --set (and its alias
// --set-sway) reach them through the state; the flags below override those.
SwayParams ResolveSwayParams(const SwayOptions& o, const CLI::App& cmd, TreeParams* params) {
  for (const std::string& item : o.sets) {
    Check(params->SetFromAssignment(item).Within("--set-sway"));
  }
  auto set = [&](const char* flag, ParamId id, double value) {
    if (cmd.count(flag)) Check(params->Set(id, value).Within(flag));
  };
  set("--wind", ParamId::kWindSpeed, o.wind);
  set("--wind-dir", ParamId::kWindDir, o.wind_dir);
  set("--dt", ParamId::kSwayDt, o.dt);
  set("--duration", ParamId::kSwayDuration, o.duration);
  if (cmd.count("--gust")) {
    std::size_t colon = o.gust.find(':');
    std::optional<double> on, off;
    if (colon != std::string::npos) {
      on = ParseNumber(o.gust.substr(0, colon));
      off = ParseNumber(o.gust.substr(colon + 1));
    }
    if (!on || !off) {
      throw BadInput{"--gust: '" + Echo(o.gust) + "' must be ON_S:OFF_S, e.g. 1:6"};
    }
    set("--gust", ParamId::kGustOn, *on);
    set("--gust", ParamId::kGustOff, *off);
  }
  const Status sway = CheckSwayParams(*params);  // a row's field, under the flag that set it
  if (!sway.ok()) throw BadInput{SwayErrorSource(o, cmd) + ": " + sway.Line()};
  Check(CheckFlag("--tips", o.tips, kTips));
  return SwayParams(*params);
}

int RunSwayCommand(const SwayOptions& o, const CLI::App& cmd, std::ostream& out) {
  const std::string out_ext = Extension(o.out_path);  // its ending and --fps: the shared flags
  Check(CheckFlag("--fps", o.fps, kFps));
  Check(CheckFlag("--max-joints", o.max_joints, kMaxJoints));
  Check(CheckFlag("--max-triangles", o.max_triangles, kSwayTriangles));
  Check(CheckFlag("--key-error", o.key_error, kKeyError));
  if (o.full_mesh && cmd.count("--max-triangles")) {
    throw BadInput{"--full-mesh: give it without --max-triangles"};
  }
  TreeState state = ResolveTreeState(o.state, cmd);
  SwayParams params = ResolveSwayParams(o, cmd, &state.params);
  Result<TreeRun> started = TreeRun::Start(state, ResolveBudget(o.state.budget));
  Check(run::RenameField(started.status(), TreeFlagNames()));
  TreeRun& run = *started;      // core/render/tree_run
  Check(run.Advance(nullptr));  // stops early (truncated) at the budget's growth limits
  ReportTruncated(run.tree().truncated_by);
  Check(run::RenameField(run.CheckPrunes(), TreeFlagNames()));
  TreeExportRequest glb_request;
  glb_request.kind = TreeExportRequest::Kind::kSwayGlb;
  glb_request.fps = o.fps;
  glb_request.max_joints = static_cast<std::size_t>(o.max_joints);
  glb_request.sway_triangles = o.full_mesh ? -1 : static_cast<long>(o.max_triangles);
  glb_request.key_error = o.key_error;
  glb_request.lod_field = "--max-triangles";
  {
    // Every output's estimate, refused before any work starts (so no output is left behind).
    Estimate total = run.SwayEstimate(o.tips);
    if (out_ext == ".glb") total = total + run.ExportWork(glb_request);
    Check(CheckEstimate(total, ResolveBudget(o.state.budget),
                        "lower --duration or --years, or raise --dt" +
                            std::string(out_ext == ".glb" ? " or lower --fps" : "")));
  }
  // Every output is staged first and renamed only when all were written (all or none).
  StagedOutputs outputs;
  SwayGlbInfo glb_info;
  LodChoice glb_choice;
  if (out_ext == ".glb") {  // core/sway/sway_gltf's skin on render/tree_lod_sway's mesh
    Result<std::string> glb = run.Export(glb_request, &glb_info, &glb_choice);
    if (!glb.ok()) {
      if (glb.status().field() == "--max-triangles") throw BadInput{glb.status().Line()};
      throw BadInput{"--out: " + glb.status().Line()};
    }
    Check(outputs.Stage("--out", o.out_path, *glb));
  }
  SwayRun sway = run.Sway(o.tips);
  if (out_ext == ".csv" || out_ext == ".svg") {
    Check(outputs.Stage("--out", o.out_path,
                        out_ext == ".csv" ? SwayCsv(sway) : SwayPlotSvg(sway, params)));
  }
  if (!o.csv_path.empty()) Check(outputs.Stage("--csv", o.csv_path, SwayCsv(sway)));
  if (!o.svg_path.empty()) Check(outputs.Stage("--svg", o.svg_path, SwayPlotSvg(sway, params)));
  Check(outputs.Commit());
  if (o.stats) {
    nlohmann::ordered_json j;
    j["preset"] = run.tree().preset;
    j["seed"] = run.tree().seed;
    j["years"] = run.tree().years;
    j["node_points"] = sway.node_points;
    j["moving"] = sway.moving;
    j["followers"] = sway.followers;
    j["fixed"] = sway.fixed;
    j["internodes"] = sway.internodes;
    j["steps"] = sway.steps;
    j["dt"] = params.dt;
    j["wind"] = params.wind_speed;
    j["ms"] = sway.ms;
    j["ns_per_internode"] = sway.ns_per_internode;
    j["max_tip_displacement"] = sway.max_tip_displacement;
    j["finite"] = sway.finite;
    // Over the last two seconds of the gust (or the part of it that was run).
    double to = std::min(params.gust_off, params.duration);
    j["jittering_tips"] = CountJitteringTips(sway, std::max(params.gust_on, to - 2.0), to);
    if (out_ext == ".glb") {  // the skin (docs/sway-model.md "Joint budget")
      nlohmann::ordered_json g;
      g["joints"] = glb_info.joints;
      g["exact_joints"] = glb_info.exact_joints;
      g["clustered"] = glb_info.clustered;
      g["keys"] = glb_info.keys;
      g["max_error_m"] = glb_info.max_error;
      g["mean_error_m"] = glb_info.mean_error;
      g["max_motion_m"] = glb_info.max_motion;
      g["joint_keys"] = glb_info.joint_keys;  // the clip's keys (docs/sway-model.md "Clip keys")
      g["full_joint_keys"] = glb_info.full_joint_keys;
      g["key_error_m"] = glb_info.key_error;
      g["full_mesh"] = glb_choice.full;  // the mesh (docs/lod-export.md)
      g["triangles"] = glb_choice.triangles;
      j["glb"] = g;
    }
    out << j.dump() << "\n";
  }
  return 0;
}

}  // namespace

void AddSwayCommands(CLI::App& app, CommandList& commands) {
  CLI::App* tree = Subcommand(app, "tree", "Grow and export trees");
  CLI::App* sway = tree->add_subcommand(
      "sway", "Sway a grown tree in a gust of wind (thesis chapter 3 node-point model)");
  auto options = std::make_shared<SwayOptions>();
  AddStateOptions(sway, TreeParamTable(), &options->state);
  AddSwayOptions(sway, options.get());
  commands.push_back(
      {sway,
       [sway, options](std::ostream& out) { return RunSwayCommand(*options, *sway, out); },
       {"--preset", "binary", "--years", "2", "--duration", "1"}});
}

}  // namespace niwa::cli

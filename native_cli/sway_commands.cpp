// niwa CLI command of the sway study: 'tree sway', the node-point wind sway of thesis chapter 3
// (core/sway, docs/sway-model.md) on a grown tree.
// cli-order: 20
#include <algorithm>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>

#include "base/echo.h"
#include "cli_common.h"
#include "sway/sway.h"
#include "sway/sway_budget.h"
#include "sway/sway_gltf.h"
#include "tree/growth.h"
#include "tree_cli.h"

namespace niwa::cli {
namespace {

const FlagRange kTips = {1, 50, true};
const FlagRange kFps = {1, 240, false};

struct SwayOptions {
  StateOptions state;
  double wind = 0, wind_dir = 0, dt = 0, duration = 0;
  std::string gust, csv_path, svg_path;
  std::vector<std::string> sets;
  bool stats = false;
  int tips = 4;
  std::string out_path;  // .glb (skinned, animated), .csv or .svg
  double fps = 30;       // keys per second in the .glb
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
  cmd->add_option("--csv", o->csv_path, "Write tip trajectories: time,node,x,y,z (s, cm)");
  cmd->add_option("--svg", o->svg_path, "Write a plot of tip displacement against time");
  cmd->add_flag("--stats", o->stats, "Print one JSON object of statistics on stdout");
  cmd->add_option("--out", o->out_path,
                  "Write the sway: .glb (tree mesh skinned to the node points, one animation clip "
                  "of the run), .csv (as --csv) or .svg (as --svg)");
  AddNumberFlag(cmd, "--fps", &o->fps, kFps,
                "Animation keys per second of simulated time in --out .glb, " + RangeHelp(kFps) +
                    " (default 30); each key is the state at the nearest time step");
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
  std::string error = CheckSwayParams(*params);
  if (!error.empty()) throw BadInput{SwayErrorSource(o, cmd) + ": " + error};
  Check(CheckFlag("--tips", o.tips, kTips));
  if (!o.csv_path.empty() && Extension(o.csv_path) != ".csv") {
    throw BadInput{"--csv: '" + Echo(o.csv_path) + "' must end in .csv"};
  }
  if (!o.svg_path.empty() && Extension(o.svg_path) != ".svg") {
    throw BadInput{"--svg: '" + Echo(o.svg_path) + "' must end in .svg"};
  }
  return SwayParams(*params);
}

int RunSwayCommand(const SwayOptions& o, const CLI::App& cmd, std::ostream& out) {
  const std::string out_ext = Extension(o.out_path);
  if (!o.out_path.empty() && out_ext != ".glb" && out_ext != ".csv" && out_ext != ".svg") {
    throw BadInput{"--out: '" + Echo(o.out_path) + "' must end in .glb, .csv or .svg"};
  }
  if (cmd.count("--fps") && out_ext != ".glb") {
    throw BadInput{"--fps: only applies with --out FILE.glb"};
  }
  Check(CheckFlag("--fps", o.fps, kFps));
  TreeState state = ResolveTreeState(o.state, cmd);
  SwayParams params = ResolveSwayParams(o, cmd, &state.params);
  Grower grower(state);  // stops early (truncated) at the budget's growth limits
  while (grower.year() < state.years && !grower.stopped()) grower.GrowYear();
  const Estimate grown = grower.estimate();
  Tree tree = grower.TakeTree();
  ReportTruncated(tree.truncated_by);
  CheckPrunes(state, tree);
  {
    // Every output's estimate, refused before any work starts (so no output is left behind).
    const SwayModel model = BuildSwayModel(tree, params);
    Estimate total = grown + EstimateSwayRun(model, params, o.tips);
    if (out_ext == ".glb") total = total + EstimateSwayGlb(model, CountTree(tree), params, o.fps);
    Check(CheckEstimate(total, ResolveBudget(o.state.budget),
                        "lower --duration or --years, or raise --dt" +
                            std::string(out_ext == ".glb" ? " or lower --fps" : "")));
  }
  // Every output is staged first and renamed only when all were written (all or none).
  StagedOutputs outputs;
  if (out_ext == ".glb") {  // core/sway/sway_gltf: exact two-joint skinning of eq. 3.15
    std::vector<unsigned char> glb;
    SwayGlbOptions glb_options;
    glb_options.fps = o.fps;
    std::string error = WriteSwayGlb(tree, params, glb_options, &glb).Line();
    if (!error.empty()) throw BadInput{"--out: " + error};
    Check(outputs.Stage("--out", o.out_path, std::string(glb.begin(), glb.end())));
  }
  SwayRun run = RunSway(tree, params, o.tips);
  if (out_ext == ".csv" || out_ext == ".svg") {
    Check(outputs.Stage("--out", o.out_path,
                        out_ext == ".csv" ? SwayCsv(run) : SwayPlotSvg(run, params)));
  }
  if (!o.csv_path.empty()) Check(outputs.Stage("--csv", o.csv_path, SwayCsv(run)));
  if (!o.svg_path.empty()) Check(outputs.Stage("--svg", o.svg_path, SwayPlotSvg(run, params)));
  Check(outputs.Commit());
  if (o.stats) {
    nlohmann::ordered_json j;
    j["preset"] = tree.preset;
    j["seed"] = tree.seed;
    j["years"] = tree.years;
    j["node_points"] = run.node_points;
    j["moving"] = run.moving;
    j["followers"] = run.followers;
    j["fixed"] = run.fixed;
    j["internodes"] = run.internodes;
    j["steps"] = run.steps;
    j["dt"] = params.dt;
    j["wind"] = params.wind_speed;
    j["ms"] = run.ms;
    j["ns_per_internode"] = run.ns_per_internode;
    j["max_tip_displacement"] = run.max_tip_displacement;
    j["finite"] = run.finite;
    // Over the last two seconds of the gust (or the part of it that was run).
    double to = std::min(params.gust_off, params.duration);
    j["jittering_tips"] = CountJitteringTips(run, std::max(params.gust_on, to - 2.0), to);
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
      {sway, [sway, options](std::ostream& out) { return RunSwayCommand(*options, *sway, out); }});
}

}  // namespace niwa::cli

// niwa CLI commands (presets, params, tree grow/mappings/sway) over the core library, with CLI11.
#include "cli.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "cli_common.h"
#include "io/gltf_export.h"
#include "io/gltf_sway.h"
#include "io/json_io.h"
#include "io/svg_export.h"
#include "io/url_codec.h"
#include "math/rotation.h"
#include "render/hybrid.h"
#include "sway/sway.h"
#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"

namespace niwa {
namespace cli {
void AddMeshCommands(CLI::App& app, CommandList& commands);  // mesh_commands.cpp
}  // namespace cli
namespace {

struct BadInput {
  std::string message;
};

std::string Extension(const std::string& path) {
  std::size_t dot = path.find_last_of('.');
  std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return path.substr(dot);
}

std::string ReadFile(const std::string& path, bool* ok) {
  std::ifstream in(path, std::ios::binary);
  *ok = static_cast<bool>(in);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Options shared by every command that grows a tree.
struct GrowOptions {
  std::string preset = "sakura";
  int years = -1;  // -1: the preset's own
  uint64_t seed = 0;
  bool seed_given = false;
  std::vector<std::string> sets, prunes;
  std::string params_file, url;
};

void AddGrowOptions(CLI::App* cmd, GrowOptions* o) {
  cmd->add_option("--preset", o->preset, "Species preset (see 'niwa presets')");
  cmd->add_option("--years", o->years, "Years to grow, 0..100 (default: the preset's)");
  cmd->add_option("--seed", o->seed, "Random seed, 0..4294967295 (default: the preset's)");
  cmd->add_option("--set", o->sets,
                  "Override a parameter: key=value (repeatable; see 'niwa params')");
  cmd->add_option("--params", o->params_file, "JSON file of parameters {\"key\": value, ...}");
  cmd->add_option(
      "--prune", o->prunes,
      "Prune after a year: YEAR:bID (branch id from the JSON) or YEAR:sinceY (repeatable)");
  cmd->add_option("--url", o->url,
                  "A share-link hash (preset=...&seed=...); other flags override it");
}

GrowRequest ResolveGrowRequest(const GrowOptions& o, CLI::App* cmd) {
  GrowRequest request;
  TreeState state;
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    state = DecodeStateHash(o.url, &notices);
    if (!notices.empty()) throw BadInput{"--url: " + notices.front()};
  }
  if (cmd->count("--preset") || o.url.empty()) {
    const Preset* preset = FindPreset(o.preset);
    if (!preset) {
      throw BadInput{"--preset: unknown '" + o.preset + "', must be one of " + PresetNames()};
    }
    if (o.url.empty() || state.preset != preset->name) {
      state.preset = preset->name;
      state.params = preset->params;
      state.years = preset->years;
      state.seed = preset->seed;
    }
  }
  request.preset = state.preset;
  request.params = state.params;
  request.years = state.years;
  request.seed = state.seed;
  request.prunes = state.prunes;
  if (cmd->count("--years")) {
    if (o.years < 0 || o.years > kMaxYears) {
      throw BadInput{"--years: " + std::to_string(o.years) +
                     " is out of range; must be a whole number in [0, " +
                     std::to_string(kMaxYears) + "]"};
    }
    request.years = o.years;
  }
  if (cmd->count("--seed")) {
    if (o.seed > 4294967295ULL) {
      throw BadInput{"--seed: must be a whole number in [0, 4294967295]"};
    }
    request.seed = o.seed;
  }
  if (!o.params_file.empty()) {
    bool ok = false;
    std::string text = ReadFile(o.params_file, &ok);
    if (!ok) throw BadInput{"--params: cannot read '" + o.params_file + "'"};
    std::string error = ApplyParamsJson(text, &request.params);
    if (!error.empty()) throw BadInput{"--params " + o.params_file + ": " + error};
  }
  for (const std::string& item : o.sets) {
    std::size_t eq = item.find('=');
    if (eq == std::string::npos) throw BadInput{"--set: '" + item + "' must be key=value"};
    std::string error = request.params.SetFromText(item.substr(0, eq), item.substr(eq + 1));
    if (!error.empty()) throw BadInput{"--set: " + error};
  }
  for (const std::string& item : o.prunes) {
    Prune prune;
    std::string error;
    if (!ParsePrune(item, &prune, &error)) throw BadInput{"--" + error};
    request.prunes.push_back(prune);
  }
  return request;
}

// A prune that cuts nothing is bad input (a mistyped id or year), found once the tree has grown.
void CheckPrunes(const GrowRequest& request, const Tree& tree) {
  for (const Prune& prune : request.prunes) {
    std::string reason = IdlePruneReason(prune, tree);
    if (!reason.empty()) throw BadInput{"--prune: " + FormatPrune(prune) + ": " + reason};
  }
}

std::string StatsJson(const Tree& tree, const GrowthTimings& t) {
  TreeStats s = ComputeStats(tree);
  nlohmann::ordered_json j;
  j["preset"] = tree.preset;
  j["seed"] = tree.seed;
  j["years"] = tree.years;
  j["internodes"] = s.internodes;
  j["branches"] = s.branches;
  j["leaves"] = s.leaves;
  j["flowers"] = s.flowers;
  j["height"] = s.height;
  j["truncated"] = tree.truncated;
  j["ms"] = t.ms_total;
  j["ms_light"] = t.ms_light;
  j["ms_hormone"] = t.ms_hormone;
  j["ms_branching"] = t.ms_branching;
  return j.dump();
}

// SVG-only drawing options of 'tree grow' (used by scripts/figures).
void AddSvgOptions(CLI::App* cmd, SvgOptions* o) {
  cmd->add_option("--svg-width", o->width, "SVG width in pixels, 100..10000 (default 600)");
  cmd->add_option("--svg-height", o->height, "SVG height in pixels, 100..10000 (default 600)");
  cmd->add_option("--svg-leaves", o->leaves, "SVG: draw leaves, 0 or 1 (default 1)");
  cmd->add_option("--svg-flowers", o->flowers, "SVG: draw flowers, 0 or 1 (default 1)");
  cmd->add_option("--caption", o->caption, "SVG: text under the tree");
}

void CheckSvgOptions(const SvgOptions& o, CLI::App* cmd, const std::string& ext) {
  for (const char* name :
       {"--svg-width", "--svg-height", "--svg-leaves", "--svg-flowers", "--caption"}) {
    if (cmd->count(name) && ext != ".svg") {
      throw BadInput{std::string(name) + ": only applies with --out FILE.svg"};
    }
  }
  if (o.width < 100 || o.width > 10000) throw BadInput{"--svg-width: must be in [100, 10000]"};
  if (o.height < 100 || o.height > 10000) throw BadInput{"--svg-height: must be in [100, 10000]"};
}

int RunGrow(const GrowOptions& options, CLI::App* cmd, const std::string& out_path, bool stats,
            const SvgOptions& svg, std::ostream& out) {
  std::string ext = Extension(out_path);
  if (!out_path.empty() && ext != ".glb" && ext != ".json" && ext != ".svg") {
    throw BadInput{"--out: '" + out_path + "' must end in .glb, .json or .svg"};
  }
  CheckSvgOptions(svg, cmd, ext);
  GrowRequest request = ResolveGrowRequest(options, cmd);
  GrowthTimings timings;
  Tree tree = GrowTree(request, &timings);
  CheckPrunes(request, tree);
  if (!out_path.empty()) {
    std::string bytes;
    if (ext == ".json") {
      bytes = TreeToJson(tree);
    } else if (ext == ".svg") {
      bytes = TreeToSvg(tree, svg);
    } else {
      std::vector<unsigned char> glb;
      std::string error = WriteGlb(BuildTreeMesh(tree), &glb);
      if (!error.empty()) throw BadInput{"--out: " + error};
      bytes.assign(glb.begin(), glb.end());
    }
    std::string error = WriteFileAtomically(out_path, bytes);
    if (!error.empty()) throw BadInput{"--out: " + error};
  }
  if (stats) out << StatsJson(tree, timings) << "\n";
  return 0;
}

// Shortest text that reads back as the same float (the model computes in float).
std::string FormatFloat(float value) {
  char buffer[32];
  for (int precision = 1; precision <= 9; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, static_cast<double>(value));
    if (std::strtof(buffer, nullptr) == value) break;
  }
  return buffer;
}

// The hormone- and age-dependent ranges as CSV, computed by the growth model's own functions
// (docs/growth-model.md plots them through scripts/figures).
void PrintMappings(const GrowRequest& request, std::ostream& out) {
  const ParamSet& p = request.params;
  double h_sat = p.Get(ParamId::kHSat);
  out << "hormone,N_long,N_dwarf,D_long_cm,D_dwarf_cm,b_L,b_g,P_terminal,P_tl,"
         "P_lateral_at_age_P_l_years\n";
  for (int i = 0; i <= 60; ++i) {
    float h = static_cast<float>(1.5 * h_sat * i / 60.0);
    // A long and a dwarf shoot of initial hormone h, as BreakBuds sizes them (fig. 2.5, fig. 2.13).
    float d_dwarf = ShootLengthRamp(p, h, true, ParamId::kDLow, ParamId::kDHigh) *
                    static_cast<float>(p.Get(ParamId::kDwarfInternodeRatio));
    BreakChances chance = BudBreakChances(p, h, 1 + static_cast<int>(p.Get(ParamId::kPLYears)));
    out << FormatFloat(h) << ","
        << FormatFloat(ShootLengthRamp(p, h, false, ParamId::kNLow, ParamId::kNHigh)) << ","
        << FormatFloat(ShootLengthRamp(p, h, true, ParamId::kNLow, ParamId::kNHigh)) << ","
        << FormatFloat(ShootLengthRamp(p, h, false, ParamId::kDLow, ParamId::kDHigh)) << ","
        << FormatFloat(d_dwarf) << ","
        << FormatFloat(HormoneRamp(p, h, ParamId::kBLLow, ParamId::kBLHigh)) << ","
        << FormatFloat(HormoneRamp(p, h, ParamId::kBGLow, ParamId::kBGHigh)) << ","
        << FormatFloat(chance.terminal) << "," << FormatFloat(chance.terminally_lateral) << ","
        << FormatFloat(chance.lateral) << "\n";
  }
  out << "\nyear,P_l_max\n";
  int last = static_cast<int>(p.Get(ParamId::kPLYears)) + 5;
  for (int year = 1; year <= last; ++year) {
    out << year << "," << FormatFloat(LateralBreakMax(p, year)) << "\n";
  }
}

// ---- tree sway: node-point wind sway of thesis chapter 3 (core/sway, docs/sway-model.md) ----
struct SwayOptions {
  double wind = 0, wind_dir = 0, dt = 0, duration = 0;
  std::string gust, csv_path, svg_path;
  std::vector<std::string> sets;
  bool stats = false;
  int tips = 4;
  std::string out_path;  // .glb (skinned, animated), .csv or .svg
  double fps = 30;       // keys per second in the .glb
};

void AddSwayOptions(CLI::App* cmd, SwayOptions* o) {
  cmd->add_option("--wind", o->wind, "Wind speed while the gust blows, m/s, 0..100 (default 5)");
  cmd->add_option("--wind-dir", o->wind_dir,
                  "Wind azimuth, degrees, -360..360: 0 blows towards +x, 90 towards +z");
  cmd->add_option("--gust", o->gust,
                  "ON_S:OFF_S: the wind starts at ON and stops at OFF (default 1:6)");
  cmd->add_option("--dt", o->dt, "Time step, s, 0.0001..0.1 (default 1/30)");
  cmd->add_option("--duration", o->duration, "Simulated time, s, 0..600 (default 12)");
  cmd->add_option("--set-sway", o->sets,
                  "Same as --set (kept for old scripts): sway and wind parameters are rows of "
                  "the one table, see 'niwa params'");
  cmd->add_option("--tips", o->tips, "Tips traced in --csv and --svg, 1..50 (default 4)");
  cmd->add_option("--csv", o->csv_path, "Write tip trajectories: time,node,x,y,z (s, cm)");
  cmd->add_option("--svg", o->svg_path, "Write a plot of tip displacement against time");
  cmd->add_flag("--stats", o->stats, "Print one JSON object of statistics on stdout");
  cmd->add_option("--out", o->out_path,
                  "Write the sway: .glb (tree mesh skinned to the node points, one animation clip "
                  "of the run), .csv (as --csv) or .svg (as --svg)");
  cmd->add_option("--fps", o->fps,
                  "Animation keys per second of simulated time in --out .glb, 1..240 (default "
                  "30); each key is the state at the nearest time step");
}

// Sway and wind parameters are rows of the one table: --url, --params, --set (and its alias
// --set-sway) reach them through the grow request; the flags below override those.
SwayParams ResolveSwayParams(const SwayOptions& o, CLI::App* cmd, ParamSet* params) {
  for (const std::string& item : o.sets) {
    std::size_t eq = item.find('=');
    if (eq == std::string::npos) throw BadInput{"--set-sway: '" + item + "' must be key=value"};
    std::string error = params->SetFromText(item.substr(0, eq), item.substr(eq + 1));
    if (!error.empty()) throw BadInput{"--set-sway: " + error};
  }
  auto set = [&](const char* flag, ParamId id, double value) {
    if (!cmd->count(flag)) return;
    std::string error = params->Set(id, value);
    if (!error.empty()) throw BadInput{std::string(flag) + ": " + error};
  };
  set("--wind", ParamId::kWindSpeed, o.wind);
  set("--wind-dir", ParamId::kWindDir, o.wind_dir);
  set("--dt", ParamId::kSwayDt, o.dt);
  set("--duration", ParamId::kSwayDuration, o.duration);
  if (cmd->count("--gust")) {
    std::size_t colon = o.gust.find(':');
    std::optional<double> on, off;
    if (colon != std::string::npos) {
      on = ParseNumber(o.gust.substr(0, colon));
      off = ParseNumber(o.gust.substr(colon + 1));
    }
    if (!on || !off) throw BadInput{"--gust: '" + o.gust + "' must be ON_S:OFF_S, e.g. 1:6"};
    set("--gust", ParamId::kGustOn, *on);
    set("--gust", ParamId::kGustOff, *off);
  }
  std::string error = CheckSwayParams(*params);
  if (!error.empty()) throw BadInput{(cmd->count("--gust") ? "--gust: " : "--set: ") + error};
  if (o.tips < 1 || o.tips > 50) throw BadInput{"--tips: must be a whole number in [1, 50]"};
  if (!o.csv_path.empty() && Extension(o.csv_path) != ".csv") {
    throw BadInput{"--csv: '" + o.csv_path + "' must end in .csv"};
  }
  if (!o.svg_path.empty() && Extension(o.svg_path) != ".svg") {
    throw BadInput{"--svg: '" + o.svg_path + "' must end in .svg"};
  }
  return SwayParams(*params);
}

int RunSwayCommand(const GrowOptions& grow_options, const SwayOptions& o, CLI::App* cmd,
                   std::ostream& out) {
  const std::string out_ext = Extension(o.out_path);
  if (!o.out_path.empty() && out_ext != ".glb" && out_ext != ".csv" && out_ext != ".svg") {
    throw BadInput{"--out: '" + o.out_path + "' must end in .glb, .csv or .svg"};
  }
  if (cmd->count("--fps") && out_ext != ".glb") {
    throw BadInput{"--fps: only applies with --out FILE.glb"};
  }
  if (!(o.fps >= 1 && o.fps <= 240)) throw BadInput{"--fps: must be a number in [1, 240]"};
  GrowRequest request = ResolveGrowRequest(grow_options, cmd);
  SwayParams params = ResolveSwayParams(o, cmd, &request.params);
  Tree tree = GrowTree(request);
  CheckPrunes(request, tree);
  if (out_ext == ".glb") {  // core/io/gltf_sway: exact two-joint skinning of eq. 3.15
    std::vector<unsigned char> glb;
    SwayGlbOptions glb_options;
    glb_options.fps = o.fps;
    std::string error = WriteSwayGlb(tree, params, glb_options, &glb);
    if (!error.empty()) throw BadInput{"--out: " + error};
    error = WriteFileAtomically(o.out_path, std::string(glb.begin(), glb.end()));
    if (!error.empty()) throw BadInput{"--out: " + error};
  }
  SwayRun run = RunSway(tree, params, o.tips);
  if (out_ext == ".csv" || out_ext == ".svg") {
    std::string error = WriteFileAtomically(
        o.out_path, out_ext == ".csv" ? SwayCsv(run) : SwayPlotSvg(run, params));
    if (!error.empty()) throw BadInput{"--out: " + error};
  }
  if (!o.csv_path.empty()) {
    std::string error = WriteFileAtomically(o.csv_path, SwayCsv(run));
    if (!error.empty()) throw BadInput{"--csv: " + error};
  }
  if (!o.svg_path.empty()) {
    std::string error = WriteFileAtomically(o.svg_path, SwayPlotSvg(run, params));
    if (!error.empty()) throw BadInput{"--svg: " + error};
  }
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

// ---- tree render-stats: thesis chapter 4 hybrid rendering counts (core/render/hybrid) ----
struct RenderStatsOptions {
  int width = 512, height = 512;
  std::string cam, target, mode = "hybrid", leaf_mode = "cluster";
  float yaw = kDefaultYaw, pitch = kDefaultPitch, distance = 10, fov_deg = 45;
  RenderOptions render;
};

void AddRenderStatsOptions(CLI::App* cmd, RenderStatsOptions* o) {
  cmd->add_option("--width", o->width, "Viewport width in pixels, 16..16384 (default 512)");
  cmd->add_option("--height", o->height, "Viewport height in pixels, 16..16384 (default 512)");
  cmd->add_option("--cam", o->cam,
                  "Camera as in the share link's cam=: yaw,pitch,distance,tx,ty,tz (default: the "
                  "page's framing of a new tree)");
  cmd->add_option("--yaw", o->yaw, "Camera yaw, radians (overrides --cam)");
  cmd->add_option("--pitch", o->pitch, "Camera pitch, radians, -0.1..1.5 (overrides --cam)");
  cmd->add_option("--distance", o->distance,
                  "Camera distance to the target, metres, 0.2..400 (overrides --cam)");
  cmd->add_option("--target", o->target, "Camera target x,y,z in metres (overrides --cam)");
  cmd->add_option("--fov", o->fov_deg, "Vertical field of view, degrees, 1..170 (default 45)");
  cmd->add_option("--mode", o->mode, "hybrid (thesis 4.2) or full (every polygon)");
  cmd->add_option("--threshold", o->render.threshold_px,
                  "Eq. 4.1 card/line threshold, pixels, 0.1..1000 (overrides the line_threshold "
                  "parameter, default 4)");
  cmd->add_option("--leaf-mode", o->leaf_mode,
                  "cluster (leaf-cluster cards, thesis 5.2) or branch (thesis 4.2.1); overrides "
                  "the leaf_cluster_cards parameter (default 1: cluster)");
  cmd->add_option("--card-planes", o->render.card_planes,
                  "Card planes per branch, 2..8 (overrides the card_planes parameter, default 2)");
  cmd->add_option("--line-segments", o->render.line_segments,
                  "Most line segments per line branch, 1..64 (default 1)");
}

int RunRenderStats(const GrowOptions& grow_options, RenderStatsOptions o, CLI::App* cmd,
                   std::ostream& out) {
  if (o.width < 16 || o.width > 16384)
    throw BadInput{"--width: must be a whole number in [16, 16384]"};
  if (o.height < 16 || o.height > 16384) {
    throw BadInput{"--height: must be a whole number in [16, 16384]"};
  }
  if (!(o.fov_deg >= 1 && o.fov_deg <= 170)) throw BadInput{"--fov: must be a number in [1, 170]"};
  if (o.mode != "hybrid" && o.mode != "full") {
    throw BadInput{"--mode: '" + o.mode + "' must be hybrid or full"};
  }
  if (o.leaf_mode != "cluster" && o.leaf_mode != "branch") {
    throw BadInput{"--leaf-mode: '" + o.leaf_mode + "' must be cluster or branch"};
  }
  std::string error = CheckRenderOptions(o.render);
  if (!error.empty()) {
    std::string field = error.substr(0, error.find(':'));
    for (char& c : field) c = c == '_' ? '-' : c;
    throw BadInput{"--" + field + error.substr(error.find(':'))};
  }
  OrbitView view;
  if (!o.cam.empty() && !ParseOrbitView(o.cam, &view, &error)) throw BadInput{"--" + error};
  if (cmd->count("--yaw")) {
    if (!std::isfinite(o.yaw)) throw BadInput{"--yaw: must be a finite number (radians)"};
    view.yaw = o.yaw;
  }
  if (cmd->count("--pitch")) {
    if (!(o.pitch >= kMinPitch && o.pitch <= kMaxPitch)) {
      throw BadInput{"--pitch: must be a number in [-0.1, 1.5] (radians)"};
    }
    view.pitch = o.pitch;
  }
  if (cmd->count("--distance")) {
    if (!(o.distance >= kMinDistance && o.distance <= kMaxDistance)) {
      throw BadInput{"--distance: must be a number in [0.2, 400] (metres)"};
    }
    view.distance = o.distance;
  }
  if (cmd->count("--target")) {
    std::stringstream stream(o.target);
    std::string item;
    std::vector<double> xyz;
    while (std::getline(stream, item, ',')) {
      std::optional<double> v = ParseNumber(item);
      if (!v || !std::isfinite(*v)) break;
      xyz.push_back(*v);
    }
    if (xyz.size() != 3 || o.target.back() == ',') {
      throw BadInput{"--target: '" + o.target + "' must be three numbers x,y,z (metres)"};
    }
    view.target = glm::vec3(static_cast<float>(xyz[0]), static_cast<float>(xyz[1]),
                            static_cast<float>(xyz[2]));
  }
  GrowRequest request = ResolveGrowRequest(grow_options, cmd);
  // The render rows of the parameter table (--set, --params, --url) give the options; the
  // --threshold, --leaf-mode and --card-planes flags override them.
  RenderOptions render = RenderOptionsFromParams(request.params);
  render.line_segments = o.render.line_segments;
  if (cmd->count("--threshold")) render.threshold_px = o.render.threshold_px;
  if (cmd->count("--card-planes")) render.card_planes = o.render.card_planes;
  if (cmd->count("--leaf-mode")) {
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
    explicit_camera = explicit_camera || cmd->count(flag) > 0;
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

std::string WriteFileAtomically(const std::string& path, const std::string& bytes) {
  std::string temp = path + ".niwa-partial";
  {
    std::ofstream file(temp, std::ios::binary | std::ios::trunc);
    if (!file) return "cannot write '" + path + "'";
    file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    file.flush();
    if (!file) {
      file.close();
      std::remove(temp.c_str());
      return "cannot write '" + path + "'";
    }
  }
  if (std::rename(temp.c_str(), path.c_str()) != 0) {
    std::remove(temp.c_str());
    return "cannot write '" + path + "'";
  }
  return "";
}

int RunCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CLI::App app{"niwa: procedural nature lab (tree growth after Kanayama 1998)", "niwa"};
  app.require_subcommand(1);
  app.set_help_all_flag("--help-all", "Help for every command");

  CLI::App* presets = app.add_subcommand("presets", "List the species presets");
  CLI::App* params = app.add_subcommand("params", "List every model parameter with its range");
  bool params_json = false;
  params->add_flag("--json", params_json, "Print the table as JSON");

  CLI::App* tree = app.add_subcommand("tree", "Grow and export trees");
  tree->require_subcommand(1);
  CLI::App* grow = tree->add_subcommand("grow", "Grow a tree and write it or its statistics");
  GrowOptions grow_options;
  std::string out_path;
  bool stats = false;
  AddGrowOptions(grow, &grow_options);
  grow->add_option("--out", out_path,
                   "Write the tree: .glb (binary glTF), .json or .svg (side view)");
  grow->add_flag("--stats", stats, "Print one JSON object of statistics on stdout");
  CLI::App* mappings = tree->add_subcommand(
      "mappings",
      "Print the hormone- and age-dependent ranges (N, D, b_L, b_g, break chances) as CSV");
  GrowOptions mapping_options;
  AddGrowOptions(mappings, &mapping_options);
  SvgOptions svg_options;
  AddSvgOptions(grow, &svg_options);
  CLI::App* sway = tree->add_subcommand(
      "sway", "Sway a grown tree in a gust of wind (thesis chapter 3 node-point model)");
  GrowOptions sway_grow_options;
  SwayOptions sway_options;
  AddGrowOptions(sway, &sway_grow_options);
  AddSwayOptions(sway, &sway_options);
  CLI::App* render_stats = tree->add_subcommand(
      "render-stats",
      "Count what hybrid rendering (thesis ch. 4: cards and lines) draws for a view, as JSON");
  GrowOptions render_grow_options;
  RenderStatsOptions render_options;
  AddGrowOptions(render_stats, &render_grow_options);
  AddRenderStatsOptions(render_stats, &render_options);
  cli::CommandList commands;
  cli::AddMeshCommands(app, commands);

  try {
    // Name unknown commands ourselves: CLI11 would only say that a subcommand is required.
    auto check_command = [](const CLI::App* parent, const std::string& word) {
      if (word.empty() || word[0] == '-') return;
      std::string names;
      for (const CLI::App* sub : parent->get_subcommands({})) {
        if (sub->get_name() == word) return;
        names += (names.empty() ? "" : ", ") + sub->get_name();
      }
      throw BadInput{"unknown command '" + word + "', must be one of " + names};
    };
    if (!args.empty()) check_command(&app, args[0]);
    if (args.size() > 1 && args[0] == "tree") check_command(tree, args[1]);
    if (args.size() > 1 && args[0] == "mesh") check_command(app.get_subcommand("mesh"), args[1]);
    std::vector<std::string> reversed(args.rbegin(), args.rend());
    app.parse(reversed);
    if (*presets) {
      for (const Preset& p : Presets()) {
        out << p.name << "\t" << p.title << "\t" << p.years << " years\t" << p.source << "\n";
      }
      return 0;
    }
    if (*params) {
      if (params_json) {
        out << ParamTableJson() << "\n";
        return 0;
      }
      for (const ParamSpec& s : ParamTable()) {
        out << s.key << "\t" << s.symbol << "\t" << (*s.unit ? s.unit : "-") << "\tdefault "
            << FormatNumber(s.default_value) << "\t" << RangeText(s) << "\t" << s.help << "\n";
      }
      return 0;
    }
    if (*mappings) {
      PrintMappings(ResolveGrowRequest(mapping_options, mappings), out);
      return 0;
    }
    if (*grow) return RunGrow(grow_options, grow, out_path, stats, svg_options, out);
    if (*render_stats) {
      return RunRenderStats(render_grow_options, render_options, render_stats, out);
    }
    if (*sway) return RunSwayCommand(sway_grow_options, sway_options, sway, out);
    for (const cli::Command& command : commands) {
      if (*command.app) return command.run(out);
    }
  } catch (const CLI::CallForHelp&) {
    out << app.help();  // CLI11 delegates to the innermost selected subcommand
    return 0;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return 0;
  } catch (const CLI::ParseError& e) {
    std::string message = e.what();
    for (char& c : message) {
      if (c == '\n') c = ' ';
    }
    err << "niwa: error: " << message << " (see --help)\n";
    return 2;
  } catch (const BadInput& e) {
    err << "niwa: error: " << e.message << "\n";
    return 2;
  } catch (const cli::BadInput& e) {
    err << "niwa: error: " << e.message << "\n";
    return 2;
  } catch (const std::exception& e) {
    err << "niwa: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace niwa

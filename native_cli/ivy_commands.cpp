// `niwa ivy grow|scenes`: grow Shindo & Sakamoto's ivy on a built-in scene or a .glb/.gltf/.obj
// mesh and print its statistics or write it as .json, .lsys (the L-string) or .glb.
// cli-order: 40
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "compose/ivy_on_tree.h"
#include "io/mesh_reader.h"
#include "ivy/ivy_budget.h"
#include "ivy/ivy_params.h"
#include "ivy/ivy_run.h"
#include "ivy/ivy_state.h"
#include "ivy/scenes.h"
#include "params/param_text.h"
#include "run/field_names.h"

namespace niwa::cli {
namespace {

// ivy::kIvyChange and kIvyStatsChange in this command's flags.
constexpr char kIvyCliChange[] = "lower --steps or --subdivide, or raise t1 and t2";
constexpr char kIvyCliStatsChange[] =
    "lower --steps or --subdivide, or raise t1 and t2, or leave out --stats";
// The numeric flags' ranges, written once: parsed by FlagNumber, shown by RangeHelp.
constexpr FlagRange kStepsRange = {0, ivy::kMaxSteps, true};
constexpr FlagRange kIvySeedRange = {0, ivy::kMaxIvySeed, true};
constexpr FlagRange kIvyTreeYearsRange = {1, ivy::kMaxTreeYears, true};
constexpr FlagRange kSubdivideRange = {0, ivy::kMaxIvySubdivide, true};
constexpr FlagRange kSvgLeavesRange = {0, 1, true};

struct IvyOptions {
  std::string scene, mesh, preset, params_file, url, accel = "bvh", units;
  double steps = 0, seed = 0, subdivide = 0, tree_years = 10, svg_leaves = 1;
  std::string tree_preset, caption;
  std::string out_path;
  std::vector<std::string> seed_points, sets;
  bool stats = false, with_support = false;
  BudgetOptions budget;
  CLI::App* cmd = nullptr;  // which flags were given
};

// The ivy run's state fields as this command's flags (core errors name the fields).
const run::FieldNames& IvyFlagNames() {
  static const run::FieldNames names = {{"steps", "--steps"},
                                        {"seed", "--seed"},
                                        {"seed_points", "--seed-point"},
                                        {"mesh", "--mesh"},
                                        {"scene", "--scene"},
                                        {"subdivide", "--subdivide"},
                                        {"tree", "--tree-preset"},
                                        {"tree_years", "--tree-years"},
                                        {"preset", "--preset"},
                                        {"accel", "--accel"},
                                        {"scale", "--units"}};
  return names;
}

// A core error under this command's flags: its field through IvyFlagNames, and a far seed point
// ("seed_points: point 2: (...) is 50 from the nearest face; ...") as the CLI has always named it
// ("--seed-point 2: (...) ...").
Status AsIvyFlags(const Status& s) {
  const std::string& m = s.message();
  const std::size_t colon = m.find(": ");
  if (s.field() == "seed_points" && m.rfind("point ", 0) == 0 && colon != std::string::npos) {
    return Status::Error("--seed-point " + m.substr(6, colon - 6), m.substr(colon + 2));
  }
  return run::RenameField(s, IvyFlagNames());
}

ivy::IvyState ResolveState(const IvyOptions& o) {
  ivy::IvyState state;
  // The tree's precedence (native_cli/tree_cli.cpp): a share link or a state file is the base and
  // every other flag overrides it.
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    ivy::ApplyIvyHash(o.url, "", &state, &notices);
    if (!notices.empty()) Fail(Status::Error("--url", notices[0]));
  }
  if (!o.params_file.empty()) {
    Result<std::string> text = ReadFile(o.params_file, "--params", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Check(ivy::ApplyIvyStateJson(*text, &state).Within("--params"));
  }
  const bool based = !o.url.empty() || !o.params_file.empty();
  // --preset replaces the base's preset (and its values) only when it names another one; with no
  // base, a tree (in metres) defaults to metric.
  if (!o.preset.empty() && (!based || state.preset != o.preset)) {
    Check(AsFlag(ivy::SetIvyPreset(o.preset, &state), "--preset"));
  } else if (o.preset.empty() && !based && !o.tree_preset.empty()) {
    Check(AsFlag(ivy::SetIvyPreset("metric", &state), "--preset"));
  }
  for (const std::string& set : o.sets) Check(state.params.SetFromAssignment(set).Within("--set"));
  // --units: the support's unit as the row "scale" (paper px per unit; 1 px = 1 mm), over the
  // preset's and --set's; auto = 0, the support's own (a mesh file: from its bounds).
  if (!o.units.empty()) {
    const std::pair<const char*, double> units[] = {
        {"auto", 0}, {"px", 1}, {"mm", 1}, {"cm", 10}, {"m", 1000}};
    bool known = false;
    for (const auto& [name, k] : units) {
      if (o.units != name) continue;
      Check(state.params.Set(IvyParam::kScale, k));
      known = true;
    }
    if (!known) {
      Fail(Status::Error("--units", "'" + Echo(o.units) +
                                        "' is unknown; must be auto, px, mm, cm "
                                        "or m"));
    }
  }
  // The flags' own strict parse (their lines), then the state's setters.
  // The flags were parsed strictly (AddNumberFlag); the state's setters check the rest.
  if (o.cmd->count("--steps")) Check(AsIvyFlags(ivy::SetIvySteps(o.steps, &state)));
  if (o.cmd->count("--seed")) Check(AsIvyFlags(ivy::SetIvySeed(o.seed, &state)));
  if (o.cmd->count("--accel")) Check(AsIvyFlags(ivy::SetIvyAccel(o.accel, &state)));
  // Each "X,Y,Z" or a scene's named seed, resolved by the run against its support; they replace
  // the state's at= (the page's clicks).
  if (!o.seed_points.empty()) state.seed_point_items = o.seed_points;
  Check(ValidateIvyParams(state.params));
  return state;
}

// The state's tree scene's error (its tree or tree_years came from `flag`): the budget's own
// line, else that flag.
Status TreeSceneError(const Status& s, const Budget& budget, const std::string& flag) {
  const std::string& field = s.field();
  if (field == budget.memory_limit || field == budget.seconds_limit) return s;
  return Status::Error(flag, s.message());
}

int RunGrow(const IvyOptions& o, std::ostream& out) {
  const auto t_start = std::chrono::steady_clock::now();
  const std::string ext = o.out_path.empty() ? "" : Extension(o.out_path);  // checked by --out
  const int levels = static_cast<int>(o.subdivide);
  ivy::IvyState state = ResolveState(o);
  const Budget budget = ResolveBudget(o.budget);
  if (!o.mesh.empty() + !o.scene.empty() + !o.tree_preset.empty() > 1) {
    Fail(Status::Error(o.mesh.empty() ? "--scene" : "--mesh",
                       "give one of --mesh FILE, --scene NAME or --tree-preset NAME"));
  }
  // The support: a tree (core/compose), a mesh file, or a built-in scene.
  ivy::IvySupportInput input;
  bool tree = false;
  if (!o.tree_preset.empty()) {
    const double years = o.tree_years;
    Result<ivy::IvySupportInput> t =
        compose::IvyTreeSupport(o.tree_preset, years, budget, "--tree-years");
    if (!t.ok()) Fail(AsIvyFlags(t.status()));  // tree, tree_years or the budget's limit
    input = std::move(t).value();
    tree = true;
  } else if (!o.mesh.empty()) {
    io::MeshReadStats read;
    Result<geom::TriMesh> mesh = io::ReadMeshFile(o.mesh, &read);
    if (!mesh.ok()) Fail(mesh.status().Within("--mesh"));
    input = ivy::IvySupportInput::Mesh(std::move(mesh).value(), o.mesh, std::move(read.materials),
                                       read.metres_per_unit);
  } else {
    // --scene, else the state's (--url scene=, --params "scene"), else cubes4.
    const std::string name = !o.scene.empty()      ? o.scene
                             : state.scene.empty() ? std::string("cubes4")
                                                   : state.scene;
    if (name == ivy::kTreeScene) {  // the page's tree scene: tree= and tree_years= of the state
      Result<ivy::IvySupportInput> t =
          compose::IvyTreeSupport(state.tree, state.tree_years, budget, "--tree-years");
      const char* flag = !o.scene.empty() ? "--scene" : !o.url.empty() ? "--url" : "--params";
      if (!t.ok()) Fail(TreeSceneError(t.status(), budget, flag));
      input = std::move(t).value();
      tree = true;
    } else {
      input = ivy::IvySupportInput::Scene(name);
    }
  }
  const std::string tree_truncated_by = input.prepared_truncated_by;
  ivy::IvySupportOptions support_options = ivy::IvySupportOptions::For(state);  // its accel
  support_options.subdivide = levels;
  // A mesh grows from the page's default seed "front" (the surface point nearest to a point in
  // front of it, +z, at a tenth of its height) when no --seed-point is given; `--seed-point front`
  // names it beside others.
  support_options.front_seed = !o.mesh.empty();
  // A tree's growth and bark took their time before the ivy's (its memory is freed but the bark).
  support_options.change = tree ? "lower --tree-years" : kIvyCliChange;
  Result<std::shared_ptr<const ivy::IvySupport>> support =
      ivy::IvySupport::Prepare(std::move(input), support_options, budget);
  if (!support.ok()) {
    const std::string& field = support.status().field();
    // A stopped tree's line comes before the support's budget refusal, after a bad input's.
    if (field != "subdivide" && field != "mesh" && field != "scene") {
      ReportTruncated(tree_truncated_by);
    }
    Fail(AsIvyFlags(support.status()));
  }
  ReportTruncated(tree_truncated_by);
  const ivy::IvyScene& scene = (*support)->scene();
  ivy::IvyRunOptions options;
  // With --stats the growth keeps room for the measurement's part that grows with every bud, and
  // an export's check counts the measurement's exact estimate (the overlap pairs, known once
  // grown).
  options.reserve_stats = o.stats;
  options.stats = o.stats;
  options.change = kIvyCliChange;
  options.export_change = o.stats ? kIvyCliStatsChange : kIvyCliChange;
  options.stats_change = kIvyCliStatsChange;
  // Refused while growing, as soon as the buds made prove the output cannot fit.
  options.planned_export = ext.empty() ? "" : ext.substr(1);
  options.planned_with_support = o.with_support;
  Result<ivy::IvyRun> run = ivy::IvyRun::Start(state, *support, budget, options);
  if (!run.ok()) Fail(AsIvyFlags(run.status()));
  Check(AsIvyFlags(run->Advance({})));
  ReportTruncated(run->log().truncated_by);
  // Nothing grown is an error, not an empty file (a row named by the core is a --set row; its
  // scale is --units).
  if (Status grew = run->CheckGrewSomething(); grew.field() == "L") {
    Fail(Status::Error("--set L", grew.message()));
  } else {
    Check(AsIvyFlags(grew));
  }
  const bool trace = std::getenv("NIWA_BUDGET_TRACE") != nullptr;  // calibration (docs/budgets.md)
  const Estimate grown = ivy::EstimateIvyGrown(run->model(), run->log(), run->limits());
  if (!o.out_path.empty()) {
    // The export's estimate on top of the grown ivy's, refused before it starts.
    const std::string format = ext.substr(1);
    if (trace) {
      const bool support_out = !scene.free && (ext == ".svg" || o.with_support);
      const Estimate export_estimate =
          ivy::EstimateIvyExport(run->model(),
                                 ext == ".json"   ? ivy::IvyExport::kJson
                                 : ext == ".lsys" ? ivy::IvyExport::kLsys
                                 : ext == ".svg"  ? ivy::IvyExport::kSvg
                                                  : ivy::IvyExport::kGlb,
                                 support_out ? static_cast<double>(scene.mesh.triangle_count()) : 0,
                                 IvyLeavesPerBud(run->params()));
      std::fprintf(stderr, "budget: grown %.0f MB %.2f s; export %.0f MB %.2f s\n",
                   grown.memory_bytes / 1048576, grown.seconds,
                   export_estimate.memory_bytes / 1048576, export_estimate.seconds);
    }
    Check(run->CheckExport(format, o.with_support));
    ivy::IvyExportOptions export_options;
    export_options.with_support = o.with_support;
    if (ext == ".svg") {
      export_options.svg.leaves = o.svg_leaves != 0;
      export_options.svg.caption = o.caption;
    }
    const auto t0 = std::chrono::steady_clock::now();
    Result<std::string> bytes = run->ExportUnchecked(format, export_options);
    if (ext == ".glb") run->timings().ms_mesh = Ms(t0, std::chrono::steady_clock::now());
    if (!bytes.ok()) Fail(bytes.status().Within("--out"));
    StagedOutputs outputs;
    Check(outputs.Stage("--out", o.out_path, *bytes));
    Check(outputs.Commit());
  }
  if (trace && o.out_path.empty()) {
    const Estimate stats_estimate = o.stats ? run->StatsEstimate() : Estimate{};
    std::fprintf(stderr, "budget: grown %.0f MB %.2f s; stats %.0f MB %.2f s\n",
                 grown.memory_bytes / 1048576, grown.seconds, stats_estimate.memory_bytes / 1048576,
                 stats_estimate.seconds);
  }
  if (o.stats && o.out_path.empty()) Check(run->CheckStats());
  if (o.stats) {
    run->timings().ms = Ms(t_start, std::chrono::steady_clock::now());
    out << run->StatsJson() << "\n";
  }
  return 0;
}

int RunScenes(std::ostream& out) {
  for (const std::string& name : ivy::IvySceneNames()) {
    ivy::IvyScene s = *ivy::MakeIvyScene(name);
    out << name << "\t" << s.mesh.triangle_count() << " tris\tseeds";
    for (const ivy::NamedSeed& seed : s.seeds) {
      out << " " << seed.name << "=(" << FormatNumber(seed.pos.x) << "," << FormatNumber(seed.pos.y)
          << "," << FormatNumber(seed.pos.z) << ")";
    }
    out << "\t" << s.description << "\n";
  }
  return 0;
}

}  // namespace

void AddIvyCommands(CLI::App& app, CommandList& commands) {
  commands.studies.push_back({"ivy",
                              &IvyTable(),
                              [](std::ostream& out) {
                                for (const std::string& name : IvyPresetNames()) {
                                  out << name;
                                  for (const auto& [key, value] : IvyPresetOverrides(name))
                                    out << "\t" << key << "=" << FormatNumber(value);
                                  out << "\n";
                                }
                              },
                              {},
                              {"ivy", "grow", "--steps", "3", "--stats"}});
  CLI::App* ivy_app = Subcommand(app, "ivy", "Grow climbing ivy over a mesh (Shindo & Sakamoto)");
  ivy_app->require_subcommand(1);
  auto o = std::make_shared<IvyOptions>();
  CLI::App* grow = ivy_app->add_subcommand(
      "grow", "Grow ivy on a built-in scene or a mesh; print --stats or write --out");
  CLI::Option* scene = grow->add_option(
      "--scene", o->scene,
      "Built-in support: cubes4 (default), wall, overhang, stairs, pillar, sphere, "
      "free (see 'niwa ivy scenes'), or tree (the state's tree= and tree_years=)");
  CLI::Option* mesh =
      AddInputFlag(grow, "--mesh", &o->mesh, "Support mesh file: .glb, .gltf or .obj");
  CLI::Option* tree = grow->add_option(
      "--tree-preset", o->tree_preset,
      "Climb a Niwa tree's bark ('niwa presets tree'; default ivy preset: metric)");
  // One support ("--scene: give only one of --scene and --mesh").
  Excludes(mesh, scene);
  Excludes(mesh, tree);
  Excludes(scene, tree);
  AddNumberFlag(grow, "--tree-years", &o->tree_years, kIvyTreeYearsRange,
                "Age of that tree, " + RangeHelp(kIvyTreeYearsRange) + " (default 10)");
  grow->add_option(
      "--seed-point", o->seed_points,
      "Growth start X,Y,Z or a scene's named seed (a mesh's: front, the default); repeat for "
      "several plants");
  AddNumberFlag(grow, "--steps", &o->steps, kStepsRange,
                "Final step number, " + RangeHelp(kStepsRange) + " (default 50)");
  AddNumberFlag(grow, "--seed", &o->seed, kIvySeedRange,
                "Random seed, " + RangeHelp(kIvySeedRange) + " (default 1)");
  grow->add_option("--preset", o->preset, "paper (default), literal, improved or metric");
  grow->add_option("--units", o->units,
                   "The support's unit: auto (default: a built-in scene's px, a tree's m, a mesh "
                   "file's from its bounds), px, mm, cm or m; the preset's lengths are in px "
                   "(1 px = 1 mm)");
  grow->add_option("--set", o->sets, "KEY=VALUE of the ivy table ('niwa params ivy')");
  AddInputFlag(grow, "--params", &o->params_file,
               "State JSON {preset, seed, steps, params}; other flags override it");
  grow->add_option("--url", o->url,
                   "Share-link hash: preset=..&seed=..&steps=..&KEY=V; other flags override it");
  grow->add_option("--accel", o->accel, "Geometry queries: bvh (default) or linear (brute force)");
  AddNumberFlag(grow, "--subdivide", &o->subdivide, kSubdivideRange,
                "Split every support triangle into 4^K coplanar ones, K in [" +
                    FormatNumber(kSubdivideRange.min) + ", " + FormatNumber(kSubdivideRange.max) +
                    "]");
  grow->add_flag("--stats", o->stats, "Print one JSON object of statistics on stdout");
  AddOutputFlag(grow, "--out", &o->out_path, {".json", ".lsys", ".glb", ".svg"},
                "Write .json (buds, internodes), .lsys, .glb or .svg (front and side views)");
  OnlyWith(
      grow->add_flag("--with-support", o->with_support, "The .glb also holds the support mesh"),
      "--out", {".glb"});
  OnlyWith(AddNumberFlag(grow, "--svg-leaves", &o->svg_leaves, kSvgLeavesRange,
                         ".svg: draw the leaves, 0 or 1 (default 1)"),
           "--out", {".svg"});
  OnlyWith(AddCaptionFlag(grow, "--caption", &o->caption,
                          ".svg: a line of printable text under the views, at most " +
                              std::to_string(kMaxCaptionBytes) + " bytes"),
           "--out", {".svg"});
  AddBudgetOptions(grow, &o->budget);
  o->cmd = grow;
  commands.push_back(
      {grow, [o](std::ostream& out) { return RunGrow(*o, out); }, {"--steps", "3", "--stats"}});
  CLI::App* scenes = ivy_app->add_subcommand("scenes", "List the built-in scenes and seeds");
  commands.push_back({scenes, [](std::ostream& out) { return RunScenes(out); }, {}});
}

}  // namespace niwa::cli

// niwa CLI commands of the garden (issue 33; core/compose/garden_*, docs/garden-model.md): 'garden
// grow' (the stage, the planting and every tree grown on one clock; the .glb, the 16-bit heightmap,
// the plan as SVG, the statistics as one JSON object) and 'garden plant' (the planting rules alone:
// positions as JSON, fast), and the table for 'niwa params garden'. A thin adapter over
// compose::GardenRun (and, with --wind-time, compose::GardenWind over its trees): flags into a
// state (the garden file's heightmap, ground mesh and mask read relative to the file), the run, its
// outputs written all or none, the stats with the CLI's timings. `--wind-time T` sways the grown
// trees T seconds in the state's wind (the page's Blow) and prints each tree's sway under "wind".
// cli-order: 70
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "compose/garden_params.h"
#include "compose/garden_run.h"
#include "compose/garden_state.h"
#include "compose/garden_wind.h"
#include "io/hash_codec.h"
#include "io/mesh_reader.h"
#include "params/param_text.h"
#include "run/field_names.h"

namespace niwa::cli {
namespace {

using compose::GardenParam;

// The one table of the garden commands' names for state fields (run/field_names.h).
const run::FieldNames kGardenFlags = {{"years", "--years"}, {"plant_seed", "--seed"}};

FlagRange GardenRowRange(GardenParam row) {
  return RowFlagRange(compose::GardenTable().row(static_cast<std::size_t>(row)));
}

struct GardenOptions {
  std::string garden, url, out, heightmap, svg;
  std::vector<std::string> sets;
  double years = -1, seed = -1;  // -1: not given
  double wind_time = -1;         // -1: no wind (garden grow)
  bool stats = false;
  BudgetOptions budget;
};

// A file the garden file names, relative to the garden file's folder.
std::string BesideGardenFile(const std::string& garden_file, const std::string& name) {
  if (name.empty() || name[0] == '/') return name;
  const std::size_t slash = garden_file.rfind('/');
  return slash == std::string::npos ? name : garden_file.substr(0, slash + 1) + name;
}

// The state from the default garden, then --url, --garden (and the files it names), --years,
// --seed and --set.
compose::GardenState ResolveGardenState(const GardenOptions& o) {
  compose::GardenState state = compose::DefaultGardenState();
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    const ShareLink link = SplitShareLink(o.url);
    if (!link.error.empty()) Fail(Status::Error("--url", link.error));
    compose::ApplyGardenHash(link.hash, "", &state, &notices);
    if (!notices.empty()) Fail(Status::Error("--url", notices.front()));
  }
  if (!o.garden.empty()) {
    Result<std::string> text = ReadFile(o.garden, "--garden", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Check(compose::ApplyGardenStateJson(*text, &state).Within("--garden " + Echo(o.garden)));
    // A heightmap ground and a mask, read beside the garden file (the reader's error names it).
    Check(
        compose::LoadGardenImages(
            [&](const std::string&, const std::string& file) -> Result<std::vector<unsigned char>> {
              Result<std::string> png =
                  ReadFile(BesideGardenFile(o.garden, file), "", compose::kMaxGardenImageBytes);
              if (!png.ok()) return png.status();
              return std::vector<unsigned char>(png->begin(), png->end());
            },
            &state)
            .Within("--garden " + Echo(o.garden)));
    // A mesh ground and mesh objects, read beside the garden file (the reader's error names it).
    Check(compose::LoadGardenMeshes(
              [&](const std::string& file) {
                return io::ReadMeshFile(BesideGardenFile(o.garden, file));
              },
              &state)
              .Within("--garden " + Echo(o.garden)));
  }
  if (o.years >= 0) Check(AsFlag(state.params.Set(GardenParam::kYears, o.years), "--years"));
  if (o.seed >= 0) Check(AsFlag(state.params.Set(GardenParam::kPlantSeed, o.seed), "--seed"));
  for (const std::string& s : o.sets) {
    // wind.KEY=VALUE: a row of the garden's wind (the tree table's "wind" group).
    if (s.rfind("wind.", 0) == 0) {
      const std::size_t eq = s.find('=');
      const std::string key = s.substr(5, eq == std::string::npos ? std::string::npos : eq - 5);
      if (!compose::IsGardenWindKey(key))
        Fail(Status::Error("--set", "wind." + Echo(key) +
                                        " is not a wind row of the garden (niwa params tree, "
                                        "group wind, but gust_on)"));
      const Status set = state.wind.SetFromAssignment(s.substr(5));
      if (!set.ok()) Fail(Status::Error("--set", "wind." + set.Line()));
      continue;
    }
    Check(state.params.SetFromAssignment(s).Within("--set"));
  }
  compose::LayOutDefaults(&state);
  Check(run::RenameField(compose::CheckGardenState(state), kGardenFlags));
  return state;
}

// garden grow: an adapter over compose::GardenRun.
int RunGardenGrow(const GardenOptions& o, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const compose::GardenState state = ResolveGardenState(o);
  const Budget budget = ResolveBudget(o.budget);
  Result<compose::GardenRun> run = compose::GardenRun::Start(state, budget);
  if (!run.ok()) Fail(run::RenameField(run.status(), kGardenFlags));
  const std::pair<const std::string*, const char*> outputs[] = {
      {&o.out, "glb"}, {&o.heightmap, "heightmap"}, {&o.svg, "svg"}};
  const char* flags[] = {"--out", "--heightmap", "--svg"};
  for (int k = 0; k < 3; ++k) {
    if (outputs[k].first->empty()) continue;
    Result<Estimate> e = run->ExportEstimate(outputs[k].second);
    if (!e.ok()) Fail(e.status().Within(flags[k]));
    Check(CheckEstimate(*e, budget, "lower max_triangles or shapes, or the trees (density, size)"));
  }
  const auto t1 = std::chrono::steady_clock::now();
  const double moss_start_ms = run->ms_moss();
  Check(run::RenameField(run->Advance({}), kGardenFlags));
  ReportTruncated(run->truncated_by());
  const auto t2 = std::chrono::steady_clock::now();
  StagedOutputs staged;
  std::vector<std::string> written;
  for (int k = 0; k < 3; ++k) {
    if (outputs[k].first->empty()) continue;
    Result<std::string> bytes = run->Export(outputs[k].second);
    if (!bytes.ok()) Fail(run::RenameField(bytes.status(), kGardenFlags).Within(flags[k]));
    Check(staged.Stage(flags[k], *outputs[k].first, *bytes));
    written.push_back(*outputs[k].first);
  }
  Check(staged.Commit());
  const auto t3 = std::chrono::steady_clock::now();
  // The wind (the page's Blow): every grown tree swayed wind_time s in the state's wind.
  std::string wind_stats;
  if (o.wind_time >= 0) {
    Result<ParamSet> rows =
        compose::GardenWindRows(run->scene().ground.size, run->state().wind, "");
    if (!rows.ok()) Fail(rows.status().Within("wind"));
    Result<compose::GardenWind> wind = compose::GardenWind::Start(*run, *rows, budget);
    if (!wind.ok()) Fail(wind.status().Within("--wind-time"));
    wind->Step(static_cast<int>(std::lround(o.wind_time / wind->dt())));
    wind_stats = wind->StatsJson(*run);
  }
  const auto t4 = std::chrono::steady_clock::now();
  nlohmann::ordered_json j;
  if (o.stats) {
    j = nlohmann::ordered_json::parse(run->StatsJson());
    j["ms"] = Ms(t0, std::chrono::steady_clock::now());
    j["ms_ground"] = run->ms_ground();
    j["ms_plant"] = run->ms_plant();
    j["ms_moss"] = run->ms_moss();          // its start (the land's cells) and its days
    j["ms_moss_cpu"] = run->cpu_ms_moss();  // the same in the process's CPU time
    j["ms_ivy"] = run->ms_ivy();            // the ivy's years: its supports and its growth
    j["ms_ivy_support"] = run->ms_ivy_support();
    j["ms_ivy_cpu"] = run->cpu_ms_ivy();                  // ms_ivy in the process's CPU time
    j["ms_ivy_support_cpu"] = run->cpu_ms_ivy_support();  // ms_ivy_support in CPU time
    j["ms_bark"] = run->ms_bark();  // the simulated barks (bark 1), after the clock
    j["ms_trees"] = Ms(t1, t2) - run->ms_ivy() - (run->ms_moss() - moss_start_ms) - run->ms_bark();
    j["ms_growth"] = run->ms_growth();  // within ms_trees: the trees' own years
    j["ms_export"] = Ms(t2, t3);
    if (!wind_stats.empty()) j["ms_wind"] = Ms(t3, t4);
  } else {
    j["trees"] = run->planting().trees.size();
    j["distinct_trees"] = run->groups().size();
    j["years"] = run->done();
    j["hash"] = run->Hash("");
    j["written"] = written;
  }
  if (!wind_stats.empty()) j["wind"] = nlohmann::ordered_json::parse(wind_stats);
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

// garden plant: the stage and the planting rules only, positions as one JSON object.
int RunGardenPlant(const GardenOptions& o, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const compose::GardenState state = ResolveGardenState(o);
  const Budget budget = ResolveBudget(o.budget);
  Result<compose::GardenScene> scene = compose::BuildGardenScene(state, budget);
  if (!scene.ok()) Fail(run::RenameField(scene.status(), kGardenFlags));
  const auto t1 = std::chrono::steady_clock::now();
  Result<compose::Planting> planting = compose::PlantGarden(state, *scene);
  if (!planting.ok()) Fail(run::RenameField(planting.status(), kGardenFlags));
  const auto t2 = std::chrono::steady_clock::now();
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(compose::PlantingJson(*planting));
  if (o.stats) {
    j["ms"] = Ms(t0, std::chrono::steady_clock::now());
    j["ms_ground"] = Ms(t0, t1);
    j["ms_plant"] = Ms(t1, t2);
  }
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

void AddGardenStateFlags(CLI::App* cmd, GardenOptions* o) {
  AddInputFlag(
      cmd, "--garden", &o->garden,
      "Garden file JSON {params, ground: {kind: flat|terrain|heightmap|mesh, terrain: {...}, "
      "file}, objects: [{kind, pos: [x, z], rot, scale}], plants: [{species, seed, age, "
      "pos, rot}], mix: {species: weight}, mask} (files relative to it)");
  cmd->add_option("--url", o->url,
                  "A share-link hash (size=...&plants=keyaki:1:0:3:2:0&terrain.preset=...); "
                  "other flags override it");
  AddNumberFlag(
      cmd, "--years", &o->years, GardenRowRange(GardenParam::kYears),
      "The garden's age (the years row), " + RangeHelp(GardenRowRange(GardenParam::kYears)));
  AddNumberFlag(cmd, "--seed", &o->seed, GardenRowRange(GardenParam::kPlantSeed),
                "Seed of the planting rules (the plant_seed row), " +
                    RangeHelp(GardenRowRange(GardenParam::kPlantSeed)));
  cmd->add_option("--set", o->sets,
                  "KEY=VALUE of the garden table (niwa params garden), or wind.KEY=VALUE of the "
                  "garden's wind (niwa params tree, group wind, but gust_on)");
  cmd->add_flag("--stats", o->stats, "Print the statistics (with timings) as one JSON object");
  AddBudgetOptions(cmd, &o->budget);
}

void PrintGardenPresets(std::ostream& out) {
  out << "default\tthe small default garden: a 40 m terrain ground, a wall, two rocks, a stone "
         "lantern, a keyaki by hand, keyaki, sakura and maple by the rules\n";
}

}  // namespace

void AddGardenCommands(CLI::App& app, CommandList& commands) {
  const std::vector<std::string> example = {"--years", "1",     "--set",
                                            "size=30", "--set", "ground_res=16"};
  std::vector<std::string> study_example = {"garden", "plant"};
  study_example.insert(study_example.end(), example.begin(), example.end());
  commands.studies.push_back(
      {"garden", &compose::GardenTable(), &PrintGardenPresets, {}, study_example});
  CLI::App* garden_app =
      Subcommand(app, "garden", "A garden: ground, objects and trees grown together on one clock");
  garden_app->require_subcommand(1);

  CLI::App* grow = garden_app->add_subcommand(
      "grow",
      "Grow the garden: the ground (flat, a terrain from a seed contour, a heightmap or a mesh), "
      "its "
      "objects, trees placed by hand and by the planting rules, grown year by year on one clock "
      "(neighbours shading each other); the .glb, heightmap, plan and statistics");
  auto o = std::make_shared<GardenOptions>();
  AddGardenStateFlags(grow, o.get());
  AddOutputFlag(grow, "--out", &o->out, {".glb"},
                "Write the garden as .glb: ground, objects, each distinct tree once within "
                "max_triangles (with bark 1, wearing its own simulated bark's maps), its copies "
                "instanced (EXT_mesh_gpu_instancing) or as plain nodes");
  AddOutputFlag(grow, "--heightmap", &o->heightmap, {".png"},
                "Write the ground as a 16-bit grey PNG (row 0 north; size and relief in its text)");
  AddOutputFlag(grow, "--svg", &o->svg, {".svg"},
                "Write the plan as .svg (north up: ground by height, objects, crowns by species)");
  const FlagRange wind_range =
      RowFlagRange(TreeParams().table().row(static_cast<std::size_t>(TreeParam::kSwayDuration)));
  AddNumberFlag(grow, "--wind-time", &o->wind_time, wind_range,
                "Sway the grown trees this many seconds in the garden's wind (the page's Blow: a "
                "gust front entering at the upwind edge) and print each tree's sway under "
                "\"wind\", " +
                    RangeHelp(wind_range) + " s");
  commands.push_back({grow, [o](std::ostream& out) { return RunGardenGrow(*o, out); }, example});

  CLI::App* plant = garden_app->add_subcommand(
      "plant",
      "The planting rules alone (density, Poisson spacing, altitude band, slope limit, mask, "
      "objects): every tree's position as one JSON object with the refusals by rule");
  auto po = std::make_shared<GardenOptions>();
  AddGardenStateFlags(plant, po.get());
  commands.push_back(
      {plant, [po](std::ostream& out) { return RunGardenPlant(*po, out); }, example});
}

}  // namespace niwa::cli

// niwa CLI commands of the moss study (Nomura 2010, paper 001; core/moss, docs/moss-model.md):
// 'moss grow' (the run over a built-in scene: --stats, --out moss.json), 'moss photons' (one day's
// photon map), 'moss scenes', 'moss soil' (one soil cell: every term of eqs 3.2-3.16 and the energy
// balance's residuals) and 'moss fitness' (eqs 3.17-3.20 for one place), each one JSON object on
// stdout; the table and presets for 'niwa params moss' and 'niwa presets moss'. Thin adapters:
// flags into a state and a cell, the core's run and reports (core/moss) out.
// cli-order: 50
#include <CLI/CLI.hpp>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "compose/moss_land.h"
#include "geom/ray_dump.h"
#include "io/gltf_writer.h"
#include "io/mesh_reader.h"
#include "moss/moss_params.h"
#include "moss/moss_report.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "moss/soil.h"
#include "moss/soil_cells.h"
#include "moss/weather.h"
#include "params/param_text.h"
#include "run/field_names.h"

namespace niwa::cli {
namespace {

using moss::MossParam;

// The one table of the moss commands' names for state and cell fields (run/field_names.h).
const run::FieldNames kMossFieldFlags = {
    {"preset", "--preset"},
    {"geology", "--geology"},
    {"theta", "--theta"},
    {"S", "--S"},
    {"m_over_M", "--mM"},
    {"V_sky", "--V"},
    {"species", "--species"},
    {"T_s", "--Ts"},
    {"rh_s", "--rhs"},
    {"days", "--days"},
    {"seed", "--seed"},
    {"scene", "--scene"},
    {"mesh", "--mesh"},
    {"photons", "--photons"},
    {"indirect", "--indirect"},
    {"map", "--map"},
    {"weather", "--weather"},
    {"tree", "--tree-preset"},
    {"tree_years", "--tree-years"},
    {"terrain", "--terrain-preset"},
    {"terrain_seed", "--terrain-seed"},
    {"rock_triangles", "--rock-triangles"},
    {"stats_every", "--every"},
};
constexpr FlagRange kDaysRange{0, moss::kMaxMossDays, true};
constexpr FlagRange kMossSeedRange{0, static_cast<double>(moss::kMaxMossSeed), true};
constexpr FlagRange kMossTreeYearsRange{1, 100, true};  // the tree study's kMaxYears
constexpr FlagRange kRockTrianglesRange{moss::kRockTrianglesMin, moss::kRockTrianglesMax, true};
constexpr FlagRange kEveryRange{1, moss::kMaxMossDays, true};

// Ranges of the flags that are not table rows (the soil cell's and the fitness place's inputs).
constexpr FlagRange kThetaRange{0, 1, false, " (at most the geology's theta_SAT)"};
constexpr FlagRange kLightRange{0, 1e6, false, " (W/m2)"};
constexpr FlagRange kShareRange{0, 1};
constexpr FlagRange kSurfaceTRange{100, 400, false, " (K)"};
constexpr FlagRange kSurfaceRhRange{0, 100};

FlagRange MossRowRange(MossParam row) {
  return RowFlagRange(moss::MossTable().row(static_cast<std::size_t>(row)));
}

// The flags every moss command shares: the state (--url, then --preset, then --set).
struct MossStateOptions {
  std::string url, preset, params_file;
  std::vector<std::string> sets;
};
void AddStateOptions(CLI::App* cmd, MossStateOptions* o) {
  cmd->add_option("--preset", o->preset,
                  "nomura2010 (default) or nomura2010-sky (niwa presets moss)");
  cmd->add_option("--set", o->sets, "KEY=VALUE of the moss table (niwa params moss)");
  cmd->add_option("--url", o->url, "A share-link hash (preset=...&T=...); other flags override it");
  AddInputFlag(cmd, "--params", &o->params_file,
               "State JSON {preset, scene, days, seed, params: {key: value}} over --url; other "
               "flags override it");
}

moss::MossState ResolveState(const MossStateOptions& o) {
  moss::MossState state;
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    moss::ApplyMossHash(o.url, "", &state, &notices);
    if (!notices.empty()) throw BadInput{"--url: " + notices.front()};
  }
  if (!o.params_file.empty()) {
    Result<std::string> text = ReadFile(o.params_file, "--params", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Check(moss::ApplyMossStateJson(*text, &state).Within("--params"));
  }
  // --preset resets the values to its own only when it names another preset than the base's.
  if (!o.preset.empty() && (o.params_file.empty() || o.preset != state.preset))
    Check(run::RenameField(moss::SetMossPreset(o.preset, &state), kMossFieldFlags));
  for (const std::string& s : o.sets) Check(state.params.SetFromAssignment(s).Within("--set"));
  return state;
}

struct SoilOptions {
  MossStateOptions state;
  std::string geology;
  double theta = 0, S = 0, T = 0, m_over_M = 0, V = 1;
};

// moss soil: one cell and day, every term of eqs 3.2-3.16 (core/moss/soil.h).
int RunSoil(const SoilOptions& o, bool T_given, bool V_given, std::ostream& out) {
  moss::MossState state = ResolveState(o.state);
  if (T_given) Check(AsFlag(state.params.Set(MossParam::kT, o.T), "--T"));
  Check(moss::CheckMossParams(state.params));
  // The sky view is read by the sky-view longwave only: given to the thesis's eq 3.3 it would be
  // silently ignored, so it is refused.
  if (V_given &&
      state.params.GetInt(MossParam::kLongwave) != static_cast<int>(moss::Longwave::kSkyView))
    Fail(Status::Error(
        "--V",
        "only applies with longwave=1 (sky-view: --preset nomura2010-sky or --set longwave=1)"));
  moss::Geology geology;
  if (!moss::GeologyFromName(o.geology.c_str(), &geology))
    Fail(Status::Error("--geology",
                       "'" + Echo(o.geology) + "' is unknown; must be humus, sandy or asphalt"));
  moss::SoilCell cell;
  cell.law = moss::GeologyLawOf(state.params, geology);
  cell.theta = o.theta;
  cell.S = o.S;
  cell.m_over_M = o.m_over_M;
  cell.V_sky = o.V;
  Check(run::RenameField(moss::CheckSoilCell(cell), kMossFieldFlags));
  const nlohmann::ordered_json j = moss::SoilReport(state, geology, cell);
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

struct FitnessOptions {
  MossStateOptions state;
  std::string species;
  double T_s = 0, rh_s = 0, S = 0;
};

// moss fitness: eqs 3.17-3.20 for one place, for one species or all three (core/moss/fitness.h).
int RunFitness(const FitnessOptions& o, std::ostream& out) {
  moss::MossState state = ResolveState(o.state);
  Check(moss::CheckMossParams(state.params));
  std::vector<moss::Species> which;
  if (o.species.empty()) {
    which = {moss::Species::kGingoke, moss::Species::kHaigoke, moss::Species::kSugigoke};
  } else {
    moss::Species s;
    if (!moss::SpeciesFromName(o.species.c_str(), &s))
      Fail(Status::Error("--species", "'" + Echo(o.species) +
                                          "' is unknown; must be gingoke, haigoke or sugigoke"));
    which = {s};
  }
  const nlohmann::ordered_json j = moss::FitnessReport(state, which, o.T_s, o.rh_s, o.S);
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

// The flags of a run (grow, photons): the scene, days, photons, seed and indirect light over the
// state, then the budget.
struct RunOptions {
  MossStateOptions state;
  std::string scene, indirect, mesh, weather, tree_preset, terrain_preset;
  double days = 0, photons = 0, seed = 0, tree_years = 10, terrain_seed = 1, every = 0,
         rock_triangles = moss::kRockTrianglesDefault;
  bool stats = false, instancing = false;
  std::string out_path, csv_path, rays_path, map = "coverage";
  BudgetOptions budget;
  CLI::App* cmd = nullptr;
};

void AddRunOptions(CLI::App* cmd, RunOptions* o, bool with_days) {
  o->cmd = cmd;
  CLI::Option* scene =
      cmd->add_option("--scene", o->scene, "Built-in scene: plane, thesis (default), walls, rocks");
  CLI::Option* tree = cmd->add_option(
      "--tree-preset", o->tree_preset,
      "Land: a Niwa tree ('niwa presets tree') on a square of humus; moss on bark and ground");
  AddNumberFlag(cmd, "--tree-years", &o->tree_years, kMossTreeYearsRange,
                "Age of that tree, " + RangeHelp(kMossTreeYearsRange) +
                    " (default 10; only with a tree: --tree-preset or a link's scene=tree)");
  CLI::Option* terrain = cmd->add_option(
      "--terrain-preset", o->terrain_preset,
      "Land: a Niwa terrain ('niwa presets terrain': simple, midpoint, fourier, improved or a "
      "figure preset) grown from the built-in disk, in metres; geology by slope and height");
  AddNumberFlag(cmd, "--terrain-seed", &o->terrain_seed, kMossSeedRange,
                "RNG seed of that terrain, " + RangeHelp(kMossSeedRange) +
                    " (default 1; only with a terrain: --terrain-preset or a link's "
                    "scene=terrain)");
  AddNumberFlag(cmd, "--rock-triangles", &o->rock_triangles, kRockTrianglesRange,
                "The rocks scene's rock triangles (the ground's 3,200 come on top; each rock an "
                "icosphere at the next level up), " +
                    RangeHelp(kRockTrianglesRange) +
                    " (default 1600; only with --scene rocks or a link's scene=rocks)");
  CLI::Option* mesh = AddInputFlag(
      cmd, "--mesh", &o->mesh,
      "Land mesh instead of a scene: .glb, .gltf or .obj (geology from material names "
      "with humus, sand or asphalt, else the base colour texture at each cell's UV times "
      "COLOR_0 times the base colour; not in the link)");
  Excludes(mesh, tree);  // --mesh with --scene: refused by the run, naming --mesh
  Excludes(scene, tree);
  Excludes(mesh, terrain);
  Excludes(scene, terrain);
  Excludes(tree, terrain);
  if (with_days)
    AddNumberFlag(cmd, "--days", &o->days, kDaysRange,
                  "Days to grow, " + RangeHelp(kDaysRange) + " (default 300)");
  AddNumberFlag(cmd, "--photons", &o->photons, MossRowRange(MossParam::kPhotons),
                "Photons a day (the photons row), " + RangeHelp(MossRowRange(MossParam::kPhotons)) +
                    " (default 8192)");
  AddNumberFlag(cmd, "--seed", &o->seed, kMossSeedRange,
                "Random seed, " + RangeHelp(kMossSeedRange) + " (default 1)");
  cmd->add_option("--indirect", o->indirect,
                  "on (default): photons bounce (fig 4.1); off: first hits only (fig 4.2)");
  AddStateOptions(cmd, &o->state);
  AddBudgetOptions(cmd, &o->budget);
}

moss::MossState ResolveRunState(const RunOptions& o) {
  moss::MossState state = ResolveState(o.state);
  if (o.cmd->count("--scene"))
    Check(run::RenameField(moss::SetMossScene(o.scene, &state), kMossFieldFlags));
  // The land: a tree or a terrain (state fields, so the link regrows it); their second flag only
  // with their scene, never accepted and ignored.
  if (!o.tree_preset.empty()) {
    Check(run::RenameField(moss::SetMossScene(moss::kTreeLand, &state), kMossFieldFlags));
    Check(run::RenameField(moss::SetMossTree(o.tree_preset, &state), kMossFieldFlags));
  }
  if (!o.terrain_preset.empty()) {
    Check(run::RenameField(moss::SetMossScene(moss::kTerrainLand, &state), kMossFieldFlags));
    Check(run::RenameField(moss::SetMossTerrain(o.terrain_preset, &state), kMossFieldFlags));
  }
  if (o.cmd->count("--tree-years")) {
    if (state.scene != moss::kTreeLand || !o.mesh.empty())
      Fail(Status::Error("--tree-years",
                         "given without a tree; must come with --tree-preset (or a link's "
                         "scene=tree)"));
    Check(run::RenameField(moss::SetMossTreeYears(o.tree_years, &state), kMossFieldFlags));
  }
  if (o.cmd->count("--terrain-seed")) {
    if (state.scene != moss::kTerrainLand || !o.mesh.empty())
      Fail(Status::Error("--terrain-seed",
                         "given without a terrain; must come with --terrain-preset (or a "
                         "link's scene=terrain)"));
    Check(run::RenameField(moss::SetMossTerrainSeed(o.terrain_seed, &state), kMossFieldFlags));
  }
  if (o.cmd->count("--rock-triangles")) {
    if (state.scene != "rocks" || !o.mesh.empty())
      Fail(Status::Error("--rock-triangles",
                         "given without the rocks scene; must come with --scene rocks (or a "
                         "link's scene=rocks)"));
    Check(run::RenameField(moss::SetMossRockTriangles(o.rock_triangles, &state), kMossFieldFlags));
  }
  if (o.cmd->get_option_no_throw("--days") != nullptr && o.cmd->count("--days"))
    Check(run::RenameField(moss::SetMossDays(o.days, &state), kMossFieldFlags));
  if (o.cmd->count("--seed"))
    Check(run::RenameField(moss::SetMossSeed(o.seed, &state), kMossFieldFlags));
  if (o.cmd->count("--photons"))
    Check(AsFlag(state.params.Set(MossParam::kPhotons, o.photons), "--photons"));
  if (o.cmd->count("--indirect")) {
    if (o.indirect != "on" && o.indirect != "off")
      Fail(Status::Error("--indirect", "'" + Echo(o.indirect) + "' is unknown; must be on or off"));
    Check(AsFlag(state.params.Set(MossParam::kIndirect, o.indirect == "on" ? 1 : 0), "--indirect"));
  }
  return state;
}

moss::MossRun StartRun(const RunOptions& o, const moss::MossState& state) {
  Result<moss::MossRun> run = Status::Error("", "");
  if (o.mesh.empty()) {
    // A built-in scene, or the state's tree or terrain grown through the composition tier.
    std::string truncated_by;
    run = compose::StartMossOnLand(state, ResolveBudget(o.budget), kMossFieldFlags, &truncated_by);
    if (run.ok()) ReportTruncated(truncated_by);
  } else {
    io::MeshReadStats read;
    Result<geom::TriMesh> mesh = io::ReadMeshFile(o.mesh, &read);
    if (!mesh.ok()) Fail(mesh.status().Within("--mesh"));
    const std::string name = o.mesh.substr(o.mesh.find_last_of('/') + 1);
    Result<moss::MossScene> scene = moss::SceneFromMesh(*mesh, read.materials, name, read.images);
    if (!scene.ok()) Fail(scene.status().Within("--mesh"));
    run = moss::MossRun::StartOnScene(state, *scene, ResolveBudget(o.budget), name);
  }
  if (!run.ok()) Fail(run::RenameField(run.status(), kMossFieldFlags));
  return std::move(*run);
}

// The bytes of --out (by its ending) for the grown run.
std::string GrowOutput(const moss::MossRun& run, const std::string& ext, moss::MossMap map,
                       bool instancing) {
  if (ext == ".glb") {
    Result<gltf::Document> doc = run.MapDocument(map, instancing);
    if (!doc.ok()) Fail(doc.status().Within("--out"));
    Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
    if (!glb.ok()) Fail(glb.status().Within("--out"));
    return std::string(glb->begin(), glb->end());
  }
  if (ext == ".svg") return run.PhotonsSvg(false);
  return run.MossesJson() + "\n";
}

// moss grow: the run to --days; --out writes every living moss and cell (.json) or the land's map
// and the tufts (.glb), all or none, its estimate refused before the days are grown.
int RunGrow(const RunOptions& o, std::ostream& out) {
  moss::MossMap map = moss::MossMap::kCoverage;
  Check(run::RenameField(moss::MossMapFromName(o.map, &map), kMossFieldFlags));
  if (!o.mesh.empty() && o.cmd->count("--scene"))
    Fail(Status::Error("--mesh", "given with --scene; must be one or the other"));
  const moss::MossState state = ResolveRunState(o);
  std::vector<moss::WeatherDay> weather;
  if (!o.weather.empty()) {
    Check(CheckEnding("--weather", o.weather, {".json", ".csv"}));
    Result<std::string> text = ReadFile(o.weather, "--weather", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Result<std::vector<moss::WeatherDay>> days =
        moss::ParseWeather(*text, Extension(o.weather) == ".csv", state.params);
    if (!days.ok()) Fail(run::RenameField(days.status(), kMossFieldFlags));
    weather = std::move(*days);
  }
  if (o.cmd->count("--every") && !o.stats)
    Fail(Status::Error("--every", "only applies with --stats"));
  moss::MossRun run = StartRun(o, state);
  if (o.cmd->count("--every")) Check(run::RenameField(run.RecordEvery(o.every), kMossFieldFlags));
  if (!weather.empty()) {
    const std::string name = o.weather.substr(o.weather.find_last_of('/') + 1);
    Check(run::RenameField(run.UseWeather(std::move(weather), name), kMossFieldFlags));
  }
  const Budget budget = ResolveBudget(o.budget);
  const std::string ext = Extension(o.out_path);
  const std::string format = ext.empty() ? "" : ext.substr(1);
  const std::string change = "lower days, photons or max_mosses";
  // Each output's format and flag; every estimate is checked before the days are grown (the
  // mosses at their cap) and again on the grown run, then every file is written, all or none.
  std::vector<std::pair<std::string, std::string>> outputs;  // {flag, format}
  if (!o.out_path.empty()) outputs.push_back({"--out", format});
  if (!o.csv_path.empty()) outputs.push_back({"--csv", "csv"});
  for (const auto& [flag, kind] : outputs) {
    Result<Estimate> planned = run.PlannedExportEstimate(kind);
    Check(AsFlag(planned.status(), flag));
    Check(CheckEstimate(*planned, budget, change));
  }
  Check(run::RenameField(run.Advance(nullptr), kMossFieldFlags));
  for (const auto& [flag, kind] : outputs) {
    Result<Estimate> now = run.ExportEstimate(kind);
    Check(AsFlag(now.status(), flag));
    Check(CheckEstimate(*now, budget, change));
  }
  StagedOutputs staged;
  if (!o.out_path.empty())
    Check(staged.Stage("--out", o.out_path, GrowOutput(run, ext, map, o.instancing)));
  if (!o.csv_path.empty()) Check(staged.Stage("--csv", o.csv_path, run.DaysCsv()));
  Check(staged.Commit());
  if (o.stats) {
    out << run.StatsJson() << "\n";
  } else {
    const moss::MossWorld& w = run.world();
    nlohmann::ordered_json j;
    j["study"] = "moss";
    j["url"] = run.Hash("");
    j["days"] = w.day;
    j["mosses"] = w.mosses.size();
    j["seeds"] = w.seeds.size();
    out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  }
  return 0;
}

// moss photons: the first day's photon map on the scene with its day-0 mosses.
int RunPhotons(const RunOptions& o, std::ostream& out) {
  if (!o.mesh.empty() && o.cmd->count("--scene"))
    Fail(Status::Error("--mesh", "given with --scene; must be one or the other"));
  moss::MossState state = ResolveRunState(o);
  state.days = 1;
  const moss::MossRun run = StartRun(o, state);
  // Each file's estimate first, then both written, all or none.
  std::vector<std::pair<std::string, std::string>> outputs;  // {flag, format}
  if (!o.out_path.empty()) outputs.push_back({"--out", "svg"});
  if (!o.rays_path.empty()) outputs.push_back({"--rays", "rays"});
  for (const auto& [flag, kind] : outputs) {
    Result<Estimate> e = run.ExportEstimate(kind);
    Check(AsFlag(e.status(), flag));
    Check(CheckEstimate(*e, ResolveBudget(o.budget), "lower photons"));
  }
  StagedOutputs staged;
  if (!o.out_path.empty()) Check(staged.Stage("--out", o.out_path, run.PhotonsSvg(true)));
  if (!o.rays_path.empty()) {
    std::vector<geom::CastRay> rays;
    run.NextDayPhotons(&rays);
    Check(staged.Stage("--rays", o.rays_path, geom::WriteRayDump(run.cells().mesh, rays)));
  }
  Check(staged.Commit());
  out << run.PhotonDayJson() << "\n";
  return 0;
}

void PrintMossPresets(std::ostream& out) {
  for (const std::string& name : moss::MossPresetNames()) {
    out << name;
    for (const auto& [key, value] : moss::MossPresetValues(name))
      out << "\t" << key << "=" << FormatNumber(value);
    out << "\t" << moss::MossPresetSource(name) << "\n";
  }
}

}  // namespace

void AddMossCommands(CLI::App& app, CommandList& commands) {
  commands.studies.push_back(
      {"moss",
       &moss::MossTable(),
       &PrintMossPresets,
       {},
       {"moss", "soil", "--geology", "humus", "--theta", "0.2", "--S", "25"}});
  CLI::App* moss_app = Subcommand(app, "moss", "Moss on soil under light (Nomura 2010)");
  moss_app->require_subcommand(1);

  CLI::App* grow = moss_app->add_subcommand(
      "grow",
      "Grow moss on a built-in scene or a mesh day by day (photons, soil, life cycle); one JSON "
      "object on stdout (--stats: all the statistics); --out moss.json: every living moss and "
      "soil cell; --out moss.glb: the land with a map and the moss tufts; --out photons.svg: the "
      "last day's photons");
  auto go = std::make_shared<RunOptions>();
  AddRunOptions(grow, go.get(), true);
  grow->add_flag("--stats", go->stats, "Print every statistic as one JSON object");
  AddNumberFlag(grow, "--every", &go->every, kEveryRange,
                "With --stats: the breakdown (mosses by species, region, orientation and "
                "irradiance band; seeds; births and deaths; photons; soil per geology) every K "
                "days and on the last day, as rows 'every_days', " +
                    RangeHelp(kEveryRange));
  AddOutputFlag(grow, "--out", &go->out_path, {".json", ".glb", ".svg"},
                "Write .json (every living moss and soil cell), .glb (the land with a per-vertex "
                "map and the moss tufts of fig 3.7, species and birth day as extras) or .svg (the "
                "last day's stored photons, first hits and bounced, figs 4.1/4.2)");
  AddInputFlag(grow, "--weather", &go->weather,
               "Daily weather replacing the table's climate: .json {\"days\": [{T, rh, U, N, N0, "
               "P}, ...]} or .csv with a header row (docs/moss-model.md); not in the link");
  AddOutputFlag(grow, "--csv", &go->csv_path, {".csv"},
                "Write one row a day: day, mosses per species, seeds, births, deaths, photons "
                "stored, mean S, T_s, rh_s and theta per geology");
  OnlyWith(grow->add_option("--map", go->map,
                            "The .glb land's COLOR_0: coverage (default), S, T_s, rh_s, theta or "
                            "fitness (the best species' G)"),
           "--out", {".glb"});
  OnlyWith(grow->add_flag("--instancing", go->instancing,
                          "The .glb draws one tuft mesh per species with "
                          "EXT_mesh_gpu_instancing instead of merging every tuft"),
           "--out", {".glb"});
  commands.push_back({grow,
                      [go](std::ostream& out) { return RunGrow(*go, out); },
                      {"--scene", "plane", "--days", "2", "--photons", "256", "--stats"}});

  CLI::App* photons = moss_app->add_subcommand(
      "photons",
      "One day's photon map (figs 4.1/4.2's right halves): photons emitted, stored by bounce "
      "depth, and per region, as one JSON object; --out photons.svg: the picture");
  auto po = std::make_shared<RunOptions>();
  AddRunOptions(photons, po.get(), false);
  AddOutputFlag(photons, "--out", &po->out_path, {".svg"},
                "Write the stored photons seen from the front (figs 4.1/4.2's right halves): first "
                "hits and bounced photons in two colours over the land");
  AddOutputFlag(photons, "--rays", &po->rays_path, {".bin"},
                "Write every ray the day's photons cast at the land, with the land hit Niwa's "
                "BVH found, and the land's triangles (the soil cells), as a little-endian binary "
                "file (geom/ray_dump.h), for timing another ray tracer on the same rays "
                "(bench/moss_rays_peer.mjs)");
  commands.push_back({photons,
                      [po](std::ostream& out) { return RunPhotons(*po, out); },
                      {"--scene", "plane", "--photons", "256"}});

  CLI::App* scenes = moss_app->add_subcommand(
      "scenes", "The built-in scenes: triangles, soil cells by geology, regions (one JSON object)");
  commands.push_back({scenes, [](std::ostream& out) {
                        out << moss::MossScenesJson() << "\n";
                        return 0;
                      }});

  CLI::App* soil = moss_app->add_subcommand(
      "soil",
      "One soil cell for one day: every term of eqs 3.2-3.16 (longwave, bucket, evaporation "
      "efficiency, linearised energy balance) and the balance's residuals, as one JSON object");
  auto so = std::make_shared<SoilOptions>();
  soil->add_option("--geology", so->geology, "humus, sandy or asphalt (table 3.4)")->required();
  AddNumberFlag(soil, "--theta", &so->theta, kThetaRange,
                "Volumetric water content theta, " + RangeHelp(kThetaRange) +
                    " (at most the geology's theta_SAT)")
      ->required();
  AddNumberFlag(soil, "--S", &so->S, kLightRange, "Light S (W/m2), " + RangeHelp(kLightRange))
      ->required();
  AddNumberFlag(soil, "--T", &so->T, MossRowRange(MossParam::kT),
                "Air temperature (K; the T row), " + RangeHelp(MossRowRange(MossParam::kT)));
  AddNumberFlag(soil, "--mM", &so->m_over_M, kShareRange,
                "m/M of eq 3.5 (moss density near the cell), " + RangeHelp(kShareRange));
  AddNumberFlag(soil, "--V", &so->V, kShareRange,
                "Sky view V (read by longwave=1, sky-view), " + RangeHelp(kShareRange));
  AddStateOptions(soil, &so->state);
  commands.push_back({soil,
                      [so, soil](std::ostream& out) {
                        return RunSoil(*so, soil->count("--T") > 0, soil->count("--V") > 0, out);
                      },
                      {"--geology", "humus", "--theta", "0.2", "--S", "25"}});

  CLI::App* fitness = moss_app->add_subcommand(
      "fitness",
      "Fitness G of eq 3.17 (with each factor's s and g, eqs 3.18-3.19) and the day's growth D "
      "(eq 3.20) at one place, for one species or all three, as one JSON object");
  auto fo = std::make_shared<FitnessOptions>();
  fitness->add_option("--species", fo->species,
                      "gingoke, haigoke or sugigoke (default: all three)");
  AddNumberFlag(fitness, "--Ts", &fo->T_s, kSurfaceTRange,
                "Surface temperature T_s (K), " + RangeHelp(kSurfaceTRange))
      ->required();
  AddNumberFlag(fitness, "--rhs", &fo->rh_s, kSurfaceRhRange,
                "Surface humidity rh_s (may exceed 1), " + RangeHelp(kSurfaceRhRange))
      ->required();
  AddNumberFlag(fitness, "--S", &fo->S, kLightRange, "Light S (W/m2), " + RangeHelp(kLightRange))
      ->required();
  AddStateOptions(fitness, &fo->state);
  commands.push_back({fitness,
                      [fo](std::ostream& out) { return RunFitness(*fo, out); },
                      {"--species", "haigoke", "--Ts", "286", "--rhs", "1", "--S", "20"}});
}

}  // namespace niwa::cli

// niwa CLI commands of the bark study (Hirota, Kato, Kaneko, paper 003; core/bark,
// docs/bark-model.md): 'bark grow' (the 2-layer or 4-layer model grown on a torus patch of the
// trunk, its maps as PNGs (or with --out trunk.glb a trunk segment wearing them), a frame a
// cycle, its cycles as CSV, its statistics as one JSON object), 'bark layers' (Fig. 7's radial
// layout of the 4-layer model) and the table and presets for 'niwa params bark' and 'niwa presets
// bark'. A thin adapter over bark::BarkRun: flags into a state, the
// run, its outputs written all or none, the stats with the CLI's timings. cli-order: 60
#include <sys/stat.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "bark/bark_params.h"
#include "bark/bark_run.h"
#include "bark/bark_state.h"
#include "bark/calibrate.h"
#include "bark/layers.h"
#include "base/echo.h"
#include "cli_common.h"
#include "io/gltf_writer.h"
#include "params/param_text.h"
#include "run/field_names.h"

namespace niwa::cli {
namespace {

using bark::BarkParam;

// The one table of the bark commands' names for state fields (run/field_names.h).
const run::FieldNames kBarkFieldFlags = {
    {"species", "--species"}, {"model", "--model"},   {"seed", "--seed"}, {"N_R", "--size"},
    {"N_H", "--size"},        {"cycles", "--cycles"}, {"vary", "--vary"}, {"seeds", "--seeds"},
};

constexpr FlagRange kBarkSeedRange = {0, bark::kMaxBarkSeed, true};
constexpr FlagRange kThreadsRange = {1, 2, true};

FlagRange BarkRowRange(BarkParam row) {
  return RowFlagRange(bark::BarkTable().row(static_cast<std::size_t>(row)));
}

struct BarkGrowOptions {
  std::string species, model, size, url, params_file;
  std::string out, normal, height, orm, csv, frames;
  std::vector<std::string> sets;
  double seed = -1;  // -1: not given
  int cycles = 0;    // 0: not given (the row starts at 1)
  int threads = 2;   // the 4-layer model's lanes (bark/step_lanes.h)
  bool stats = false;
  BudgetOptions budget;
};

// The state from --url, then --species, --params, --model, --size, --seed, --cycles and --set.
bark::BarkState ResolveBarkState(const BarkGrowOptions& o) {
  bark::BarkState state;
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    bark::ApplyBarkHash(o.url, "", &state, &notices);
    if (!notices.empty()) throw BadInput{"--url: " + notices.front()};
  }
  if (!o.species.empty())
    Check(run::RenameField(bark::SetBarkSpecies(o.species, &state), kBarkFieldFlags));
  if (!o.params_file.empty()) {
    Result<std::string> text = ReadFile(o.params_file, "--params", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Check(bark::ApplyBarkStateJson(*text, &state).Within("--params " + o.params_file));
  }
  if (!o.model.empty())
    Check(run::RenameField(bark::SetBarkModel(o.model, &state), kBarkFieldFlags));
  if (!o.size.empty()) Check(run::RenameField(bark::SetBarkSize(o.size, &state), kBarkFieldFlags));
  if (o.seed >= 0) Check(run::RenameField(bark::SetBarkSeed(o.seed, &state), kBarkFieldFlags));
  if (o.cycles > 0)
    Check(run::RenameField(state.params.Set(BarkParam::kCycles, o.cycles), kBarkFieldFlags));
  for (const std::string& s : o.sets) Check(state.params.SetFromAssignment(s).Within("--set"));
  Check(run::RenameField(bark::CheckBarkState(state), kBarkFieldFlags));
  return state;
}

struct OutputFile {
  std::string field, path, bytes;
};

// bark grow: an adapter over bark::BarkRun (core/bark/bark_run.h).
int RunGrow(const BarkGrowOptions& o, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  const bark::BarkState state = ResolveBarkState(o);
  const Budget budget = ResolveBudget(o.budget);
  if (!o.frames.empty()) {
    // An existing folder, named without climbing out of it (no ".." part: frames land where asked).
    const std::string wrapped = "/" + o.frames + "/";
    struct stat info;
    if (wrapped.find("/../") != std::string::npos)
      Fail(Status::Error("--frames",
                         "'" + Echo(o.frames) + "' climbs out with '..'; must name a folder"));
    if (stat(o.frames.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
      Fail(Status::Error("--frames",
                         "'" + Echo(o.frames) + "' is not a folder; must be an existing folder"));
  }
  Result<bark::BarkRun> run = bark::BarkRun::Start(state, budget);
  if (!run.ok()) Fail(run::RenameField(run.status(), kBarkFieldFlags));
  if (Extension(o.out) == ".glb") {
    // The .glb's maps and mesh on top of the run's estimate, before any growth.
    Result<Estimate> glb = run->ExportEstimate("glb");
    if (!glb.ok()) Fail(glb.status().Within("--out"));
    Check(CheckEstimate(bark::EstimateBarkRun(state) + *glb, budget,
                        "lower N_R, N_H, cycles, T, settle_steps or map_size"));
  }
  run->RecordFrames(!o.frames.empty());
  run->SetLanes(o.threads);
  const auto t1 = std::chrono::steady_clock::now();
  Check(run::RenameField(run->Advance({}), kBarkFieldFlags));
  const auto t2 = std::chrono::steady_clock::now();
  // The maps' raster (drawn once, on first use) timed apart from their PNG encoding.
  const bool any_map = !o.out.empty() || !o.normal.empty() || !o.height.empty() || !o.orm.empty();
  if (any_map) (void)run->maps();
  const auto t2r = std::chrono::steady_clock::now();
  std::vector<OutputFile> files;
  const std::pair<const std::string*, const char*> maps[] = {
      {&o.out, "base_colour"}, {&o.normal, "normal"}, {&o.height, "height"}, {&o.orm, "orm"}};
  const char* flags[] = {"--out", "--normal", "--height", "--orm"};
  for (int k = 0; k < 4; ++k) {
    if (maps[k].first->empty()) continue;
    if (k == 0 && Extension(o.out) == ".glb") {
      // The trunk segment wearing the maps (bark_gltf.h).
      Result<gltf::Document> doc = run->Document();
      if (!doc.ok()) Fail(doc.status().Within("--out"));
      Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
      if (!glb.ok()) Fail(glb.status().Within("--out"));
      files.push_back({"--out", o.out, std::string(glb->begin(), glb->end())});
      continue;
    }
    Result<std::string> png = run->MapPng(maps[k].second);
    if (!png.ok()) Fail(png.status().Within(flags[k]));
    files.push_back({flags[k], *maps[k].first, *png});
  }
  if (!o.csv.empty()) files.push_back({"--csv", o.csv, run->CyclesCsv()});
  // --frames DIR: bark_cycle_001.png ... one base-colour map a cycle.
  for (std::size_t k = 0; k < run->FramePngs().size(); ++k) {
    char name[48];
    std::snprintf(name, sizeof name, "bark_cycle_%03zu.png", k + 1);
    files.push_back({"--frames", o.frames + "/" + name, run->FramePngs()[k]});
  }
  const auto t3 = std::chrono::steady_clock::now();
  StagedOutputs staged;
  for (const OutputFile& f : files) Check(staged.Stage(f.field, f.path, f.bytes));
  Check(staged.Commit());
  nlohmann::ordered_json j;
  if (o.stats) {
    j = nlohmann::ordered_json::parse(run->StatsJson());
    const auto t4 = std::chrono::steady_clock::now();
    const double ms_grow = std::chrono::duration<double, std::milli>(t2 - t1).count();
    j["ms"] = std::chrono::duration<double, std::milli>(t4 - t0).count();
    j["ms_grow"] = ms_grow;
    j["ms_maps"] = std::chrono::duration<double, std::milli>(t3 - t2).count();
    // ms_maps = the raster (the spec's "raster (4 maps)" goal) + the PNG encoding (and the CSV
    // and frames when asked).
    j["ms_maps_raster"] = std::chrono::duration<double, std::milli>(t2r - t2).count();
    j["ms_maps_png"] = std::chrono::duration<double, std::milli>(t3 - t2r).count();
    j["ns_per_spring_step"] = run->spring_steps() > 0 ? ms_grow * 1e6 / run->spring_steps() : 0.0;
  } else {
    j["species"] = state.species;
    j["model"] = state.model;
    j["seed"] = state.seed;
    j["hash"] = run->Hash("");
    nlohmann::ordered_json written = nlohmann::ordered_json::array();
    for (const OutputFile& f : files) written.push_back(f.path);
    j["written"] = written;
  }
  out << j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  return 0;
}

struct LayersOptions {
  BarkGrowOptions state;
  std::string csv;
};

// bark layers: Fig. 7's radial layout of the 4-layer model over the state's cycles
// (core/bark/layers.h), one JSON object; --csv writes the timeline.
int RunLayers(const LayersOptions& o, std::ostream& out) {
  const bark::BarkState state = ResolveBarkState(o.state);
  const int cycles = state.params.GetInt(BarkParam::kCycles);
  const std::vector<bark::LayerRadii> rows = bark::LayerTimeline(state.params, cycles, 10);
  if (!o.csv.empty()) {
    StagedOutputs staged;
    Check(staged.Stage("--csv", o.csv, bark::LayerTimelineCsv(rows)));
    Check(staged.Commit());
  }
  const bark::LayerRadii& first = rows.front();
  const bark::LayerRadii& last = rows.back();
  nlohmann::ordered_json j;
  j["cycles"] = cycles;
  j["rows"] = rows.size();
  j["R_o"] = first.r_inner;
  j["D"] = state.params.Get(BarkParam::kD);
  j["T"] = state.params.Get(BarkParam::kT);
  j["r_I_end"] = last.r_inner;
  j["surface_start"] = first.s_out;
  j["surface_end"] = last.s_out;
  j["layers_shed"] = cycles;  // one surface layer a role exchange
  out << j.dump() << "\n";
  return 0;
}

struct Table3Options {
  BarkGrowOptions state;
  std::string seeds = "1-5";
};

// bark table3: Table 3 of the paper beside the 2-layer model's regions over seeds A..B
// (bark::Table3Json), one JSON object.
// "A-B": two whole seeds, A <= B, at most 20 of them.
std::pair<uint64_t, uint64_t> ParseSeeds(const std::string& seeds) {
  const std::size_t dash = seeds.find('-');
  std::optional<double> first, last;
  if (dash != std::string::npos) {
    first = ParseNumber(seeds.substr(0, dash));
    last = ParseNumber(seeds.substr(dash + 1));
  }
  if (!first || !last || *first != std::floor(*first) || *last != std::floor(*last) || *first < 0 ||
      *last > bark::kMaxBarkSeed || *first > *last || *last - *first >= 20) {
    Fail(Status::Error("--seeds", "'" + Echo(seeds) +
                                      "' is not A-B; must be two whole seeds in [0, 4294967295], "
                                      "A <= B, at most 20 of them (e.g. 1-5)"));
  }
  return {static_cast<uint64_t>(*first), static_cast<uint64_t>(*last)};
}

int RunTable3(const Table3Options& o, std::ostream& out) {
  const auto [first, last] = ParseSeeds(o.seeds);
  std::vector<bark::BarkState> states;
  for (const char* species : {"camphor", "tallow", "pine"}) {
    BarkGrowOptions one = o.state;
    one.species = species;
    states.push_back(ResolveBarkState(one));
  }
  Result<std::string> table = bark::Table3Json(states, first, last, ResolveBudget(o.state.budget));
  if (!table.ok()) Fail(run::RenameField(table.status(), kBarkFieldFlags));
  out << *table << "\n";
  return 0;
}

struct CalibrateOptions {
  BarkGrowOptions state;
  std::string seeds = "1-3";
  std::vector<std::string> vary;
};

// bark calibrate: the grid search of bark::CalibrateJson over --vary rows (default: the model's
// DefaultCalibrateAxes), one JSON object.
int RunCalibrate(const CalibrateOptions& o, std::ostream& out) {
  const auto [first, last] = ParseSeeds(o.seeds);
  bark::CalibrateRequest request;
  request.base = ResolveBarkState(o.state);
  request.first_seed = first;
  request.last_seed = last;
  for (const std::string& v : o.vary) {
    Result<bark::CalibrateAxis> axis = bark::ParseCalibrateAxis(v, request.base.model);
    if (!axis.ok()) Fail(run::RenameField(axis.status(), kBarkFieldFlags));
    request.vary.push_back(*axis);
  }
  if (request.vary.empty()) request.vary = bark::DefaultCalibrateAxes(request.base.model);
  Result<std::string> json = bark::CalibrateJson(request, ResolveBudget(o.state.budget));
  if (!json.ok()) Fail(run::RenameField(json.status(), kBarkFieldFlags));
  out << *json << "\n";
  return 0;
}

void PrintBarkPresets(std::ostream& out) {
  for (const std::string& name : bark::BarkPresetNames()) {
    out << name;
    for (const auto& [key, value] : bark::BarkPresetValues(name))
      out << "\t" << key << "=" << FormatNumber(value);
    out << "\t" << bark::BarkPresetSource(name) << "\n";
  }
}

}  // namespace

void AddBarkCommands(CLI::App& app, CommandList& commands) {
  const std::vector<std::string> example = {"--size", "16x8", "--set", "map_size=256", "--stats"};
  std::vector<std::string> study_example = {"bark", "grow"};
  study_example.insert(study_example.end(), example.begin(), example.end());
  commands.studies.push_back({"bark", &bark::BarkTable(), &PrintBarkPresets, {}, study_example});
  CLI::App* bark_app =
      Subcommand(app, "bark", "Bark that cracks as the trunk grows (Hirota, Kato, Kaneko)");
  bark_app->require_subcommand(1);

  CLI::App* grow = bark_app->add_subcommand(
      "grow",
      "Grow the 2-layer spring model (paper 003 §3) or the 4-layer one (§4: peeling and shedding) "
      "on a torus patch of the trunk: cracks, maps (base colour, normal, 16-bit height, "
      "occlusion/roughness) and statistics");
  auto o = std::make_shared<BarkGrowOptions>();
  grow->add_option("--species", o->species,
                   "camphor (default), tallow or pine: Table 2 (niwa presets bark)");
  grow->add_option("--model", o->model,
                   "2layer (default; paper §3) or 4layer (§4: S, M1, M2 over the inner layer, "
                   "role exchange each cycle, peeling by Table 4, shedding)");
  grow->add_option("--size", o->size,
                   "Lattice WxH: N_R columns around (even, " +
                       RangeHelp(BarkRowRange(BarkParam::kNR)) + ") by N_H nodes along (" +
                       RangeHelp(BarkRowRange(BarkParam::kNH)) + "); default 128x64");
  AddNumberFlag(grow, "--seed", &o->seed, kBarkSeedRange, "RNG seed, " + RangeHelp(kBarkSeedRange));
  AddNumberFlag(
      grow, "--cycles", &o->cycles, BarkRowRange(BarkParam::kCycles),
      "Growth periods T (the cycles row), " + RangeHelp(BarkRowRange(BarkParam::kCycles)));
  grow->add_option("--set", o->sets, "KEY=VALUE of the bark table (niwa params bark)");
  AddInputFlag(grow, "--params", &o->params_file,
               "State JSON {species, model, seed, params: {key: value}}");
  grow->add_option("--url", o->url,
                   "A share-link hash (species=...&seed=...&N_R=...); other flags override it");
  grow->add_flag("--stats", o->stats, "Print the statistics as one JSON object");
  AddOutputFlag(grow, "--out", &o->out, {".png", ".glb"},
                "Write the base colour map as .png, or a trunk segment of the grown patch's radius "
                "and height wearing the maps (base colour, normal, occlusion/roughness; metres, "
                "y up) as .glb");
  AddOutputFlag(grow, "--normal", &o->normal, {".png"},
                "Write the normal map as .png (tangent space, OpenGL: +y up)");
  AddOutputFlag(grow, "--height", &o->height, {".png"},
                "Write the height map as a 16-bit greyscale .png (0: inner layer, 65535: surface)");
  AddOutputFlag(grow, "--orm", &o->orm, {".png"},
                "Write occlusion (R), roughness (G) and metallic (B) as .png");
  AddOutputFlag(grow, "--csv", &o->csv, {".csv"},
                "Write broken springs and strains every tenth of a cycle as .csv");
  grow->add_option("--frames", o->frames,
                   "Write a base-colour map of each cycle's end into this existing folder "
                   "(bark_cycle_001.png, ...)");
  AddNumberFlag(grow, "--threads", &o->threads, kThreadsRange,
                "Threads of the 4-layer model's steps, " + RangeHelp(kThreadsRange) +
                    " (default 2; the same bytes either way; one where the build has no threads)");
  AddBudgetOptions(grow, &o->budget);
  commands.push_back({grow, [o](std::ostream& out) { return RunGrow(*o, out); }, example});

  CLI::App* layers = bark_app->add_subcommand(
      "layers",
      "Fig. 7: the 4-layer model's radial layout (inner layer, M2, M1, surface) over the cycles, "
      "roles moving outward at each cycle, as one JSON object");
  auto lo = std::make_shared<LayersOptions>();
  layers->add_option("--species", lo->state.species, "camphor (default), tallow or pine");
  layers->add_option("--size", lo->state.size,
                     "Lattice WxH (R_o = √3·L_o·N_R/4π; N_R even, " +
                         RangeHelp(BarkRowRange(BarkParam::kNR)) + ")");
  AddNumberFlag(layers, "--cycles", &lo->state.cycles, BarkRowRange(BarkParam::kCycles),
                "Cycles, " + RangeHelp(BarkRowRange(BarkParam::kCycles)));
  layers->add_option("--set", lo->state.sets, "KEY=VALUE of the bark table (niwa params bark)");
  layers->add_option("--url", lo->state.url, "A share-link hash; other flags override it");
  AddOutputFlag(layers, "--csv", &lo->csv, {".csv"},
                "Write t, cycle, tau, r_I, the layers' outer radii and birth cycles as .csv");
  commands.push_back(
      {layers, [lo](std::ostream& out) { return RunLayers(*lo, out); }, {"--cycles", "3"}});

  CLI::App* table3 = bark_app->add_subcommand(
      "table3",
      "Table 3 of the paper (crack-region sizes of camphor, tallow and pine) beside the 2-layer "
      "model's, mean and sd over seeds, as one JSON object");
  auto to = std::make_shared<Table3Options>();
  table3->add_option("--seeds", to->seeds, "Seeds A-B (at most 20; default 1-5)");
  table3->add_option(
      "--size", to->state.size,
      "Lattice WxH (N_R even, " + RangeHelp(BarkRowRange(BarkParam::kNR)) + "); default 128x64");
  table3->add_option("--set", to->state.sets,
                     "KEY=VALUE of the bark table over every species' preset (e.g. dH=0.03, "
                     "dR=0.021 and D=1: level A, one growth for all)");
  AddBudgetOptions(table3, &to->state.budget);
  commands.push_back({table3,
                      [to](std::ostream& out) { return RunTable3(*to, out); },
                      {"--seeds", "1-1", "--size", "16x8"}});

  CLI::App* calibrate = bark_app->add_subcommand(
      "calibrate",
      "Search the rows the spec lets a species calibrate (2layer: dH, dR, D against Table 3's "
      "means and maxima of the crack spacing along scan lines; 4layer: kappa_h, gamma, A, eta "
      "against a partly peeled surface) on a "
      "grid over seeds, as one JSON object with every candidate, the best and whether it meets "
      "the bars");
  auto co = std::make_shared<CalibrateOptions>();
  calibrate->add_option("--species", co->state.species, "camphor (default), tallow or pine");
  calibrate->add_option("--model", co->state.model, "2layer (default) or 4layer");
  calibrate->add_option("--vary", co->vary,
                        "KEY=LO:HI:N (N evenly spaced values, 1-9) or KEY=V; repeat for a grid. "
                        "Default 2layer dH=0.02:0.05:7; 4layer kappa_h=0.03:0.3:4 gamma=0.25:1:2 "
                        "A=2:8:2");
  calibrate->add_option("--seeds", co->seeds, "Seeds A-B (at most 20; default 1-3)");
  calibrate->add_option(
      "--size", co->state.size,
      "Lattice WxH (N_R even, " + RangeHelp(BarkRowRange(BarkParam::kNR)) + "); default 128x64");
  AddNumberFlag(calibrate, "--cycles", &co->state.cycles, BarkRowRange(BarkParam::kCycles),
                "Cycles (4layer: at least 2), " + RangeHelp(BarkRowRange(BarkParam::kCycles)));
  calibrate->add_option("--set", co->state.sets,
                        "KEY=VALUE of the bark table over the species' preset");
  AddBudgetOptions(calibrate, &co->state.budget);
  commands.push_back({calibrate,
                      [co](std::ostream& out) { return RunCalibrate(*co, out); },
                      {"--seeds", "1-1", "--size", "16x8", "--vary", "dH=0.03"}});
}

}  // namespace niwa::cli

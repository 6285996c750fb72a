// niwa CLI commands of the terrain study: 'terrain grow' (a whole mountain from one seed contour,
// Misawa, Chiba, Saito 1987; core/terrain, docs/terrain-model.md), 'terrain compare', 'terrain
// shrink' (the shrinking algorithm traced for Figs 2-8 and 12), 'terrain render' (a bird's-eye
// picture of any heightmap, Fig 17) and 'terrain seeds'.
// cli-order: 40
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "image/png.h"
#include "image/relief.h"
#include "io/gltf_writer.h"
#include "run/field_names.h"
#include "terrain/compare.h"
#include "terrain/contour_io.h"
#include "terrain/contour_repair.h"
#include "terrain/generate.h"
#include "terrain/seeds.h"
#include "terrain/shrink_trace.h"
#include "terrain/terrain_budget.h"
#include "terrain/terrain_output.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_run.h"
#include "terrain/terrain_state.h"

namespace niwa::cli {
namespace {

using terrain::TerrainParam;

// The one table of the terrain commands' names for state fields (run/field_names.h): a core error
// naming the field reads with the flag that set it (errors of a --url, --params or --set value
// keep the field, under that flag).
const run::FieldNames kTerrainFieldFlags = {
    {"builtin", "--builtin"}, {"contour", "--contour"}, {"preset", "--method"},
    {"seed", "--seed"},       {"res", "--res"},         {"heightmap", "--heightmap"},
    {"dem", "--dem"},
};

// The flag ranges of table rows, written once in the terrain table (terrain_params.cpp).
FlagRange TerrainRowRange(TerrainParam row) {
  return RowFlagRange(terrain::TerrainTable().row(static_cast<std::size_t>(row)));
}
// The RNG seed's range (a state field: terrain::SetTerrainSeed checks the same).
constexpr FlagRange kTerrainSeedRange = {0, terrain::kMaxTerrainSeed, true};

struct TerrainGrowOptions {
  std::string contour, builtin, method, contours_out, params_file, url, out, heightmap;
  std::vector<std::string> sets;
  double seed = -1;  // -1: not given (the seed's range starts at 0)
  int res = 0;       // 0: not given (the row's range starts at 8)
  bool stats = false, repair = false;
  BudgetOptions budget;
};

// Several outputs of one run are all written or none (cli::StagedOutputs: each staged to a
// unique temporary file beside its target, then all renamed; any failure removes them all).
struct OutputFile {
  std::string field, path, bytes;
};
void WriteAllOrNone(const std::vector<OutputFile>& files) {
  StagedOutputs outputs;
  for (const OutputFile& f : files) Check(outputs.Stage(f.field, f.path, f.bytes));
  Check(outputs.Commit());
}

// --repair: a seed contour that crosses itself (a drawing saved from the page, a traced file) made
// simple as the page makes a fresh drawing (core/terrain/contour_repair.h), with a notice.
void RepairSeed(const TerrainGrowOptions& o, terrain::TerrainState* state) {
  Result<terrain::ContourRepair> r = terrain::RepairContour(state->points);
  // A file's contour is the flag's; one from --url or --params keeps its field under that flag.
  if (!r.ok()) {
    Fail(!o.contour.empty()       ? run::RenameField(r.status(), kTerrainFieldFlags)
         : !o.params_file.empty() ? r.status().Within("--params " + o.params_file)
                                  : r.status().Within("--url"));
  }
  if (!r->repaired) return;
  std::cerr << "niwa: repaired: the seed contour crossed itself ("
            << (r->method == "loops"
                    ? std::to_string(r->loops_removed) + " loop" +
                          (r->loops_removed == 1 ? "" : "s") + " cut, §4.4 method 2"
                    : std::string("its largest simple piece kept"))
            << "): " << r->ring.size() << " points\n";
  state->points = r->ring;
}

// The state from --url, then the seed flags, --method, --params, --seed, --set and --res.
terrain::TerrainState ResolveTerrainState(const TerrainGrowOptions& o) {
  terrain::TerrainState state;
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    terrain::ApplyTerrainHash(o.url, "", &state, &notices);
    if (!notices.empty()) throw BadInput{"--url: " + notices.front()};
  }
  if (!o.contour.empty() && !o.builtin.empty()) {
    Fail(Status::Error("--contour", "give one of --contour FILE or --builtin NAME, not both"));
  }
  bool file_elevation = false;
  double elevation = 0;
  if (!o.builtin.empty()) {
    Check(run::RenameField(terrain::SetTerrainBuiltin(o.builtin, &state), kTerrainFieldFlags));
  } else if (!o.contour.empty()) {
    Result<std::string> text = ReadFile(o.contour, "--contour", kMaxContourFileBytes);
    if (!text.ok()) Fail(text.status());
    Result<terrain::SeedFile> file = terrain::ParseContourJson(*text);
    if (!file.ok()) Fail(file.status().Within("--contour"));
    // A contour that cannot seed a mountain is the file's fault: name the flag (Grow checks again).
    if (!o.repair) {
      Result<terrain::Ring> checked = terrain::CheckSeed(file->ring);
      if (!checked.ok()) Fail(run::RenameField(checked.status(), kTerrainFieldFlags));
    }
    state.builtin.clear();
    state.points = file->ring;
    file_elevation = file->has_elevation;
    elevation = file->elevation;
  } else if (o.url.empty() && o.params_file.empty()) {
    Fail(Status::Error("--contour",
                       "give one of --contour FILE, --builtin NAME (disk, dumbbell, lobes7, "
                       "jacksboro, valleys), --url HASH or --params FILE"));
  }
  // Without --url the preset is always applied (the built-in's d, Δh, h0, then the method's rows).
  if (!o.method.empty() || o.url.empty())
    Check(run::RenameField(terrain::SetTerrainPreset(o.method, &state), kTerrainFieldFlags));
  if (file_elevation) Check(AsFlag(state.params.Set(TerrainParam::kH0, elevation), "elevation"));
  if (!o.params_file.empty()) {
    Result<std::string> text = ReadFile(o.params_file, "--params", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Check(terrain::ApplyTerrainStateJson(*text, &state).Within("--params " + o.params_file));
  }
  if (o.seed >= 0)
    Check(run::RenameField(terrain::SetTerrainSeed(o.seed, &state), kTerrainFieldFlags));
  for (const std::string& s : o.sets) Check(state.params.SetFromAssignment(s).Within("--set"));
  if (o.res != 0)
    Check(run::RenameField(state.params.Set(TerrainParam::kRes, o.res), kTerrainFieldFlags));
  if (o.repair && state.builtin.empty()) RepairSeed(o, &state);
  return state;
}

// The format of TerrainRun::Export a --contours path asks for, by its extension.
std::string ContoursFormat(const std::string& path) {
  const std::string ext = Extension(path);
  return ext == ".json" ? "json" : ext == ".geojson" ? "geojson" : "svg";
}

// terrain grow: an adapter over terrain::TerrainRun (core/terrain/terrain_run.h): flags into a
// state, the run, its outputs written all or none, its stats with the CLI's timings.
int RunGrow(const TerrainGrowOptions& o, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  // The outputs' endings were checked by their declared flags (AddOutputFlag).
  if (!o.heightmap.empty() &&
      o.heightmap.substr(0, o.heightmap.size() - 4) + ".json" == o.contours_out) {
    Fail(Status::Error("--contours", "'" + o.contours_out +
                                         "' is the --heightmap sidecar; "
                                         "must be another file"));
  }
  const terrain::TerrainState state = ResolveTerrainState(o);
  const Budget budget = ResolveBudget(o.budget);
  terrain::TerrainRunPlan plan;
  plan.words = kTerrainFieldFlags;
  if (!o.out.empty()) plan.outputs.push_back(terrain::TerrainOutput::kGlb);
  if (!o.heightmap.empty()) plan.outputs.push_back(terrain::TerrainOutput::kHeightmap);
  if (!o.contours_out.empty())
    plan.outputs.push_back(*terrain::TerrainOutputOfFormat(ContoursFormat(o.contours_out)));
  Result<terrain::TerrainRun> run = terrain::TerrainRun::Start(state, budget, std::move(plan));
  if (!run.ok()) Fail(run::RenameField(run.status(), kTerrainFieldFlags));
  const Status advanced = run->Advance({});
  ReportTruncated(run->truncated_by());
  if (std::getenv("NIWA_BUDGET_TRACE") && run->checked_estimate()) {  // docs/budgets.md
    const Estimate& e = *run->checked_estimate();
    std::fprintf(stderr, "budget: %.0f MB %.2f s (%s)\n", e.memory_bytes / 1048576, e.seconds,
                 e.what.c_str());
    Result<terrain::Ring> seed = terrain::StateSeed(state);
    if (seed.ok()) {
      const terrain::SeedShrinkForecast f = terrain::ForecastSeedShrink(*seed, state.params);
      std::fprintf(stderr,
                   "budget: the seed's sweep: %.0f work estimated (%.0f windings, %.0f split "
                   "points, %.0f pairs tried), %.0f made\n",
                   f.work(), f.windings, f.split_points, f.tried_pairs,
                   run->terrain().counts.sweep_tests);
    }
  }
  Check(run::RenameField(advanced, kTerrainFieldFlags));
  const auto t2 = std::chrono::steady_clock::now();
  std::vector<OutputFile> files;
  if (!o.contours_out.empty()) {
    Result<std::string> text = run->Export(ContoursFormat(o.contours_out));
    if (!text.ok()) Fail(text.status().Within("--contours"));
    files.push_back({"--contours", o.contours_out, *text});
  }
  if (!o.out.empty()) {
    Result<std::string> glb = run->Export("glb");
    if (!glb.ok()) Fail(glb.status().Within("--out"));
    files.push_back({"--out", o.out, *glb});
  }
  if (!o.heightmap.empty()) {
    Result<terrain::Heightmap> hm = run->EncodeHeightmapFiles();
    if (!hm.ok()) Fail(run::RenameField(hm.status(), kTerrainFieldFlags));
    files.push_back({"--heightmap", o.heightmap, std::string(hm->png.begin(), hm->png.end())});
    const std::string stem = o.heightmap.substr(0, o.heightmap.size() - 4);
    files.push_back({"--heightmap", stem + ".json", hm->sidecar_json});
  }
  const auto t3 = std::chrono::steady_clock::now();
  WriteAllOrNone(files);
  const auto t4 = std::chrono::steady_clock::now();
  if (o.stats) {
    nlohmann::json j = nlohmann::json::parse(run->StatsJson());
    const auto t5 = std::chrono::steady_clock::now();
    const terrain::GrowCounts& counts = run->terrain().counts;
    j["ms"] = std::chrono::duration<double, std::milli>(t5 - t0).count();  // the whole run
    // Up to the heightfield: the flags, the state, the checks and the grow.
    j["ms_grow"] = std::chrono::duration<double, std::milli>(t2 - t0).count() -
                   run->ms_heightfield() - run->ms_erosion();
    j["ms_shrink"] = counts.ms_shrink;
    j["ms_mpd"] = counts.ms_mpd;
    j["ms_fd"] = counts.ms_fd;
    j["ms_loops"] = counts.ms_loops;
    j["ms_heightfield"] = run->ms_heightfield();
    if (j.contains("erosion")) j["ms_erosion"] = run->ms_erosion();
    j["ms_encode"] = std::chrono::duration<double, std::milli>(t3 - t2).count();
    j["ms_write"] = std::chrono::duration<double, std::milli>(t4 - t3).count();
    j["ms_stats"] = std::chrono::duration<double, std::milli>(t5 - t4).count();
    out << j.dump() << "\n";
  }
  return 0;
}

// terrain compare: an adapter over terrain::CompareWithDem (core/terrain/terrain_run.h): flags
// into a state, the DEM's two files read, the comparison printed.
int RunCompare(const TerrainGrowOptions& o, const std::string& dem_path, std::ostream& out) {
  Check(CheckEnding("--dem", dem_path, {".png"}));
  Result<std::string> png = ReadFile(dem_path, "--dem", kMaxDemFileBytes);
  if (!png.ok()) Fail(png.status());
  const std::string side_path = dem_path.substr(0, dem_path.size() - 4) + ".json";
  Result<std::string> side = ReadFile(side_path, "--dem", kMaxParamsFileBytes);
  if (!side.ok()) Fail(side.status());
  const terrain::TerrainState state = ResolveTerrainState(o);
  Result<terrain::DemComparison> c = terrain::CompareWithDem(
      state, std::vector<unsigned char>(png->begin(), png->end()), *side, ResolveBudget(o.budget));
  if (!c.ok()) Fail(run::RenameField(c.status(), kTerrainFieldFlags));
  ReportTruncated(c->truncated_by);
  out << c->json << "\n";
  return 0;
}

struct RenderOptions {
  std::string dem, out, frame, tint;
  double view_from = 200, elevation = 35, fov = 30, exaggeration = 1, sun_from = 315,
         sun_elevation = 40, floor = -1e9;
  int width = 960, height = 600;
};

// "A,B[,C,D]": `count` numbers, each finite, or one line naming the flag.
std::vector<double> NumberList(const std::string& flag, const std::string& text, std::size_t count,
                               const std::string& form) {
  std::vector<std::string> parts;
  std::size_t at = 0;
  for (std::size_t k; (k = text.find(',', at)) != std::string::npos; at = k + 1)
    parts.push_back(text.substr(at, k - at));
  parts.push_back(text.substr(at));
  if (parts.size() != count) Fail(Status::Error(flag, "'" + text + "' must be " + form));
  std::vector<double> values;
  for (const std::string& part : parts)
    values.push_back(FlagNumber(flag, part, {-1e9, 1e9, false, " (m)"}));
  return values;
}

// terrain render: a bird's-eye PNG of a 16-bit heightmap and its sidecar (a grown mountain's
// --heightmap or a real DEM), through image::RenderRelief; one JSON object on stdout.
int RunRender(const RenderOptions& o, std::ostream& out) {
  Check(CheckEnding("--dem", o.dem, {".png"}));
  Result<std::string> png = ReadFile(o.dem, "--dem", kMaxDemFileBytes);
  if (!png.ok()) Fail(png.status());
  const std::string side_path = o.dem.substr(0, o.dem.size() - 4) + ".json";
  Result<std::string> side = ReadFile(side_path, "--dem", kMaxParamsFileBytes);
  if (!side.ok()) Fail(side.status());
  Result<terrain::Heightfield> dem =
      terrain::ReadHeightmap(std::vector<unsigned char>(png->begin(), png->end()), *side, "--dem");
  if (!dem.ok()) Fail(dem.status());
  image::ReliefGrid grid;
  grid.width = dem->width;
  grid.height = dem->height;
  grid.cell = dem->cell;
  grid.x0 = dem->x0 + 0.5 * dem->cell;  // sample (0, 0) is the north-west cell's centre
  grid.y1 = dem->y1 - 0.5 * dem->cell;
  grid.heights = dem->h;
  image::ReliefView view;
  view.width = o.width;
  view.height = o.height;
  view.view_from_deg = o.view_from;
  view.elevation_deg = o.elevation;
  view.fov_deg = o.fov;
  view.exaggeration = o.exaggeration;
  view.sun_from_deg = o.sun_from;
  view.sun_elevation_deg = o.sun_elevation;
  if (o.floor > -1e9) view.floor = o.floor;
  if (!o.frame.empty()) {
    const std::vector<double> f = NumberList("--frame", o.frame, 4, "X_MIN,Y_MIN,X_MAX,Y_MAX (m)");
    if (!(f[0] < f[2] && f[1] < f[3]))
      Fail(Status::Error("--frame", "'" + o.frame + "' must have X_MIN < X_MAX and Y_MIN < Y_MAX"));
    for (int k = 0; k < 4; ++k) view.frame[k] = f[static_cast<std::size_t>(k)];
  }
  if (!o.tint.empty()) {
    const std::vector<double> t = NumberList("--tint", o.tint, 2, "LOW,HIGH (m)");
    if (!(t[0] < t[1])) Fail(Status::Error("--tint", "'" + o.tint + "' must have LOW < HIGH"));
    view.tint_min = t[0];
    view.tint_max = t[1];
  }
  Result<image::Rgba8Image> picture = image::RenderRelief(grid, view);
  if (!picture.ok()) {
    // The core names "grid" (the heightmap) or "view" (the flags).
    const Status& st = picture.status();
    Fail(Status::Error(st.field() == "grid"                              ? "--dem"
                       : st.message().find("frame") != std::string::npos ? "--frame"
                                                                         : "--floor",
                       st.message()));
  }
  Result<std::vector<unsigned char>> bytes = image::EncodeRgba8Png(*picture);
  if (!bytes.ok()) Fail(bytes.status());
  WriteAllOrNone({{"--out", o.out, std::string(bytes->begin(), bytes->end())}});
  nlohmann::json j = {{"out", o.out},
                      {"width", view.width},
                      {"height", view.height},
                      {"samples", {grid.width, grid.height}},
                      {"cell", grid.cell}};
  out << j.dump() << "\n";
  return 0;
}

struct ShrinkCommandOptions {
  std::string contour, builtin, join = "capped", displace, fourier, svg;
  double d = 0, c = 1.4, clean_len = 0, clean_angle = 0;
  int steps = 1;
  uint64_t seed = 1;
  bool outward = false;
};
constexpr FlagRange kShrinkD{0, 1e6, false, " (m; 0 = the built-in's d)"};
constexpr FlagRange kShrinkC{1, 100};
constexpr FlagRange kShrinkSteps{0, terrain::kMaxTraceSteps, true};
constexpr FlagRange kCleanLen{0, 1e6, false, " (m)"};
constexpr FlagRange kCleanAngle{0, 180, false, " (degrees)"};

nlohmann::json RingJson(const terrain::Ring& r) {
  nlohmann::json a = nlohmann::json::array();
  for (const terrain::Vec2& p : r) a.push_back({p.x, p.y});
  return a;
}

// terrain shrink: one JSON object of the measures per step on stdout, the figure as --svg.
int RunShrink(const ShrinkCommandOptions& o, bool seed_given, std::ostream& out) {
  if (seed_given && o.displace.empty() && o.fourier.empty())
    Fail(Status::Error(
        "--seed", "only applies with --displace D0,D2,THETA_MIN,THETA_MAX or --fourier F0[,N]"));
  if (o.contour.empty() == o.builtin.empty())
    Fail(Status::Error("--contour",
                       "give one of --contour FILE or --builtin NAME (disk, "
                       "dumbbell, lobes7, jacksboro, valleys)"));
  terrain::Ring seed;
  double d = o.d;
  if (!o.builtin.empty()) {
    Result<terrain::Ring> r = terrain::BuiltinSeed(o.builtin);
    if (!r.ok()) Fail(run::RenameField(r.status(), kTerrainFieldFlags));
    seed = *r;
    for (const terrain::SeedInfo& info : terrain::BuiltinSeeds())
      if (info.name == o.builtin && d == 0) d = info.d;
  } else {
    Result<std::string> text = ReadFile(o.contour, "--contour", kMaxContourFileBytes);
    if (!text.ok()) Fail(text.status());
    Result<terrain::SeedFile> file = terrain::ParseContourJson(*text);
    if (!file.ok()) Fail(file.status().Within("--contour"));
    seed = file->ring;
    if (d == 0) Fail(Status::Error("--d", "give the offset distance d in (0, 1e6] m"));
  }
  terrain::ShrinkTraceOptions t;
  t.shrink.d = d;
  t.shrink.c = o.c;
  const int join = terrain::JoinFromName(o.join);
  if (join < 0)
    Fail(Status::Error("--join", "'" + o.join + "' must be miter, bevel, round or capped"));
  t.shrink.join = static_cast<terrain::Join>(join);
  t.shrink.clean_len = o.clean_len;
  t.shrink.clean_angle_deg = o.clean_angle;
  t.shrink.outward = o.outward;
  t.steps = o.steps;
  t.rng_seed = o.seed;
  if (!o.displace.empty()) {  // D0,D2,THETA_MIN,THETA_MAX
    std::vector<std::string> parts;
    std::size_t at = 0;
    for (std::size_t k; (k = o.displace.find(',', at)) != std::string::npos; at = k + 1)
      parts.push_back(o.displace.substr(at, k - at));
    parts.push_back(o.displace.substr(at));
    if (parts.size() != 4)
      Fail(Status::Error("--displace", "'" + o.displace + "' must be D0,D2,THETA_MIN,THETA_MAX"));
    t.displace = true;
    t.d0 = FlagNumber("--displace", parts[0], {0, 1e6, false, " (d0, m)"});
    t.d2 = FlagNumber("--displace", parts[1], {0, 1e6, false, " (d'', m)"});
    t.theta_min_deg = FlagNumber("--displace", parts[2], {0, 89, false, " (theta min, degrees)"});
    t.theta_max_deg = FlagNumber("--displace", parts[3], {0, 89, false, " (theta max, degrees)"});
  }
  if (!o.fourier.empty()) {  // F0[,N]: Fig 14, every kept ring phase-randomised
    const std::size_t comma = o.fourier.find(',');
    t.fourier = true;
    t.fd_f0 = static_cast<int>(
        FlagNumber("--fourier", o.fourier.substr(0, comma), {1, 32768, true, " (f0)"}));
    if (comma != std::string::npos)
      t.fd_n = static_cast<int>(FlagNumber("--fourier", o.fourier.substr(comma + 1),
                                           {16, 65536, true, " (FFT samples n)"}));
  }
  Result<terrain::ShrinkTrace> trace = terrain::TraceShrink(seed, t);
  if (!trace.ok()) {
    // The core names its option; the flag that set it: d0, d2 and theta come from --displace.
    const Status& s = trace.status();
    const std::string& f = s.field();
    const std::string flag = f == "d0" || f == "d2" || f == "theta"         ? "--displace"
                             : f == "fd_f0" || f == "fd_n" || f == "fd_amp" ? "--fourier"
                             : f == "clean_len"                             ? "--clean-len"
                             : f == "clean_angle"                           ? "--clean-angle"
                                                                            : "--" + f;
    Fail(Status::Error(flag, s.message()));
  }
  nlohmann::json j;
  j["d"] = d;
  j["join"] = terrain::JoinName(join);
  j["c"] = o.c;
  j["seed_points"] = trace->seed.size();
  j["seed_min_angle_deg"] = terrain::MinInteriorAngleDeg(trace->seed);
  if (t.displace) {
    j["displaced_points"] = trace->displaced.size();
    j["max_displacement"] = trace->max_displacement;
  }
  nlohmann::json steps = nlohmann::json::array();
  for (const terrain::ShrinkTraceStep& s : trace->steps) {
    nlohmann::json rings = nlohmann::json::array();
    for (const terrain::Ring& r : s.rings) rings.push_back(RingJson(r));
    steps.push_back({{"convex", s.convex},
                     {"reflex", s.reflex},
                     {"gaps", s.gaps},
                     {"crossings", s.crossings},
                     {"raw_points",
                      [&] {
                        std::size_t n = 0;
                        for (const terrain::Ring& r : s.raw) n += r.size();
                        return n;
                      }()},
                     {"raw_self_intersections", s.raw_self_intersections},
                     {"rings", s.rings.size()},
                     {"points", s.points},
                     {"min_angle_deg", s.min_angle_deg},
                     {"cleaned_points", s.counts.cleaned_points},
                     {"holes_filled", s.counts.holes_filled},
                     {"dropped_rings", s.counts.dropped_rings},
                     {"contours", rings}});
    if (t.fourier) {
      steps.back()["fourier_max_shift"] = s.fourier_max_shift;
      steps.back()["fourier_not_simple"] = s.fourier_not_simple;
    }
  }
  j["steps"] = steps;
  if (!o.svg.empty()) WriteAllOrNone({{"--svg", o.svg, terrain::ShrinkTraceToSvg(*trace)}});
  out << j.dump() << "\n";
  return 0;
}
}  // namespace

void AddTerrainCommands(CLI::App& app, CommandList& commands) {
  CLI::App* terrain_cmd = Subcommand(app, "terrain", "Grow mountains from one seed contour");
  CLI::App* grow = terrain_cmd->add_subcommand(
      "grow", "Grow every contour above a seed contour (Misawa, Chiba, Saito 1987)");
  auto o = std::make_shared<TerrainGrowOptions>();
  CLI::Option* contour =
      AddInputFlag(grow, "--contour", &o->contour,
                   "Seed contour: {\"points\": [[x, y], ...]} in metres, or GeoJSON");
  CLI::Option* builtin = grow->add_option(
      "--builtin", o->builtin, "Built-in seed: disk, dumbbell, lobes7, jacksboro, valleys");
  Excludes(contour, builtin);
  grow->add_option("--method", o->method,
                   "simple (Fig 9c), midpoint (Fig 13b), fourier (Fig 15), improved (Fig 16) or a "
                   "figure preset fig9a..fig16");
  AddNumberFlag(grow, "--seed", &o->seed, kTerrainSeedRange,
                "RNG seed, " + RangeHelp(kTerrainSeedRange));
  grow->add_option("--set", o->sets, "KEY=VALUE of the terrain table (niwa params terrain)");
  AddInputFlag(grow, "--params", &o->params_file,
               "State JSON {preset, builtin, contour: [[x, y], ...], seed, params: {key: value}}");
  grow->add_option("--url", o->url,
                   "A share-link hash (preset=...&builtin=... or contour=x,y;...); other flags "
                   "override it");
  AddNumberFlag(grow, "--res", &o->res, TerrainRowRange(TerrainParam::kRes),
                "Heightfield cells along the longer side (the res row), " +
                    RangeHelp(TerrainRowRange(TerrainParam::kRes)));
  grow->add_flag("--stats", o->stats, "Print the statistics as one JSON object");
  grow->add_flag("--repair", o->repair,
                 "Make a seed contour that crosses itself simple first, as the page does a drawing "
                 "(§4.4 loop removal, else its largest simple piece), with a notice");
  AddOutputFlag(grow, "--contours", &o->contours_out, {".json", ".geojson", ".svg"},
                "Write the contour tree as .json, .geojson (Polygons, summits) or .svg (plan)");
  AddOutputFlag(grow, "--out", &o->out, {".glb"},
                "Write the surface as .glb (metres, y up, normals, tint row, contours as lines)");
  AddOutputFlag(grow, "--heightmap", &o->heightmap, {".png"},
                "Write a square 16-bit greyscale .png of 2^k + 1 samples (res 256: 257, as "
                "engines take them) and its sidecar FILE.json (min, max, cell, origin)");
  AddBudgetOptions(grow, &o->budget);
  commands.push_back({grow,
                      [o](std::ostream& out) { return RunGrow(*o, out); },
                      {"--builtin", "disk", "--set", "res=32", "--stats"}});

  CLI::App* compare = terrain_cmd->add_subcommand(
      "compare",
      "Grow from one contour of a real DEM and compare the two mountains (hypsometric integral, "
      "slopes, peaks, each level's IoU) as one JSON object");
  auto co = std::make_shared<TerrainGrowOptions>();
  auto dem = std::make_shared<std::string>();
  AddInputFlag(compare, "--dem", dem.get(),
               "The real DEM: a 16-bit .png with its sidecar FILE.json")
      ->required();
  CLI::Option* compare_contour =
      AddInputFlag(compare, "--contour", &co->contour, "Its seed contour (a file, as for grow)");
  CLI::Option* compare_builtin =
      compare->add_option("--builtin", co->builtin, "Or a built-in seed (jacksboro)");
  Excludes(compare_contour, compare_builtin);
  compare->add_option("--method", co->method, "As for grow");
  AddNumberFlag(compare, "--seed", &co->seed, kTerrainSeedRange,
                "RNG seed, " + RangeHelp(kTerrainSeedRange));
  compare->add_option("--set", co->sets, "KEY=VALUE of the terrain table");
  AddInputFlag(compare, "--params", &co->params_file, "State JSON, as for grow");
  compare->add_option("--url", co->url, "A share-link hash, as for grow");
  AddBudgetOptions(compare, &co->budget);
  commands.push_back(
      {compare,
       [co, dem](std::ostream& out) { return RunCompare(*co, *dem, out); },
       // (a path under tests/data/ is the source tree's: the hostile suite resolves it)
       {"--dem", "tests/data/terrain/jacksboro_dem.png", "--builtin", "jacksboro"}});

  CLI::App* shrink = terrain_cmd->add_subcommand(
      "shrink",
      "Trace the polygon shrinking algorithm on a contour (Figs 2-8, 12): naive offsets, the raw "
      "path with its joins, the rings kept, repeated steps; one JSON object of measures per step");
  auto so = std::make_shared<ShrinkCommandOptions>();
  CLI::Option* shrink_contour = AddInputFlag(shrink, "--contour", &so->contour,
                                             "The contour: {\"points\": [[x, y], ...]} or GeoJSON");
  CLI::Option* shrink_builtin =
      shrink->add_option("--builtin", so->builtin, "Or a built-in seed (terrain seeds)");
  Excludes(shrink_contour, shrink_builtin);
  AddNumberFlag(shrink, "--d", &so->d, kShrinkD,
                "Offset distance d (m), " + RangeHelp(kShrinkD) + "; default the built-in's d");
  shrink->add_option("--join", so->join,
                     "Valley join: miter (Fig 5a), bevel (5b), round (5c), capped (Fig 7)");
  AddNumberFlag(shrink, "--c", &so->c, kShrinkC, "Fig 7 cap c, " + RangeHelp(kShrinkC));
  AddNumberFlag(
      shrink, "--clean-len", &so->clean_len, kCleanLen,
      "Fig 8 pre-clean: drop a point of an edge shorter than this (m), " + RangeHelp(kCleanLen));
  AddNumberFlag(shrink, "--clean-angle", &so->clean_angle, kCleanAngle,
                "Fig 8 pre-clean: drop a vertex with an angle below this (degrees), " +
                    RangeHelp(kCleanAngle));
  shrink->add_flag("--outward", so->outward, "Offset outward (downhill) instead of shrinking");
  AddNumberFlag(shrink, "--steps", &so->steps, kShrinkSteps,
                "Successive shrinks, " + RangeHelp(kShrinkSteps));
  shrink->add_option("--displace", so->displace,
                     "D0,D2,THETA_MIN,THETA_MAX: midpoint-displace the contour first (Fig 12)");
  shrink->add_option("--fourier", so->fourier,
                     "F0[,N]: phase-randomise every ring each step keeps for |k| >= F0, FFT of N "
                     "samples (default 1024), not fed back (Fig 14)");
  AddNumberFlag(shrink, "--seed", &so->seed, kTerrainSeedRange,
                "RNG seed of --displace and --fourier, " + RangeHelp(kTerrainSeedRange));
  AddOutputFlag(shrink, "--svg", &so->svg, {".svg"}, "Write the figure as .svg");
  commands.push_back(
      {shrink,
       [so, shrink](std::ostream& out) { return RunShrink(*so, shrink->count("--seed") > 0, out); },
       {"--builtin", "disk"}});

  CLI::App* render = terrain_cmd->add_subcommand(
      "render",
      "Draw a bird's-eye picture of a heightmap (a grown mountain's --heightmap or a real DEM): "
      "perspective, hypsometric tint, sun-lit (Fig 17's views); one JSON object");
  auto ro = std::make_shared<RenderOptions>();
  AddInputFlag(render, "--dem", &ro->dem, "The heightmap: a 16-bit .png with its sidecar FILE.json")
      ->required();
  AddOutputFlag(render, "--out", &ro->out, {".png"}, "Write the picture as .png")->required();
  AddNumberFlag(render, "--width", &ro->width, {16, 4096, true}, "Picture width (px), 16..4096");
  AddNumberFlag(render, "--height", &ro->height, {16, 4096, true}, "Picture height (px), 16..4096");
  AddNumberFlag(render, "--view-from", &ro->view_from, {0, 360, false, " (degrees)"},
                "Compass bearing the camera stands towards (0 north, 180 south), 0..360");
  AddNumberFlag(render, "--elevation", &ro->elevation, {5, 90, false, " (degrees)"},
                "Camera elevation above the horizon, 5..90 (90: straight down)");
  AddNumberFlag(render, "--fov", &ro->fov, {5, 120, false, " (degrees)"},
                "Vertical field of view, 5..120");
  AddNumberFlag(render, "--exaggeration", &ro->exaggeration, {0.1, 20},
                "Vertical exaggeration, 0.1..20");
  AddNumberFlag(render, "--sun-from", &ro->sun_from, {0, 360, false, " (degrees)"},
                "Compass bearing of the sun, 0..360 (default 315: north-west)");
  AddNumberFlag(render, "--sun-elevation", &ro->sun_elevation, {0, 90, false, " (degrees)"},
                "Sun elevation, 0..90");
  AddNumberFlag(render, "--floor", &ro->floor, {-1e9, 1e9, false, " (m)"},
                "Draw heights below this at this (a DEM cut at a seed contour's level), m");
  render->add_option("--frame", ro->frame,
                     "X_MIN,Y_MIN,X_MAX,Y_MAX (m): the box framed and drawn (default the "
                     "heightmap's own; one box gives several pictures one camera)");
  render->add_option("--tint", ro->tint,
                     "LOW,HIGH (m): heights at the ends of the colour ramp (default the "
                     "heightmap's range)");
  commands.push_back({render,
                      [ro](std::ostream& out) { return RunRender(*ro, out); },
                      {"--dem", "tests/data/terrain/jacksboro_dem.png", "--out", "render.png"}});

  CLI::App* seeds = terrain_cmd->add_subcommand("seeds", "List the built-in seed contours");
  commands.push_back({seeds, [](std::ostream& out) {
                        nlohmann::json j = nlohmann::json::array();
                        for (const terrain::SeedInfo& s : terrain::BuiltinSeeds()) {
                          Result<terrain::Ring> r = terrain::BuiltinSeed(s.name);
                          j.push_back({{"name", s.name},
                                       {"points", r.ok() ? r->size() : 0},
                                       {"d", s.d},
                                       {"dh", s.dh},
                                       {"h0", s.h0},
                                       {"source", s.source}});
                        }
                        out << j.dump(2) << "\n";
                        return 0;
                      }});
  commands.studies.push_back(
      {"terrain",
       &terrain::TerrainTable(),
       [](std::ostream& out) {
         out << "terrain figure presets:\n";
         for (const terrain::FigurePreset& p : terrain::FigurePresets())
           out << "  " << p.name << ": " << p.caption << "\n";
       },
       {},
       {"terrain", "grow", "--builtin", "disk", "--set", "res=32", "--stats"}});
}

}  // namespace niwa::cli

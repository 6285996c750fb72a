// niwa CLI commands of the terrain study: 'terrain grow' (a whole mountain from one seed contour,
// Misawa, Chiba, Saito 1987; core/terrain, docs/terrain-model.md) and 'terrain seeds'.
// cli-order: 40
#include <chrono>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "terrain/contour_io.h"
#include "terrain/generate.h"
#include "terrain/heightfield.h"
#include "terrain/seeds.h"
#include "terrain/terrain_params.h"

namespace niwa::cli {
namespace {

using terrain::TerrainParam;

struct GrowOptions {
  std::string contour, builtin, method, seed, contours_out;
  std::vector<std::string> sets;
  bool stats = false;
};

int RunGrow(const GrowOptions& o, std::ostream& out) {
  const auto t0 = std::chrono::steady_clock::now();
  if (o.contour.empty() == o.builtin.empty()) {
    Fail(Status::Error("--contour",
                       "give exactly one of --contour FILE or --builtin NAME "
                       "(disk, dumbbell, lobes7)"));
  }
  terrain::TerrainParams params;
  terrain::Ring seed;
  if (!o.builtin.empty()) {
    Result<terrain::Ring> r = terrain::BuiltinSeed(o.builtin);
    if (!r.ok()) Fail(r.status());
    seed = std::move(r).value();
    for (const terrain::SeedInfo& info : terrain::BuiltinSeeds()) {
      if (info.name != o.builtin) continue;
      Check(params.Set(TerrainParam::kD, info.d));
      Check(params.Set(TerrainParam::kDh, info.dh));
      Check(params.Set(TerrainParam::kH0, info.h0));
    }
  } else {
    Result<std::string> text = ReadFile(o.contour, "--contour", kMaxContourFileBytes);
    if (!text.ok()) Fail(text.status());
    Result<terrain::SeedFile> file = terrain::ParseContourJson(*text);
    if (!file.ok()) Fail(file.status().Within("--contour"));
    seed = file->ring;
    // A contour that cannot seed a mountain is the file's fault: name the flag (Grow checks again).
    Result<terrain::Ring> checked = terrain::CheckSeed(seed);
    if (!checked.ok()) Fail(Status::Error("--contour", checked.status().message()));
    if (file->has_elevation)
      Check(AsFlag(params.Set(TerrainParam::kH0, file->elevation), "elevation"));
  }
  if (!o.method.empty()) Check(AsFlag(terrain::ApplyPreset(o.method, &params), "--method"));
  if (!o.seed.empty()) Check(AsFlag(params.SetFromText("seed", o.seed), "--seed"));
  for (const std::string& s : o.sets) Check(params.SetFromAssignment(s).Within("--set"));
  Result<terrain::Terrain> t = terrain::Grow(seed, params);
  if (!t.ok()) Fail(t.status());
  const auto t1 = std::chrono::steady_clock::now();
  terrain::Heightfield hf = terrain::BuildHeightfield(*t, params.GetInt(TerrainParam::kRes));
  const auto t2 = std::chrono::steady_clock::now();
  if (!o.contours_out.empty()) {
    if (Extension(o.contours_out) != ".json") {
      Fail(Status::Error("--contours", "'" + Echo(o.contours_out) + "' must end in .json"));
    }
    StagedOutputs outputs;  // every output of a run is staged, then renamed together
    Check(outputs.Stage("--contours", o.contours_out, terrain::TerrainToJson(*t)));
    Check(outputs.Commit());
  }
  if (o.stats) {
    terrain::TerrainStats s = terrain::ComputeStats(*t, &hf);
    nlohmann::json j;
    j["method"] = terrain::MethodName(params.GetInt(TerrainParam::kMethod));
    j["seed"] = params.GetInt(TerrainParam::kSeed);
    j["levels"] = s.levels;
    j["contours"] = s.contours;
    j["peaks"] = s.peaks;
    j["splits"] = s.splits;
    j["vertices"] = s.vertices;
    j["self_intersections"] = s.self_intersections;
    j["nesting_violations"] = s.nesting_violations;
    j["relief"] = s.relief;
    j["hypsometric_integral"] = s.hypsometric_integral;
    j["mean_slope_deg"] = s.mean_slope_deg;
    j["pits"] = s.pits;
    j["loops_removed"] = t->counts.loops_removed;
    j["perturbations_reverted"] = t->counts.perturbations_reverted;
    j["truncated"] = t->counts.truncated;
    j["ms"] = std::chrono::duration<double, std::milli>(t2 - t0).count();
    j["ms_shrink"] = t->counts.ms_shrink;
    j["ms_mpd"] = t->counts.ms_mpd;
    j["ms_fd"] = t->counts.ms_fd;
    j["ms_loops"] = t->counts.ms_loops;
    j["ms_heightfield"] = std::chrono::duration<double, std::milli>(t2 - t1).count();
    out << j.dump() << "\n";
  }
  return 0;
}

}  // namespace

void AddTerrainCommands(CLI::App& app, CommandList& commands) {
  CLI::App* terrain_cmd = Subcommand(app, "terrain", "Grow mountains from one seed contour");
  CLI::App* grow = terrain_cmd->add_subcommand(
      "grow", "Grow every contour above a seed contour (Misawa, Chiba, Saito 1987)");
  auto o = std::make_shared<GrowOptions>();
  grow->add_option("--contour", o->contour,
                   "Seed contour: {\"points\": [[x, y], ...]} in metres, or GeoJSON");
  grow->add_option("--builtin", o->builtin, "Built-in seed: disk, dumbbell, lobes7");
  grow->add_option("--method", o->method,
                   "simple (Fig 9c), midpoint (Fig 13b), fourier (Fig 15), improved (Fig 16) or a "
                   "figure preset fig9a..fig16");
  grow->add_option("--seed", o->seed, "RNG seed, a whole number in [0, 4294967295]");
  grow->add_option("--set", o->sets, "KEY=VALUE of the terrain table (niwa params terrain)");
  grow->add_flag("--stats", o->stats, "Print the statistics as one JSON object");
  grow->add_option("--contours", o->contours_out, "Write the contour tree as JSON (.json)");
  commands.push_back({grow, [o](std::ostream& out) { return RunGrow(*o, out); }});

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
  commands.studies.push_back({"terrain", &terrain::TerrainTable(), [](std::ostream& out) {
                                out << "terrain figure presets:\n";
                                for (const terrain::FigurePreset& p : terrain::FigurePresets())
                                  out << "  " << p.name << ": " << p.caption << "\n";
                              }});
}

}  // namespace niwa::cli

// `niwa ivy grow|scenes`: grow Shindo & Sakamoto's ivy on a built-in scene or a .glb/.gltf/.obj
// mesh and print its statistics or write it as .json, .lsys (the L-string) or .glb.
// cli-order: 40
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "base/echo.h"
#include "cli_common.h"
#include "geom/bvh.h"
#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "io/mesh_reader.h"
#include "ivy/growth.h"
#include "ivy/ivy_budget.h"
#include "ivy/ivy_mesh.h"
#include "ivy/ivy_params.h"
#include "ivy/ivy_report.h"
#include "ivy/ivy_state.h"
#include "ivy/ivy_svg.h"
#include "ivy/lstring.h"
#include "ivy/scenes.h"
#include "ivy_tree_support.h"
#include "params/param_text.h"

namespace niwa::cli {
namespace {

constexpr int kMaxSubdivide = 8;
constexpr double kMaxCoordinate = 1e30;

struct IvyOptions {
  std::string scene, mesh, steps, seed, preset, params_file, url, accel = "bvh", subdivide = "0";
  std::string tree_preset, tree_years = "10";
  std::string svg_leaves = "1", caption;
  std::string out_path;
  std::vector<std::string> seed_points, sets;
  bool stats = false, with_support = false;
  BudgetOptions budget;
};

double Ms(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

double ParseFlagNumber(const std::string& flag, const std::string& text, const FlagRange& range) {
  return FlagNumber(flag, text, range);  // the one strict parser (cli_common)
}

// "X,Y,Z" or a named seed of the scene.
glm::dvec3 ParseSeedPoint(const std::string& text, const ivy::IvyScene* scene) {
  if (scene != nullptr) {
    for (const ivy::NamedSeed& s : scene->seeds)
      if (s.name == text) return s.pos;
  }
  std::string names;
  if (scene != nullptr) {
    for (const ivy::NamedSeed& s : scene->seeds) names += (names.empty() ? "" : ", ") + s.name;
  }
  const std::string range = "must be X,Y,Z (each in [-1e30, 1e30])" +
                            (names.empty() ? std::string() : " or one of " + names);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 3)
    Fail(Status::Error("--seed-point", "'" + Echo(text) + "' is unknown; " + range));
  glm::dvec3 p;
  for (int i = 0; i < 3; ++i) {
    std::optional<double> x = ParseNumber(parts[static_cast<std::size_t>(i)]);
    if (!x || std::fabs(*x) > kMaxCoordinate) {
      Fail(Status::Error("--seed-point", "'" + Echo(text) + "' is out of range; " + range));
    }
    p[i] = *x;
  }
  return p;
}

ivy::IvyState ResolveState(const IvyOptions& o) {
  ivy::IvyState state;
  // A tree is in metres: its default preset is metric.
  if (!o.tree_preset.empty()) Check(AsFlag(ivy::SetIvyPreset("metric", &state), "--preset"));
  if (!o.preset.empty()) Check(AsFlag(ivy::SetIvyPreset(o.preset, &state), "--preset"));
  if (!o.params_file.empty()) {
    Result<std::string> text = ReadFile(o.params_file, "--params", kMaxParamsFileBytes);
    if (!text.ok()) Fail(text.status());
    Check(ivy::ApplyIvyStateJson(*text, &state).Within("--params"));
  }
  if (!o.url.empty()) {
    std::vector<std::string> notices;
    ivy::ApplyIvyHash(o.url, "", &state, &notices);
    if (!notices.empty()) Fail(Status::Error("--url", notices[0]));
  }
  for (const std::string& set : o.sets) Check(state.params.SetFromAssignment(set).Within("--set"));
  if (!o.steps.empty()) {
    state.steps = static_cast<int>(ParseFlagNumber("--steps", o.steps, {0, 10000, true}));
  }
  if (!o.seed.empty()) {
    state.seed =
        static_cast<uint64_t>(ParseFlagNumber("--seed", o.seed, {0, ivy::kMaxIvySeed, true}));
  }
  Check(ValidateIvyParams(state.params));
  return state;
}

int RunGrow(const IvyOptions& o, std::ostream& out) {
  const auto t_start = std::chrono::steady_clock::now();
  const std::string ext = o.out_path.empty() ? "" : Extension(o.out_path);
  if (!o.out_path.empty() && ext != ".json" && ext != ".lsys" && ext != ".glb" && ext != ".svg") {
    Fail(Status::Error("--out",
                       "'" + Echo(o.out_path) + "' must end in .json, .lsys, .glb or .svg"));
  }
  if (o.accel != "bvh" && o.accel != "linear") {
    Fail(Status::Error("--accel", "'" + Echo(o.accel) + "' is unknown; must be bvh or linear"));
  }
  const int levels =
      static_cast<int>(ParseFlagNumber("--subdivide", o.subdivide, {0, kMaxSubdivide, true}));
  ivy::IvyState state = ResolveState(o);
  const Budget budget = ResolveBudget(o.budget);
  if (!o.mesh.empty() + !o.scene.empty() + !o.tree_preset.empty() > 1) {
    Fail(Status::Error(o.mesh.empty() ? "--scene" : "--mesh",
                       "give one of --mesh FILE, --scene NAME or --tree-preset NAME"));
  }
  ivy::IvyScene scene;
  io::MeshReadStats read;
  Estimate tree_estimate;  // a tree support: growing it and its bark (time shared with the ivy)
  std::string tree_truncated_by;
  if (!o.tree_preset.empty()) {
    const double years = ParseFlagNumber("--tree-years", o.tree_years, {1, kMaxYears, true});
    Result<ivy::IvyScene> s =
        TreeSupportScene(o.tree_preset, years, budget, &tree_estimate, &tree_truncated_by);
    if (!s.ok()) Fail(s.status());
    scene = std::move(s).value();
  } else if (!o.mesh.empty()) {
    Result<geom::TriMesh> mesh = io::ReadMeshFile(o.mesh, &read);
    if (!mesh.ok()) Fail(mesh.status().Within("--mesh"));
    scene.name = o.mesh;
    scene.mesh = std::move(mesh).value();
    Check(geom::ValidateMesh(scene.mesh, "--mesh"));
  } else {
    // --scene, else the state's (--url scene=, --params "scene"), else cubes4.
    const std::string name = !o.scene.empty()      ? o.scene
                             : state.scene.empty() ? std::string("cubes4")
                                                   : state.scene;
    if (name == ivy::kTreeScene) {  // the page's tree scene: tree= and tree_years= of the state
      Result<ivy::IvyScene> s = TreeSupportScene(state.tree, state.tree_years, budget,
                                                 &tree_estimate, &tree_truncated_by);
      if (!s.ok()) {
        const std::string& field = s.status().field();
        if (field == budget.memory_limit || field == budget.seconds_limit) Fail(s.status());
        const char* flag = !o.scene.empty() ? "--scene" : !o.url.empty() ? "--url" : "--params";
        Fail(Status::Error(flag, s.status().message()));
      }
      scene = std::move(s).value();
    } else {
      Result<ivy::IvyScene> s = ivy::MakeIvyScene(name);
      if (!s.ok()) Fail(s.status());
      scene = std::move(s).value();
    }
  }
  if (levels > 0 && !scene.free) {
    double after = static_cast<double>(scene.mesh.triangle_count()) * std::pow(4.0, levels);
    if (after > static_cast<double>(io::kMaxMeshTriangles)) {
      Fail(Status::Error("--subdivide", std::to_string(levels) + " would make " +
                                            FormatNumber(after) +
                                            " triangles; the limit is 4000000 (4 M)"));
    }
  }
  // The support's memory and time (the subdivision, its BVH), refused before subdividing.
  ivy::IvySupportSize support_size;
  support_size.triangles = scene.free ? 0 : static_cast<double>(scene.mesh.triangle_count());
  support_size.levels = scene.free ? 0 : levels;
  support_size.bvh = o.accel == "bvh";
  support_size.obstacles = !o.mesh.empty();  // a mesh's noivy triangles: a second mesh and BVH
  ReportTruncated(tree_truncated_by);
  Estimate support_estimate = ivy::EstimateIvySupport(support_size);
  // A tree's growth and bark took their time before the ivy's (its memory is freed but the bark).
  support_estimate.seconds += tree_estimate.seconds;
  Check(CheckEstimate(support_estimate, budget,
                      tree_estimate.what.empty() ? ivy::kIvyChange : "lower --tree-years"));
  if (levels > 0 && !scene.free) scene.mesh = geom::Subdivide(scene.mesh, levels);
  std::vector<glm::dvec3> seeds;
  for (const std::string& s : o.seed_points)
    seeds.push_back(ParseSeedPoint(s, o.mesh.empty() ? &scene : nullptr));  // scene or tree seeds
  if (seeds.empty()) seeds = state.seed_points;  // the state's at= (the page's clicks)
  if (seeds.empty()) {
    if (!o.mesh.empty()) {
      Fail(Status::Error("--seed-point", "required with --mesh; must be X,Y,Z within d of a face"));
    }
    seeds.push_back(scene.seeds[0].pos);
  }
  const auto t_bvh0 = std::chrono::steady_clock::now();
  geom::Bvh bvh, attach_bvh;
  std::size_t obstacles = 0;
  geom::TriMesh attach;
  if (!o.mesh.empty()) attach = ivy::IvyAttachTriangles(scene.mesh, read.materials, &obstacles);
  if (!scene.free && o.accel == "bvh") bvh = geom::Bvh::Build(scene.mesh);
  if (obstacles > 0 && o.accel == "bvh") attach_bvh = geom::Bvh::Build(attach);
  const auto t_bvh1 = std::chrono::steady_clock::now();
  ivy::Support support;
  if (!scene.free) {
    support = {&scene.mesh, &bvh, o.accel == "bvh" ? ivy::Accel::kBvh : ivy::Accel::kLinear};
    if (obstacles > 0) {
      support.attach_mesh = &attach;
      support.attach_bvh = &attach_bvh;
    }
  }
  ivy::GrowLog log;
  const ivy::IvyGrowLimits limits =
      ivy::IvyLimits(state.params, budget, support_estimate, !scene.free);
  // With --stats the growth keeps room for the measurement's part that grows with every bud.
  ivy::IvyGrowLimits grow_limits = limits;
  const double support_triangles =
      scene.free ? 0 : static_cast<double>(scene.mesh.triangle_count());
  if (o.stats) ivy::ReserveIvyStats(support_triangles, &grow_limits);
  Result<ivy::IvyModel> model =
      ivy::Grow(support, seeds, state.params, state.steps, state.seed, &log, &grow_limits);
  if (!model.ok()) Fail(model.status());
  ReportTruncated(log.truncated_by);
  // The measurement's exact count (the overlap sweep's pairs are known only now), checked with
  // the growth and the export before either is done.
  Estimate stats_estimate;
  if (o.stats) {
    stats_estimate =
        ivy::EstimateIvyStats(ivy::CountIvyStatsWork(*model, state.params, support_triangles));
  }
  ivy::IvyTimings t;
  t.ms_bvh = Ms(t_bvh0, t_bvh1);
  t.ms_rules = log.ms_rules;
  t.ms_search = log.ms_search;
  if (!o.out_path.empty()) {
    // The export's estimate on top of the grown ivy's, refused before it starts.
    const ivy::IvyExport kind = ext == ".json"   ? ivy::IvyExport::kJson
                                : ext == ".lsys" ? ivy::IvyExport::kLsys
                                : ext == ".svg"  ? ivy::IvyExport::kSvg
                                                 : ivy::IvyExport::kGlb;
    const bool support_out = !scene.free && (ext == ".svg" || o.with_support);
    const Estimate grown = ivy::EstimateIvyGrown(*model, log, limits);
    const Estimate export_estimate = ivy::EstimateIvyExport(
        *model, kind, support_out ? static_cast<double>(scene.mesh.triangle_count()) : 0);
    if (std::getenv("NIWA_BUDGET_TRACE")) {  // calibration (docs/budgets.md)
      std::fprintf(stderr, "budget: grown %.0f MB %.2f s; export %.0f MB %.2f s\n",
                   grown.memory_bytes / 1048576, grown.seconds,
                   export_estimate.memory_bytes / 1048576, export_estimate.seconds);
    }
    Check(CheckEstimate(grown + export_estimate + stats_estimate, budget,
                        o.stats ? ivy::kIvyStatsChange : ivy::kIvyChange));
    std::string bytes;
    if (ext == ".json") {
      bytes = ivy::IvyModelJson(*model, state.params, state.seed, state.steps) + "\n";
    } else if (ext == ".lsys") {
      bytes = ivy::PrintLString(*model);
    } else if (ext == ".svg") {
      ivy::IvySvgOptions svg;
      svg.leaves = ParseFlagNumber("--svg-leaves", o.svg_leaves, {0, 1, true}) != 0;
      svg.caption = o.caption;
      bytes = ivy::IvySvg(*model, state.params, scene.free ? nullptr : &scene.mesh, svg);
    } else {
      const auto t0 = std::chrono::steady_clock::now();
      Result<std::vector<unsigned char>> glb =
          ivy::WriteIvyGlb(*model, state.params, state.seed, state.steps,
                           scene.free || !o.with_support ? nullptr : &scene.mesh);
      t.ms_mesh = Ms(t0, std::chrono::steady_clock::now());
      if (!glb.ok()) Fail(glb.status().Within("--out"));
      bytes.assign(glb->begin(), glb->end());
    }
    StagedOutputs outputs;
    Check(outputs.Stage("--out", o.out_path, bytes));
    Check(outputs.Commit());
  }
  if (std::getenv("NIWA_BUDGET_TRACE") && o.out_path.empty()) {
    const Estimate grown = ivy::EstimateIvyGrown(*model, log, limits);
    std::fprintf(stderr, "budget: grown %.0f MB %.2f s; stats %.0f MB %.2f s\n",
                 grown.memory_bytes / 1048576, grown.seconds, stats_estimate.memory_bytes / 1048576,
                 stats_estimate.seconds);
  }
  if (o.stats && o.out_path.empty()) {
    Check(CheckEstimate(ivy::EstimateIvyGrown(*model, log, limits) + stats_estimate, budget,
                        ivy::kIvyStatsChange));
  }
  if (o.stats) {
    ivy::IvyStats stats = ivy::MeasureIvy(*model, log, scene.free ? nullptr : &scene.mesh,
                                          state.params, obstacles > 0 ? &attach : nullptr);
    stats.tree_truncated_by = tree_truncated_by;
    t.ms = Ms(t_start, std::chrono::steady_clock::now());
    out << ivy::IvyStatsJson(stats, log, *model, t) << "\n";
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
  commands.studies.push_back({"ivy", &IvyTable(), [](std::ostream& out) {
                                for (const std::string& name : IvyPresetNames()) {
                                  out << name;
                                  for (const auto& [key, value] : IvyPresetOverrides(name))
                                    out << "\t" << key << "=" << FormatNumber(value);
                                  out << "\n";
                                }
                              }});
  CLI::App* ivy_app = Subcommand(app, "ivy", "Grow climbing ivy over a mesh (Shindo & Sakamoto)");
  ivy_app->require_subcommand(1);
  auto o = std::make_shared<IvyOptions>();
  CLI::App* grow = ivy_app->add_subcommand(
      "grow", "Grow ivy on a built-in scene or a mesh; print --stats or write --out");
  grow->add_option("--scene", o->scene,
                   "Built-in support: cubes4 (default), wall, overhang, stairs, pillar, sphere, "
                   "free (see 'niwa ivy scenes'), or tree (the state's tree= and tree_years=)");
  grow->add_option("--mesh", o->mesh, "Support mesh file: .glb, .gltf or .obj");
  grow->add_option("--tree-preset", o->tree_preset,
                   "Climb a Niwa tree's bark ('niwa presets tree'; default ivy preset: metric)");
  grow->add_option("--tree-years", o->tree_years, "Age of that tree, 1..100 (default 10)");
  grow->add_option("--seed-point", o->seed_points,
                   "Growth start X,Y,Z or a scene's named seed; repeat for several plants");
  grow->add_option("--steps", o->steps, "Final step number, 0..10000 (default 50)");
  grow->add_option("--seed", o->seed, "Random seed, 0..4294967295 (default 1)");
  grow->add_option("--preset", o->preset, "paper (default), literal, improved or metric");
  grow->add_option("--set", o->sets, "KEY=VALUE of the ivy table ('niwa params ivy')");
  grow->add_option("--params", o->params_file, "State JSON {preset, seed, steps, params}");
  grow->add_option("--url", o->url, "Share-link hash: preset=..&seed=..&steps=..&KEY=V");
  grow->add_option("--accel", o->accel, "Geometry queries: bvh (default) or linear (brute force)");
  grow->add_option("--subdivide", o->subdivide,
                   "Split every support triangle into 4^K coplanar ones, K in [0, 8]");
  grow->add_flag("--stats", o->stats, "Print one JSON object of statistics on stdout");
  grow->add_option("--out", o->out_path,
                   "Write .json (buds, internodes), .lsys, .glb or .svg (front and side views)");
  grow->add_flag("--with-support", o->with_support, "The .glb also holds the support mesh");
  grow->add_option("--svg-leaves", o->svg_leaves, ".svg: draw the leaves, 0 or 1 (default 1)");
  grow->add_option("--caption", o->caption, ".svg: a line of text under the views");
  AddBudgetOptions(grow, &o->budget);
  commands.push_back({grow, [o](std::ostream& out) { return RunGrow(*o, out); }});
  CLI::App* scenes = ivy_app->add_subcommand("scenes", "List the built-in scenes and seeds");
  commands.push_back({scenes, [](std::ostream& out) { return RunScenes(out); }});
}

}  // namespace niwa::cli

// The garden's run (see garden_run.h).
#include "compose/garden_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <map>
#include <nlohmann/json.hpp>
#include <tuple>

#include "compose/bark_support.h"
#include "compose/garden_moss.h"
#include "compose/garden_shapes.h"
#include "compose/tree_neighbours.h"
#include "geom/linear_queries.h"
#include "geom/mesh_metrics.h"
#include "image/png.h"
#include "io/gltf_writer.h"
#include "ivy/ivy_state.h"
#include "math/det_math.h"
#include "render/tree_lod.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_budget.h"
#include "tree/tree_look.h"
#include "tree/tree_state.h"

namespace niwa::compose {
namespace {

using Clock = std::chrono::steady_clock;
double MsSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// Bytes and seconds of one distinct tree's .glb part per triangle of its budget (the LOD mesh,
// its atlas share and the writer's copies), generous as docs/budgets.md's constants.
constexpr double kGardenGlbBytesPerTriangle = 400;
constexpr double kGardenGlbSecondsPerTriangle = 2e-6;
// The cards' atlas of a distinct tree in the garden's .glb (texels a side; render/tree_lod).
constexpr int kGardenAtlasSize = 512;

gltf::Material PlainMaterial(const std::string& name, double r, double g, double b,
                             double roughness) {
  gltf::Material m;
  m.name = name;
  m.base_color_factor = {r, g, b, 1};
  m.metallic_factor = 0;
  m.roughness_factor = roughness;
  return m;
}

// Appends `from`'s meshes, materials and textures to `into` (indices remapped); returns the
// offset of its meshes in `into`.
int AppendGardenDocument(gltf::Document* into, const gltf::Document& from) {
  const int mesh_base = static_cast<int>(into->meshes.size());
  const int material_base = static_cast<int>(into->materials.size());
  // A texture already in `into` with the same bytes and sampler (a species' bark and leaf
  // textures, the same for every tree of it) is shared, not written again.
  std::vector<int> texture_at;
  for (const gltf::Texture& t : from.textures) {
    int found = -1;
    for (std::size_t k = 0; k < into->textures.size() && found < 0; ++k) {
      const gltf::Texture& u = into->textures[k];
      if (u.png == t.png && u.wrap_s == t.wrap_s && u.wrap_t == t.wrap_t &&
          u.mag_filter == t.mag_filter && u.min_filter == t.min_filter)
        found = static_cast<int>(k);
    }
    if (found < 0) {
      found = static_cast<int>(into->textures.size());
      into->textures.push_back(t);
    }
    texture_at.push_back(found);
  }
  for (gltf::Material m : from.materials) {
    for (int* tex : {&m.base_color_texture, &m.metallic_roughness_texture, &m.normal_texture,
                     &m.occlusion_texture})
      if (*tex >= 0) *tex = texture_at[static_cast<std::size_t>(*tex)];
    into->materials.push_back(std::move(m));
  }
  for (gltf::Mesh mesh : from.meshes) {
    for (gltf::Primitive& p : mesh.primitives)
      if (p.material >= 0) p.material += material_base;
    into->meshes.push_back(std::move(mesh));
  }
  return mesh_base;
}

// A share as a percentage for a line: "25 %", "0.5 %".
std::string SharePercent(double share) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", share * 100.0);
  return text;
}

std::array<double, 4> YawQuaternion(double rot_deg) {
  const double half = rot_deg * det::kPi / 360.0;
  return {0, det::Sin(half), 0, det::Cos(half)};
}

std::string SpeciesColour(const std::string& species) {
  static const std::map<std::string, std::string> colours = {
      {"keyaki", "#5d8f3a"},          {"keyaki-thesis", "#5d8f3a"}, {"sakura", "#d98fa8"},
      {"sakura-thesis", "#d98fa8"},   {"maple", "#c4502c"},         {"pine", "#2f5d3a"},
      {"ginkgo", "#d8c03a"},          {"weeping", "#7fa65a"},       {"tsutsuji", "#c0457a"},
      {"tsutsuji-thesis", "#c0457a"}, {"binary", "#808080"}};
  const auto it = colours.find(species);
  return it == colours.end() ? "#4c7a3c" : it->second;
}

}  // namespace

Result<GardenRun> GardenRun::Start(const GardenState& state, const Budget& budget,
                                   bool record_years, double record_share) {
  if (!(record_share > 0 && record_share < 1))
    return Status::Error("record_share", "must be in (0, 1)");
  NIWA_RETURN_IF_ERROR(CheckGardenState(state));
  GardenRun run;
  run.state_ = state;
  run.budget_ = budget;
  run.record_years_ = record_years;
  auto t0 = Clock::now();
  Result<GardenScene> scene = BuildGardenScene(state, budget);
  if (!scene.ok()) return scene.status();
  run.scene_ = std::move(*scene);
  run.truncated_by_ = run.scene_.truncated_by;
  run.ms_ground_ = MsSince(t0);
  t0 = Clock::now();
  Result<Planting> planting = PlantGarden(state, run.scene_);
  if (!planting.ok()) return planting.status();
  run.planting_ = std::move(*planting);
  run.ms_plant_ = MsSince(t0);

  // Groups: a tree with a neighbour within shade_reach (shade 1) is grown on its own; the rest
  // share one growth per (species, seed, age).
  const std::vector<PlacedTree>& trees = run.planting_.trees;
  const bool shade = state.params.GetBool(GardenParam::kShade);
  const double reach = state.params.Get(GardenParam::kShadeReach);
  std::vector<bool> near(trees.size(), false);
  if (shade) {
    for (std::size_t a = 0; a < trees.size(); ++a)
      for (std::size_t b = a + 1; b < trees.size(); ++b) {
        const double dx = trees[a].x - trees[b].x, dz = trees[a].z - trees[b].z;
        if (dx * dx + dz * dz < reach * reach) near[a] = near[b] = true;
      }
  }
  std::map<std::tuple<std::string, uint64_t, int>, int> shared;
  run.tree_group_.assign(trees.size(), -1);
  for (std::size_t t = 0; t < trees.size(); ++t) {
    const PlacedTree& p = trees[t];
    const auto key = std::make_tuple(p.species, p.seed, p.age);
    const auto it = near[t] ? shared.end() : shared.find(key);
    int g = it != shared.end() ? it->second : -1;
    if (g < 0) {
      g = static_cast<int>(run.groups_.size());
      if (!near[t]) shared[key] = g;
      GardenTreeGroup group;
      group.species = p.species;
      group.seed = p.seed;
      group.age = p.age;
      group.shaded = near[t];
      group.name = near[t]
                       ? p.species + "_t" + std::to_string(t)
                       : p.species + "_s" + std::to_string(p.seed) + "_a" + std::to_string(p.age);
      run.groups_.push_back(std::move(group));
    }
    run.groups_[g].trees.push_back(static_cast<int>(t));
    run.tree_group_[t] = g;
  }
  const int years = state.params.GetInt(GardenParam::kYears);
  // The moss, started before the trees so its whole run's estimate is taken off their share (it
  // is refused up front, as the moss study refuses a run over its budget).
  Budget tree_budget = budget;
  const int moss_days = state.params.GetInt(GardenParam::kMossDays);
  if (moss_days > 0 && years > 0) {
    t0 = Clock::now();
    const std::clock_t c0 = std::clock();
    moss::MossState ms = state.moss;
    NIWA_RETURN_IF_ERROR(moss::SetMossDays(years * moss_days, &ms).Within("moss_days"));
    NIWA_RETURN_IF_ERROR(
        moss::SetMossSeed(state.params.Get(GardenParam::kPlantSeed), &ms).Within("plant_seed"));
    moss::MossScene land = GardenMossLand(run.scene_);
    // Refused in the garden's words first (the land's triangles are the fewest cells it can have),
    // at the garden's measured costs.
    const moss::MossCosts costs = GardenMossCosts();
    const Status fits =
        CheckEstimate(moss::MossRun::RunEstimate(ms, land.mesh.triangle_count(),
                                                 geom::SurfaceArea(land.mesh), costs),
                      budget, "lower moss_days or years, or set moss_days 0 (no moss)");
    if (!fits.ok()) return Status::Error("moss_days", "the moss: " + fits.Line());
    Result<moss::MossRun> moss =
        moss::MossRun::StartOnScene(ms, std::move(land), budget, "garden", costs);
    if (!moss.ok()) return Status::Error("moss_days", "the moss: " + moss.status().Line());
    const Estimate used = moss->RunEstimate();
    tree_budget.seconds = std::max(0.0, budget.seconds - used.seconds);
    tree_budget.memory_bytes = static_cast<uint64_t>(
        std::max(0.0, static_cast<double>(budget.memory_bytes) - used.memory_bytes));
    run.moss_estimate_ = used;
    run.moss_ = std::make_unique<moss::MossRun>(std::move(*moss));
    run.ms_moss_ = MsSince(t0);
    run.cpu_ms_moss_ = 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  }
  // The year records' share of the memory, kept from the trees' (docs/garden-model.md "One
  // clock"): the trees share the rest, so the garden and its records stay within the budget.
  if (record_years) {
    run.record_share_ = record_share;
    run.record_limit_ = record_share * static_cast<double>(budget.memory_bytes);
    tree_budget.memory_bytes = static_cast<uint64_t>(
        std::max(0.0, static_cast<double>(tree_budget.memory_bytes) - run.record_limit_));
  }
  // Each group's growth within an equal share of the budget above the process's own base (the
  // tree's limits count that base once per tree; its limits stop a tree with a line).
  const double groups = std::max<double>(1, static_cast<double>(run.groups_.size()));
  for (GardenTreeGroup& g : run.groups_) {
    TreeState ts;
    NIWA_RETURN_IF_ERROR(SetStatePreset(g.species, &ts));
    NIWA_RETURN_IF_ERROR(SetStateSeed(static_cast<double>(g.seed), &ts));
    NIWA_RETURN_IF_ERROR(SetStateYears(std::min(kMaxYears, g.age + years), &ts).Within("years"));
    ts.limits = TreeGrowLimits(ts.params, tree_budget, "years");
    run.tree_base_bytes_ = ts.limits.base_bytes;
    ts.limits.max_bytes =
        ts.limits.base_bytes + std::max(0.0, ts.limits.max_bytes - ts.limits.base_bytes) / groups;
    ts.limits.max_seconds /= groups;
    Result<TreeRun> tree_run = TreeRun::Start(ts, budget);
    if (!tree_run.ok()) return tree_run.status();
    g.run = std::make_unique<TreeRun>(std::move(*tree_run));
  }
  // Each distinct tree's bark (compose/garden_bark); its least cost refused up front.
  std::vector<std::string> species;
  for (const GardenTreeGroup& g : run.groups_) species.push_back(g.species);
  Result<GardenBarks> barks = StartGardenBarks(state, species);
  if (!barks.ok()) return barks.status();
  run.barks_ = std::move(*barks);
  const Status bark_fits =
      CheckEstimate(GardenBarkLeastEstimate(run.barks_), budget,
                    "set bark 0, or plant fewer distinct trees (density, variants)");
  if (!bark_fits.ok()) return Status::Error("bark", bark_fits.message());
  return run;
}

Status GardenRun::Advance(const run::Observer& observer) {
  const auto t0 = Clock::now();
  const int years = target();
  if (!nursery_done_) {
    // The nursery: a tree planted at age a grows its first a years alone, before the clock.
    const auto tn = Clock::now();
    for (std::size_t k = 0; k < groups_.size(); ++k) {
      GardenTreeGroup& g = groups_[k];
      while (g.run->done() < g.age && !g.run->stopped()) {
        g.run->GrowYear();
        RecordGardenTrunk(g.tree(), k, &barks_);  // the bark's history (bark 1)
      }
    }
    nursery_done_ = true;
    ms_growth_ += MsSince(tn);
    if (year_ == 0) RecordYear();  // year 0: the planted garden
  }
  // The trees grown with their neighbours' shade (each one tree), where they stand.
  std::vector<TreeAt> together;
  for (GardenTreeGroup& g : groups_) {
    if (!g.shaded) continue;
    const PlacedTree& p = planting_.trees[g.trees.front()];
    together.push_back({g.run.get(), p.x, p.y, p.z, p.rot});
  }
  NeighbourShade shade;
  shade.shade_each_other = state_.params.GetBool(GardenParam::kShade);
  shade.reach_m = state_.params.Get(GardenParam::kShadeReach);
  while (year_ < years) {
    if (observer && !observer({"grow", static_cast<double>(year_), static_cast<double>(years)}))
      return run::CancelledStatus();
    const auto ty = Clock::now();
    if (!together.empty()) (void)GrowTogetherYear(together, shade);
    for (GardenTreeGroup& g : groups_)
      if (!g.shaded && g.run->done() < g.age + year_ + 1 && !g.run->stopped()) g.run->GrowYear();
    for (std::size_t k = 0; k < groups_.size(); ++k)
      RecordGardenTrunk(groups_[k].tree(), k, &barks_);
    ms_growth_ += MsSince(ty);
    ++year_;
    if (moss_) GrowMossYear();
    NIWA_RETURN_IF_ERROR(GrowIvyYear());
    if (ivy_) {
      ivy_by_year_.resize(static_cast<std::size_t>(year_), 0);
      ivy_by_year_[static_cast<std::size_t>(year_ - 1)] =
          static_cast<long>(ivy_->model_so_far().internodes.size());
    }
    RecordYear();
  }
  if (observer) observer({"grow", static_cast<double>(year_), static_cast<double>(years)});
  for (const GardenTreeGroup& g : groups_)
    if (truncated_by_.empty() && g.tree().truncated)
      truncated_by_ = g.name + ": " + g.tree().truncated_by;
  ms_trees_ += MsSince(t0);
  return GrowBarks(observer);
}

Budget GardenRun::BudgetLeft(bool ivy_support) const {
  Budget left = budget_;
  double seconds = moss_estimate_.seconds, bytes = moss_estimate_.memory_bytes;
  for (const GardenTreeGroup& g : groups_) {
    const Estimate used = g.run->grown();
    seconds += used.seconds;
    bytes += std::max(0.0, used.memory_bytes - tree_base_bytes_);
  }
  if (ivy_support && ivy_) {
    seconds += ivy_->support().estimate().seconds;
    bytes += ivy_->support().estimate().memory_bytes;
  }
  bytes += record_bytes_;  // the year records (record_years), within their share
  left.seconds = budget_.seconds - seconds;
  left.memory_bytes =
      static_cast<uint64_t>(std::max(0.0, static_cast<double>(budget_.memory_bytes) - bytes));
  return left;
}

Status GardenRun::GrowBarks(const run::Observer& observer) {
  if (!barks_.on || barks_.grown) return Status::Ok();
  const Budget left = BudgetLeft(true);
  std::vector<const Tree*> trees;
  std::vector<uint64_t> seeds;
  for (const GardenTreeGroup& g : groups_) {
    trees.push_back(&g.tree());
    seeds.push_back(g.seed);
  }
  return GrowGardenBarks(trees, seeds, left, observer, &barks_, &truncated_by_);
}

namespace {

// Trees whose trunk stands within this of an ivy seed's foot lend their bark to the ivy's support.
constexpr double kIvyTreeReach = 6;
// Bytes the ivy's support takes per triangle (its mesh and BVHs), as ivy_budget's.
constexpr double kIvySupportBytesPerTriangle = 160;

void AppendMoved(geom::TriMesh* into, const geom::TriMesh& part, double x, double y, double z,
                 double rot_deg) {
  const double a = rot_deg * det::kPi / 180.0;
  const float c = static_cast<float>(det::Cos(a)), s = static_cast<float>(det::Sin(a));
  const uint32_t base = static_cast<uint32_t>(into->positions.size());
  for (const glm::vec3& p : part.positions)
    into->positions.emplace_back(c * p.x + s * p.z + static_cast<float>(x),
                                 p.y + static_cast<float>(y),
                                 -s * p.x + c * p.z + static_cast<float>(z));
  for (uint32_t i : part.indices) into->indices.push_back(base + i);
}

}  // namespace

ivy::IvyCosts GardenIvyCosts() {
  // CPU time natively (docs/garden-model.md "The ivy's estimate"; set beside the estimate by
  // bench/garden_estimates.mjs; tests/compose/garden_test.cpp TheIvysEstimateCountsItsWork holds
  // the estimate to these counted).
  // The scale garden grown to its 900 steps (25.5 M candidates, 57.6 M bud-steps, 14.7 M support
  // triangles over its 15 years; a year at a time, 15 points) and the small garden of that test.
  ivy::IvyCosts c;
  c.triangle_build = 0.3e-6;  // a support triangle's BVH (0.34-0.59 µs with its mesh measured)
  c.candidate = 1.0e-6;       // a candidate position tested: 0.66-0.99 µs measured
  c.bud_step = 0.15e-6;       // a bud a step: 0.12 µs fitted beside the candidates
  return c;
}

Status GardenRun::GrowIvyYear() {
  // The ivy's steps of garden year year_ (docs/garden-model.md "One clock"), on the garden as it
  // stands after that year's growth: the ground, every object, and the bark of the trees whose
  // trunk stands near a seed, each tree as it is this year.
  if (ivy_done_ || state_.ivy_on.empty() || year_ < 1) return Status::Ok();
  const int per_year = state_.params.GetInt(GardenParam::kIvySteps);
  const int steps = std::min(ivy::kMaxSteps, per_year * target());
  if (per_year <= 0 || steps <= 0) {
    ivy_done_ = true;
    return Status::Ok();
  }
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  ivy::IvyScene scene;
  scene.name = "garden";
  scene.description = "the garden's ground, objects and trunks (metres)";
  scene.px_per_unit = 1000;  // metres: the ivy's px are mm
  // The ground and the objects are the same every year: a bud anchored there keeps its triangle,
  // and their mesh is made once (their BVH too, below), the trunks' part after it each year.
  const bool kept_new = !ivy_kept_meshed_;
  if (kept_new) {
    ivy_kept_mesh_ = scene_.ground.Mesh();
    ivy_kept_mesh_.normals.clear();
    ivy_kept_mesh_.uvs.clear();
    for (const PlacedObject& o : scene_.objects) AppendMoved(&ivy_kept_mesh_, o.mesh, 0, 0, 0, 0);
    ivy_kept_meshed_ = true;
  }
  const auto kept = static_cast<uint32_t>(ivy_kept_mesh_.triangle_count());
  geom::TriMesh trunks;
  std::vector<glm::dvec3> feet;
  for (const std::string& on : state_.ivy_on) {
    Result<GardenIvyTarget> t = ParseIvyTarget(on, state_);
    if (!t.ok()) return t.status();
    if (t->object) {
      const PlacedObject& o = scene_.objects[t->index];
      feet.emplace_back(o.x, o.base_y, o.z);
    } else {
      const PlacedTree& p = planting_.trees[t->index];  // hand-placed trees come first
      feet.emplace_back(p.x, p.y, p.z);
    }
  }
  std::map<int, geom::TriMesh> bark_of_group;
  for (std::size_t t = 0; t < planting_.trees.size(); ++t) {
    const PlacedTree& p = planting_.trees[t];
    bool near = false;
    for (const glm::dvec3& f : feet)
      near = near || std::hypot(f.x - p.x, f.z - p.z) <= kIvyTreeReach;
    if (!near) continue;
    const int g = tree_group_[t];
    if (!bark_of_group.count(g)) {
      // The bark only: meshed in winter (no leaves or flowers; the bark is the same in every
      // season), so a year's support costs its tubes, not the crown's cards.
      MeshOptions bare;
      bare.look = LookFromParams(groups_[g].tree().params);
      bare.look->season = Season::kWinter;
      bare.look->autumn = AutumnColour::kRedOrange;
      bark_of_group[g] = BarkTriMesh(BuildTreeMesh(groups_[g].tree(), bare).bark);
    }
    AppendMoved(&trunks, bark_of_group[g], p.x, p.y, p.z, p.rot);
  }
  // The year's support: the kept part, then the trunks (the same floats and order as one mesh
  // made at once).
  scene.mesh = ivy_kept_mesh_;
  const auto trunks_base = static_cast<uint32_t>(scene.mesh.positions.size());
  scene.mesh.positions.insert(scene.mesh.positions.end(), trunks.positions.begin(),
                              trunks.positions.end());
  for (uint32_t i : trunks.indices) scene.mesh.indices.push_back(trunks_base + i);
  const double triangles = static_cast<double>(scene.mesh.triangle_count());
  // Its estimate: each triangle meshed and its BVH built when new (the kept part in the ivy's
  // first year, the trunks every year), every triangle joined and copied each year; its memory
  // the year's support and the kept part held beside it.
  const ivy::IvyCosts costs = GardenIvyCosts();
  const double per_new = kGardenIvyMeshSecondsPerTriangle + costs.triangle_build;
  const double kept_d = static_cast<double>(kept), trunks_d = triangles - kept_d;
  const Estimate support{
      (triangles + kept_d) * kIvySupportBytesPerTriangle,
      ((kept_new ? kept_d : 0) + trunks_d) * per_new + triangles * kGardenIvyJoinSecondsPerTriangle,
      "the ivy's support (" + FormatCount(triangles) + " triangles)"};
  if (!ivy_) {
    // Each seed, placed once (the first year): the support point nearest to a point just outside
    // its object's footprint (south, 0.3 m up) or its trunk's foot (south, 0.3 m up).
    for (std::size_t k = 0; k < state_.ivy_on.size(); ++k) {
      Result<GardenIvyTarget> t = ParseIvyTarget(state_.ivy_on[k], state_);
      glm::dvec3 probe;
      geom::TriMesh part;
      if (t->object) {
        const PlacedObject& o = scene_.objects[t->index];
        const double a = o.rot * det::kPi / 180.0;
        const double lz = o.hz + 0.02;
        probe = {o.x + det::Sin(a) * lz, o.base_y + 0.3, o.z + det::Cos(a) * lz};
        part = o.mesh;
      } else {
        const PlacedTree& p = planting_.trees[t->index];
        probe = {p.x, p.y + 0.3, p.z + 0.05};
        AppendMoved(&part, bark_of_group[tree_group_[t->index]], p.x, p.y, p.z, p.rot);
      }
      const geom::ClosestHit hit =
          geom::ClosestPointLinear(part, glm::vec3(probe), std::numeric_limits<float>::infinity());
      if (!hit.found)
        return Status::Error("ivy", "'" + state_.ivy_on[k] + "' has no surface to climb");
      scene.seeds.push_back({state_.ivy_on[k], glm::dvec3(hit.point)});
    }
  }
  // The garden is one job with one budget: the ivy gets what the trees' growth so far, the moss
  // and the records left of it, so a garden stops within the budget as a whole.
  const Budget left = BudgetLeft(false);
  ivy_budget_ = left;
  const std::string change = "lower ivy_steps or the ivy seeds, or years or density";
  if (!ivy_ && (left.seconds < support.seconds ||
                static_cast<double>(left.memory_bytes) < support.memory_bytes)) {
    // Nothing left for the ivy: the garden shows its trees and says why the ivy is missing.
    const std::string& limit =
        left.seconds < support.seconds ? budget_.seconds_limit : budget_.memory_limit;
    if (truncated_by_.empty())
      truncated_by_ = "ivy: " + TruncatedLine(limit, "before step 1",
                                              "the trees' growth used the garden's budget",
                                              change + RaiseHint(limit));
    ivy_done_ = true;
    ms_ivy_ += MsSince(t0);
    cpu_ms_ivy_ += 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    return Status::Ok();
  }
  ivy::IvyState ivy_state;
  NIWA_RETURN_IF_ERROR(ivy::SetIvyPreset(state_.ivy_preset, &ivy_state).Within("ivy"));
  NIWA_RETURN_IF_ERROR(
      ivy::SetIvySeed(state_.params.Get(GardenParam::kPlantSeed), &ivy_state).Within("ivy"));
  NIWA_RETURN_IF_ERROR(ivy::SetIvySteps(steps, &ivy_state).Within("ivy_steps"));
  ivy_state.seed_point_items = state_.ivy_on;
  ivy::IvySupportOptions options = ivy::IvySupportOptions::For(ivy_state);
  options.change = change;
  options.check_budget = false;  // the ivy's limits count it: a short budget stops the ivy
  options.costs = costs;         // the growth's (the support's are counted above)
  ivy::IvySupportInput input = ivy::IvySupportInput::Prepared(std::move(scene), support, "");
  if (options.accel == ivy::Accel::kBvh && options.subdivide == 0) {
    // The kept part's BVH built once; each year the trunks' joined to it: the same answers to
    // every query as one BVH built over the year's support (geom::Bvh::Join).
    if (!ivy_kept_built_) {
      ivy_kept_bvh_ = geom::Bvh::Build(ivy_kept_mesh_);
      ivy_kept_built_ = true;
    }
    input.prepared_bvh = geom::Bvh::Join(ivy_kept_bvh_, geom::Bvh::Build(trunks));
  }
  Result<std::shared_ptr<const ivy::IvySupport>> prepared =
      ivy::IvySupport::Prepare(std::move(input), options, left);
  if (!prepared.ok()) return prepared.status();
  ms_ivy_support_ += MsSince(t0);
  cpu_ms_ivy_support_ += 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  if (!ivy_) {
    ivy::IvyRunOptions run_options;
    run_options.change = change;
    run_options.extra_bytes_per_bud = ivy_extra_bytes_per_bud_;
    Result<ivy::IvyRun> run = ivy::IvyRun::Start(ivy_state, *prepared, left, run_options);
    if (!run.ok()) return run.status();
    ivy_ = std::make_unique<ivy::IvyRun>(std::move(*run));
  }
  NIWA_RETURN_IF_ERROR(
      ivy_->AdvanceOn(*prepared, kept, left, std::min(steps, per_year * year_), nullptr));
  if (ivy_->grown()) {
    ivy_done_ = true;
    if (truncated_by_.empty() && !ivy_->log().truncated_by.empty())
      truncated_by_ = "ivy: " + ivy_->log().truncated_by;
  }
  ms_ivy_ += MsSince(t0);
  cpu_ms_ivy_ += 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  return Status::Ok();
}

void GardenRun::GrowMossYear() {
  const auto t0 = Clock::now();
  const std::clock_t c0 = std::clock();
  std::vector<moss::CanopySphere> canopy;
  if (state_.params.GetBool(GardenParam::kMossShade)) {
    std::vector<TreeAt> trees;
    for (std::size_t t = 0; t < planting_.trees.size(); ++t) {
      const PlacedTree& p = planting_.trees[t];
      trees.push_back({groups_[tree_group_[t]].run.get(), p.x, p.y, p.z, p.rot});
    }
    canopy = GardenCanopy(trees, state_.params.Get(GardenParam::kMossCanopy));
  }
  moss_->SetCanopy(std::move(canopy));
  (void)moss_->AdvanceTo(year_ * state_.params.GetInt(GardenParam::kMossDays), nullptr);
  ms_moss_ += MsSince(t0);
  cpu_ms_moss_ += 1000.0 * static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
}

void GardenRun::RecordYear() {
  const auto t0 = Clock::now();
  RecordYearPicture();
  ms_records_ += MsSince(t0);
}

void GardenRun::RecordYearPicture() {
  if (!record_years_ || !record_stopped_by_.empty()) return;
  if (!records_.empty() && records_.back().year >= year_) return;  // already kept
  GardenYearRecord r;
  r.year = year_;
  const GardenYearRecord* last = records_.empty() ? nullptr : &records_.back();
  // A tree that grew no year since the last record (at its years, or stopped) shares its copy.
  std::vector<bool> fresh(groups_.size(), true);
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    const GardenTreeGroup& g = groups_[k];
    fresh[k] = last == nullptr || last->trees[k]->years != g.tree().years;
    if (fresh[k])  // a copy of the tree: what its growth estimate counts, the process's base aside
      r.bytes += std::max(0.0, g.run->grown().memory_bytes - tree_base_bytes_);
  }
  if (moss_) {
    r.moss_light = GardenMossGroundLight(*moss_, scene_.ground);
    r.mosses = static_cast<long>(moss_->world().mosses.size());
    r.bytes += 4.0 * static_cast<double>(r.moss_light.size());
  }
  if (ivy_) {  // the ivy of this year (its buds born by this year's last step)
    r.ivy_steps = ivy_->log_so_far().steps_run;
    r.ivy_internodes = static_cast<long>(ivy_->model_so_far().internodes.size());
  }
  r.bytes += 64.0 * static_cast<double>(groups_.size());  // the record's pointers
  if (record_bytes_ + r.bytes > record_limit_) {
    record_stopped_by_ = TruncatedLine(
        budget_.memory_limit, "after year " + std::to_string(year_ - 1),
        "the years' pictures took " + FormatBytes(record_bytes_) + " and year " +
            std::to_string(year_) + "'s needs " + FormatBytes(r.bytes) + ", more than their " +
            FormatBytes(record_limit_) + " (" + SharePercent(record_share_) + " of the budget)",
        "lower years, density or size to replay every year; the later years regrow");
    return;
  }
  for (std::size_t k = 0; k < groups_.size(); ++k)
    r.trees.push_back(fresh[k] ? std::make_shared<const Tree>(groups_[k].tree()) : last->trees[k]);
  record_bytes_ += r.bytes;
  records_.push_back(std::move(r));
}

const Tree* GardenRun::TreeAtYear(int group, int year) const {
  if (group < 0 || group >= static_cast<int>(groups_.size())) return nullptr;
  if (year == year_) return &groups_[group].tree();
  for (const GardenYearRecord& r : records_)
    if (r.year == year) return r.trees[static_cast<std::size_t>(group)].get();
  return nullptr;
}

namespace {

// A tree's leaf-area centroid in its own frame (m; nodes are in cm).
glm::dvec3 LocalLeafCentroid(const Tree& tree) {
  glm::dvec3 sum(0.0);
  double n = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const Leaf& leaf : b.leaves) {
      sum += glm::dvec3(b.nodes[leaf.node]);
      n += 1;
    }
  }
  return n > 0 ? sum / n / 100.0 : glm::dvec3(0.0);
}

// A lean shorter than this (m) has no direction worth turning a shape to.
constexpr double kShapeLeanMin = 0.01;

}  // namespace

double GardenRun::CrownRadius(int group) const {
  double r2 = 0;
  for (const Branch& b : groups_[group].tree().branches) {
    if (!b.alive) continue;
    for (const glm::vec3& p : b.nodes)
      r2 = std::max(r2, static_cast<double>(p.x) * p.x + static_cast<double>(p.z) * p.z);
  }
  return std::sqrt(r2) / 100.0;  // nodes are in cm
}

glm::dvec3 GardenRun::CrownCentroid(int t) const {
  const PlacedTree& p = planting_.trees[t];
  const glm::dvec3 local = LocalLeafCentroid(groups_[tree_group_[t]].tree());
  const glm::dvec2 turned = TurnPlan(local.x, local.z, p.rot);
  return {p.x + turned.x, p.y + local.y, p.z + turned.y};
}

std::vector<std::vector<int>> GardenRun::SharedVariants() const {
  std::vector<std::vector<int>> out;
  if (state_.params.GetInt(GardenParam::kShapes) <= 0) return out;
  std::map<std::tuple<std::string, uint64_t, int>, std::vector<int>> variants;
  for (std::size_t k = 0; k < groups_.size(); ++k) {
    const GardenTreeGroup& g = groups_[k];
    if (g.shaded) variants[{g.species, g.seed, g.age}].push_back(static_cast<int>(k));
  }
  for (auto& [key, members] : variants) out.push_back(std::move(members));
  return out;
}

std::vector<std::vector<GardenExportTree>> GardenRun::ExportTrees() const {
  std::vector<std::vector<GardenExportTree>> out(groups_.size());
  const int shapes = state_.params.GetInt(GardenParam::kShapes);
  const std::vector<std::vector<int>> variants = SharedVariants();
  for (std::size_t k = 0; k < groups_.size(); ++k)
    if (shapes <= 0 || !groups_[k].shaded)
      for (int t : groups_[k].trees) out[k].push_back({t, planting_.trees[t].rot, 1.0});
  for (const std::vector<int>& members : variants) {
    std::vector<TreeShape> measured;
    std::vector<glm::dvec3> lean;  // each member's leaf centroid in its own frame
    for (int k : members) {
      const Tree& tree = groups_[k].tree();
      lean.push_back(LocalLeafCentroid(tree));
      measured.push_back({ComputeStats(tree).height / 100.0, CrownRadius(k),
                          std::hypot(lean.back().x, lean.back().z)});
    }
    const std::vector<int> rep_of = ShareShapes(measured, shapes);
    for (std::size_t i = 0; i < members.size(); ++i) {
      const std::size_t r = static_cast<std::size_t>(rep_of[i]);
      const int rep = members[r];
      for (int t : groups_[members[i]].trees) {
        const double rot = planting_.trees[t].rot;
        if (r == i) {
          out[rep].push_back({t, rot, 1.0});
          continue;
        }
        // Turned so that the shape's lean points where this tree's does: a turn about y by a
        // adds a to atan2(x, z) (CrownCentroid's frame), and this tree's lean is its own
        // local lean turned by rot.
        double yaw = rot;
        if (measured[i].lean >= kShapeLeanMin && measured[r].lean >= kShapeLeanMin) {
          const double own = det::Atan2(lean[i].x, lean[i].z);
          const double shape = det::Atan2(lean[r].x, lean[r].z);
          yaw = rot + (own - shape) * 180.0 / det::kPi;
        }
        const double scale = measured[r].height > 0
                                 ? std::clamp(measured[i].height / measured[r].height,
                                              1.0 / kShapeScaleLimit, kShapeScaleLimit)
                                 : 1.0;
        out[rep].push_back({t, yaw, scale});
      }
    }
  }
  return out;
}

std::vector<run::Part> GardenRun::Parts() const {
  std::vector<run::Part> parts;
  run::Part ground;
  ground.name = "ground";
  ground.mesh = scene_.ground.Mesh();
  ground.material = PlainMaterial("ground", 0.36, 0.42, 0.24, 0.95);
  parts.push_back(std::move(ground));
  for (std::size_t k = 0; k < scene_.objects.size(); ++k) {
    run::Part o;
    o.name = "object_" + std::to_string(k) + "_" + scene_.objects[k].kind;
    o.mesh = scene_.objects[k].mesh;
    o.material = scene_.objects[k].kind == "wall" ? PlainMaterial("plaster", 0.86, 0.82, 0.74, 0.9)
                                                  : PlainMaterial("stone", 0.52, 0.52, 0.5, 0.85);
    parts.push_back(std::move(o));
  }
  return parts;
}

Result<gltf::Document> GardenRun::Document() const {
  gltf::Document doc;
  doc.scene_name = "garden";
  nlohmann::ordered_json extras;
  extras["niwa"] = {{"study", "garden"}, {"url", "#" + Hash("")}};
  doc.asset_extras_json = extras.dump();
  for (const run::Part& part : Parts()) {
    gltf::Mesh mesh;
    mesh.name = part.name;
    gltf::Primitive prim;
    prim.mesh = part.mesh;
    prim.material = static_cast<int>(doc.materials.size());
    doc.materials.push_back(part.material);
    mesh.primitives.push_back(std::move(prim));
    gltf::Node node;
    node.name = part.name;
    node.mesh = static_cast<int>(doc.meshes.size());
    doc.meshes.push_back(std::move(mesh));
    doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
    doc.nodes.push_back(std::move(node));
  }
  if (const ivy::IvyRun* grown_ivy = ivy()) {
    Result<gltf::Document> ivy_doc = grown_ivy->Document();
    if (!ivy_doc.ok()) return ivy_doc.status();
    // The suckers (rootlets under a centimetre) are left out: invisible at a garden's scale, they
    // were a third of its ivy's bytes (9 of 25 MB at 8 years). Only the kept nodes' meshes are
    // appended.
    gltf::Document kept = *ivy_doc;
    kept.meshes.clear();
    std::vector<std::pair<std::string, int>> kept_nodes;
    for (const gltf::Node& n : ivy_doc->nodes) {
      if (n.mesh < 0 || n.name.find("sucker") != std::string::npos ||
          ivy_doc->meshes[static_cast<std::size_t>(n.mesh)].name.find("sucker") !=
              std::string::npos)
        continue;
      kept_nodes.emplace_back(n.name, static_cast<int>(kept.meshes.size()));
      kept.meshes.push_back(ivy_doc->meshes[static_cast<std::size_t>(n.mesh)]);
    }
    const int mesh_base = AppendGardenDocument(&doc, kept);
    for (const auto& [name, mesh] : kept_nodes) {
      gltf::Node node;
      node.name = name.rfind("ivy", 0) == 0 ? name : "ivy_" + name;
      node.mesh = mesh_base + mesh;
      doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
      doc.nodes.push_back(std::move(node));
    }
  }
  if (moss_ && !moss_->world().mosses.empty()) {
    // The mosses as tufts (moss_gltf.h: COLOR_0 by species); the land's coverage map is not
    // written (the ground is the garden's own).
    gltf::Mesh mesh;
    mesh.name = "moss_tufts";
    gltf::Primitive prim;
    prim.mesh = moss::MergedTufts(moss_->Tufts());
    gltf::Material m;
    m.name = "moss_tufts";
    m.metallic_factor = 0;
    m.roughness_factor = 0.95;
    m.double_sided = true;
    prim.material = static_cast<int>(doc.materials.size());
    doc.materials.push_back(std::move(m));
    mesh.primitives.push_back(std::move(prim));
    gltf::Node node;
    node.name = "moss_tufts";
    node.mesh = static_cast<int>(doc.meshes.size());
    doc.meshes.push_back(std::move(mesh));
    doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
    doc.nodes.push_back(std::move(node));
  }
  const long max_triangles = state_.params.GetInt(GardenParam::kMaxTriangles);
  const bool lod = state_.params.GetBool(GardenParam::kLod);
  const bool instancing = state_.params.GetBool(GardenParam::kInstancing);
  LodOptions options;
  options.atlas_size = kGardenAtlasSize;
  const std::vector<std::vector<GardenExportTree>> drawn = ExportTrees();
  for (const GardenTreeGroup& g : groups_) {
    const std::size_t k = static_cast<std::size_t>(&g - groups_.data());
    if (drawn[k].empty()) continue;  // drawn with another group's shape
    std::vector<LodMesh> levels;
    if (lod) {
      Result<std::vector<LodMesh>> made =
          BuildLodLevels(g.tree(), max_triangles, options, "max_triangles");
      if (!made.ok()) return made.status();
      levels = std::move(*made);
    } else {
      Result<LodMesh> made = BuildLodMesh(g.tree(), max_triangles, options, "max_triangles");
      if (!made.ok()) return made.status();
      levels.push_back(std::move(*made));
    }
    // The simulated bark of this distinct tree (bark 1), on every level's tubes.
    const BarkFrame* bark =
        k < barks_.trees.size() && barks_.trees[k].frame ? barks_.trees[k].frame.get() : nullptr;
    if (bark != nullptr) WrapGardenBarkUvs(g.tree(), *bark, &levels);
    Result<gltf::Document> tree_doc = LodGltfDocument(levels, g.name);
    if (!tree_doc.ok()) return tree_doc.status();
    if (bark != nullptr) DressGardenBark(*bark, &*tree_doc);
    const int mesh_base = AppendGardenDocument(&doc, *tree_doc);
    // The tree document's nodes, one a level, each name its level's mesh.
    for (const gltf::Node& level : tree_doc->nodes) {
      if (level.mesh < 0) continue;
      const int mesh = mesh_base + level.mesh;
      if (instancing) {
        gltf::Node node;
        node.name = level.name;
        node.mesh = mesh;
        // The node stands where its first tree does (its own TRS), and the instances are relative
        // to it (the extension applies the node's transform after each instance's): a loader that
        // ignores EXT_mesh_gpu_instancing still shows that first tree in its place, not a tree at
        // the garden's origin (Blender 3.4 showed none: docs/garden-model.md "Export").
        const GardenExportTree& first = drawn[k].front();
        const PlacedTree& p0 = planting_.trees[first.tree];
        node.translation = {p0.x, p0.y, p0.z};
        node.rotation = YawQuaternion(first.yaw_deg);
        node.scale = {first.scale, first.scale, first.scale};
        const bool scaled =
            std::any_of(drawn[k].begin(), drawn[k].end(),
                        [&](const GardenExportTree& e) { return e.scale != first.scale; });
        for (const GardenExportTree& e : drawn[k]) {
          const PlacedTree& p = planting_.trees[e.tree];
          // inverse(T0 R0 S0) applied to (p, yaw, scale): turned back by yaw0 about y, then / s0.
          const double dx = p.x - p0.x, dy = p.y - p0.y, dz = p.z - p0.z;
          const glm::dvec2 back = TurnPlan(dx, dz, -first.yaw_deg) / first.scale;
          node.instance_translations.insert(
              node.instance_translations.end(),
              {static_cast<float>(back.x), static_cast<float>(dy / first.scale),
               static_cast<float>(back.y)});
          const std::array<double, 4> q = YawQuaternion(e.yaw_deg - first.yaw_deg);
          for (double v : q) node.instance_rotations.push_back(static_cast<float>(v));
          if (scaled)
            node.instance_scales.insert(node.instance_scales.end(), 3,
                                        static_cast<float>(e.scale / first.scale));
        }
        doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
        doc.nodes.push_back(std::move(node));
      } else {
        for (const GardenExportTree& e : drawn[k]) {
          const PlacedTree& p = planting_.trees[e.tree];
          gltf::Node node;
          node.name = g.name + "_" + std::to_string(e.tree) +
                      (levels.size() > 1 ? level.name.substr(level.name.rfind('_')) : "");
          node.mesh = mesh;
          node.translation = {p.x, p.y, p.z};
          node.rotation = YawQuaternion(e.yaw_deg);
          node.scale = {e.scale, e.scale, e.scale};
          doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()));
          doc.nodes.push_back(std::move(node));
        }
      }
    }
  }
  return doc;
}

std::string GardenRun::StatsJson() const {
  nlohmann::ordered_json j;
  j["study"] = "garden";
  j["years"] = year_;
  j["size"] = state_.params.Get(GardenParam::kSize);
  j["ground"] = {
      {"source", scene_.ground.source}, {"res", scene_.ground.n}, {"relief", scene_.ground.relief}};
  j["objects"] = scene_.objects.size();
  std::map<std::string, long> by_species;
  for (const PlacedTree& t : planting_.trees) ++by_species[t.species];
  double internodes = 0, leaves = 0;
  long shaded = 0;
  // Each distinct tree counted once, times its copies (CountTree walks the whole tree).
  for (const GardenTreeGroup& g : groups_) {
    const TreeCounts c = CountTree(g.tree());
    const double copies = static_cast<double>(g.trees.size());
    internodes += c.internodes * copies;
    leaves += c.leaves * copies;
    shaded += g.shaded ? 1 : 0;
  }
  nlohmann::ordered_json species = nlohmann::ordered_json::object();
  for (const auto& [name, count] : by_species) species[name] = count;
  j["trees"] = {{"count", planting_.trees.size()}, {"distinct", groups_.size()},
                {"grown_with_neighbours", shaded}, {"by_species", species},
                {"internodes", internodes},        {"leaves", leaves}};
  j["planting"] = nlohmann::ordered_json::parse(PlantingJson(planting_))["report"];
  if (const ivy::IvyRun* grown_ivy = ivy()) {
    j["ivy"] = {{"seeds", state_.ivy_on.size()},
                {"steps", grown_ivy->log().steps_run},
                {"internodes", grown_ivy->model().internodes.size()},
                {"support_triangles", grown_ivy->support().triangles()},
                {"internodes_by_year", ivy_by_year_}};
  }
  if (moss_) j["moss"] = GardenMossStats(*moss_, moss_->canopy());
  {
    // The budget's estimates of what grew (seconds of work, MB; the process's base counted once,
    // in the ivy's): what the budget was checked against, beside --stats' measured ms.
    double tree_s = 0, tree_b = 0;
    for (const GardenTreeGroup& g : groups_) {
      tree_s += g.run->grown().seconds;
      tree_b += std::max(0.0, g.run->grown().memory_bytes - tree_base_bytes_);
    }
    nlohmann::ordered_json e = {{"trees_s", tree_s},
                                {"trees_mb", tree_b / 1e6},
                                {"moss_s", moss_estimate_.seconds},
                                {"moss_mb", moss_estimate_.memory_bytes / 1e6}};
    if (const ivy::IvyRun* grown_ivy = ivy()) {
      const Estimate ivy_e =
          ivy::EstimateIvyGrown(grown_ivy->model(), grown_ivy->log(), grown_ivy->limits());
      e["ivy_s"] = ivy_e.seconds;
      e["ivy_support_s"] = grown_ivy->limits().seconds_before;
      // Without what a front end holds beside it (the page's meshes), so the page's stats are the
      // CLI's.
      e["ivy_mb"] = (ivy_e.memory_bytes - ivy_extra_bytes_per_bud_ *
                                              static_cast<double>(grown_ivy->model().buds.size())) /
                    1e6;
    }
    j["estimates"] = e;
  }
  if (barks_.on) j["bark"] = nlohmann::ordered_json::parse(GardenBarksJson(barks_));
  if (!truncated_by_.empty()) j["truncated_by"] = truncated_by_;
  return j.dump();
}

std::string GardenRun::Hash(const std::string& prefix) const {
  return EncodeGardenHash(state_, prefix);
}

Result<Estimate> GardenRun::ExportEstimate(const std::string& format) const {
  // The meshes the .glb holds: one a group, or at most `shapes` for the shaded groups of one
  // (species, seed, age) (an upper bound: the count before the trees have grown).
  const int shapes = state_.params.GetInt(GardenParam::kShapes);
  const std::vector<std::vector<int>> variants = SharedVariants();
  double groups = static_cast<double>(groups_.size());
  for (const std::vector<int>& members : variants)
    groups -= static_cast<double>(members.size()) -
              std::min(static_cast<double>(members.size()), static_cast<double>(shapes));
  const double ground_vertices = static_cast<double>(scene_.ground.n + 1) * (scene_.ground.n + 1);
  if (format == "glb") {
    Estimate moss{0, 0, ""};
    if (moss_)  // the tufts at the cap (the land map is not written, but counted: an upper bound)
      moss = moss::MossGlbEstimate(
          moss_->cells().size(),
          static_cast<std::size_t>(moss_->state().params.Get(moss::MossParam::kMaxMosses)));
    const double tri = static_cast<double>(state_.params.GetInt(GardenParam::kMaxTriangles)) *
                       (state_.params.GetBool(GardenParam::kLod) ? 1.3 : 1.0);
    return Estimate{
               groups * tri * kGardenGlbBytesPerTriangle + ground_vertices * 120 +
                   groups * 4.0 * kGardenAtlasSize * kGardenAtlasSize + moss.memory_bytes,
               groups * tri * kGardenGlbSecondsPerTriangle + ground_vertices * 1e-6 + moss.seconds,
               "writing the garden's .glb (" + FormatCount(groups) + " tree meshes)"} +
           GardenBarkExportEstimate(barks_);
  }
  if (format == "heightmap" || format == "svg" || format == "json")
    return Estimate{ground_vertices * 16 + static_cast<double>(planting_.trees.size()) * 200.0,
                    ground_vertices * 1e-7, "writing the garden's " + format};
  return Status::Error("format", "'" + format +
                                     "' is not an export; must be glb, heightmap, svg "
                                     "or json");
}

Result<std::string> GardenRun::Export(const std::string& format) const {
  if (format == "glb") {
    Result<gltf::Document> doc = Document();
    if (!doc.ok()) return doc.status();
    Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
    if (!glb.ok()) return glb.status();
    return std::string(glb->begin(), glb->end());
  }
  if (format == "json") return PlantingJson(planting_);
  if (format == "heightmap") {
    const GardenGround& g = scene_.ground;
    image::Gray16Image img;
    img.width = img.height = g.n + 1;
    img.pixels.resize(static_cast<std::size_t>(img.width) * img.height);
    for (std::size_t k = 0; k < g.h.size(); ++k)
      img.pixels[k] = static_cast<uint16_t>(
          g.relief > 0 ? std::lround(std::clamp(g.h[k] / g.relief, 0.0, 1.0) * 65535.0) : 0);
    image::PngWriteOptions options;
    options.text = {{"niwa:size_m", FormatNumber(g.size)},
                    {"niwa:relief_m", FormatNumber(g.relief)},
                    {"niwa:rows", "row 0 is the north edge (z = -size/2), column 0 the west"}};
    Result<std::vector<unsigned char>> png = image::EncodeGray16Png(img, options);
    if (!png.ok()) return png.status();
    return std::string(png->begin(), png->end());
  }
  if (format == "svg") {
    // The plan, north up: the ground shaded by height, objects as their footprints, each tree a
    // circle of its crown's reach in its species' colour.
    const GardenGround& g = scene_.ground;
    const double px = 800.0 / g.size;
    std::string svg =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"800\" "
        "viewBox=\"0 0 800 800\">\n";
    const int cells = std::min(g.n, 64);
    const double step = g.size / cells;
    for (int j = 0; j < cells; ++j)
      for (int i = 0; i < cells; ++i) {
        const double h = g.HeightAt(-g.size / 2 + (i + 0.5) * step, -g.size / 2 + (j + 0.5) * step);
        const int shade = static_cast<int>(150 + 80 * (g.relief > 0 ? h / g.relief : 0));
        svg += "<rect x=\"" + FormatNumber(i * step * px) + "\" y=\"" +
               FormatNumber(j * step * px) + "\" width=\"" + FormatNumber(step * px + 0.5) +
               "\" height=\"" + FormatNumber(step * px + 0.5) + "\" fill=\"rgb(" +
               std::to_string(shade - 40) + "," + std::to_string(shade) + "," +
               std::to_string(shade - 70) + ")\"/>\n";
      }
    for (const PlacedObject& o : scene_.objects) {
      svg += "<rect class=\"object\" x=\"" + FormatNumber((o.x - o.hx + g.size / 2) * px) +
             "\" y=\"" + FormatNumber((o.z - o.hz + g.size / 2) * px) + "\" width=\"" +
             FormatNumber(2 * o.hx * px) + "\" height=\"" + FormatNumber(2 * o.hz * px) +
             "\" transform=\"rotate(" + FormatNumber(-o.rot) + " " +
             FormatNumber((o.x + g.size / 2) * px) + " " + FormatNumber((o.z + g.size / 2) * px) +
             ")\" fill=\"#8a8478\" stroke=\"#333\"><title>" + o.kind + "</title></rect>\n";
    }
    for (std::size_t t = 0; t < planting_.trees.size(); ++t) {
      const PlacedTree& p = planting_.trees[t];
      const double r = std::max(0.3, CrownRadius(tree_group_[t]));
      svg += "<circle class=\"tree\" cx=\"" + FormatNumber((p.x + g.size / 2) * px) + "\" cy=\"" +
             FormatNumber((p.z + g.size / 2) * px) + "\" r=\"" + FormatNumber(r * px) +
             "\" fill=\"" + SpeciesColour(p.species) +
             "\" fill-opacity=\"0.55\" stroke=\"#222\"><title>" + p.species + " seed " +
             std::to_string(p.seed) + (p.hand >= 0 ? " (by hand)" : "") + "</title></circle>\n";
    }
    svg += "</svg>\n";
    return svg;
  }
  return Status::Error("format", "'" + format +
                                     "' is not an export; must be glb, heightmap, svg "
                                     "or json");
}

}  // namespace niwa::compose

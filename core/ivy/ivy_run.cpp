// The ivy study's run: support, growth, statistics and exports once (see ivy_run.h).
#include "ivy/ivy_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <utility>

#include "base/echo.h"
#include "geom/closest_point.h"
#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "ivy/lstring.h"
#include "params/param_text.h"

namespace niwa::ivy {
namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

Result<IvyExport> ExportKind(const std::string& format) {
  if (format == "json") return IvyExport::kJson;
  if (format == "lsys") return IvyExport::kLsys;
  if (format == "svg") return IvyExport::kSvg;
  if (format == "glb") return IvyExport::kGlb;
  return Status::Error("format", "'" + format + "' is unknown; must be json, lsys, svg or glb");
}

// The default seed of a dropped mesh: the surface point nearest to a point in front of the mesh
// (+z) at a tenth of its height, 1e-5 of its extent toward that point (Grow lifts it to d/2 off
// that face, on that side).
void AddFrontSeed(const geom::TriMesh& seedable, const geom::Bvh& bvh, IvyScene* scene) {
  if (seedable.triangle_count() == 0) return;
  const geom::Bounds3 b = geom::MeshBounds(seedable);
  const glm::vec3 size = b.max - b.min;
  const glm::vec3 probe(0.5f * (b.min.x + b.max.x), b.min.y + 0.1f * size.y,
                        b.max.z + std::max({size.x, size.y, size.z}));
  geom::ClosestHit hit =
      geom::ClosestPoint(seedable, bvh, probe, std::numeric_limits<float>::infinity());
  if (!hit.found) return;
  // A hair off the surface toward the probe, which is outside: Grow lifts a seed to the side it is
  // on, and one exactly on the surface along the face's winding, which a scan with inward faces
  // turns inside (issue 31 item 7: the ivy, leaves and all, grew inside the bunny).
  const glm::dvec3 at(hit.point);
  const glm::dvec3 to_probe = glm::dvec3(probe) - at;
  const double extent = std::max({size.x, size.y, size.z});
  const double len = std::sqrt(glm::dot(to_probe, to_probe));
  scene->seeds.push_back({"front", len > 0 ? at + to_probe * (1e-5 * extent / len) : at});
}

// One of the state's seed_point_items on a scene: "X,Y,Z" (each in [-1e30, 1e30]) or one of the
// scene's named seeds; errors name "seed_points" and list the names.
Result<glm::dvec3> SeedPointOf(const std::string& text, const IvyScene& scene) {
  std::string names;
  for (const NamedSeed& s : scene.seeds) {
    if (s.name == text) return s.pos;
    names += (names.empty() ? "" : ", ") + s.name;
  }
  const std::string range = "must be X,Y,Z (each in [-1e30, 1e30])" +
                            (names.empty() ? std::string() : " or one of " + names);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    parts.push_back(text.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (parts.size() != 3)
    return Status::Error("seed_points", "'" + Echo(text) + "' is unknown; " + range);
  glm::dvec3 p;
  for (int i = 0; i < 3; ++i) {
    std::optional<double> x = ParseNumber(parts[static_cast<std::size_t>(i)]);
    if (!x || std::fabs(*x) > 1e30)
      return Status::Error("seed_points", "'" + Echo(text) + "' is out of range; " + range);
    p[i] = *x;
  }
  return p;
}

// The state as the run holds it on a support: its seed_point_items resolved into seed_points
// (in order), its accel the support's.
Result<IvyState> ResolvedOn(const IvyState& state, const IvySupport& support) {
  if (state.accel != support.accel()) {
    return Status::Error("accel", std::string("the support was prepared for ") +
                                      (support.accel() == Accel::kBvh ? "bvh" : "linear") +
                                      " queries; must be prepared with the state's accel");
  }
  IvyState out = state;
  if (state.seed_point_items.empty()) return out;
  out.seed_points.clear();
  for (const std::string& item : state.seed_point_items) {
    Result<glm::dvec3> p = SeedPointOf(item, support.scene());
    if (!p.ok()) return p.status();
    out.seed_points.push_back(*p);
  }
  out.seed_point_items.clear();
  return out;
}

// The seed points of a state on a support: the state's, else the scene's first named seed.
Result<std::vector<glm::dvec3>> SeedsOn(const IvyState& state, const IvySupport& support) {
  std::vector<glm::dvec3> seeds = state.seed_points;
  if (seeds.empty() && !support.scene().seeds.empty())
    seeds.push_back(support.scene().seeds[0].pos);
  if (seeds.empty()) {
    return Status::Error("seed_points",
                         "required on a support with no named seed; must be X,Y,Z within d of a "
                         "face");
  }
  return seeds;
}

}  // namespace

IvySupportOptions IvySupportOptions::For(const IvyState& state) {
  IvySupportOptions options;
  options.accel = state.accel;
  return options;
}

IvySupportInput IvySupportInput::Scene(std::string name) {
  IvySupportInput in;
  in.kind = Kind::kScene;
  in.scene = std::move(name);
  return in;
}

IvySupportInput IvySupportInput::Mesh(geom::TriMesh mesh, std::string name,
                                      std::vector<io::MeshMaterial> materials,
                                      double metres_per_unit) {
  IvySupportInput in;
  in.kind = Kind::kMesh;
  in.mesh = std::move(mesh);
  in.name = std::move(name);
  in.materials = std::move(materials);
  in.metres_per_unit = metres_per_unit;
  return in;
}

IvySupportInput IvySupportInput::Prepared(IvyScene scene, Estimate estimate,
                                          std::string truncated_by) {
  IvySupportInput in;
  in.kind = Kind::kPrepared;
  in.prepared = std::move(scene);
  in.prepared_estimate = std::move(estimate);
  in.prepared_truncated_by = std::move(truncated_by);
  return in;
}

Result<std::shared_ptr<const IvySupport>> IvySupport::Prepare(IvySupportInput input,
                                                              const IvySupportOptions& options,
                                                              const Budget& budget) {
  auto out = std::make_shared<IvySupport>();
  IvySupport& s = *out;
  double prepared_seconds = 0;
  switch (input.kind) {
    case IvySupportInput::Kind::kScene: {
      Result<IvyScene> scene = MakeIvyScene(input.scene);
      if (!scene.ok()) return scene.status();
      s.scene_ = std::move(scene).value();
      break;
    }
    case IvySupportInput::Kind::kMesh: {
      NIWA_RETURN_IF_ERROR(geom::ValidateMesh(input.mesh, "mesh"));
      s.scene_.name = input.name;
      s.scene_.mesh = std::move(input.mesh);
      s.is_mesh_ = true;
      // 1000 px (mm) per metre: a glTF's tubes and leaves are sized in metres (IvyLookPxPerUnit).
      if (input.metres_per_unit > 0 && std::isfinite(input.metres_per_unit))
        s.scene_.unit_px_per_unit = 1000 * input.metres_per_unit;
      break;
    }
    case IvySupportInput::Kind::kPrepared:
      s.scene_ = std::move(input.prepared);
      prepared_seconds = input.prepared_estimate.seconds;
      s.truncated_by_ = std::move(input.prepared_truncated_by);
      break;
  }
  const int levels = options.subdivide;
  if (levels < 0 || levels > kMaxIvySubdivide) {
    return Status::Error(
        "subdivide", std::to_string(levels) + " is out of range; must be a whole number in [0, 8]");
  }
  if (levels > 0 && !s.scene_.free) {
    const double after =
        static_cast<double>(s.scene_.mesh.triangle_count()) * std::pow(4.0, levels);
    if (after > static_cast<double>(io::kMaxMeshTriangles)) {
      return Status::Error("subdivide", std::to_string(levels) + " would make " +
                                            FormatNumber(after) +
                                            " triangles; the limit is 4000000 (4 M)");
    }
  }
  // The support's memory and time (the subdivision, its BVH), refused before subdividing.
  std::vector<io::MeshMaterial> materials = std::move(input.materials);
  if (s.is_mesh_) s.attach_ = IvyAttachTriangles(s.scene_.mesh, materials, &s.obstacles_);
  IvySupportSize size;
  size.triangles = s.triangles();
  size.levels = s.scene_.free ? 0 : levels;
  size.bvh = options.accel == Accel::kBvh;
  size.obstacles = s.is_mesh_ && (options.mesh_attach_always_counted || s.obstacles_ > 0);
  size.costs = options.costs;
  s.costs_ = options.costs;
  // A BVH made by the caller is used as it is (its time is in the prepared estimate).
  const bool own_bvh = input.prepared_bvh.has_value() && levels == 0 && !s.scene_.free &&
                       options.accel == Accel::kBvh &&
                       input.prepared_bvh->triangle_count() == s.scene_.mesh.triangle_count();
  if (own_bvh) size.costs.triangle_build = 0;
  s.estimate_ = EstimateIvySupport(size);
  // A prepared support's building (a tree's growth and bark) took its time before the ivy's.
  s.estimate_.seconds += prepared_seconds;
  if (options.check_budget)
    NIWA_RETURN_IF_ERROR(CheckEstimate(s.estimate_, budget, options.change));
  if (!s.scene_.free && s.scene_.mesh.triangle_count() > 0) {
    const geom::Bounds3 b = geom::MeshBounds(s.scene_.mesh);
    if (!b.empty()) s.extent_ = std::max({b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z});
  }
  if (levels > 0 && !s.scene_.free) s.scene_.mesh = geom::Subdivide(s.scene_.mesh, levels);
  const auto t0 = Clock::now();
  s.accel_ = options.accel;
  if (own_bvh)
    s.bvh_ = std::move(*input.prepared_bvh);
  else if (!s.scene_.free && s.accel_ == Accel::kBvh)
    s.bvh_ = geom::Bvh::Build(s.scene_.mesh);
  if (s.obstacles_ > 0 && s.accel_ == Accel::kBvh) s.attach_bvh_ = geom::Bvh::Build(s.attach_);
  if (s.is_mesh_ && options.front_seed && s.accel_ == Accel::kBvh) {
    AddFrontSeed(s.obstacles_ > 0 ? s.attach_ : s.scene_.mesh,
                 s.obstacles_ > 0 ? s.attach_bvh_ : s.bvh_, &s.scene_);
  }
  s.ms_bvh_ = Ms(t0, Clock::now());
  return std::shared_ptr<const IvySupport>(std::move(out));
}

double IvySupport::px_per_unit() const {
  return IvyPxPerUnit(IvyParams(), scene_.px_per_unit, extent_);
}

double IvySupport::look_px_per_unit() const {
  return IvyLookPxPerUnit(IvyParams(), scene_.px_per_unit, scene_.unit_px_per_unit, px_per_unit());
}

Result<IvyParams> IvySupport::Scaled(const IvyParams& declared) const {
  const double k = IvyPxPerUnit(declared, scene_.px_per_unit, extent_);
  return IvyScaledParams(
      declared, k, IvyLookPxPerUnit(declared, scene_.px_per_unit, scene_.unit_px_per_unit, k));
}

Support IvySupport::ForGrow() const {
  Support support;
  if (scene_.free) return support;
  support = {&scene_.mesh, &bvh_, accel_};
  if (obstacles_ > 0) {
    support.attach_mesh = &attach_;
    support.attach_bvh = &attach_bvh_;
  }
  return support;
}

Result<IvyRun> IvyRun::Start(const IvyState& state, std::shared_ptr<const IvySupport> support,
                             const Budget& budget, const IvyRunOptions& options) {
  NIWA_RETURN_IF_ERROR(ValidateIvyParams(state.params));
  Result<IvyState> resolved = ResolvedOn(state, *support);
  if (!resolved.ok()) return resolved.status();
  IvyRun run;
  run.state_ = std::move(resolved).value();
  run.support_ = std::move(support);
  run.budget_ = budget;
  run.options_ = options;
  Result<std::vector<glm::dvec3>> seeds = SeedsOn(run.state_, *run.support_);
  if (!seeds.ok()) return seeds.status();
  run.seeds_ = std::move(seeds).value();
  Result<IvyParams> scaled = run.support_->Scaled(run.state_.params);
  if (!scaled.ok()) return scaled.status();
  run.params_ = std::move(scaled).value();
  run.leaf_support_ = run.support_->ForGrow();
  run.SetLimits();
  run.timings_.ms_bvh = run.support_->ms_bvh();
  return run;
}

const Support* IvyRun::LeafSupport() const {
  return leaf_support_.mesh != nullptr ? &leaf_support_ : nullptr;
}

void IvyRun::SetLimits() {
  limits_ = IvyLimits(params_, budget_, support_->estimate(), !support_->free(), support_->costs());
  limits_.seconds_before += earlier_supports_seconds_;  // AdvanceOn's earlier supports
  limits_.bytes_per_bud += options_.extra_bytes_per_bud;
  // The page's meshes hold each bud's further leaves too (the row leaf_spacing).
  const double leaves_per_bud = IvyLeavesPerBud(params_);
  if (options_.build_meshes)
    limits_.bytes_per_bud += IvyPageMeshBytesPerBud(leaves_per_bud) - IvyPageMeshBytesPerBud();
  if (!options_.change.empty()) limits_.change = options_.change;
  grow_limits_ = limits_;
  if (options_.reserve_stats) {
    ReserveIvyStats(support_->triangles(), &grow_limits_,
                    !options_.build_meshes && !support_->free(), leaves_per_bud);
  }
}

Status IvyRun::Advance(const run::Observer& observer) {
  if (grown_) return Status::Ok();
  GrowLog log;
  // The planned outputs' check on the buds so far, each time they have grown by a quarter: the
  // estimates only grow with the buds, so a refusal here is the refusal the grown ivy would get.
  Status early;
  double checked_buds = 0;
  const bool check_early = !options_.planned_export.empty() || options_.stats;
  // And, for a planned export or the statistics, their projection to the last step (issue 34:
  // --steps 10000 on cubes4 was refused only at step 389 of 10000, with 139,222 buds, and with
  // --stats alone at step 357 with 87,705): ProjectIvyBuds.
  double step_buds = 0;  // the buds after the previous step
  double bud_steps = 0;  // Σ buds over the steps made
  BudProjection projection;
  // The planned outputs' estimate on the buds so far: the export (with the statistics when asked
  // for), else the grown ivy and its statistics.
  const auto planned = [&](const IvyModel& model, const GrowLog& so_far) -> Result<Estimate> {
    if (!options_.planned_export.empty())
      return ExportEstimateOf(model, so_far, options_.planned_export,
                              options_.planned_with_support);
    return EstimateIvyGrown(model, so_far, limits_) + EstimateIvyStats(StatsWork(model));
  };
  const std::string change =
      options_.planned_export.empty() ? options_.stats_change : options_.export_change;
  const StepObserver on_step = [&](int step, int steps, const IvyModel& model,
                                   const GrowLog& so_far) {
    const double buds = static_cast<double>(model.buds.size());
    const double new_buds = buds - step_buds;
    step_buds = buds;
    bud_steps += buds;
    if (check_early && buds >= 1.05 * projection.buds + 64) {
      Result<Estimate> exported = planned(model, so_far);
      if (exported.ok()) {
        const Status fits = ProjectIvyBuds(&projection, buds, new_buds, bud_steps, *exported,
                                           EstimateIvyGrown(model, so_far, grow_limits_).seconds,
                                           grow_limits_, budget_, step, steps, change);
        if (!fits.ok()) {
          early = fits;
          return false;
        }
      }
    }
    if (check_early && buds >= 1.25 * checked_buds + 64) {
      checked_buds = buds;
      Result<Estimate> exported = planned(model, so_far);
      const Estimate e = exported.ok() ? *exported : Estimate{};
      const Status fits = CheckEstimate(e, budget_, change);
      if (!fits.ok()) {
        early =
            Status::Error(fits.field(), "at step " + std::to_string(step) + " of " +
                                            std::to_string(steps) + " already: " + fits.message());
        return false;
      }
    }
    return !observer || observer({"grow", static_cast<double>(step), static_cast<double>(steps)});
  };
  ++grows_;
  Result<IvyModel> model = Grow(support_->ForGrow(), seeds_, params_, state_.steps, state_.seed,
                                &log, &grow_limits_, on_step);
  if (!early.ok()) return early;
  if (!model.ok()) return model.status();
  FinishGrowth(std::move(model).value(), std::move(log), observer);
  return Status::Ok();
}

Status IvyRun::AdvanceOn(std::shared_ptr<const IvySupport> support, uint32_t kept_triangles,
                         const Budget& budget, int to, const run::Observer& observer) {
  if (grown_) return Status::Ok();
  if (support != support_) {
    earlier_supports_seconds_ += support_->estimate().seconds;
    support_ = std::move(support);
    leaf_support_ = support_->ForGrow();
    if (growth_) growth_->SetSupport(leaf_support_, kept_triangles);
  }
  budget_ = budget;
  SetLimits();
  if (!growth_) {
    ++grows_;
    Result<IvyGrowth> growth =
        IvyGrowth::Start(leaf_support_, seeds_, params_, state_.steps, state_.seed);
    if (!growth.ok()) return growth.status();
    growth_ = std::make_shared<IvyGrowth>(std::move(*growth));
  }
  const StepObserver on_step = [&](int step, int steps, const IvyModel&, const GrowLog&) {
    return !observer || observer({"grow", static_cast<double>(step), static_cast<double>(steps)});
  };
  NIWA_RETURN_IF_ERROR(growth_->GrowTo(std::min(to, state_.steps), &grow_limits_, on_step));
  if (growth_->finished()) {
    IvyModel model = growth_->TakeModel();
    GrowLog log = growth_->TakeLog();
    growth_.reset();
    FinishGrowth(std::move(model), std::move(log), observer);
  }
  return Status::Ok();
}

void IvyRun::FinishGrowth(IvyModel model, GrowLog log, const run::Observer& observer) {
  model_ = std::move(model);
  log_ = std::move(log);
  timings_.ms_rules = log_.ms_rules;
  timings_.ms_search = log_.ms_search;
  timings_.ms_mesh = 0;
  meshes_ = IvyMeshes{};
  if (options_.build_meshes) {
    // A stage of its own on the progress line (a big ivy's leaves are checked against the
    // support); its answer cannot cancel a grown ivy.
    const double buds = static_cast<double>(model_.buds.size());
    if (observer) (void)observer({"meshing", 0, buds});
    const auto t0 = Clock::now();
    placement_ = LeafPlacement{};
    meshes_ = BuildIvyMeshes(model_, params_, LeafSupport(), &placement_);
    ++remeshes_;
    timings_.ms_mesh = Ms(t0, Clock::now());
  }
  grown_ = true;
}

Status IvyRun::Update(const IvyState& given) {
  NIWA_RETURN_IF_ERROR(ValidateIvyParams(given.params));
  Result<IvyState> resolved = ResolvedOn(given, *support_);
  if (!resolved.ok()) return resolved.status();
  const IvyState& state = *resolved;
  bool regrow = !grown_ || state.preset != state_.preset || state.seed != state_.seed ||
                state.steps != state_.steps || state.scene != state_.scene ||
                state.seed_points != state_.seed_points || state.tree != state_.tree ||
                state.tree_years != state_.tree_years;
  bool remesh = false;
  for (std::size_t i = 0; !regrow && i < state.params.size(); ++i) {
    if (state.params.Get(i) == state_.params.Get(i)) continue;
    if (state.params.table().row(i).stage == Stage::kGrow) regrow = true;
    if (state.params.table().row(i).stage == Stage::kMesh) remesh = true;
  }
  Result<std::vector<glm::dvec3>> seeds = SeedsOn(state, *support_);
  if (!seeds.ok()) return seeds.status();
  Result<IvyParams> scaled = support_->Scaled(state.params);
  if (!scaled.ok()) return scaled.status();
  params_ = std::move(scaled).value();
  state_ = state;
  seeds_ = std::move(seeds).value();
  SetLimits();
  if (regrow) {
    grown_ = false;
    model_ = IvyModel{};
    log_ = GrowLog{};
    meshes_ = IvyMeshes{};
    return Status::Ok();
  }
  if (remesh && options_.build_meshes) {
    const auto t0 = Clock::now();
    placement_ = LeafPlacement{};
    meshes_ = BuildIvyMeshes(model_, params_, LeafSupport(), &placement_);
    ++remeshes_;
    timings_.ms_mesh = Ms(t0, Clock::now());
  }
  return Status::Ok();
}

std::vector<run::Part> IvyRun::Parts() const {
  std::vector<run::Part> parts;
  Result<gltf::Document> doc = Document();
  if (!doc.ok()) return parts;
  for (const gltf::Mesh& mesh : doc->meshes) {
    for (const gltf::Primitive& prim : mesh.primitives) {
      run::Part part;
      part.name = mesh.name;
      part.mode = prim.mode;
      part.mesh = prim.mesh;
      if (prim.material >= 0) {
        part.material = doc->materials[static_cast<std::size_t>(prim.material)];
        if (part.material.base_color_texture >= 0) {
          part.textures.push_back(
              doc->textures[static_cast<std::size_t>(part.material.base_color_texture)]);
          part.material.base_color_texture = 0;
        }
      }
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

Result<gltf::Document> IvyRun::Document() const {
  if (!grown_) return Status::Error("ivy", "nothing grown yet");
  return BuildIvyDocument(model_, params_, state_.seed, state_.steps, nullptr, LeafSupport());
}

IvyStatsWork IvyRun::StatsWork(const IvyModel& model) const {
  IvyStatsWork w = CountIvyStatsWork(model, params_, support_->triangles());
  if (support_->mesh() != nullptr) {  // StatsJson's leaves as drawn and their cover
    w.meshed_buds = options_.build_meshes ? 0 : w.buds;
    w.leaves_per_bud = IvyLeavesPerBud(params_);
    w.leaf_cover = true;
    w.cover_triangles = support_->triangles() + kIvyLeafTrianglesPerBud * w.leaves_per_bud * w.buds;
  }
  return w;
}

Estimate IvyRun::StatsEstimate() const { return EstimateIvyStats(StatsWork(model_)); }

Status IvyRun::CheckGrewSomething() const {
  if (state_.steps == 0 || !model_.internodes.empty() || !log_.truncated_by.empty())
    return Status::Ok();
  const double L = params_.Get(IvyParam::kL), d = params_.Get(IvyParam::kD);
  const double size = support_->extent();
  const std::string grew = "grew no internode in " + std::to_string(state_.steps) + " steps";
  if (size > 0 && std::max(L, d) >= 0.5 * size) {
    // The lengths are the preset's (in px) and a scale was given (the row, or the preset's own):
    // the scale does not fit the support; else the user's own L or d do not.
    Result<IvyParams> preset = IvyPreset(state_.preset);
    const bool presets_lengths = preset.ok() &&
                                 preset->Get(IvyParam::kL) == state_.params.Get(IvyParam::kL) &&
                                 preset->Get(IvyParam::kD) == state_.params.Get(IvyParam::kD);
    const double k = state_.params.Get(IvyParam::kScale);
    const std::string across = " scene units, and the support is " +
                               FormatNumber(std::round(size * 1000) / 1000) + " across";
    if (presets_lengths && k > 0) {
      return Status::Error(
          "scale", grew + ": at " + FormatNumber(k) + " px per unit the internode length L = " +
                       FormatNumber(L) + " and distance d = " + FormatNumber(d) + across +
                       "; give the support's units (m, cm, mm, px) or 0 to read the scale from "
                       "its bounds (" +
                       FormatNumber(kIvyPaperExtent / size) + " px per unit)");
    }
    return Status::Error("L", grew + ": its internode length L = " + FormatNumber(L) +
                                  " and distance d = " + FormatNumber(d) + across +
                                  "; set L and d below half its size");
  }
  return Status::Error("seed_points", grew + ": no seed found a place to grow within d = " +
                                          FormatNumber(d) + " of the support");
}

Status IvyRun::CheckStats() const {
  if (!grown_) return Status::Ok();
  return CheckEstimate(EstimateIvyGrown(model_, log_, limits_) + StatsEstimate(), budget_,
                       options_.stats_change);
}

std::string IvyRun::StatsJson() const {
  if (!grown_) return "{}";
  // The measurement's exact estimate (the overlap sweep's pairs, counted before any is tested)
  // with the grown ivy's; when it does not fit, the sweep is left out and its line is a notice.
  const Status fits = CheckStats();
  IvyStats stats =
      MeasureIvy(model_, log_, support_->mesh(), params_, support_->attach(), fits.ok());
  stats.overlap_skipped_by = fits.Line();
  stats.tree_truncated_by = support_->truncated_by();
  // The leaves as drawn: their count after thinning and their cover seen from the front.
  if (support_->mesh() != nullptr) {
    IvyMeshes local;
    LeafPlacement placement = placement_;
    const IvyMeshes* meshes = &meshes_;
    if (!options_.build_meshes) {
      placement = LeafPlacement{};
      local = BuildIvyMeshes(model_, params_, LeafSupport(), &placement);
      meshes = &local;
    }
    // (one a bud less those thinned, unless leaf_spacing gives a bud more or fewer)
    stats.leaves_thinned = static_cast<int>(placement.thinned);
    stats.leaves = static_cast<int>(placement.drawn);
    stats.leaf_cover = LeafCoverFront(*support_->mesh(), meshes->leaves);
  }
  return IvyStatsJson(stats, log_, model_, timings_);
}

std::string IvyRun::Hash(const std::string& prefix) const { return EncodeIvyHash(state_, prefix); }

Result<Estimate> IvyRun::ExportEstimate(const std::string& format) const {
  return ExportEstimate(format, false);
}

Result<Estimate> IvyRun::ExportEstimate(const std::string& format, bool with_support) const {
  return ExportEstimateOf(model_, log_, format, with_support);
}

Result<Estimate> IvyRun::ExportEstimateOf(const IvyModel& model, const GrowLog& log,
                                          const std::string& format, bool with_support) const {
  Result<IvyExport> kind = ExportKind(format);
  if (!kind.ok()) return kind.status();
  const bool support_out =
      !support_->free() && (*kind == IvyExport::kSvg || (with_support && *kind == IvyExport::kGlb));
  Estimate e =
      EstimateIvyGrown(model, log, options_.export_with_stats_room ? grow_limits_ : limits_) +
      EstimateIvyExport(model, *kind, support_out ? support_->triangles() : 0,
                        IvyLeavesPerBud(params_));
  if (options_.stats) {
    e = e + EstimateIvyStats(StatsWork(model));
  }
  return e;
}

Status IvyRun::CheckExport(const std::string& format, bool with_support) const {
  if (!grown_) return Status::Ok();
  Result<Estimate> e = ExportEstimate(format, with_support);
  if (!e.ok()) return e.status();
  return CheckEstimate(*e, budget_, options_.export_change);
}

Result<std::string> IvyRun::Export(const std::string& format,
                                   const IvyExportOptions& options) const {
  NIWA_RETURN_IF_ERROR(CheckExport(format, options.with_support));
  return ExportUnchecked(format, options);
}

Result<std::string> IvyRun::ExportUnchecked(const std::string& format,
                                            const IvyExportOptions& options) const {
  if (!grown_) return Status::Error(format, "nothing grown yet");
  if (format == "json") return IvyModelJson(model_, params_, state_.seed, state_.steps) + "\n";
  if (format == "lsys") return PrintLString(model_);
  if (format == "svg") return IvySvg(model_, params_, support_->mesh(), options.svg);
  if (format == "glb") {
    Result<std::vector<unsigned char>> glb =
        WriteIvyGlb(model_, params_, state_.seed, state_.steps,
                    options.with_support ? support_->mesh() : nullptr, LeafSupport());
    if (!glb.ok()) return glb.status();
    return std::string(glb->begin(), glb->end());
  }
  return ExportKind(format).status();
}

}  // namespace niwa::ivy

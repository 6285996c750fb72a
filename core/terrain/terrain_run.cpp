// TerrainRun: the terrain pipeline once, for the CLI and the page (see terrain_run.h).
#include "terrain/terrain_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <nlohmann/json.hpp>

#include "terrain/compare.h"
#include "terrain/contour_io.h"
#include "terrain/generate.h"
#include "terrain/polygon.h"
#include "terrain/terrain_params.h"
#include "terrain/terrain_report.h"

namespace niwa::terrain {
namespace {

using Clock = std::chrono::steady_clock;

double Ms(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// The levels above the seed a mountain of this seed probably reaches: its inradius, about 2A/P
// (exact for a disk), over d, within the cap (Advance's progress total; raised when passed).
int EstimatedLevels(const Ring& seed, const TerrainParams& params) {
  const double perimeter = Perimeter(seed);
  const double d = params.Get(TerrainParam::kD);
  const int cap = params.GetInt(TerrainParam::kMaxLevels);
  if (!(perimeter > 0) || !(d > 0)) return cap;
  const double levels = std::ceil(2 * std::fabs(Area(seed)) / perimeter / d);
  return levels < cap ? std::max(1, static_cast<int>(levels)) : cap;
}

int LevelsOf(const Terrain& t) {
  if (t.contours.empty()) return 0;
  int lo = 0, hi = 0;
  for (const ContourNode& c : t.contours) {
    lo = std::min(lo, c.level);
    hi = std::max(hi, c.level);
  }
  return hi - lo + 1;
}

}  // namespace

Result<TerrainOutput> TerrainOutputOfFormat(const std::string& format) {
  if (format == "glb") return TerrainOutput::kGlb;
  if (format == "heightmap" || format == "sidecar") return TerrainOutput::kHeightmap;
  if (format == "json") return TerrainOutput::kContoursJson;
  if (format == "geojson") return TerrainOutput::kGeoJson;
  if (format == "svg") return TerrainOutput::kSvg;
  return Status::Error("format",
                       "unknown format; must be glb, heightmap, sidecar, json, geojson or svg");
}

std::string TerrainRun::Change() const {
  std::string res = "res";
  for (const auto& [field, word] : plan_.words)
    if (field == "res") res = word;
  return "lower " + res;
}

Result<Ring> TerrainRun::Check(const TerrainState& state) const {
  Result<Ring> seed = StateSeed(state);
  if (!seed.ok()) return seed.status();
  // The heightfield alone ((res + 2)² cells at most) must fit before anything grows.
  const double side = state.params.GetInt(TerrainParam::kRes) + 2.0;
  NIWA_RETURN_IF_ERROR(
      CheckEstimate(EstimateHeightfield(Terrain{}, {side, side}), budget_, Change()));
  NIWA_RETURN_IF_ERROR(CheckTerrainParams(state.params));
  // A seed whose shape makes even its first shrink too slow (a comb), refused before it starts.
  NIWA_RETURN_IF_ERROR(CheckSeedShape(*seed, state.params, budget_));
  return seed;
}

Result<TerrainRun> TerrainRun::Start(const TerrainState& state, const Budget& budget,
                                     TerrainRunPlan plan) {
  TerrainRun run;
  run.budget_ = budget;
  run.plan_ = std::move(plan);
  Result<Ring> seed = run.Check(state);
  if (!seed.ok()) return seed.status();
  run.next_ = state;
  run.next_seed_ = std::move(seed).value();
  run.redo_ = Redo::kGrow;
  return run;
}

Status TerrainRun::Update(const TerrainState& state) {
  Result<Ring> seed = Check(state);
  if (!seed.ok()) return seed.status();
  Stage stage = Stage::kView;
  if (!grown_ || state.builtin != state_.builtin || state.points != state_.points ||
      state.seed != state_.seed) {
    stage = Stage::kGrow;
  } else {
    const ParamTable& table = TerrainTable();
    for (std::size_t row = 0; row < table.size(); ++row)
      if (state.params.Get(row) != state_.params.Get(row))
        stage = std::min(stage, table[row].stage);
  }
  bool erosion_only = false;
  if (stage == Stage::kMesh) {
    // Only erosion rows (and view rows) changed: the kept heightfield is re-eroded.
    erosion_only = true;
    const ParamTable& table = TerrainTable();
    for (std::size_t row = 0; row < table.size(); ++row) {
      if (table[row].stage != Stage::kMesh || state.params.Get(row) == state_.params.Get(row))
        continue;
      if (std::string(table[row].group) != "erosion") erosion_only = false;
    }
  }
  if (stage == Stage::kMesh && !erosion_only) {
    // res is held back from the grow's budget (TerrainLimits): the kept contours are what a regrow
    // would give when the limits are the same, or when no limit stopped them and every check of
    // their grow passes the new limits too.
    const TerrainGrowLimits now = TerrainLimits(state.params, budget_);
    const bool same = now.max_bytes == limits_.max_bytes && now.max_seconds == limits_.max_seconds;
    const bool fits =
        terrain_.counts.truncated_by.empty() && GrowFitsLimits(terrain_, state_.params, now);
    if (!same && !fits) stage = Stage::kGrow;
  }
  next_ = state;
  next_seed_ = std::move(seed).value();
  if (stage == Stage::kGrow) {
    redo_ = Redo::kGrow;
  } else if (stage == Stage::kMesh) {
    redo_ = erosion_only ? Redo::kErosion : Redo::kHeightfield;
  } else {  // sway and view rows: nothing built depends on them until it is asked for
    state_ = next_;
    redo_ = Redo::kNothing;
  }
  return Status::Ok();
}

int TerrainRun::done() const { return grown_ && redo_ == Redo::kNothing ? LevelsOf(terrain_) : 0; }

int TerrainRun::target() const {
  if (grown_ && redo_ == Redo::kNothing) return done();
  return next_.params.GetInt(TerrainParam::kMaxLevels) + next_.params.GetInt(TerrainParam::kDown);
}

void TerrainRun::ErodeKept(const TerrainState& state) {
  const ErosionParams p = ErosionParamsOf(state.params);
  const auto t0 = Clock::now();
  if (p.mode == static_cast<int>(ErosionMode::kOff)) {
    if (!hf_raw_.h.empty()) hf_ = std::move(hf_raw_);
    hf_raw_ = Heightfield();
    erosion_ = ErosionReport();
    ms_erosion_ = 0;
    return;
  }
  if (hf_raw_.h.empty()) hf_raw_ = hf_;
  hf_ = hf_raw_;
  erosion_ = Erode(p, &hf_);
  ++counts_.erosions;
  ms_erosion_ = Ms(t0, Clock::now());
}

Status TerrainRun::Advance(const run::Observer& observer) {
  if (redo_ == Redo::kNothing) return Status::Ok();
  if (redo_ == Redo::kErosion) {
    // The kept surface's erosion again, refused before it starts when it cannot fit.
    NIWA_RETURN_IF_ERROR(CheckEstimate(
        EstimateErosion({static_cast<double>(hf_.width), static_cast<double>(hf_.height)},
                        next_.params),
        budget_, Change()));
    if (observer && !observer({"erosion", 0, 1})) return run::CancelledStatus();
    ErodeKept(next_);
    if (observer) observer({"erosion", 1, 1});
    heightmap_.reset();
    state_ = next_;
    redo_ = Redo::kNothing;
    ms_grow_ = 0;
    ms_heightfield_ = 0;
    return Status::Ok();
  }
  const auto t0 = Clock::now();
  const TerrainParams& params = next_.params;
  std::optional<Terrain> grown;
  TerrainGrowLimits limits = limits_;
  if (redo_ == Redo::kGrow) {
    limits = TerrainLimits(params, budget_);
    run::Progress progress{"levels", 0,
                           static_cast<double>(EstimatedLevels(next_seed_, params) +
                                               params.GetInt(TerrainParam::kDown))};
    int last_level = 0;
    GrowWatch watch;
    if (observer) {
      watch = [&](int level) {
        if (level != last_level) {
          last_level = level;
          progress.done += 1;
          progress.total = std::max(progress.total, progress.done);
        }
        return observer(progress);
      };
    }
    Result<Terrain> t = Grow(next_seed_, params, next_.seed, &limits, watch);
    truncated_by_.clear();
    checked_estimate_.reset();
    if (!t.ok()) return t.status();
    ++counts_.grows;
    truncated_by_ = t->counts.truncated_by;
    grown.emplace(std::move(t).value());
  }
  const Terrain& t = grown ? *grown : terrain_;
  if (plan_.max_contour_vertices > 0) {
    double vertices = 0;
    for (const ContourNode& c : t.contours) vertices += static_cast<double>(c.ring.size());
    if (vertices > plan_.max_contour_vertices) {
      const bool down = params.GetInt(TerrainParam::kDown) > 0;
      const std::string field = down ? "down" : "max_levels";
      return Status::Error(field, FormatCount(vertices) + " contour vertices are more than " +
                                      plan_.contour_vertex_holder + " (" +
                                      FormatCount(plan_.max_contour_vertices) + "); lower " +
                                      field + " or raise d");
    }
  }
  {
    // The heightfield and the plan's outputs on top of the grown contours, refused before they
    // start.
    const GridSize grid = TerrainGridSize(t, params.GetInt(TerrainParam::kRes));
    Estimate e = EstimateTerrainGrown(t, limits) + EstimateHeightfield(t, grid) +
                 EstimateErosion(grid, params);
    for (TerrainOutput kind : plan_.outputs) e = e + EstimateTerrainOutput(t, grid, kind);
    checked_estimate_ = e;
    NIWA_RETURN_IF_ERROR(CheckEstimate(e, budget_, Change()));
  }
  if (observer && !observer({"surface", 0, 1})) return run::CancelledStatus();
  const auto t1 = Clock::now();
  Heightfield hf = BuildHeightfield(t, params.GetInt(TerrainParam::kRes));
  ++counts_.heightfields;
  const auto t2 = Clock::now();
  if (observer) observer({"surface", 1, 1});
  if (grown) {
    terrain_ = std::move(*grown);
    limits_ = limits;
  }
  hf_ = std::move(hf);
  hf_raw_ = Heightfield();
  ErodeKept(next_);
  heightmap_.reset();
  state_ = next_;
  grown_ = true;
  redo_ = Redo::kNothing;
  ms_grow_ = grown ? Ms(t0, t1) : 0;
  ms_heightfield_ = Ms(t1, t2);
  return Status::Ok();
}

Result<gltf::Document> TerrainRun::Document() const {
  if (!grown_) return Status::Error("run", "nothing grown yet");
  nlohmann::json extras;  // the page's .glb and the CLI's are the same bytes
  extras["generator"] = "niwa terrain grow";
  extras["url"] = EncodeTerrainHash(state_);
  return TerrainDocument(terrain_, hf_, state_.params.GetBool(TerrainParam::kTint), extras.dump());
}

std::vector<run::Part> TerrainRun::Parts() const {
  std::vector<run::Part> parts;
  Result<gltf::Document> doc = Document();
  if (!doc.ok()) return parts;
  for (gltf::Mesh& mesh : doc->meshes) {
    for (gltf::Primitive& p : mesh.primitives) {
      run::Part part;
      part.name = mesh.name;
      part.mode = p.mode;
      part.mesh = std::move(p.mesh);
      if (p.material >= 0) part.material = doc->materials[static_cast<std::size_t>(p.material)];
      parts.push_back(std::move(part));
    }
  }
  return parts;
}

std::string TerrainRun::StatsJson() const {
  if (!grown_) return "{}";
  nlohmann::json j = TerrainStatsJson(state_, terrain_, hf_, ComputeStats(terrain_, &hf_));
  // Only with erosion on, so every stats object without it is as before.
  if (state_.params.GetInt(TerrainParam::kErosion) != 0) j["erosion"] = ErosionJson(erosion_);
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string TerrainRun::Hash(const std::string& prefix) const {
  return EncodeTerrainHash(state_, prefix);
}

Result<Estimate> TerrainRun::ExportEstimate(const std::string& format) const {
  Result<TerrainOutput> kind = TerrainOutputOfFormat(format);
  if (!kind.ok()) return kind.status();
  const GridSize grid = {static_cast<double>(hf_.width), static_cast<double>(hf_.height)};
  // The heightmap is the surface rebuilt on its square grid: that build and its samples.
  const Heightfield square = HeightmapGrid(hf_, state_.params.GetInt(TerrainParam::kRes));
  const GridSize map = {static_cast<double>(square.width), static_cast<double>(square.height)};
  const auto output = [&](TerrainOutput out) {
    return out == TerrainOutput::kHeightmap
               ? EstimateHeightfield(terrain_, map) + EstimateTerrainOutput(terrain_, map, out)
               : EstimateTerrainOutput(terrain_, grid, out);
  };
  Estimate e;
  for (TerrainOutput held : plan_.outputs) e = e + output(held);
  return e + EstimateHeightfield(terrain_, grid) + output(*kind);
}

Status TerrainRun::CheckExport(const std::string& format) const {
  Result<Estimate> e = ExportEstimate(format);
  if (!e.ok()) return e.status();
  return CheckEstimate(*e, budget_, Change());
}

const Heightfield& TerrainRun::heightmap_field() const {
  if (!heightmap_) {
    heightmap_ =
        BuildHeightfieldOn(terrain_, HeightmapGrid(hf_, state_.params.GetInt(TerrainParam::kRes)));
    // The erosion's change, carried from the surface's grid to the heightmap's (erosion.h).
    if (!hf_raw_.h.empty()) AddErosionChange(hf_raw_, hf_, &*heightmap_);
  }
  return *heightmap_;
}

Result<Heightmap> TerrainRun::EncodeHeightmapFiles() const {
  return EncodeHeightmap(heightmap_field());
}

Result<std::string> TerrainRun::Export(const std::string& format) const {
  Result<TerrainOutput> kind = TerrainOutputOfFormat(format);
  if (!kind.ok()) return kind.status();
  if (!grown_) return Status::Error("run", "nothing grown yet");
  switch (*kind) {
    case TerrainOutput::kGlb: {
      Result<gltf::Document> doc = Document();
      if (!doc.ok()) return doc.status();
      Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
      if (!glb.ok()) return glb.status();
      return std::string(glb->begin(), glb->end());
    }
    case TerrainOutput::kHeightmap: {
      Result<Heightmap> hm = EncodeHeightmapFiles();
      if (!hm.ok()) return hm.status();
      if (format == "sidecar") return hm->sidecar_json;
      return std::string(hm->png.begin(), hm->png.end());
    }
    case TerrainOutput::kContoursJson:
      return TerrainToJson(terrain_);
    case TerrainOutput::kGeoJson:
      return TerrainToGeoJson(terrain_);
    case TerrainOutput::kSvg:
      return TerrainToSvg(terrain_);
  }
  return Status::Error("format", "unknown format");
}

namespace {
nlohmann::json MeasuresJson(const SurfaceMeasures& m) {
  return {{"cells", m.cells},
          {"relief", m.relief},
          {"hypsometric_integral", m.hypsometric_integral},
          {"mean_slope_deg", m.mean_slope_deg},
          {"slope_p90_deg", m.slope_p90_deg},
          {"slope_share", m.slope_share},
          {"peaks", m.peaks}};
}
}  // namespace

Result<DemComparison> CompareWithDem(const TerrainState& state,
                                     const std::vector<unsigned char>& dem_png,
                                     const std::string& dem_sidecar, const Budget& budget) {
  Result<Heightfield> dem = ReadHeightmap(dem_png, dem_sidecar, "dem");
  if (!dem.ok()) return dem.status();
  // The peak search over the DEM's cells, refused before anything grows (a small cell under a
  // large d made it hang).
  NIWA_RETURN_IF_ERROR(CheckCompareCost(*dem, state.params.Get(TerrainParam::kD), budget));
  Result<Ring> seed = StateSeed(state);
  if (!seed.ok()) return seed.status();
  const TerrainGrowLimits limits = TerrainLimits(state.params, budget);
  Result<Terrain> t = Grow(*seed, state.params, state.seed, &limits);
  if (!t.ok()) return t.status();
  DemComparison out;
  out.truncated_by = t->counts.truncated_by;
  // The heightfield on the DEM's grid, refused before it is built.
  const GridSize grid = {static_cast<double>(dem->width), static_cast<double>(dem->height)};
  NIWA_RETURN_IF_ERROR(
      CheckEstimate(EstimateTerrainGrown(*t, limits) + EstimateHeightfield(*t, grid), budget,
                    "use a smaller DEM"));
  const Comparison c = CompareTerrain(*dem, *t);
  if (c.real.cells == 0)
    return Status::Error("dem", "no DEM cell lies inside the seed contour; must cover it");
  nlohmann::json j;
  j["method"] = MethodName(state.params.GetInt(TerrainParam::kMethod));
  j["seed"] = state.seed;
  j["h0"] = t->h0;
  j["dh"] = t->dh;
  j["d"] = t->d;
  j["url"] = EncodeTerrainHash(state);
  j["real"] = MeasuresJson(c.real);
  j["grown"] = MeasuresJson(c.grown);
  nlohmann::json levels = nlohmann::json::array();
  for (const LevelOverlap& l : c.levels)
    levels.push_back({{"level", l.level},
                      {"elevation", l.elevation},
                      {"real_cells", l.real_cells},
                      {"grown_cells", l.grown_cells},
                      {"iou", l.iou}});
  j["levels"] = levels;
  j["mean_iou"] = c.mean_iou;
  j["slope_share_l1"] = c.slope_share_l1;
  out.json = j.dump();
  return out;
}

void TerrainRun::FillSurfaceBuffers(SurfaceBuffers* out) const {
  BuildSurfaceBuffers(terrain_, hf_, out);
}

}  // namespace niwa::terrain

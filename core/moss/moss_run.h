// The moss study's run (Nomura 2010 §3.3, §3.7; spec §1.1, §1.5): a run::StudyRun that advances
// day by day on a built-in scene: the photon pass through the land and the mosses, the gather, the
// soil of every cell from the day's weather (eqs 3.2-3.16, m/M from the mosses near it), then the
// mosses in the thesis's order (germination, growth and death, gemmae, spores), the landing of new
// seeds on faces and on mosses, the contest for occupied places, immigration and the caps; with
// progress and cancel, and its estimate refused up front over the budget; the stats time the stages
// (ms_* fields, the only bytes that differ between runs); its outputs: the .glb of the land's map
// and the tufts (moss_gltf.h), the mosses and cells as JSON. Does not: load a mesh file, read a
// weather file, or spread the sun over the day's arc (sun_path 1 is refused by photons.h).
#pragma once

#include <array>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "geom/radius_grid.h"
#include "moss/fitness.h"
#include "moss/life_cycle.h"
#include "moss/moss_gltf.h"
#include "moss/moss_state.h"
#include "moss/photons.h"
#include "moss/soil.h"
#include "moss/soil_cells.h"
#include "moss/weather.h"
#include "random/pcg32.h"
#include "run/study_run.h"

namespace niwa::moss {

// A living moss: its centre (on a face, or s from the moss it rests on), the normal of what it
// grows on, its soil cell (a resting moss: its supporter's), species, birth day and growth.
struct MossPlant {
  glm::dvec3 pos{0}, normal{0, 1, 0};
  uint32_t cell = 0;
  Species species = Species::kGingoke;
  int birth_day = 0;
  MossGrowth growth;
  double G_max = 0;  // the running maximum of G_moss (gemmae, spec §4.20)
  bool on_moss = false;
  bool growing = false;  // today's D > 0
  double S = 0;          // its light on its last day of growth [W/m²] (with
                         // light_smoothing_days: its exponential mean)
  bool lit = false;      // S holds a day's light (the mean's start)
  // The mosses within interior_radius·s of it, itself included (the mats' count, §3.8), at the
  // last day's end; kept while no moss near it is born or dies. -1: not counted yet.
  int mat_count = -1;
};

// A waiting seed (a gemma or a spore) where it landed.
struct MossSeed {
  glm::dvec3 pos{0}, normal{0, 1, 0};
  uint32_t cell = 0;
  Species species = Species::kGingoke;
  SeedKind kind = SeedKind::kGemma;
  int birth_day = 0;
  bool on_moss = false;
};

// Why a seed left the pool without a moss, or never entered it.
enum class SeedLoss : int { kFellOff, kBackFace, kLostContest, kExpired, kCap, kCount };

// One grown day's record (the --csv rows), taken at the day's end.
struct MossDayRecord {
  int day = 0;
  int seeds = 0;               // waiting
  int births = 0, deaths = 0;  // that day (deaths: declined and lost contests)
  int64_t photons_stored = 0;  // that day's photon map, every depth
  // Area-weighted mean S, T_s, rh_s, theta per geology; NaN for a geology without cells.
  std::array<std::array<double, 4>, kGeologyCount> soil{};
};

// Everything a day changes (copied at the start of an Advance, so a cancel restores it).
struct MossWorld {
  int day = 0;
  std::vector<MossPlant> mosses;
  std::vector<MossSeed> seeds;
  std::vector<Bucket> buckets;                        // per cell
  std::vector<double> S, T_s, rh_s, theta, m_over_M;  // per cell, the last day's
  std::vector<double> S_mean;  // per cell, light_smoothing_days' exponential mean of S
  // Per cell: the living mosses within r_CH of its centroid (eq 3.5's m), kept as mosses are born
  // and die (they never move); empty until the first day counts them.
  std::vector<int> m_near;
  Pcg32 photon_rng, growth_rng, rain_rng, place_rng;
  int64_t births = 0, deaths_declined = 0, deaths_contest = 0;
  std::array<int64_t, 2> seeds_made{};  // by SeedKind
  int64_t immigrants = 0;
  // Photons the canopy's leaves intercepted and, of them, absorbed, over every day (SetCanopy).
  int64_t canopy_intercepted = 0, canopy_absorbed = 0;
  std::array<int64_t, static_cast<int>(SeedLoss::kCount)> seeds_lost{};
  std::vector<std::array<int, kSpeciesCount>> population;  // day 0 .. day
  int emitted_sun = 0, emitted_sky = 0;                    // the last day's
  std::vector<int64_t> stored_by_depth;                    // the last day's
  std::vector<int64_t> stored_by_depth_total;              // over every day
  std::vector<MossDayRecord> days;                         // day 1 .. day
  // With RecordEvery(K): the stats' breakdown (MossRun::Breakdown, "day" first) at the end of
  // every K-th day and of the run's last day, as JSON text.
  std::vector<std::string> every_rows;
};

// What RunEstimate counts a unit of the work at, in seconds. The defaults are the study's own
// provisional upper bounds (no terms for the density of the land under the gather's disc); a
// composed run passes its measured figures (compose/garden_moss.h GardenMossCosts). "Within
// r_gather" is counted from the land's mean density: cells (or a day's photons) × π r² / area.
struct MossCosts {
  double cell_build = 2e-5;  // a cell built (its split, soil depth ray, BVH, indexes)
  double cell_list = 0;      // and each cell within r_gather of it (its spread lists; at most 96)
  double photon = 2e-6;      // a photon's path through the land (and the canopy)
  double photon_cell = 0;    // a photon and a cell within r_gather of it (the soil's spread)
  double cell_day = 2e-6;    // a cell's day: its gather's share, m/M and the soil
  double moss_day = 4e-6;    // a moss or seed's day, at the caps (max_mosses + seed_cap)
  double moss_photon = 0;    // a moss or seed and a photon within r_gather of it (its gather)
};

class MossRun : public run::StudyRun {
 public:
  // Builds the scene and its soil cells, places n_init mosses (day 0) and checks the estimate of
  // the whole run against the budget first. Errors name state fields ("scene", "days", a row
  // such as "sun_path") or the budget's limit.
  static Result<MossRun> Start(const MossState& state, const Budget& budget);
  // The same on a scene made by the caller (a loaded mesh through soil_cells.h SceneFromMesh):
  // the state's scene is not read; `mesh_name` (the file's name) goes into the stats beside
  // "scene": "mesh" (a mesh is not part of the link). With `mesh_name` "" the scene is the land
  // of the state's scene, tree or terrain, grown by the composition tier (compose/moss_land.h):
  // the stats and the link say the state's scene and its land fields. Errors as Start's, and
  // "mesh" for a scene without triangles. (Start refuses the scenes tree and terrain, naming
  // "scene": core/moss cannot grow them.)
  // `costs`: what the estimates count a unit of work at (a composed run's measured figures).
  static Result<MossRun> StartOnScene(const MossState& state, MossScene scene, const Budget& budget,
                                      const std::string& mesh_name,
                                      const MossCosts& costs = MossCosts{});
  // Daily weather replacing the table's climate from day 1 (before any day is grown): day d reads
  // row (d − 1) mod rows; a row's N also sets the sun's beam S_sun = I_beam·N/24 of that day's
  // photons. `name` (the file's name) goes into the stats as "weather" (not part of the link).
  // Errors name "weather".
  Status UseWeather(std::vector<WeatherDay> days, const std::string& name);
  // Records the stats' breakdown (mosses by species, region, orientation and irradiance band, on
  // mosses and coverage; seeds waiting, made and lost; births and deaths by cause so far; the
  // day's photons by depth; mean S, T_s, rh_s, theta per geology) at the end of every `every`-th
  // day and of the last day (spec §6's `--every K`); StatsJson then adds "every" and
  // "every_days" (the rows). 0: none (the default; the stats keep their bytes). Before the first
  // day only; the error names "stats_every" (a whole number in [0, 3650]).
  Status RecordEvery(double every);
  // Leaves the study does not grow shading the next days' photons (canopy.h; the garden's tree
  // crowns, handed in again each garden year); empty: none. The land and its cells are unchanged.
  void SetCanopy(std::vector<CanopySphere> spheres);
  const CanopyShade* canopy() const { return light_.canopy.get(); }
  // Grows the days up to min(day, the state's days) (Advance grows them all): a composed run
  // grows its days in parts between other studies' years. A cancel restores the world as it was.
  Status AdvanceTo(int day, const run::Observer& observer);
  // What the run of `state` on `cells` cells of a land of `area_m2` (0: unknown, no density
  // terms) needs, at `costs` (the study's provisional upper bounds by default).
  static Estimate RunEstimate(const MossState& state, std::size_t cells, double area_m2 = 0,
                              const MossCosts& costs = MossCosts{});
  // The same for this run (its state, cells, land area and costs).
  Estimate RunEstimate() const;
  const MossCosts& costs() const { return costs_; }
  double land_area() const { return land_area_; }  // m², the cells' sum

  const char* study() const override { return "moss"; }
  const char* unit() const override { return "days"; }
  int done() const override { return world_.day; }
  int target() const override { return state_.days; }
  Status Advance(const run::Observer& observer) override;
  std::vector<run::Part> Parts() const override;
  Result<gltf::Document> Document() const override;
  std::string StatsJson() const override;
  std::string Hash(const std::string& prefix) const override;
  // format "glb", "json", "csv", "svg" (the photons), "rays" (the next day's rays,
  // geom/ray_dump.h): what writing it needs now, with what the run holds (cells, photons).
  Result<Estimate> ExportEstimate(const std::string& format) const override;
  // The same with the mosses at their cap (max_mosses), and the days' time added, for a refusal
  // before the days are grown.
  Result<Estimate> PlannedExportEstimate(const std::string& format) const;
  // The .glb's document: the land with `map` and the tufts, merged or instanced (moss_gltf.h).
  // Document() is the coverage map with merged tufts.
  Result<gltf::Document> MapDocument(MossMap map, bool instancing) const;
  // Each cell's value of `map` (the last day's) and where it falls on the map's ramp (in [0, 1]).
  std::vector<double> MapValues(MossMap map, std::vector<double>* ramp) const;
  // A tuft for every living moss, in the mosses' order: s·(0.5 + 0.5·min(1, G_moss/spore_G)) tall
  // (half size when new, full at spore-making growth), turned about its normal by a draw of its
  // own display stream (never the simulation's).
  std::vector<TuftPlace> Tufts() const;

  // One row a grown day: day, mosses per species, seeds waiting, births, deaths, photons stored,
  // then mean S, T_s, rh_s, theta of each geology (empty for a geology without cells).
  std::string DaysCsv() const;
  // Every living moss (species, pos, normal, birth_day, G_moss, on_moss) and every soil cell (its
  // geology, centre, normal and the last day's S, T_s, rh_s, theta, m_over_M) as one JSON object.
  std::string MossesJson() const;
  // The next day's photon map (traced through the land and today's mosses, without advancing):
  // photons emitted, stored and by depth, power, and per region the stored photons (first hits,
  // bounced) and the cells' mean gathered S.
  std::string PhotonDayJson() const;
  // The next day's photon map (traced through the land and today's mosses, without advancing);
  // with `rays`, every ray it cast at the land and the hit (photons.h TracePhotons).
  PhotonMap NextDayPhotons(std::vector<geom::CastRay>* rays = nullptr) const;
  // The stored photons of the next day's map (`next_day`) or of the last grown day's, seen from
  // the front as in figs 4.1/4.2 (moss_svg.h).
  std::string PhotonsSvg(bool next_day) const;
  // Where a seed starting at `start` would land among today's mosses (spec §1.5.6 and the mat
  // rule: it rests only on mosses inside a mat); false with the loss when it is dropped.
  bool LandSeed(const glm::dvec3& start, MossSeed* seed, SeedLoss* loss) const;
  const MossState& state() const { return state_; }
  const MossWorld& world() const { return world_; }
  const SoilCells& cells() const { return cells_; }
  const PhotonMap& photon_map() const { return map_; }

 private:
  MossRun() = default;
  // The land's name for a picture: the mesh file, "tree:<preset>", "terrain:<preset>" or the scene.
  std::string LandName() const;
  // The stats' fields of a tree or terrain land (tree, tree_years; terrain, terrain_seed).
  void AddLandFields(nlohmann::ordered_json* j) const;
  // The world's breakdown now: {mosses, seeds, births, deaths, photons (the day's), soil (the
  // day's means per geology)}, as StatsJson prints them for the last day.
  nlohmann::ordered_json Breakdown() const;
  void Day();                                  // one day, world_.day + 1
  double WindowScore(int age, SeedKind kind);  // SeedWindowScore(age, kind, rules_), cached
  // Where a seed starting at `start` comes to rest (spec §1.5.6); false with the loss otherwise.
  // `centres` are the mosses a seed may rest on (those inside a mat), owner[k] their index.
  // `mats`, when given, holds those centres in buckets (life_cycle.h MatBuckets): the same
  // answers as the passes over all of them.
  bool Land(const glm::dvec3& start, const std::vector<glm::dvec3>& centres,
            const std::vector<uint32_t>& owner, const MatBuckets* mats, MossSeed* seed,
            SeedLoss* loss) const;
  void AddSeed(const glm::dvec3& start, Species species, SeedKind kind,
               const std::vector<glm::dvec3>& centres, const std::vector<uint32_t>& owner,
               const MatBuckets* mats);
  void PlaceAtRandom(Species species, bool as_seed);
  Result<Estimate> ExportEstimateAt(const std::string& format, double mosses) const;

  MossState state_;
  std::string mesh_name_;            // the loaded mesh's file name; "" on a built-in scene
  std::vector<WeatherDay> weather_;  // a weather file's days; empty: the table's climate
  std::string weather_name_;
  int stats_every_ = 0;  // RecordEvery's K; 0: no rows
  Budget budget_;
  MossCosts costs_;       // what the estimates count the work at
  double land_area_ = 0;  // m²: the cells' areas summed
  SoilCells cells_;
  std::vector<double> cumulative_area_;
  PhotonLight light_;
  SoilConstants constants_{};
  LifeRules rules_{};
  MossWorld world_;
  PhotonMap map_;  // scratch: the last day's photons
  // Milliseconds over every Advance (not restored by a cancel): tracing; the indexes and the
  // cells' S and m/M; the soil; the life cycle (its own gathers included).
  double ms_photons_ = 0, ms_gather_ = 0, ms_soil_ = 0, ms_growth_ = 0;
  MossOccluders occluders_;  // scratch
  // Each cell's last soil balance and the weather it was worked out under (soil.h SoilMemo): a
  // cache keyed by its inputs' bits, so a cancel need not restore it.
  std::vector<SoilMemo> soil_memo_;
  Weather soil_memo_weather_{};
  // The fitness factors by their inputs' bits (fitness.h FitnessMemo; a cache, like soil_memo_).
  FitnessMemo fitness_memo_;
  // SeedWindowScore by kind and whole age in days (L = day − birth day), filled as ages come (a
  // cache of the same bits; NaN: not yet worked out).
  std::array<std::vector<double>, 2> window_score_;
  // Built once (the cells do not move): each day's photons and mosses are spread onto the cells
  // near them, work in photons and mosses rather than a query per cell (spec §4.6, eq 3.5): the
  // photons through each cell's candidate lists (photons.h), the mosses through the centroids in
  // buckets of r_CH.
  std::shared_ptr<const SoilPhotonSpread> soil_spread_;
  std::shared_ptr<const geom::RadiusGrid> cells_by_ch_;
};

// Every built-in scene: name, description, triangles, soil cells by geology, regions.
std::string MossScenesJson();

}  // namespace niwa::moss

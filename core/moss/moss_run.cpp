// The moss study's run: the daily loop of §3.7 over a built-in scene (moss_run.h).
#include "moss/moss_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "geom/closest_point.h"
#include "geom/mesh_metrics.h"
#include "geom/point_index.h"
#include "geom/ray_cast.h"
#include "math/det_math.h"
#include "moss/moss_svg.h"
#include "params/param_text.h"

namespace niwa::moss {
namespace {

// The run's RNG streams (spec §4.28: one per subsystem, so the photon count never reshuffles the
// growth draws).
constexpr uint64_t kPhotonStream = 1, kGrowthStream = 2, kRainStream = 3, kPlaceStream = 4;
// The tufts' turns about their normals (display only: never read by the simulation).
constexpr uint64_t kDisplayStream = 5;

// Calibrated upper bounds of the memory (bytes per item); the seconds are MossCosts' (moss_run.h:
// its defaults are the study's provisional figures: 30 days of `thesis` at 8,192 photons and ~100
// mosses took 1.2 s natively, about 40 ms a day; a cell's build, soil depth ray, BVH and lists,
// measured on rocks 10-11 µs, counted at 20 µs).
// A cell's bytes at the run's peak (building the cells: the split, mesh, BVH, values, bucket; the
// spread lists, <= 96 x 4 B): measured on rocks (2026-12-06, native, CPU time and peak RSS of niwa
// moss grow --days 0): 1,100 B a cell at 105 k and 412 k cells, 1,375 B at 1.64 M (vectors' growth
// slack). 800 B before.
constexpr double kBytesPerCell = 1500;
constexpr double kBytesPerPhoton = 3 * 64.0;  // stored photons (~2 a path) and the index
constexpr double kBytesPerMoss = 200;         // moss or seed, indices

using MossClock = std::chrono::steady_clock;
double MossMs(MossClock::time_point a, MossClock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// The irradiance bands of the stats (spec §3: the peak is expected in 10-60 W/m², none above 120).
const char* IrradianceBand(double S) {
  return S <= 0.0     ? "0"
         : S <= 10.0  ? "0-10"
         : S <= 30.0  ? "10-30"
         : S <= 60.0  ? "30-60"
         : S <= 120.0 ? "60-120"
                      : ">120";
}

const char* SeedLossName(SeedLoss loss) {
  switch (loss) {
    case SeedLoss::kFellOff:
      return "fell_off";
    case SeedLoss::kBackFace:
      return "back_face";
    case SeedLoss::kLostContest:
      return "lost_contest";
    case SeedLoss::kExpired:
      return "expired";
    default:
      return "cap";
  }
}

const char* OrientationName(const glm::dvec3& n) {
  return n.y > 0.5 ? "up" : (n.y < -0.5 ? "down" : "vertical");
}

// Buckets for a day's grid over the mosses: about 64 a moss (mats are dense, so a coarser grid
// puts tens of mosses in a bucket), at least 4,096, at most RadiusGrid's 2^21 (an empty
// bucket costs its start entry, built every day).
std::size_t MossGridBuckets(std::size_t mosses) {
  return std::min<std::size_t>(std::size_t{1} << 21, std::max<std::size_t>(4096, 64 * mosses));
}

std::vector<glm::dvec3> CentresOf(const std::vector<MossPlant>& mosses) {
  std::vector<glm::dvec3> centres;
  centres.reserve(mosses.size());
  for (const MossPlant& m : mosses) centres.push_back(m.pos);
  return centres;
}

}  // namespace

Estimate MossRun::RunEstimate(const MossState& state, std::size_t cells, double area_m2,
                              const MossCosts& costs) {
  const double days = state.days;
  const double photons = state.params.Get(MossParam::kPhotons);
  const double mosses =
      state.params.Get(MossParam::kMaxMosses) + state.params.Get(MossParam::kSeedCap);
  const double n_cells = static_cast<double>(cells);
  // The share of the land under one gather's disc (π r², at the land's mean density), at most all.
  const double r = state.params.Get(MossParam::kRGather);
  const double share = area_m2 > 0 ? std::min(1.0, det::kPi * r * r / area_m2) : 0.0;
  const double cells_near = n_cells * share, photons_near = photons * share;
  const double listed =
      std::min(cells_near, static_cast<double>(SoilPhotonSpread::kMaxCandidatesPerCell));
  Estimate e;
  e.seconds =
      n_cells * (costs.cell_build + listed * costs.cell_list) +
      days * (photons * (costs.photon + cells_near * costs.photon_cell) + n_cells * costs.cell_day +
              mosses * (costs.moss_day + photons_near * costs.moss_photon));
  e.memory_bytes = n_cells * kBytesPerCell + photons * kBytesPerPhoton + mosses * kBytesPerMoss;
  e.what = "growing " + FormatCount(days) + " days of " + FormatCount(photons) + " photons on " +
           FormatCount(n_cells) + " soil cells";
  return e;
}

Estimate MossRun::RunEstimate() const {
  return RunEstimate(state_, cells_.size(), land_area_, costs_);
}

Result<MossRun> MossRun::Start(const MossState& state, const Budget& budget) {
  if (state.scene == kTreeLand || state.scene == kTerrainLand)
    return Status::Error("scene", "'" + state.scene +
                                      "' is another study's land; it is grown through the "
                                      "composition tier (compose/moss_land.h)");
  // The rocks (up to 6.5 M triangles): their estimate before the scene is built (the rocks' own
  // triangles are the fewest cells).
  if (state.scene == "rocks" && state.rock_triangles >= kRockTrianglesMin &&
      state.rock_triangles <= kRockTrianglesMax)
    NIWA_RETURN_IF_ERROR(CheckEstimate(RunEstimate(state, RockTrianglesBuilt(state.rock_triangles)),
                                       budget,
                                       "lower days, photons, max_mosses or rock_triangles"));
  Result<MossScene> scene = BuildScene(state.scene, state.rock_triangles);
  if (!scene.ok()) return scene.status();
  return StartOnScene(state, std::move(*scene), budget, "");
}

Result<MossRun> MossRun::StartOnScene(const MossState& state, MossScene scene_value,
                                      const Budget& budget, const std::string& mesh_name,
                                      const MossCosts& costs) {
  NIWA_RETURN_IF_ERROR(CheckMossParams(state.params));
  if (scene_value.mesh.triangle_count() == 0)
    return Status::Error("mesh", "has no triangles; must have at least one");
  const MossScene* scene = &scene_value;
  MossRun run;
  run.state_ = state;
  run.mesh_name_ = mesh_name;
  run.budget_ = budget;
  run.costs_ = costs;
  SoilCellOptions options;
  options.soil_edge = state.params.Get(MossParam::kSoilEdge);
  options.h_max = state.params.Get(MossParam::kHMax);
  options.h_wall = state.params.Get(MossParam::kHWall);
  options.sky_view =
      state.params.GetInt(MossParam::kLongwave) == static_cast<int>(Longwave::kSkyView);
  // The estimate before the cells are built: the scene's triangles are the fewest cells.
  const double area = geom::SurfaceArea(scene->mesh);
  NIWA_RETURN_IF_ERROR(CheckEstimate(RunEstimate(state, scene->mesh.triangle_count(), area, costs),
                                     budget, "lower days, photons or max_mosses"));
  Result<SoilCells> cells = MakeSoilCells(*scene, options);
  if (!cells.ok()) return cells.status();
  run.cells_ = std::move(*cells);
  run.land_area_ = 0;
  for (double a : run.cells_.area) run.land_area_ += a;
  NIWA_RETURN_IF_ERROR(
      CheckEstimate(run.RunEstimate(), budget, "lower days, photons or max_mosses"));
  Result<PhotonLight> light = PhotonLightOf(state.params, run.cells_);
  if (!light.ok()) return light.status();
  run.light_ = *light;
  run.soil_spread_ = std::make_shared<const SoilPhotonSpread>(run.cells_, run.light_.r_gather);
  run.cells_by_ch_ = std::make_shared<const geom::RadiusGrid>(run.cells_.centroid,
                                                              state.params.Get(MossParam::kRCH));
  run.constants_ = SoilConstantsOf(state.params);
  run.rules_ = LifeRulesOf(state.params);

  const std::size_t n = run.cells_.size();
  double total = 0;
  run.cumulative_area_.reserve(n);
  for (double a : run.cells_.area) run.cumulative_area_.push_back(total += a);
  MossWorld& w = run.world_;
  w.photon_rng = Pcg32(state.seed, kPhotonStream);
  w.growth_rng = Pcg32(state.seed, kGrowthStream);
  w.rain_rng = Pcg32(state.seed, kRainStream);
  w.place_rng = Pcg32(state.seed, kPlaceStream);
  const double O_start = state.params.Get(MossParam::kOStart);
  for (std::size_t i = 0; i < n; ++i)
    w.buckets.push_back(
        MakeBucket(run.cells_.h[i], GeologyLawOf(state.params, run.cells_.geology[i]), O_start));
  w.S.assign(n, 0.0);
  w.T_s.assign(n, 0.0);
  w.rh_s.assign(n, 0.0);
  w.theta.assign(n, 0.0);
  w.m_over_M.assign(n, 0.0);
  // Day 0: n_init mosses at random points, area-weighted, species uniform (spec §1.5.9).
  const int n_init = state.params.GetInt(MossParam::kNInit);
  const int max_mosses = state.params.GetInt(MossParam::kMaxMosses);
  for (int i = 0; i < n_init && static_cast<int>(w.mosses.size()) < max_mosses; ++i) {
    const Species species =
        static_cast<Species>(std::min(2, static_cast<int>(w.place_rng.Uniform() * 3)));
    run.PlaceAtRandom(species, false);
  }
  std::array<int, kSpeciesCount> pop{};
  for (const MossPlant& m : w.mosses) ++pop[static_cast<int>(m.species)];
  w.population.push_back(pop);
  return run;
}

void MossRun::PlaceAtRandom(Species species, bool as_seed) {
  MossWorld& w = world_;
  const double u = w.place_rng.Uniform() * cumulative_area_.back();
  const std::size_t cell =
      std::min<std::size_t>(cumulative_area_.size() - 1,
                            static_cast<std::size_t>(std::upper_bound(cumulative_area_.begin(),
                                                                      cumulative_area_.end(), u) -
                                                     cumulative_area_.begin()));
  // Uniform in the triangle (u1, u2 -> √ warp).
  const double r1 = std::sqrt(w.place_rng.Uniform()), r2 = w.place_rng.Uniform();
  const glm::dvec3 a(cells_.mesh.positions[3 * cell]), b(cells_.mesh.positions[3 * cell + 1]),
      c(cells_.mesh.positions[3 * cell + 2]);
  const glm::dvec3 p = (1 - r1) * a + (r1 * (1 - r2)) * b + (r1 * r2) * c;
  if (as_seed) {
    MossSeed seed;
    seed.pos = p;
    seed.normal = cells_.normal[cell];
    seed.cell = static_cast<uint32_t>(cell);
    seed.species = species;
    seed.kind = SeedKind::kSpore;
    seed.birth_day = w.day;
    if (static_cast<int>(w.seeds.size()) >= state_.params.GetInt(MossParam::kSeedCap)) {
      ++w.seeds_lost[static_cast<int>(SeedLoss::kCap)];
    } else {
      w.seeds.push_back(seed);
    }
    return;
  }
  MossPlant moss;
  moss.pos = p;
  moss.normal = cells_.normal[cell];
  moss.cell = static_cast<uint32_t>(cell);
  moss.species = species;
  moss.birth_day = w.day;
  w.mosses.push_back(moss);
}

bool MossRun::Land(const glm::dvec3& start, const std::vector<glm::dvec3>& centres,
                   const std::vector<uint32_t>& owner, const MatBuckets* mats, MossSeed* seed,
                   SeedLoss* loss) const {
  const double s = rules_.s;
  // On the front side of a face, or behind it (inside a solid)?
  auto behind_a_face = [&](const glm::dvec3& p) {
    const geom::ClosestHit near =
        geom::ClosestPoint(cells_.mesh, cells_.bvh, glm::vec3(p), static_cast<float>(0.5 * s));
    return near.found && glm::dot(p - glm::dvec3(near.point), cells_.normal[near.triangle]) < 0.0;
  };
  auto rest_on = [&](const glm::dvec3& at, uint32_t moss) {
    if (behind_a_face(at)) return *loss = SeedLoss::kBackFace, false;
    const glm::dvec3 d = at - centres[moss];
    const double len = glm::length(d);
    seed->pos = at;
    seed->normal = len > 0 ? d / len : glm::dvec3(0, 1, 0);
    seed->cell = world_.mosses[owner[moss]].cell;  // spec §4.25: the supporter's cell
    seed->on_moss = true;
    return true;
  };
  // 1. Adjacent to a face: within s/2, snapped to the closest point; behind it: dropped.
  const geom::ClosestHit near =
      geom::ClosestPoint(cells_.mesh, cells_.bvh, glm::vec3(start), static_cast<float>(0.5 * s));
  if (near.found) {
    const glm::dvec3 n = cells_.normal[near.triangle];
    if (glm::dot(start - glm::dvec3(near.point), n) < 0.0)
      return *loss = SeedLoss::kBackFace, false;
    seed->pos = glm::dvec3(near.point);
    seed->normal = n;
    seed->cell = near.triangle;
    seed->on_moss = false;
    return true;
  }
  // 2. Touching a moss: rests on it.
  const MossRest rest = mats ? mats->Rest(start, rules_) : RestOnMoss(start, centres, rules_);
  if (rest.touches) return rest_on(rest.position, rest.moss);
  // 3. Falling along −y onto the highest of a face and a moss below.
  const geom::RayHit hit =
      geom::FirstHit(cells_.mesh, cells_.bvh, glm::vec3(start), glm::vec3(0, -1, 0),
                     std::numeric_limits<float>::infinity());
  const MossRest fall = mats ? mats->Fall(start, rules_) : FallOntoMosses(start, centres, rules_);
  if (fall.touches && (!hit.hit || fall.position.y >= static_cast<double>(hit.point.y)))
    return rest_on(fall.position, fall.moss);
  if (!hit.hit) return *loss = SeedLoss::kFellOff, false;
  const glm::dvec3 n = cells_.normal[hit.triangle];
  if (n.y <= 0.0) return *loss = SeedLoss::kBackFace, false;  // its back, or edge-on
  seed->pos = glm::dvec3(hit.point);
  seed->normal = n;
  seed->cell = hit.triangle;
  seed->on_moss = false;
  return true;
}

bool MossRun::LandSeed(const glm::dvec3& start, MossSeed* seed, SeedLoss* loss) const {
  const std::vector<glm::dvec3> centres = CentresOf(world_.mosses);
  Result<geom::PointIndex> index = geom::PointIndex::Build(centres);
  std::vector<glm::dvec3> dense;
  std::vector<uint32_t> owner;
  for (std::size_t j = 0; index.ok() && j < centres.size(); ++j)
    if (static_cast<int>(
            index->WithinRadius(centres[j], rules_.interior_radius * rules_.s).size()) -
            1 >=
        rules_.interior_count) {
      dense.push_back(centres[j]);
      owner.push_back(static_cast<uint32_t>(j));
    }
  return Land(start, dense, owner, nullptr, seed, loss);
}

void MossRun::AddSeed(const glm::dvec3& start, Species species, SeedKind kind,
                      const std::vector<glm::dvec3>& centres, const std::vector<uint32_t>& owner,
                      const MatBuckets* mats) {
  MossWorld& w = world_;
  ++w.seeds_made[static_cast<int>(kind)];
  MossSeed seed;
  SeedLoss loss = SeedLoss::kFellOff;
  if (!Land(start, centres, owner, mats, &seed, &loss)) {
    ++w.seeds_lost[static_cast<int>(loss)];
    return;
  }
  if (static_cast<int>(w.seeds.size()) >= state_.params.GetInt(MossParam::kSeedCap)) {
    ++w.seeds_lost[static_cast<int>(SeedLoss::kCap)];
    return;
  }
  seed.species = species;
  seed.kind = kind;
  seed.birth_day = w.day;
  w.seeds.push_back(seed);
}

double MossRun::WindowScore(int age, SeedKind kind) {
  std::vector<double>& table = window_score_[static_cast<int>(kind)];
  const std::size_t i = static_cast<std::size_t>(age);
  if (i >= table.size()) table.resize(i + 1, std::numeric_limits<double>::quiet_NaN());
  if (std::isnan(table[i])) table[i] = SeedWindowScore(static_cast<double>(age), kind, rules_);
  return table[i];
}

void MossRun::Day() {
  MossWorld& w = world_;
  const MossParams& p = state_.params;
  ++w.day;
  const int day = w.day;
  const GForm g_form = static_cast<GForm>(p.GetInt(MossParam::kGForm));
  const double s = rules_.s;

  // The day's weather: the table's climate and rain, or a weather file's day over them.
  Weather weather = ClimateOf(p);
  const double P_year = p.Get(MossParam::kPYear);
  const int P_days = p.GetInt(MossParam::kPDays);
  if (p.GetInt(MossParam::kRainRandom) != 0) {
    weather.P = (P_days > 0 && w.rain_rng.Bernoulli(P_days / 365.0)) ? P_year / P_days : 0.0;
  } else {
    weather.P = EvenRainOfDay(day, P_year, P_days);
  }
  PhotonLight light = light_;
  if (!weather_.empty()) {
    weather = WeatherOfDay(weather, weather_[static_cast<std::size_t>(day - 1) % weather_.size()]);
    light.S_sun = p.Get(MossParam::kIBeam) * weather.N / 24.0;
  }

  const MossClock::time_point t0 = MossClock::now();
  // 1. The photon map through the land and the mosses (1 cm spheres), and its gather.
  std::vector<glm::dvec3> centres = CentresOf(w.mosses);
  occluders_.Build(centres, 0.5 * s);
  TracePhotons(cells_, occluders_, light, p.GetInt(MossParam::kPhotons), &w.photon_rng, &map_);
  w.emitted_sun = map_.emitted_sun;
  w.emitted_sky = map_.emitted_sky;
  w.canopy_intercepted += map_.canopy_intercepted;
  w.canopy_absorbed += map_.canopy_absorbed;
  w.stored_by_depth = map_.stored_by_depth;
  if (w.stored_by_depth_total.size() < map_.stored_by_depth.size())
    w.stored_by_depth_total.resize(map_.stored_by_depth.size(), 0);
  for (std::size_t d = 0; d < map_.stored_by_depth.size(); ++d)
    w.stored_by_depth_total[d] += map_.stored_by_depth[d];
  const MossClock::time_point t1 = MossClock::now();
  Result<PhotonGather> gather = PhotonGather::Build(map_, light_.r_gather);
  if (!gather.ok()) return;  // finite positions only: cannot happen

  // 2. The soil of every cell (spec §1.4 order), m/M from the mosses within r_CH (eq 3.5).
  const bool rain_day = weather.P > 0.0;
  const double M = p.Get(MossParam::kMCH);
  // S of each cell: the soil photons within r_gather on faces turned its way (PhotonGather::Soil's
  // sum, spread from the photons, in photon order); m of eq 3.5: the mosses within r_CH.
  std::fill(w.S.begin(), w.S.end(), 0.0);
  soil_spread_->Spread(cells_, map_, &w.S);
  const double gather_area = det::kPi * light_.r_gather * light_.r_gather;
  // m: counted once over every moss, then kept by the births and deaths at the day's end (the same
  // radius query, so the same counts).
  if (w.m_near.size() != cells_.size()) {
    w.m_near.assign(cells_.size(), 0);
    for (const glm::dvec3& c : centres)
      cells_by_ch_->ForEachWithin(c, [&](uint32_t i, double) { ++w.m_near[i]; });
  }
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    w.S[i] /= gather_area;
    w.m_over_M[i] = std::min(1.0, static_cast<double>(w.m_near[i]) / M);
  }
  // light_smoothing_days N > 0 (spec §1.3's option): each cell's S is the exponential mean
  // S̄_d = S̄_{d−1} + k·(S_d − S̄_{d−1}), k = 1 − e^(−1/N), S̄_1 = S_1 (choice 31).
  const double smoothing = p.Get(MossParam::kLightSmoothingDays);
  const double k_smooth = smoothing > 0 ? 1.0 - det::Exp(-1.0 / smoothing) : 1.0;
  if (smoothing > 0) {
    if (w.S_mean.size() != cells_.size()) {
      w.S_mean = w.S;
    } else {
      for (std::size_t i = 0; i < cells_.size(); ++i) {
        w.S_mean[i] += k_smooth * (w.S[i] - w.S_mean[i]);
        w.S[i] = w.S_mean[i];
      }
    }
  }
  const MossClock::time_point t2 = MossClock::now();
  // The day's weather terms and the geologies' laws once, not once a cell (the same values); a
  // cell whose S, m/M and θ are yesterday's bits under yesterday's weather keeps yesterday's
  // balance (soil.h SoilMemo: the same bits, without the arithmetic).
  const SoilWeatherTerms weather_terms = SoilWeatherTermsOf(constants_, weather);
  std::array<GeologyLaw, kGeologyCount> laws;
  for (int g = 0; g < kGeologyCount; ++g) laws[g] = GeologyLawOf(p, static_cast<Geology>(g));
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; };
  if (soil_memo_.size() != cells_.size() || !same(weather.T, soil_memo_weather_.T) ||
      !same(weather.rh, soil_memo_weather_.rh) || !same(weather.U, soil_memo_weather_.U) ||
      !same(weather.N, soil_memo_weather_.N) || !same(weather.N_0, soil_memo_weather_.N_0)) {
    soil_memo_.assign(cells_.size(), SoilMemo{});
    soil_memo_weather_ = weather;
  }
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const SoilCellDay soil = AdvanceSoilDayKept(
        constants_, weather, weather_terms, laws[static_cast<int>(cells_.geology[i])], w.S[i],
        w.m_over_M[i], cells_.V_sky[i], &w.buckets[i], &soil_memo_[i]);
    w.T_s[i] = soil.T_s;
    w.rh_s[i] = soil.rh_s;
    w.theta[i] = soil.theta;
  }

  MossDayRecord record;
  record.day = day;
  const int64_t births_before = w.births, deaths_before = w.deaths_declined + w.deaths_contest;
  for (int64_t n : map_.stored_by_depth) record.photons_stored += n;
  {
    std::array<double, kGeologyCount> area{};
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      const int g = static_cast<int>(cells_.geology[i]);
      const double a = cells_.area[i];
      area[g] += a;
      record.soil[g][0] += a * w.S[i];
      record.soil[g][1] += a * w.T_s[i];
      record.soil[g][2] += a * w.rh_s[i];
      record.soil[g][3] += a * w.theta[i];
    }
    for (int g = 0; g < kGeologyCount; ++g)
      for (double& v : record.soil[g])
        v = area[g] > 0 ? v / area[g] : std::numeric_limits<double>::quiet_NaN();
  }

  const MossClock::time_point t3 = MossClock::now();
  // 3a. Germination (eq 3.24) of the seeds made before today, in pool order.
  const int max_mosses = p.GetInt(MossParam::kMaxMosses);
  // The species' rows once a day (SpeciesOf reads 13 rows), and the day's first mosses in buckets
  // of overlap·s for the contests (the same points and distances as a PointIndex radius query;
  // a contest does not depend on the order its occupants come in).
  std::array<SpeciesRanges, kSpeciesCount> species_of;
  for (int k = 0; k < kSpeciesCount; ++k) species_of[k] = SpeciesOf(p, static_cast<Species>(k));
  const geom::RadiusGrid index(centres, rules_.overlap * s, MossGridBuckets(centres.size()));
  const std::size_t old_count = w.mosses.size();
  std::vector<bool> alive(old_count, true);
  std::vector<MossSeed> waiting;
  waiting.reserve(
      w.seeds.capacity());  // the pool's room so far: today's new seeds seldom regrow it
  int living = static_cast<int>(old_count);
  for (const MossSeed& seed : w.seeds) {
    if (seed.birth_day >= day) {
      waiting.push_back(seed);
      continue;
    }
    const SpeciesRanges& species = species_of[static_cast<int>(seed.species)];
    const double L = day - seed.birth_day;
    // Outside its window (g(L) <= τ_b) a seed's fate is that of G = 0 for every G in [0, 1]
    // (SeedWindowScore): its light and fitness are not needed.
    // Nor is it when g_T·g_rh·g(L) <= τ_b: G = g_T·g_rh·g_S with g_S in [0, 1] is at most g_T·g_rh
    // (rounding is monotone), so G·g(L) <= τ_b whatever the light, the fate of G = 0.
    double G = 0.0;
    const double g_window = WindowScore(day - seed.birth_day, seed.kind);
    if (g_window > species.tau_b &&
        fitness_memo_.TemperatureHumidity(seed.species, species, w.T_s[seed.cell],
                                          w.rh_s[seed.cell], g_form) *
                g_window >
            species.tau_b) {
      const double S_seed = gather->Moss(seed.pos, seed.normal);
      G = fitness_memo_.G(seed.species, species, w.T_s[seed.cell], w.rh_s[seed.cell], S_seed,
                          g_form);
    }
    const SeedFate fate =
        SeedDayOfScore(G, g_window, L, seed.kind, species.tau_b, living >= max_mosses, rules_);
    if (fate == SeedFate::kWaits) {
      waiting.push_back(seed);
      continue;
    }
    if (fate == SeedFate::kExpires) {
      ++w.seeds_lost[static_cast<int>(SeedLoss::kExpired)];
      continue;
    }
    // The contest for an occupied place (spec §1.5.7): the day's first mosses and today's births.
    const double limit2 = (rules_.overlap * s) * (rules_.overlap * s);
    std::vector<std::size_t> occupants;
    std::vector<double> priorities;
    index.ForEachWithin(seed.pos, [&](uint32_t j, double d2) {
      if (d2 < limit2 && alive[j]) {
        occupants.push_back(j);
        priorities.push_back(PlacePriority(species_of[static_cast<int>(w.mosses[j].species)],
                                           w.mosses[j].growth.G_moss));
      }
    });
    for (std::size_t j = old_count; j < w.mosses.size(); ++j) {
      const glm::dvec3 d = w.mosses[j].pos - seed.pos;
      if (alive[j] && glm::dot(d, d) < limit2) {
        occupants.push_back(j);
        priorities.push_back(PlacePriority(species_of[static_cast<int>(w.mosses[j].species)], 0.0));
      }
    }
    if (!WinsPlace(PlacePriority(species, 0.0), priorities)) {
      ++w.seeds_lost[static_cast<int>(SeedLoss::kLostContest)];
      continue;
    }
    for (std::size_t j : occupants) {
      alive[j] = false;
      ++w.deaths_contest;
      --living;
    }
    MossPlant moss;
    moss.pos = seed.pos;
    moss.normal = seed.normal;
    moss.cell = seed.cell;
    moss.species = seed.species;
    moss.birth_day = day;
    moss.on_moss = seed.on_moss;
    w.mosses.push_back(moss);
    alive.push_back(true);
    ++living;
    ++w.births;
  }
  w.seeds.swap(waiting);

  // 3b. Growth and death (eqs 3.17-3.21) of the mosses born before today.
  for (std::size_t j = 0; j < old_count; ++j) {
    if (!alive[j]) continue;
    MossPlant& m = w.mosses[j];
    const SpeciesRanges& species = species_of[static_cast<int>(m.species)];
    double S_moss = gather->Moss(m.pos, m.normal);
    if (smoothing > 0 && m.lit) S_moss = m.S + k_smooth * (S_moss - m.S);  // its own mean
    const double G =
        fitness_memo_.G(m.species, species, w.T_s[m.cell], w.rh_s[m.cell], S_moss, g_form);
    const GrowthDay grown = AdvanceGrowth(species, G, &m.growth);
    m.lit = true;
    m.growing = grown.growing;
    m.S = S_moss;
    if (grown.dies) {
      alive[j] = false;
      ++w.deaths_declined;
    }
  }
  std::vector<MossPlant> next;
  next.reserve(w.mosses.size());
  std::vector<bool> was_old;
  std::vector<glm::dvec3> changed;  // where an old moss died or a new one lives on
  for (std::size_t j = 0; j < w.mosses.size(); ++j) {
    // The day's deaths of old mosses and its surviving births, in m (eq 3.5) for tomorrow.
    const bool old = j < old_count;
    if (old != alive[j]) {
      const int change = alive[j] ? 1 : -1;
      cells_by_ch_->ForEachWithin(w.mosses[j].pos,
                                  [&](uint32_t i, double) { w.m_near[i] += change; });
      changed.push_back(w.mosses[j].pos);
    }
    if (alive[j]) {
      next.push_back(w.mosses[j]);
      was_old.push_back(old);
    }
  }
  w.mosses.swap(next);

  // 3c-d. Gemmae (eq 3.22) and spores (eq 3.23) of the mosses that grew today; they land among
  // the mosses as they are after growth and death.
  centres = CentresOf(w.mosses);
  // The mats' count through buckets of interior_radius·s: PointIndex::WithinRadius's points (the
  // same distance expression and <= r²), without its per-query allocation and sort.
  const geom::RadiusGrid after(centres, rules_.interior_radius * s,
                               MossGridBuckets(centres.size()));
  const std::size_t parents = w.mosses.size();
  // §3.8's mats: a moss with interior_count others within interior_radius·s. A seed rests only on
  // the surface of such dense moss (§3.3, "密生したコケモデルの表面"), so lone mosses never carry
  // others and stacks stay cushions on mats, not columns on single mosses.
  std::vector<bool> dense(parents, false);
  std::vector<glm::dvec3> dense_centres;
  std::vector<uint32_t> dense_owner;
  // A moss's count changes only with a birth or death within the radius (the same distance either
  // way round): those are counted again, the others keep yesterday's count.
  std::vector<bool> recount(parents, false);
  for (const glm::dvec3& c : changed)
    after.ForEachWithin(c, [&](uint32_t j, double) { recount[j] = true; });
  for (std::size_t j = 0; j < parents; ++j) {
    MossPlant& m = w.mosses[j];
    if (m.mat_count < 0 || recount[j])
      m.mat_count = static_cast<int>(after.CountWithin(centres[j]));
    dense[j] = m.mat_count - 1 >= rules_.interior_count;
    if (dense[j]) {
      dense_centres.push_back(centres[j]);
      dense_owner.push_back(static_cast<uint32_t>(j));
    }
  }
  const MatBuckets mats(dense_centres, rules_, MossGridBuckets(dense_centres.size()));
  for (std::size_t j = 0; j < parents; ++j) {
    if (!was_old[j]) continue;
    const MossPlant parent = w.mosses[j];
    const bool inside_mat = dense[j];
    double G_max = parent.G_max;
    const int gemmae = GemmaeDue(parent.growth.G_moss, rules_.gemma_step, inside_mat, &G_max);
    w.mosses[j].G_max = G_max;
    for (int g = 0; g < gemmae; ++g)
      AddSeed(GemmaStart(parent.pos, rules_.k, &w.growth_rng), parent.species, SeedKind::kGemma,
              dense_centres, dense_owner, &mats);
    if (MakesSpore(parent.growth.G_moss, parent.growing, rain_day, rules_.spore_G))
      AddSeed(SporeStart(parent.pos, parent.normal, rules_.l, &w.growth_rng), parent.species,
              SeedKind::kSpore, dense_centres, dense_owner, &mats);
  }

  // 4. Immigration: one outside spore every immigration_days, at a random surface point.
  const int every = p.GetInt(MossParam::kImmigrationDays);
  if (every > 0 && day % every == 0) {
    const Species species =
        static_cast<Species>(std::min(2, static_cast<int>(w.place_rng.Uniform() * 3)));
    ++w.immigrants;
    PlaceAtRandom(species, true);
  }
  std::array<int, kSpeciesCount> pop{};
  for (const MossPlant& m : w.mosses) ++pop[static_cast<int>(m.species)];
  w.population.push_back(pop);
  record.seeds = static_cast<int>(w.seeds.size());
  record.births = static_cast<int>(w.births - births_before);
  record.deaths = static_cast<int>(w.deaths_declined + w.deaths_contest - deaths_before);
  w.days.push_back(record);
  if (stats_every_ > 0 && (day % stats_every_ == 0 || day == state_.days)) {
    nlohmann::ordered_json row;
    row["day"] = day;
    row.update(Breakdown());
    w.every_rows.push_back(row.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
  }
  const MossClock::time_point t4 = MossClock::now();
  ms_photons_ += MossMs(t0, t1);
  ms_gather_ += MossMs(t1, t2);
  ms_soil_ += MossMs(t2, t3);
  ms_growth_ += MossMs(t3, t4);
}

Status MossRun::RecordEvery(double every) {
  if (world_.day > 0) return Status::Error("stats_every", "given after day 0; must be given first");
  NIWA_RETURN_IF_ERROR(CheckValue("stats_every", every, 0, kMaxMossDays, true));
  stats_every_ = static_cast<int>(every);
  return Status::Ok();
}

Status MossRun::UseWeather(std::vector<WeatherDay> days, const std::string& name) {
  if (world_.day > 0) return Status::Error("weather", "given after day 0; must be given first");
  if (days.empty() || days.size() > static_cast<std::size_t>(kMaxWeatherDays))
    return Status::Error("weather", "has " + std::to_string(days.size()) +
                                        " days; must have 1 to " + std::to_string(kMaxWeatherDays));
  weather_ = std::move(days);
  weather_name_ = name;
  return Status::Ok();
}

Status MossRun::Advance(const run::Observer& observer) { return AdvanceTo(state_.days, observer); }

Status MossRun::AdvanceTo(int day, const run::Observer& observer) {
  const int last = std::min(day, state_.days);
  const MossWorld before = world_;
  while (world_.day < last) {
    if (observer &&
        !observer({"grow", static_cast<double>(world_.day), static_cast<double>(state_.days)})) {
      world_ = before;
      return run::CancelledStatus();
    }
    Day();
  }
  if (observer)
    observer({"grow", static_cast<double>(world_.day), static_cast<double>(state_.days)});
  return Status::Ok();
}

void MossRun::SetCanopy(std::vector<CanopySphere> spheres) {
  if (spheres.empty()) {
    light_.canopy.reset();
    return;
  }
  auto canopy = std::make_shared<CanopyShade>();
  canopy->Build(std::move(spheres));
  light_.canopy = std::move(canopy);
}

std::vector<run::Part> MossRun::Parts() const {
  std::vector<double> ramp;
  const std::vector<double> value = MapValues(MossMap::kCoverage, &ramp);
  run::Part land;
  land.name = "land";
  land.mesh = LandMapMesh(cells_, MossMap::kCoverage, value, ramp);
  land.material.name = "land";
  land.material.metallic_factor = 0;
  run::Part tufts;
  tufts.name = "tufts";
  tufts.mesh = MergedTufts(Tufts());
  tufts.material.name = "tufts";
  tufts.material.metallic_factor = 0;
  tufts.material.double_sided = true;
  return {land, tufts};
}

std::vector<double> MossRun::MapValues(MossMap map, std::vector<double>* ramp) const {
  const MossWorld& w = world_;
  const std::size_t n = cells_.size();
  std::vector<double> value(n, 0.0);
  ramp->assign(n, 0.0);
  const MapRamp range = MossMapRamp(map);
  switch (map) {
    case MossMap::kCoverage: {
      std::vector<int> on_cell(n, 0);
      for (const MossPlant& m : w.mosses)
        if (!m.on_moss) ++on_cell[m.cell];
      const double s2 = rules_.s * rules_.s;
      for (std::size_t i = 0; i < n; ++i)
        value[i] = cells_.area[i] > 0 ? std::min(1.0, on_cell[i] * s2 / cells_.area[i]) : 0.0;
      break;
    }
    case MossMap::kS:
      value = w.S;
      break;
    case MossMap::kT_s:
      value = w.T_s;
      break;
    case MossMap::kRh_s:
      value = w.rh_s;
      break;
    case MossMap::kTheta:
      value = w.theta;
      break;
    case MossMap::kFitness: {
      const GForm g_form = static_cast<GForm>(state_.params.GetInt(MossParam::kGForm));
      for (std::size_t i = 0; i < n && w.day > 0; ++i)
        for (int sp = 0; sp < kSpeciesCount; ++sp)
          value[i] =
              std::max(value[i], FitnessOf(SpeciesOf(state_.params, static_cast<Species>(sp)),
                                           w.T_s[i], w.rh_s[i], w.S[i], g_form)
                                     .G);
      break;
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    double v = value[i];
    if (map == MossMap::kTheta) v /= GeologyLawOf(state_.params, cells_.geology[i]).theta_SAT;
    (*ramp)[i] = (v - range.lo) / (range.hi - range.lo);
  }
  return value;
}

std::vector<TuftPlace> MossRun::Tufts() const {
  Pcg32 turns(state_.seed, kDisplayStream);
  const double spore_G = std::max(rules_.spore_G, 1e-9);
  std::vector<TuftPlace> tufts;
  tufts.reserve(world_.mosses.size());
  for (const MossPlant& m : world_.mosses) {
    TuftPlace t;
    t.pos = m.pos;
    t.normal = m.normal;
    t.size = rules_.s * (0.5 + 0.5 * std::clamp(m.growth.G_moss / spore_G, 0.0, 1.0));
    t.angle = 2.0 * det::kPi * turns.Uniform();
    t.species = m.species;
    t.birth_day = m.birth_day;
    tufts.push_back(t);
  }
  return tufts;
}

Result<gltf::Document> MossRun::Document() const { return MapDocument(MossMap::kCoverage, false); }

Result<gltf::Document> MossRun::MapDocument(MossMap map, bool instancing) const {
  std::vector<double> ramp;
  const std::vector<double> value = MapValues(map, &ramp);
  return MossDocument(LandMapMesh(cells_, map, value, ramp), map, world_.day, Tufts(), instancing);
}

std::string MossRun::LandName() const {
  if (!mesh_name_.empty()) return mesh_name_;
  if (state_.scene == kTreeLand) return "tree:" + state_.tree;
  if (state_.scene == kTerrainLand) return "terrain:" + state_.terrain;
  return state_.scene;
}

void MossRun::AddLandFields(nlohmann::ordered_json* j) const {
  if (!mesh_name_.empty()) return;
  if (state_.scene == kTreeLand) {
    (*j)["tree"] = state_.tree;
    (*j)["tree_years"] = state_.tree_years;
  } else if (state_.scene == kTerrainLand) {
    (*j)["terrain"] = state_.terrain;
    (*j)["terrain_seed"] = state_.terrain_seed;
  } else if (state_.scene == "rocks" && state_.rock_triangles != kRockTrianglesDefault) {
    (*j)["rock_triangles"] = state_.rock_triangles;
  }
}

std::string MossRun::Hash(const std::string& prefix) const {
  return EncodeMossHash(state_, prefix);
}

Result<Estimate> MossRun::ExportEstimate(const std::string& format) const {
  return ExportEstimateAt(format, static_cast<double>(world_.mosses.size()));
}

Result<Estimate> MossRun::PlannedExportEstimate(const std::string& format) const {
  Result<Estimate> e = ExportEstimateAt(format, state_.params.Get(MossParam::kMaxMosses));
  if (!e.ok()) return e;
  Estimate days = RunEstimate();
  days.memory_bytes = 0;  // already held
  return days + *e;
}

Result<Estimate> MossRun::ExportEstimateAt(const std::string& format, double mosses) const {
  const double cells = static_cast<double>(cells_.size());
  Estimate held;  // the run's cells, photons and mosses, kept while the file is made
  held.memory_bytes = RunEstimate().memory_bytes;
  if (format == "glb")
    return held + MossGlbEstimate(cells_.size(), static_cast<std::size_t>(mosses));
  if (format == "json") {
    // A moss ~160 bytes of text and ~1 kB as JSON values; a cell ~330 and ~2 kB.
    Estimate e;
    e.memory_bytes = 1200.0 * mosses + 2400.0 * cells;
    e.seconds = 1e-6 * mosses + 2e-6 * cells;
    e.what = "writing " + FormatCount(mosses) + " mosses and " + FormatCount(cells) + " cells";
    return held + e;
  }
  if (format == "csv") {
    Estimate e;
    e.memory_bytes = 2.0 * 400.0 * state_.days;  // a row of ~20 numbers, and the text's copy
    e.seconds = 1e-6 * state_.days;
    e.what = "writing " + FormatCount(state_.days) + " days as .csv";
    return held + e;
  }
  if (format == "svg") {
    // A cell's path ~110 bytes, a stored photon's circle ~70 (about 3 stored a path at most),
    // the items sorted and the text's copy.
    const double photons = 3.0 * state_.params.Get(MossParam::kPhotons);
    const double bytes = 110.0 * cells + 70.0 * photons;
    Estimate e;
    e.memory_bytes = 2.0 * bytes + 16.0 * (cells + photons) + 64.0 * photons;
    e.seconds = 2e-7 * (cells + photons) + 1e-8 * bytes;
    e.what = "writing the photons' .svg (" + FormatCount(cells) + " cells, " +
             FormatCount(photons) + " photons)";
    return held + e;
  }
  if (format == "rays") {
    // geom/ray_dump.h: the cells' mesh (3 corners a cell) and the rays, each a CastRay (40 B)
    // and its 36 bytes, traced again (the next day's photons). A path casts 1 + its reflections:
    // 1/(1 − ρ) on average for the roulette's larger ρ, at most max_bounces + 1; 1.5x that.
    const double rho = light_.indirect ? std::max(light_.rho_mesh, light_.rho_moss) : 0.0;
    const double per_path = std::min(light_.max_bounces + 1.0, 1.0 / std::max(1e-3, 1.0 - rho));
    const double rays = 1.5 * per_path * state_.params.Get(MossParam::kPhotons);
    const double bytes = geom::kRayDumpHeaderBytes + 48.0 * cells + 36.0 * rays;
    Estimate e;
    e.memory_bytes = 2.0 * bytes + 40.0 * rays + kBytesPerPhoton * rays;
    e.seconds = costs_.photon * state_.params.Get(MossParam::kPhotons) + 1e-8 * bytes;
    e.what = "writing the photons' rays (" + FormatCount(cells) + " cells, " + FormatCount(rays) +
             " rays)";
    return held + e;
  }
  return Status::Error("format",
                       "'" + format + "' is unknown; must be glb, json, csv, svg or rays");
}

PhotonMap MossRun::NextDayPhotons(std::vector<geom::CastRay>* rays) const {
  Pcg32 rng = world_.photon_rng;
  PhotonMap map;
  MossOccluders occluders;
  occluders.Build(CentresOf(world_.mosses), 0.5 * rules_.s);
  TracePhotons(cells_, occluders, light_, state_.params.GetInt(MossParam::kPhotons), &rng, &map,
               rays);
  return map;
}

std::string MossRun::PhotonsSvg(bool next_day) const {
  const int day = next_day ? world_.day + 1 : world_.day;
  const std::string title = "moss photons day " + std::to_string(day) + ", " + LandName() +
                            ", indirect " +
                            (state_.params.GetInt(MossParam::kIndirect) != 0 ? "on" : "off");
  return PhotonSvg(cells_, next_day ? NextDayPhotons() : map_, title);
}

std::string MossRun::PhotonDayJson() const {
  const PhotonMap map = NextDayPhotons();
  nlohmann::ordered_json j;
  j["study"] = "moss";
  j["scene"] = mesh_name_.empty() ? state_.scene : "mesh";
  if (!mesh_name_.empty()) j["mesh"] = mesh_name_;
  AddLandFields(&j);
  j["url"] = Hash("");
  j["day"] = world_.day + 1;
  j["mosses"] = world_.mosses.size();
  j["emitted_sun"] = map.emitted_sun;
  j["emitted_sky"] = map.emitted_sky;
  j["dPhi_sun"] = map.dPhi_sun;
  j["dPhi_sky"] = map.dPhi_sky;
  j["power_emitted"] = map.power_emitted;
  j["stored_by_depth"] = map.stored_by_depth;
  j["power_by_depth"] = map.power_by_depth;
  j["escaped"] = map.escaped;
  j["absorbed"] = map.absorbed;
  // Per region: stored photons first-hit and bounced, and the cells' mean gathered S.
  Result<PhotonGather> gather = PhotonGather::Build(map, light_.r_gather);
  const std::size_t regions = cells_.region_names.size();
  std::vector<int64_t> direct(regions, 0), bounced(regions, 0), on_moss(1, 0);
  for (const Photon& p : map.photons) {
    if (p.on_moss) {
      ++on_moss[0];
      continue;
    }
    ++(p.depth == 0 ? direct : bounced)[cells_.region[p.target]];
  }
  std::vector<double> S(regions, 0.0), area(regions, 0.0);
  for (std::size_t i = 0; gather.ok() && i < cells_.size(); ++i) {
    S[cells_.region[i]] += cells_.area[i] * gather->Soil(cells_.centroid[i], cells_.normal[i]);
    area[cells_.region[i]] += cells_.area[i];
  }
  for (std::size_t r = 0; r < regions; ++r)
    j["regions"][cells_.region_names[r]] = {{"direct", direct[r]},
                                            {"bounced", bounced[r]},
                                            {"mean_S", area[r] > 0 ? S[r] / area[r] : 0.0}};
  j["on_mosses"] = on_moss[0];
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string MossScenesJson() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const std::string& name : SceneNames()) {
    Result<MossScene> scene = BuildScene(name);
    if (!scene.ok()) continue;
    Result<SoilCells> cells = MakeSoilCells(*scene, SoilCellOptions{});
    nlohmann::ordered_json o;
    o["name"] = name;
    o["description"] = scene->description;
    o["triangles"] = scene->mesh.triangle_count();
    o["cells"] = cells.ok() ? cells->size() : 0;
    std::array<int, kGeologyCount> by_geology{};
    if (cells.ok())
      for (Geology g : cells->geology) ++by_geology[static_cast<int>(g)];
    for (int g = 0; g < kGeologyCount; ++g)
      o["by_geology"][GeologyName(static_cast<Geology>(g))] = by_geology[g];
    o["regions"] = scene->region_names;
    list.push_back(o);
  }
  nlohmann::ordered_json j;
  j["scenes"] = list;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

std::string MossRun::DaysCsv() const {
  std::string out = "day,gingoke,haigoke,sugigoke,seeds,births,deaths,photons_stored";
  for (int g = 0; g < kGeologyCount; ++g)
    for (const char* what : {"S", "T_s", "rh_s", "theta"})
      out += std::string(",") + GeologyName(static_cast<Geology>(g)) + "_" + what;
  out += "\n";
  for (const MossDayRecord& r : world_.days) {
    const std::array<int, kSpeciesCount>& pop = world_.population[r.day];
    out += std::to_string(r.day);
    for (int n : pop) out += "," + std::to_string(n);
    out += "," + std::to_string(r.seeds) + "," + std::to_string(r.births) + "," +
           std::to_string(r.deaths) + "," + std::to_string(r.photons_stored);
    for (const auto& soil : r.soil)
      for (double v : soil) out += "," + (v == v ? FormatNumber(v) : std::string());
    out += "\n";
  }
  return out;
}

std::string MossRun::MossesJson() const {
  nlohmann::ordered_json j;
  j["study"] = "moss";
  j["url"] = Hash("");
  j["day"] = world_.day;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const MossPlant& m : world_.mosses) {
    nlohmann::ordered_json o;
    o["species"] = SpeciesName(m.species);
    o["pos"] = {m.pos.x, m.pos.y, m.pos.z};
    o["normal"] = {m.normal.x, m.normal.y, m.normal.z};
    o["birth_day"] = m.birth_day;
    o["G_moss"] = m.growth.G_moss;
    o["on_moss"] = m.on_moss;
    list.push_back(o);
  }
  j["mosses"] = list;
  nlohmann::ordered_json cells = nlohmann::ordered_json::array();
  const MossWorld& w = world_;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    nlohmann::ordered_json o;
    const glm::dvec3 &c = cells_.centroid[i], &n = cells_.normal[i];
    o["geology"] = GeologyName(cells_.geology[i]);
    o["centre"] = {c.x, c.y, c.z};
    o["normal"] = {n.x, n.y, n.z};
    o["S"] = w.S[i];
    o["T_s"] = w.T_s[i];
    o["rh_s"] = w.rh_s[i];
    o["theta"] = w.theta[i];
    o["m_over_M"] = w.m_over_M[i];
    cells.push_back(o);
  }
  j["cells"] = cells;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

nlohmann::ordered_json MossRun::Breakdown() const {
  const MossWorld& w = world_;
  nlohmann::ordered_json j;
  // Mosses by species, region, orientation; on mosses; coverage of the faces by orientation.
  nlohmann::ordered_json mosses;
  mosses["total"] = w.mosses.size();
  std::array<int, kSpeciesCount> by_species{};
  std::vector<int> moss_region(cells_.region_names.size(), 0);
  std::map<std::string, int> by_orientation{{"up", 0}, {"down", 0}, {"vertical", 0}};
  int on_moss = 0;
  std::vector<int> on_cell(cells_.size(), 0);
  for (const MossPlant& m : w.mosses) {
    ++by_species[static_cast<int>(m.species)];
    ++moss_region[cells_.region[m.cell]];
    ++by_orientation[OrientationName(cells_.normal[m.cell])];
    if (m.on_moss) {
      ++on_moss;
    } else {
      ++on_cell[m.cell];
    }
  }
  for (int s = 0; s < kSpeciesCount; ++s)
    mosses["by_species"][SpeciesName(static_cast<Species>(s))] = by_species[s];
  for (std::size_t r = 0; r < moss_region.size(); ++r)
    mosses["by_region"][cells_.region_names[r]] = moss_region[r];
  for (const char* o : {"up", "down", "vertical"}) mosses["by_orientation"][o] = by_orientation[o];
  mosses["on_mosses"] = on_moss;
  // By their light on their last day of growth (the day's newborn: 0 until they grow).
  std::map<std::string, int> bands;
  for (const MossPlant& m : w.mosses) ++bands[IrradianceBand(m.S)];
  for (const char* b : {"0", "0-10", "10-30", "30-60", "60-120", ">120"})
    mosses["by_irradiance_band"][b] = bands[b];
  // Coverage (spec §3): each cell min(1, n·s²/A), area-weighted by face orientation.
  std::map<std::string, std::pair<double, double>> coverage;
  const double s2 = rules_.s * rules_.s;
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    auto& [covered, area] = coverage[OrientationName(cells_.normal[i])];
    covered += std::min(cells_.area[i], on_cell[i] * s2);
    area += cells_.area[i];
  }
  for (const char* o : {"up", "down", "vertical"})
    mosses["coverage"][o] = coverage[o].second > 0 ? coverage[o].first / coverage[o].second : 0.0;
  j["mosses"] = mosses;
  // Seeds, births and deaths.
  std::array<int, 2> waiting{};
  for (const MossSeed& seed : w.seeds) ++waiting[static_cast<int>(seed.kind)];
  nlohmann::ordered_json seeds;
  seeds["waiting"] = {{"gemma", waiting[0]}, {"spore", waiting[1]}};
  seeds["made"] = {
      {"gemma", w.seeds_made[0]}, {"spore", w.seeds_made[1]}, {"immigrant", w.immigrants}};
  for (int l = 0; l < static_cast<int>(SeedLoss::kCount); ++l)
    seeds["lost"][SeedLossName(static_cast<SeedLoss>(l))] = w.seeds_lost[l];
  j["seeds"] = seeds;
  j["births"] = w.births;
  j["deaths"] = {{"declined", w.deaths_declined}, {"lost_contest", w.deaths_contest}};
  // The day's photons by bounce depth.
  nlohmann::ordered_json photons;
  photons["emitted_sun"] = w.emitted_sun;
  photons["emitted_sky"] = w.emitted_sky;
  photons["stored_by_depth"] = w.stored_by_depth;
  j["photons"] = photons;
  // The last day's soil per geology: mean S, T_s, rh_s, θ (area-weighted).
  nlohmann::ordered_json soil;
  for (int g = 0; g < kGeologyCount; ++g) {
    double area = 0, S = 0, T_s = 0, rh_s = 0, theta = 0;
    for (std::size_t i = 0; i < cells_.size(); ++i) {
      if (static_cast<int>(cells_.geology[i]) != g) continue;
      const double a = cells_.area[i];
      area += a, S += a * w.S[i], T_s += a * w.T_s[i], rh_s += a * w.rh_s[i],
          theta += a * w.theta[i];
    }
    if (area <= 0 || w.day == 0) continue;
    soil[GeologyName(static_cast<Geology>(g))] = {
        {"S", S / area}, {"T_s", T_s / area}, {"rh_s", rh_s / area}, {"theta", theta / area}};
  }
  j["soil"] = soil.is_null() ? nlohmann::ordered_json::object() : soil;
  return j;
}

std::string MossRun::StatsJson() const {
  const MossWorld& w = world_;
  nlohmann::ordered_json j;
  j["study"] = "moss";
  j["scene"] = mesh_name_.empty() ? state_.scene : "mesh";
  if (!mesh_name_.empty()) j["mesh"] = mesh_name_;  // a loaded mesh: not in the link
  AddLandFields(&j);
  if (!weather_.empty())  // a weather file: not in the link
    j["weather"] = {{"file", weather_name_}, {"days", weather_.size()}};
  j["preset"] = state_.preset;
  j["url"] = Hash("");
  j["days"] = w.day;
  j["seed"] = state_.seed;
  j["photons"] = state_.params.GetInt(MossParam::kPhotons);
  j["indirect"] = state_.params.GetInt(MossParam::kIndirect);
  // Soil cells by geology and region.
  std::array<int, kGeologyCount> by_geology{};
  std::vector<int> by_region(cells_.region_names.size(), 0);
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    ++by_geology[static_cast<int>(cells_.geology[i])];
    ++by_region[cells_.region[i]];
  }
  nlohmann::ordered_json cells;
  cells["total"] = cells_.size();
  for (int g = 0; g < kGeologyCount; ++g)
    cells["by_geology"][GeologyName(static_cast<Geology>(g))] = by_geology[g];
  for (std::size_t r = 0; r < by_region.size(); ++r)
    cells["by_region"][cells_.region_names[r]] = by_region[r];
  j["cells"] = cells;
  const nlohmann::ordered_json b = Breakdown();
  j["mosses"] = b["mosses"];
  nlohmann::ordered_json population = nlohmann::ordered_json::array();
  for (const auto& pop : w.population) population.push_back({pop[0], pop[1], pop[2]});
  j["population"] = {{"species", {"gingoke", "haigoke", "sugigoke"}}, {"by_day", population}};
  j["seeds"] = b["seeds"];
  j["births"] = b["births"];
  j["deaths"] = b["deaths"];
  // The photons: the last day's and every day's, by bounce depth.
  nlohmann::ordered_json photons = b["photons"];
  photons["stored_by_depth_all_days"] = w.stored_by_depth_total;
  j["photons_last_day"] = photons;
  if (light_.canopy != nullptr)  // a composed run's leaves (SetCanopy)
    j["canopy"] = {{"spheres", light_.canopy->size()},
                   {"photons_intercepted", w.canopy_intercepted},
                   {"photons_absorbed", w.canopy_absorbed}};
  j["soil_last_day"] = b["soil"];
  // Every K days (--every K): the same breakdown as it stood at the end of those days.
  if (stats_every_ > 0) {
    j["every"] = stats_every_;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const std::string& row : w.every_rows) rows.push_back(nlohmann::ordered_json::parse(row));
    j["every_days"] = rows;
  }
  // The stages' wall time (the only fields that differ between runs of one state).
  j["ms"] = ms_photons_ + ms_gather_ + ms_soil_ + ms_growth_;
  j["ms_photons"] = ms_photons_;
  j["ms_gather"] = ms_gather_;
  j["ms_soil"] = ms_soil_;
  j["ms_growth"] = ms_growth_;
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace niwa::moss

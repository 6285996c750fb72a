// The moss study's light (Nomura 2010 §3.4, §3.5.1; spec §1.3): the photon pass from a square sun
// light (eq 3.1 emission, directions that miss the scene's enclosing sphere redrawn), optional sky
// photons (the nomura2010-sky extension), diffuse bounces with Russian roulette on the land and on
// the mosses (1 cm spheres, found through a uniform grid rebuilt every day), the "without indirect
// light" mode (first hits only, no sky), and the gather: irradiance at a point from the stored
// photons within r_gather whose normal faces it (geom::RadiusGrid). Deterministic: double math,
// det_math's sin/cos, the caller's Pcg32. Does not: keep photons across days, smooth light over
// days, place or move mosses (the run), or spread the sun over a day's arc (sun_path 1 is refused).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

#include "base/status.h"
#include "geom/radius_grid.h"
#include "geom/ray_dump.h"
#include "moss/canopy.h"
#include "moss/moss_params.h"
#include "moss/soil_cells.h"
#include "random/pcg32.h"

namespace niwa::moss {

// The light of one day, from the table's light rows and the land's enclosing sphere.
struct PhotonLight {
  glm::dvec3 sun;     // unit vector towards the sun (core/light: altitude, azimuth)
  glm::dvec3 centre;  // C, the enclosing sphere's centre
  double R = 0;       // its radius
  double sun_distance = 10, sun_size = 0.5;  // in R
  double S_sun = 250;                        // daily mean beam irradiance I_beam·N/24 [W/m²]
  double S_sky = 0;                          // diffuse sky irradiance on open ground [W/m²]
  double rho_mesh = 0.5, rho_moss = 0.2;
  int max_bounces = 16;
  bool indirect = true;   // false: first hits only, no sky photons (fig 4.2)
  double r_gather = 0.1;  // m
  // Leaves the study does not grow (a garden's tree crowns; none on the study's own scenes): a
  // photon's path through them is intercepted by Beer–Lambert (canopy.h); an intercepted photon
  // is scattered with probability omega_leaf (the leaves' broadband single-scattering albedo:
  // reflected or transmitted, one half each, cosine-weighted), else absorbed; none is stored.
  std::shared_ptr<const CanopyShade> canopy;
  double omega_leaf = 0.5;
};
// The light of `params` over `cells` (the sun_altitude row is at least 1°); the error names
// "sun_path" (the arc is not built).
Result<PhotonLight> PhotonLightOf(const MossParams& params, const SoilCells& cells);

// The mosses as occluders and reflectors: spheres of one radius (s/2) in a uniform grid.
class MossOccluders {
 public:
  // Indexes the centres (copied); reuses its arrays from the last build.
  void Build(const std::vector<glm::dvec3>& centres, double radius);
  std::size_t size() const { return centres_.size(); }
  const glm::dvec3& centre(uint32_t i) const { return centres_[i]; }
  // The first sphere the ray origin + t·dir (dir unit) enters with t in (0, max_t]; a sphere
  // holding the origin is passed through (a photon leaving a face inside a moss's lower half).
  // Ties go to the lower index. False when none.
  bool FirstHit(const glm::dvec3& origin, const glm::dvec3& dir, double max_t, double* t,
                uint32_t* index) const;
  // The same by testing every sphere (the oracle).
  bool FirstHitLinear(const glm::dvec3& origin, const glm::dvec3& dir, double max_t, double* t,
                      uint32_t* index) const;

 private:
  std::vector<glm::dvec3> centres_;
  double radius_ = 0;
  glm::dvec3 lo_{0};
  double cell_ = 1;
  int dims_[3] = {0, 0, 0};
  std::vector<uint32_t> start_, items_;
  // 1 where a cell lists a sphere: FirstHit's walk passes the empty ones (most of a ray's cells)
  // with one byte read and its step, without their exit or list.
  std::vector<uint8_t> occupied_;
};

// One stored photon: where it hit, the normal of the side it hit, its power, its bounce depth
// (0: straight from the sun or the sky), and the soil cell or moss it hit.
struct Photon {
  glm::dvec3 position;
  glm::dvec3 normal;
  double power;  // W
  uint32_t target;
  uint8_t depth;
  bool on_moss;
};

struct PhotonMap {
  std::vector<Photon> photons;
  int emitted_sun = 0, emitted_sky = 0;
  double dPhi_sun = 0, dPhi_sky = 0;     // power of one photon [W]
  double power_emitted = 0;              // W
  std::vector<int64_t> stored_by_depth;  // max_bounces + 1 entries
  std::vector<double> power_by_depth;    // W stored at each depth
  int64_t escaped = 0;                   // paths that left without a hit
  int64_t absorbed = 0;                  // paths ended by the roulette (or the bounce cap)
  int64_t canopy_intercepted = 0;        // interceptions by the canopy's leaves
  int64_t canopy_absorbed = 0;           // of them, paths ended there
  double canopy_power_absorbed = 0;      // W
};

// Eq 3.1's emission from the sun's square: a uniform point on the square (two draws), then a
// cosine-weighted direction about the light's normal conditioned on meeting the enclosing sphere,
// drawn inside the sphere's cone from that point (uniform in the cone, kept with probability equal
// to its cosine to the normal: the same distribution as redrawing eq 3.1 until the ray meets the
// sphere, without the ~99 % misses at 10 R).
void EmitSunPhoton(const PhotonLight& light, Pcg32* rng, glm::dvec3* origin, glm::dvec3* dir);
// The literal form: eq 3.1 redrawn until the ray meets the sphere (the oracle of the above).
void EmitSunPhotonByRejection(const PhotonLight& light, Pcg32* rng, glm::dvec3* origin,
                              glm::dvec3* dir);

// The day's photon pass: `photons` accepted emissions (sun and, with S_sky > 0 and indirect on, sky
// photons in the budget's share f_sky = 2·S_sky/(S_sun + 2·S_sky)) traced through the land and the
// mosses. Reuses map's arrays. With `rays`: every ray cast at the land appended, in order, with
// the land hit it found (the moss spheres are not in it; geom/ray_dump.h writes them out).
void TracePhotons(const SoilCells& cells, const MossOccluders& mosses, const PhotonLight& light,
                  int photons, Pcg32* rng, PhotonMap* map,
                  std::vector<geom::CastRay>* rays = nullptr);

// The soil cells' share of a day's gather, spread from the photons (spec §4.6): for each stored
// land photon in map order, its power added to every cell whose centroid lies within r_gather of it
// and whose normal n has n_p·n > 0.5 (PhotonGather::Soil's sum at every cell at once, without the
// division by πr²). The candidates of a photon that hit cell t are listed once per cell (the cells
// within r + reach_t of t's centroid, reach_t the farthest a hit on t lies from it, split by which
// side was hit), so a photon tests about the cells its disc covers instead of a radius query's 27
// buckets; the same distance expression and order of additions as the grid, so the same bits. A
// photon farther than reach_t from its cell's centroid (it cannot be, but for rounding) falls back
// to the grid; lists longer than kMaxCandidatesPerCell a cell on average are not built (the grid
// serves every photon). When the map's land photons carry one power, or two in two runs (the
// sun's, then the sky's: every day's map), each cell's photons are counted and its additions
// replayed from the counts (the same bits); the cells within r_gather − reach_t of t's centroid
// come first in t's lists and are counted without a distance test.
class SoilPhotonSpread {
 public:
  static constexpr std::size_t kMaxCandidatesPerCell = 96;
  SoilPhotonSpread(const SoilCells& cells, double r_gather);
  // S[c] += power of every land photon of `map` within r_gather of cell c facing its way; `cells`
  // are the ones it was built on, S is their size.
  void Spread(const SoilCells& cells, const PhotonMap& map, std::vector<double>* S) const;
  bool listed() const { return !start_.empty(); }  // the lists were built

 private:
  // The list of the side of its cell a photon hit (0 front, 1 back), or -1 for the grid.
  int SideOf(const SoilCells& cells, const Photon& ph) const;
  // add(c) for every cell c within r_gather of ph facing its way (any order).
  template <class Add>
  void ForEachCellOf(const SoilCells& cells, const Photon& ph, Add&& add) const;
  geom::RadiusGrid grid_;  // the centroids in buckets of r_gather (the fallback)
  double r2_;
  std::vector<double> reach2_;   // per cell
  std::vector<uint32_t> start_;  // 2 lists a cell (front side hit, back side hit): start_[2c + s]
  // Each list: first the cells within r_gather − reach_t of t's centroid (within r_gather of any
  // photon on t: counted without a distance test), up to sure_end_[2c + s], then the others.
  std::vector<uint32_t> sure_end_;
  std::vector<uint32_t> items_;  // candidate cells, list by list, each part in cell order
};

// The gather (§3.5.1): E(x, n) = Σ dPhi_p / (π r²) over stored photons within r of x with
// n_p·n > 0.5; soil cells count land hits only (a moss shades the soil), mosses every hit.
class PhotonGather {
 public:
  static Result<PhotonGather> Build(const PhotonMap& map, double r_gather);
  double Soil(const glm::dvec3& x, const glm::dvec3& n) const { return Gather(x, n, false); }
  double Moss(const glm::dvec3& x, const glm::dvec3& n) const { return Gather(x, n, true); }

 private:
  // A photon's normal, power and kind beside its position in the grid's slot order, so a query
  // reads its candidates in runs instead of through the map.
  struct Slot {
    glm::dvec3 normal;
    double power;
    bool on_moss;
  };
  PhotonGather(geom::RadiusGrid grid, std::vector<Slot> slots, double r)
      : grid_(std::move(grid)), slots_(std::move(slots)), r_(r) {}
  double Gather(const glm::dvec3& x, const glm::dvec3& n, bool all) const;
  geom::RadiusGrid
      grid_;  // the photons in buckets of r_gather (radius_grid.h: no allocation a query)
  std::vector<Slot> slots_;
  double r_;
};

}  // namespace niwa::moss

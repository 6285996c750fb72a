// The moss study's photon pass and gather (photons.h).
#include "moss/photons.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <limits>

#include "geom/ray_cast.h"
#include "light/sun.h"
#include "math/det_math.h"
#include "moss/sampling.h"
#include "moss/sphere_cells.h"

namespace niwa::moss {
namespace {

constexpr double kPhotonOffset = 1e-5;  // m: a bounce leaves this far off the face it hit

// The first t > 0 at which origin + t·dir (unit) enters the sphere; false when it does not or the
// origin is inside.
bool EnterSphere(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& c, double r,
                 double* t) {
  const glm::dvec3 m = origin - c;
  const double b = glm::dot(m, dir);
  const double cc = glm::dot(m, m) - r * r;
  if (cc <= 0.0 || b > 0.0) return false;
  const double disc = b * b - cc;
  if (disc < 0.0) return false;
  *t = -b - std::sqrt(disc);
  return *t > 0.0;
}

// Does origin + t·dir, t > 0, pass within R of c?
bool MeetsSphere(const glm::dvec3& origin, const glm::dvec3& dir, const glm::dvec3& c, double R) {
  const glm::dvec3 m = c - origin;
  const double t = glm::dot(m, dir);
  if (t <= 0.0) return glm::dot(m, m) <= R * R;
  return glm::dot(m, m) - t * t <= R * R;
}

// The sun square's normal and sides (the same for every photon of a light).
struct SunFrame {
  glm::dvec3 n, b1, b2;
  explicit SunFrame(const PhotonLight& light) : n(-light.sun) { BasisAbout(n, &b1, &b2); }
};

glm::dvec3 SunSquarePoint(const PhotonLight& light, const SunFrame& frame, Pcg32* rng) {
  const double side = light.sun_size * light.R;
  const double u = rng->Uniform(), v = rng->Uniform();
  return light.centre + (light.sun_distance * light.R) * light.sun + ((u - 0.5) * side) * frame.b1 +
         ((v - 0.5) * side) * frame.b2;
}

// EmitSunPhoton with the light's frame worked out once (TracePhotons: once a day, not a photon).
void EmitSunPhotonIn(const PhotonLight& light, const SunFrame& frame, Pcg32* rng,
                     glm::dvec3* origin, glm::dvec3* dir) {
  const glm::dvec3& n = frame.n;
  *origin = SunSquarePoint(light, frame, rng);
  const glm::dvec3 m = light.centre - *origin;
  const double D = glm::length(m);
  const glm::dvec3 axis = m / D;
  const double sin_a = std::min(1.0, light.R / D);
  const double cos_a = std::sqrt(std::max(0.0, 1.0 - sin_a * sin_a));
  glm::dvec3 b1, b2;
  BasisAbout(axis, &b1, &b2);
  for (;;) {
    // Uniform in the sphere's cone, kept with probability cos θ to the light's normal: together
    // the cosine weight of eq 3.1 restricted to the directions that meet the sphere.
    const double cos_g = 1.0 - rng->Uniform() * (1.0 - cos_a);
    const double sin_g = std::sqrt(std::max(0.0, 1.0 - cos_g * cos_g));
    double s = 0, c = 1;
    det::SinCos(2.0 * det::kPi * rng->Uniform(), &s, &c);
    const glm::dvec3 w = cos_g * axis + (sin_g * c) * b1 + (sin_g * s) * b2;
    const double cos_theta = glm::dot(w, n);
    if (rng->Uniform() < cos_theta) {
      *dir = w;
      return;
    }
  }
}

}  // namespace

Result<PhotonLight> PhotonLightOf(const MossParams& params, const SoilCells& cells) {
  if (params.GetInt(MossParam::kSunPath) != 0)
    return Status::Error("sun_path", "1 (arc) is not built yet; must be 0 (fixed)");
  const double altitude = params.Get(MossParam::kSunAltitude);
  PhotonLight light;
  light.sun = glm::dvec3(light::SunDirection(
      static_cast<float>(altitude), static_cast<float>(params.Get(MossParam::kSunAzimuth))));
  light.sun = glm::normalize(light.sun);
  light.centre = cells.centre;
  light.R = cells.radius;
  light.sun_distance = params.Get(MossParam::kSunDistance);
  light.sun_size = params.Get(MossParam::kSunSize);
  light.S_sun = params.Get(MossParam::kIBeam) * params.Get(MossParam::kN) / 24.0;
  light.S_sky = params.Get(MossParam::kSSky);
  light.rho_mesh = params.Get(MossParam::kRhoMesh);
  light.rho_moss = params.Get(MossParam::kRhoMoss);
  light.max_bounces = params.GetInt(MossParam::kMaxBounces);
  light.indirect = params.GetInt(MossParam::kIndirect) != 0;
  light.r_gather = params.Get(MossParam::kRGather);
  return light;
}

// ---- the mosses' grid

void MossOccluders::Build(const std::vector<glm::dvec3>& centres, double radius) {
  centres_ = centres;
  radius_ = radius;
  start_.clear();
  items_.clear();
  dims_[0] = dims_[1] = dims_[2] = 0;
  if (centres_.empty()) return;
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const glm::dvec3& c : centres_) lo = glm::min(lo, c), hi = glm::max(hi, c);
  lo -= glm::dvec3(radius);
  hi += glm::dvec3(radius);
  // Cells of two diameters, grown until the grid has at most 2^21 cells and at most about four
  // cells a moss: a ray walks every cell it crosses, so a fine grid over a few scattered mosses
  // cost more than their tests (a day-60 thesis run spent 22 % of its time walking empty cells).
  cell_ = 4.0 * radius;
  const glm::dvec3 extent = hi - lo;
  const double most = std::min(static_cast<double>(1 << 21),
                               std::max(64.0, 4.0 * static_cast<double>(centres_.size())));
  for (;;) {
    for (int a = 0; a < 3; ++a)
      dims_[a] = std::max(1, static_cast<int>(std::ceil(extent[a] / cell_)));
    if (static_cast<double>(dims_[0]) * dims_[1] * dims_[2] <= most) break;
    cell_ *= 2.0;
  }
  lo_ = lo;
  const std::size_t n_cells = static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2];
  ListSpheresInCells(
      centres_.size(), [&](uint32_t s) -> const glm::dvec3& { return centres_[s]; },
      [&](uint32_t) { return radius_; }, lo_, cell_, dims_, &start_, &items_);
  occupied_.resize(n_cells);
  for (std::size_t k = 0; k < n_cells; ++k) occupied_[k] = start_[k] != start_[k + 1] ? 1 : 0;
}

bool MossOccluders::FirstHitLinear(const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
                                   double* t, uint32_t* index) const {
  bool found = false;
  double best = max_t;
  for (uint32_t s = 0; s < centres_.size(); ++s) {
    double ts;
    if (EnterSphere(origin, dir, centres_[s], radius_, &ts) && ts <= best &&
        (!found || ts < best)) {
      best = ts, *index = s, found = true;
    }
  }
  if (found) *t = best;
  return found;
}

bool MossOccluders::FirstHit(const glm::dvec3& origin, const glm::dvec3& dir, double max_t,
                             double* t, uint32_t* index) const {
  if (centres_.empty()) return false;
  // Clip the ray to the grid's box (slabs).
  double t0 = 0.0, t1 = max_t;
  const glm::dvec3 hi = lo_ + cell_ * glm::dvec3(dims_[0], dims_[1], dims_[2]);
  for (int a = 0; a < 3; ++a) {
    if (dir[a] == 0.0) {
      if (origin[a] < lo_[a] || origin[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo_[a] - origin[a]) / dir[a], tb = (hi[a] - origin[a]) / dir[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  // 3-D DDA (Amanatides and Woo 1987) from the entry point; in each cell the nearest sphere whose
  // entry lies before the cell's exit is the answer (a later one may sit in a later cell).
  const glm::dvec3 p = origin + t0 * dir;
  int cell[3], step[3];
  double next[3], delta[3];
  for (int a = 0; a < 3; ++a) {
    cell[a] = std::clamp(static_cast<int>(std::floor((p[a] - lo_[a]) / cell_)), 0, dims_[a] - 1);
    if (dir[a] > 0.0) {
      step[a] = 1;
      next[a] = (lo_[a] + (cell[a] + 1) * cell_ - origin[a]) / dir[a];
      delta[a] = cell_ / dir[a];
    } else if (dir[a] < 0.0) {
      step[a] = -1;
      next[a] = (lo_[a] + cell[a] * cell_ - origin[a]) / dir[a];
      delta[a] = -cell_ / dir[a];
    } else {
      step[a] = 0;
      next[a] = std::numeric_limits<double>::infinity();
      delta[a] = std::numeric_limits<double>::infinity();
    }
  }
  // The walk's cell index, stepped with the cell (the same cells as cell[]).
  const std::ptrdiff_t stride[3] = {1, dims_[0], static_cast<std::ptrdiff_t>(dims_[0]) * dims_[1]};
  std::ptrdiff_t k =
      (static_cast<std::ptrdiff_t>(cell[2]) * dims_[1] + cell[1]) * dims_[0] + cell[0];
  const uint8_t* occupied = occupied_.data();
  for (;;) {
    // The axis whose cell side comes first (the lowest next[], ties to the lower axis).
    const int a = next[0] <= next[1] ? (next[0] <= next[2] ? 0 : 2) : (next[1] <= next[2] ? 1 : 2);
    if (occupied[k] != 0) {
      const double exit = std::min(std::min(next[0], next[1]), std::min(next[2], t1));
      bool found = false;
      double best = exit;
      for (uint32_t j = start_[k]; j < start_[k + 1]; ++j) {
        const uint32_t s = items_[j];
        double ts;
        if (EnterSphere(origin, dir, centres_[s], radius_, &ts) && ts <= best &&
            (!found || ts < best || (ts == best && s < *index))) {
          best = ts, *index = s, found = true;
        }
      }
      if (found) {
        *t = best;
        return true;
      }
    }
    // An empty cell is passed by its exit alone: min(next[], t1) >= t1 is next[a] >= t1 (no
    // NaN here: t1 is finite, next[] finite or +inf), the occupied cells' test above.
    if (next[a] >= t1) return false;
    cell[a] += step[a];
    if (cell[a] < 0 || cell[a] >= dims_[a]) return false;
    k += step[a] * stride[a];
    next[a] += delta[a];
  }
}

// ---- emission

void EmitSunPhoton(const PhotonLight& light, Pcg32* rng, glm::dvec3* origin, glm::dvec3* dir) {
  EmitSunPhotonIn(light, SunFrame(light), rng, origin, dir);
}

void EmitSunPhotonByRejection(const PhotonLight& light, Pcg32* rng, glm::dvec3* origin,
                              glm::dvec3* dir) {
  const SunFrame frame(light);
  const glm::dvec3& n = frame.n;
  *origin = SunSquarePoint(light, frame, rng);
  do {
    *dir = CosineDirection(n, rng);  // moss eq. 3.1
  } while (!MeetsSphere(*origin, *dir, light.centre, light.R));
}

// ---- tracing

void TracePhotons(const SoilCells& cells, const MossOccluders& mosses, const PhotonLight& light,
                  int photons, Pcg32* rng, PhotonMap* map, std::vector<geom::CastRay>* rays) {
  map->photons.clear();
  map->stored_by_depth.assign(static_cast<std::size_t>(light.max_bounces) + 1, 0);
  map->power_by_depth.assign(static_cast<std::size_t>(light.max_bounces) + 1, 0.0);
  map->escaped = map->absorbed = 0;
  map->canopy_intercepted = map->canopy_absorbed = 0;
  map->canopy_power_absorbed = 0;
  const CanopyShade* canopy =
      light.canopy != nullptr && !light.canopy->empty() ? light.canopy.get() : nullptr;
  const double piR2 = det::kPi * light.R * light.R;
  // The budget's sky share (spec §1.3); no sky photons without indirect light.
  const bool sky = light.indirect && light.S_sky > 0.0;
  const double f_sky = sky ? 2.0 * light.S_sky / (light.S_sun + 2.0 * light.S_sky) : 0.0;
  map->emitted_sky = static_cast<int>(std::lround(photons * f_sky));
  map->emitted_sun = photons - map->emitted_sky;
  map->dPhi_sun = map->emitted_sun > 0 ? light.S_sun * piR2 / map->emitted_sun : 0.0;
  map->dPhi_sky = map->emitted_sky > 0 ? 2.0 * piR2 * light.S_sky / map->emitted_sky : 0.0;
  map->power_emitted = map->emitted_sun * map->dPhi_sun + map->emitted_sky * map->dPhi_sky;
  const SunFrame sun_frame(light);
  for (int i = 0; i < photons; ++i) {
    glm::dvec3 origin, dir;
    double power;
    if (i < map->emitted_sun) {
      EmitSunPhotonIn(light, sun_frame, rng, &origin, &dir);
      power = map->dPhi_sun;
    } else {
      // A sky photon: a direction uniform over the upper hemisphere, a parallel beam from a disc
      // of radius R at 2R on the sky side.
      const double y = rng->Uniform();
      const double r_xz = std::sqrt(std::max(0.0, 1.0 - y * y));
      double s = 0, c = 1;
      det::SinCos(2.0 * det::kPi * rng->Uniform(), &s, &c);
      const glm::dvec3 to_sky(r_xz * c, y, r_xz * s);
      glm::dvec3 b1, b2;
      BasisAbout(to_sky, &b1, &b2);
      const double rr = light.R * std::sqrt(rng->Uniform());
      det::SinCos(2.0 * det::kPi * rng->Uniform(), &s, &c);
      origin = light.centre + (2.0 * light.R) * to_sky + (rr * c) * b1 + (rr * s) * b2;
      dir = -to_sky;
      power = map->dPhi_sky;
    }
    for (int depth = 0;; ++depth) {
      const geom::RayHit hit =
          geom::FirstHitWithoutNormal(cells.mesh, cells.bvh, glm::vec3(origin), glm::vec3(dir),
                                      std::numeric_limits<float>::infinity());
      if (rays != nullptr)
        rays->push_back({glm::vec3(origin), glm::vec3(dir), std::numeric_limits<float>::infinity(),
                         hit.hit, hit.triangle, hit.distance});
      double t_moss = 0;
      uint32_t moss = 0;
      const double t_mesh =
          hit.hit ? static_cast<double>(hit.distance) : std::numeric_limits<double>::infinity();
      const bool on_moss = mosses.FirstHit(origin, dir, t_mesh, &t_moss, &moss);
      if (canopy != nullptr) {
        // The leaves before the first hit: an optical depth drawn for the path (one draw a path
        // segment, only with a canopy, so a scene without one keeps its bits).
        const double tau = -det::Log(1.0 - rng->Uniform());
        double t_leaf = 0;
        if (canopy->Intercept(origin, dir, on_moss ? t_moss : t_mesh, tau, &t_leaf)) {
          ++map->canopy_intercepted;
          if (!light.indirect || depth >= light.max_bounces || rng->Uniform() >= light.omega_leaf) {
            ++map->canopy_absorbed;
            map->canopy_power_absorbed += power;
            ++map->absorbed;
            break;
          }
          // Reflected (about −dir) or transmitted (about dir), one half each.
          const glm::dvec3 facing = rng->Uniform() < 0.5 ? -dir : dir;
          origin += t_leaf * dir;
          dir = CosineDirection(facing, rng);
          continue;
        }
      }
      if (!hit.hit && !on_moss) {
        ++map->escaped;
        break;
      }
      Photon p;
      p.depth = static_cast<uint8_t>(depth);
      p.power = power;
      p.on_moss = on_moss;
      if (on_moss) {
        p.position = origin + t_moss * dir;
        p.normal = glm::normalize(p.position - mosses.centre(moss));
        p.target = moss;
      } else {
        p.position = glm::dvec3(hit.point);
        const glm::dvec3 n = cells.normal[hit.triangle];
        p.normal = glm::dot(n, dir) < 0.0 ? n : -n;  // the side hit
        p.target = hit.triangle;
      }
      map->photons.push_back(p);
      ++map->stored_by_depth[depth];
      map->power_by_depth[depth] += power;
      // Russian roulette (§3.4): reflected with probability ρ, power kept; else absorbed.
      if (!light.indirect || depth >= light.max_bounces ||
          rng->Uniform() >= (on_moss ? light.rho_moss : light.rho_mesh)) {
        ++map->absorbed;
        break;
      }
      dir = CosineDirection(p.normal, rng);  // moss eq. 3.1 about the surface normal
      origin = p.position + kPhotonOffset * p.normal;
    }
  }
}

// ---- the soil's spread

SoilPhotonSpread::SoilPhotonSpread(const SoilCells& cells, double r_gather)
    : grid_(cells.centroid, r_gather), r2_(r_gather * r_gather) {
  const std::size_t n = cells.size();
  if (n == 0) return;
  // reach_t: the farthest corner of cell t from its centroid, with room for the ray test's edge
  // slack and the hit point's rounding to float.
  reach2_.resize(n);
  double reach_max = 0;
  for (std::size_t t = 0; t < n; ++t) {
    double far2 = 0;
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3 d = glm::dvec3(cells.mesh.positions[3 * t + k]) - cells.centroid[t];
      far2 = std::max(far2, glm::dot(d, d));
    }
    const double reach = std::sqrt(far2) * (1 + 1e-3) + 1e-6;
    reach2_[t] = reach * reach;
    reach_max = std::max(reach_max, reach);
  }
  const double r = std::sqrt(r2_);
  const geom::RadiusGrid wide(cells.centroid, r + reach_max);
  // One query a cell for both sides; over the cap, the grid alone.
  start_.assign(2 * n + 1, 0);
  sure_end_.assign(2 * n, 0);
  std::vector<uint32_t> lists[2][2];  // [side][0: sure, 1: maybe]
  for (std::size_t t = 0; t < n; ++t) {
    const double reach = std::sqrt(reach2_[t]);
    const double limit = (r + reach) * (1 + 1e-9);
    const double limit2 = limit * limit;
    // Within r − reach_t of t's centroid (with a relative 1e-6 to spare for the roundings of
    // either distance), a cell is within r of every point at most reach_t from that centroid.
    const double sure = (r - reach) * (1 - 1e-6);
    const double sure2 = sure > 0 ? sure * sure : -1.0;
    const glm::dvec3 front = cells.normal[t], back = -cells.normal[t];
    for (auto& side : lists)
      for (auto& list : side) list.clear();
    wide.ForEachWithin(cells.centroid[t], [&](uint32_t c, double d2) {
      if (d2 > limit2) return;
      const int kind = d2 <= sure2 ? 0 : 1;
      // The photon's own test, n_p·n > 0.5, with n_p the side hit (TracePhotons).
      if (glm::dot(front, cells.normal[c]) > 0.5) lists[0][kind].push_back(c);
      if (glm::dot(back, cells.normal[c]) > 0.5) lists[1][kind].push_back(c);
    });
    for (int side = 0; side < 2; ++side) {
      start_[2 * t + side] = static_cast<uint32_t>(items_.size());
      for (int kind = 0; kind < 2; ++kind) {
        std::sort(lists[side][kind].begin(), lists[side][kind].end());
        items_.insert(items_.end(), lists[side][kind].begin(), lists[side][kind].end());
        if (kind == 0) sure_end_[2 * t + side] = static_cast<uint32_t>(items_.size());
      }
    }
    if (items_.size() > kMaxCandidatesPerCell * n) {
      start_.clear();
      sure_end_.clear();
      items_.clear();
      items_.shrink_to_fit();
      return;
    }
  }
  start_[2 * n] = static_cast<uint32_t>(items_.size());
}

int SoilPhotonSpread::SideOf(const SoilCells& cells, const Photon& ph) const {
  if (start_.empty()) return -1;
  const uint32_t t = ph.target;
  const glm::dvec3 d = ph.position - cells.centroid[t];
  if (!(glm::dot(d, d) <= reach2_[t])) return -1;
  if (ph.normal == cells.normal[t]) return 0;
  if (ph.normal == -cells.normal[t]) return 1;
  return -1;
}

template <class Add>
void SoilPhotonSpread::ForEachCellOf(const SoilCells& cells, const Photon& ph, Add&& add) const {
  const int side = SideOf(cells, ph);
  if (side < 0) {  // the grid's radius query
    grid_.ForEachWithin(ph.position, [&](uint32_t c, double) {
      if (glm::dot(ph.normal, cells.normal[c]) > 0.5) add(c);
    });
    return;
  }
  const std::size_t list = 2 * static_cast<std::size_t>(ph.target) + side;
  const uint32_t* items = items_.data();
  // The sure cells are within r of the photon (SoilPhotonSpread's build) without a test.
  const uint32_t* sure_end = items + sure_end_[list];
  const uint32_t* it = items + start_[list];
  for (; it != sure_end; ++it) add(*it);
  // The grid's distance, ((dx² + dy²) + dz²) from the centroid to the photon (radius_grid.h).
  const glm::dvec3* centroid = cells.centroid.data();
  const glm::dvec3& q = ph.position;
  const uint32_t* end = items + start_[list + 1];
  for (; it != end; ++it) {
    const glm::dvec3& p = centroid[*it];
    const double dx = p.x - q.x, dy = p.y - q.y, dz = p.z - q.z;
    if ((dx * dx + dy * dy) + dz * dz <= r2_) add(*it);
  }
}

void SoilPhotonSpread::Spread(const SoilCells& cells, const PhotonMap& map,
                              std::vector<double>* S) const {
  double* out = S->data();
  // The land photons' powers in map order as runs of one power (bits): the sun's photons, then the
  // sky's. With at most two runs, a cell's sum is its first run's power added k_1 times, then the
  // second's k_2 times, so counts give the same bits as the additions (and a table of the first
  // power's running sums from 0 serves every cell that starts at zero).
  const auto bits_of = [](double x) {
    uint64_t b;
    std::memcpy(&b, &x, sizeof b);
    return b;
  };
  double power[2] = {0, 0};
  int runs = 0;
  for (const Photon& ph : map.photons) {
    if (ph.on_moss) continue;
    if (runs > 0 && bits_of(ph.power) == bits_of(power[runs - 1])) continue;
    if (runs == 2) {
      runs = 3;
      break;
    }
    power[runs++] = ph.power;
  }
  if (runs > 2) {  // any other map (tests' made-up photons): one addition a photon and cell
    for (const Photon& ph : map.photons)
      if (!ph.on_moss) ForEachCellOf(cells, ph, [&](uint32_t c) { out[c] += ph.power; });
    return;
  }
  if (runs == 0) return;
  const std::size_t n = cells.size();
  std::vector<uint32_t> counts(2 * n, 0);  // [run][cell]
  int run = 0;
  for (const Photon& ph : map.photons) {
    if (ph.on_moss) continue;
    if (run == 0 && bits_of(ph.power) != bits_of(power[0])) run = 1;
    uint32_t* count = counts.data() + run * n;
    ForEachCellOf(cells, ph, [&](uint32_t c) { ++count[c]; });
  }
  std::vector<double> sums(1, 0.0);  // sums[k]: 0 + power[0] added k times
  for (std::size_t c = 0; c < n; ++c) {
    const uint32_t k0 = counts[c], k1 = counts[n + c];
    double v = out[c];
    if (k0 > 0) {
      if (v == 0.0) {
        while (sums.size() <= k0) sums.push_back(sums.back() + power[0]);
        v = sums[k0];
      } else {
        for (uint32_t k = 0; k < k0; ++k) v += power[0];
      }
    }
    for (uint32_t k = 0; k < k1; ++k) v += power[1];
    out[c] = v;
  }
}

// ---- the gather

Result<PhotonGather> PhotonGather::Build(const PhotonMap& map, double r_gather) {
  std::vector<glm::dvec3> points;
  points.reserve(map.photons.size());
  for (const Photon& p : map.photons) points.push_back(p.position);
  for (const glm::dvec3& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      return Status::Error("photons", "a photon's position is not finite");
  if (!(r_gather > 0) || !std::isfinite(r_gather))
    return Status::Error("r_gather", "must be a positive number");
  geom::RadiusGrid grid(points, r_gather);
  std::vector<Slot> slots;
  slots.reserve(points.size());
  for (uint32_t i : grid.order()) {
    const Photon& p = map.photons[i];
    slots.push_back({p.normal, p.power, p.on_moss});
  }
  return PhotonGather(std::move(grid), std::move(slots), r_gather);
}

// The photons' power within r of x on faces turned the query's way (spec §4.6), summed in the
// grid's order (its buckets, then photon index: the same in every build); the distance as
// RadiusGrid::ForEachWithin's.
double PhotonGather::Gather(const glm::dvec3& x, const glm::dvec3& n, bool all) const {
  double sum = 0.0;
  const double r2 = r_ * r_;
  const glm::dvec3* points = grid_.slot_points().data();
  const Slot* slots = slots_.data();
  grid_.ForEachRowAround(x, [&](uint32_t k0, uint32_t k1) {
    for (uint32_t k = k0; k < k1; ++k) {
      const glm::dvec3& p = points[k];
      const double dx = p.x - x.x, dy = p.y - x.y, dz = p.z - x.z;
      if (!((dx * dx + dy * dy) + dz * dz <= r2)) continue;
      const Slot& s = slots[k];
      if ((all || !s.on_moss) && glm::dot(s.normal, n) > 0.5) sum += s.power;
    }
  });
  return sum / (det::kPi * r_ * r_);
}

}  // namespace niwa::moss

// A moss's gemmae, spores, germination and the seed rules among mosses: eqs 3.22-3.24 of Nomura
// 2010.
#include "moss/life_cycle.h"

#include <algorithm>
#include <cmath>

#include "math/det_math.h"
#include "moss/fitness.h"

namespace niwa::moss {
namespace {

// ((dx² + dy²) + dz²) in double, as geom::PointIndex computes it.
double LifeCycleDistance2(const glm::dvec3& a, const glm::dvec3& b) {
  const double dx = a.x - b.x, dy = a.y - b.y, dz = a.z - b.z;
  return (dx * dx + dy * dy) + dz * dz;
}

// A draw in (0, 1): the middle of one of 2³² equal steps, never 0 or 1.
double LifeCycleOpenUniform(Pcg32* rng) {
  return (static_cast<double>(rng->NextU32()) + 0.5) * (1.0 / 4294967296.0);
}

// The relative slack of ContactDistance.
constexpr double kLifeCycleContactSlack = 1e-9;

}  // namespace

LifeRules LifeRulesOf(const MossParams& p) {
  LifeRules r;
  r.s = p.Get(MossParam::kMossSize);
  r.gemma_step = p.Get(MossParam::kGemmaStep);
  r.spore_G = p.Get(MossParam::kSporeG);
  r.L_spore_0 = p.Get(MossParam::kLSpore0);
  r.L_spore_1 = p.Get(MossParam::kLSpore1);
  r.L_gemma_0 = p.Get(MossParam::kLGemma0);
  r.L_gemma_1 = p.Get(MossParam::kLGemma1);
  r.k = p.Get(MossParam::kKGemma);
  r.l = p.Get(MossParam::kLSporeDistance);
  r.interior_count = p.GetInt(MossParam::kInteriorCount);
  r.interior_radius = p.Get(MossParam::kInteriorRadius);
  r.overlap = p.Get(MossParam::kOverlap);
  return r;
}

int GemmaeDue(double G_moss, double gemma_step, bool inside_mat, double* G_max) {
  if (!(G_moss > *G_max)) return 0;
  // §3.6: one gemma each time G_moss rises by gemma_step (0.5), counted from the running maximum.
  const double before = std::floor(*G_max / gemma_step);
  const double after = std::floor(G_moss / gemma_step);
  *G_max = G_moss;
  if (inside_mat) return 0;  // §3.8: inside a mat a moss grows but makes no gemmae
  return static_cast<int>(std::min(after - before, 1.0e9));
}

bool InsideMat(const glm::dvec3& centre, const std::vector<glm::dvec3>& others,
               const LifeRules& rules) {
  const double radius = rules.interior_radius * rules.s;
  const double radius2 = radius * radius;
  int count = 0;
  for (const glm::dvec3& other : others) {
    if (LifeCycleDistance2(centre, other) <= radius2 && ++count >= rules.interior_count) {
      return true;
    }
  }
  return false;
}

glm::dvec3 RandomUnitVector(Pcg32* rng) {
  const double z = 1.0 - 2.0 * rng->Uniform();
  const double psi = 2.0 * det::kPi * rng->Uniform();
  const double r = std::sqrt(std::max(0.0, (1.0 - z) * (1.0 + z)));
  double sin_psi = 0, cos_psi = 1;
  det::SinCos(psi, &sin_psi, &cos_psi);
  return {r * cos_psi, r * sin_psi, z};
}

glm::dvec3 GemmaStart(const glm::dvec3& parent, double k, Pcg32* rng) {
  const glm::dvec3 I = RandomUnitVector(rng);
  return parent + k * I;  // moss eq. 3.22: B = M + k·I
}

bool MakesSpore(double G_moss, bool growing, bool rain_day, double spore_G) {
  // §3.6: G_moss ≥ 2.0 and growing, in an environment that allows spores (a rain day, §4.19).
  return G_moss >= spore_G && growing && rain_day;
}

glm::dvec3 SporeDirection(const glm::dvec3& N, Pcg32* rng) {
  // cos φ uniform over (cos 45°, 1) ∪ (−1, −cos 45°): equal solid angles, one draw picks both.
  const double one_minus_c45 = 1.0 - std::sqrt(0.5);
  const double t = 2.0 * LifeCycleOpenUniform(rng);
  const double cos_phi = t < 1.0 ? 1.0 - t * one_minus_c45 : -(1.0 - (t - 1.0) * one_minus_c45);
  const double sin_phi = std::sqrt(std::max(0.0, (1.0 - cos_phi) * (1.0 + cos_phi)));
  const double psi = 2.0 * det::kPi * rng->Uniform();
  double sin_psi = 0, cos_psi = 1;
  det::SinCos(psi, &sin_psi, &cos_psi);
  // An orthonormal basis about N (Duff et al. 2017, branchless up to the sign).
  const double sign = N.z >= 0.0 ? 1.0 : -1.0;
  const double a = -1.0 / (sign + N.z);
  const double b = N.x * N.y * a;
  const glm::dvec3 b1(1.0 + sign * N.x * N.x * a, sign * b, -sign * N.x);
  const glm::dvec3 b2(b, sign + N.y * N.y * a, -N.y);
  return (sin_phi * cos_psi) * b1 + (sin_phi * sin_psi) * b2 + cos_phi * N;
}

glm::dvec3 SporeStart(const glm::dvec3& parent, const glm::dvec3& N, double l, Pcg32* rng) {
  const glm::dvec3 I_N = SporeDirection(N, rng);
  return parent + l * I_N;  // moss eq. 3.23: Q = M + l·I_N
}

double GerminationScore(double G, double L, SeedKind kind, const LifeRules& rules) {
  const double L_0 = kind == SeedKind::kSpore ? rules.L_spore_0 : rules.L_gemma_0;
  const double L_1 = kind == SeedKind::kSpore ? rules.L_spore_1 : rules.L_gemma_1;
  // moss eq. 3.24: G·g(L, L_0, L_1, 1), and g with n = 1 is the range score s (eq 3.19).
  return G * RangeScore(L, L_0, L_1);
}

double SeedWindowScore(double L, SeedKind kind, const LifeRules& rules) {
  const double L_0 = kind == SeedKind::kSpore ? rules.L_spore_0 : rules.L_gemma_0;
  const double L_1 = kind == SeedKind::kSpore ? rules.L_spore_1 : rules.L_gemma_1;
  return RangeScore(L, L_0, L_1);  // g of eq 3.24 (GerminationScore's factor)
}

SeedFate SeedDay(double G, double L, SeedKind kind, double tau_b, bool at_cap,
                 const LifeRules& rules) {
  return SeedDayOfScore(G, SeedWindowScore(L, kind, rules), L, kind, tau_b, at_cap, rules);
}

SeedFate SeedDayOfScore(double G, double g, double L, SeedKind kind, double tau_b, bool at_cap,
                        const LifeRules& rules) {
  if (G * g > tau_b) {  // moss eq. 3.24 (GerminationScore: G·g)
    return at_cap ? SeedFate::kWaits : SeedFate::kGerminates;
  }
  // Past the window's centre g(L) only falls, and G ≤ 1: once g(L) ≤ τ_b the seed never will.
  const double L_0 = kind == SeedKind::kSpore ? rules.L_spore_0 : rules.L_gemma_0;
  const double L_1 = kind == SeedKind::kSpore ? rules.L_spore_1 : rules.L_gemma_1;
  if (L > (L_0 + L_1) / 2.0 && g <= tau_b) return SeedFate::kExpires;
  return SeedFate::kWaits;
}

double ContactDistance(const LifeRules& rules) { return rules.s * (1.0 + kLifeCycleContactSlack); }

MossRest RestOnMoss(const glm::dvec3& seed, const std::vector<glm::dvec3>& centres,
                    const LifeRules& rules) {
  MossRest rest;
  const double contact = ContactDistance(rules);
  double best2 = contact * contact;
  for (uint32_t i = 0; i < centres.size(); ++i) {
    const double d2 = LifeCycleDistance2(seed, centres[i]);
    if (d2 < best2 || (!rest.touches && d2 == best2)) {
      best2 = d2;
      rest.touches = true;
      rest.moss = i;
    }
  }
  if (!rest.touches) {
    rest.position = seed;
    return rest;
  }
  return RestedOn(seed, centres, rest.moss, best2, rules);
}

MossRest RestedOn(const glm::dvec3& seed, const std::vector<glm::dvec3>& centres, uint32_t moss,
                  double d2, const LifeRules& rules) {
  MossRest rest;
  rest.touches = true;
  rest.moss = moss;
  rest.position = seed;
  const double o = rules.overlap * rules.s;
  // §3.6 (spec §1.5.6): a seed touching a moss rests on it, s from its centre.
  if (d2 > 0.0 && !(d2 < o * o)) {
    const glm::dvec3& c = centres[moss];
    rest.position = c + (seed - c) * (rules.s / std::sqrt(d2));
  }
  return rest;
}

MossRest FallOntoMosses(const glm::dvec3& seed, const std::vector<glm::dvec3>& centres,
                        const LifeRules& rules) {
  MossRest rest;
  const double s2 = rules.s * rules.s;
  double best_y = 0;
  for (uint32_t i = 0; i < centres.size(); ++i) {
    const glm::dvec3& c = centres[i];
    const double dx = seed.x - c.x, dz = seed.z - c.z;
    const double h2 = dx * dx + dz * dz;
    if (h2 > s2) continue;
    // §3.3: a falling seed stops where it first touches a moss: the top of the sphere of radius s
    // about the moss's centre (two spheres of diameter s touch).
    const double y = c.y + std::sqrt(s2 - h2);
    if (y > seed.y) continue;
    if (!rest.touches || y > best_y) {
      rest.touches = true;
      rest.moss = i;
      best_y = y;
    }
  }
  rest.position = rest.touches ? glm::dvec3(seed.x, best_y, seed.z) : seed;
  return rest;
}

namespace {
std::vector<glm::dvec3> Flat(const std::vector<glm::dvec3>& points) {
  std::vector<glm::dvec3> flat;
  flat.reserve(points.size());
  for (const glm::dvec3& p : points) flat.emplace_back(p.x, 0.0, p.z);
  return flat;
}
}  // namespace

MatBuckets::MatBuckets(const std::vector<glm::dvec3>& centres, const LifeRules& rules,
                       std::size_t max_buckets)
    : centres_(&centres),
      near_(centres, ContactDistance(rules), max_buckets),
      below_(Flat(centres), rules.s, max_buckets) {}

MossRest MatBuckets::Rest(const glm::dvec3& seed, const LifeRules& rules) const {
  // RestOnMoss: the least d² within ContactDistance (the grid's r² is its contact²), ties to the
  // lower index.
  bool touches = false;
  uint32_t best = 0;
  double best2 = 0;
  near_.ForEachWithin(seed, [&](uint32_t i, double d2) {
    if (!touches || d2 < best2 || (d2 == best2 && i < best)) touches = true, best = i, best2 = d2;
  });
  if (!touches) {
    MossRest rest;
    rest.position = seed;
    return rest;
  }
  return RestedOn(seed, *centres_, best, best2, rules);
}

MossRest MatBuckets::Fall(const glm::dvec3& seed, const LifeRules& rules) const {
  // FallOntoMosses: h² <= s², the highest contact not above the seed, ties to the lower index.
  MossRest rest;
  const double s2 = rules.s * rules.s;
  double best_y = 0;
  below_.ForEachWithin(glm::dvec3(seed.x, 0.0, seed.z), [&](uint32_t i, double h2) {
    const double y = (*centres_)[i].y + std::sqrt(s2 - h2);
    if (y > seed.y) return;
    if (!rest.touches || y > best_y || (y == best_y && i < rest.moss))
      rest.touches = true, rest.moss = i, best_y = y;
  });
  rest.position = rest.touches ? glm::dvec3(seed.x, best_y, seed.z) : seed;
  return rest;
}

double PlacePriority(const SpeciesRanges& species, double G_moss) {
  return species.alpha_g * (1.0 + std::max(G_moss, 0.0));  // spec §4.22
}

std::vector<uint32_t> Occupants(const glm::dvec3& position, const std::vector<glm::dvec3>& centres,
                                const LifeRules& rules) {
  const double o = rules.overlap * rules.s;
  std::vector<uint32_t> out;
  for (uint32_t i = 0; i < centres.size(); ++i) {
    if (LifeCycleDistance2(position, centres[i]) < o * o) out.push_back(i);
  }
  return out;
}

bool WinsPlace(double seed_priority, const std::vector<double>& occupant_priorities) {
  for (double p : occupant_priorities) {
    if (!(seed_priority > p)) return false;  // ties keep the incumbent
  }
  return true;
}

}  // namespace niwa::moss

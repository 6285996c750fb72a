// A moss's life cycle after its growth (Nomura 2010 §3.3, §3.6, §3.8; ../shared/specs/moss.md
// §1.5.4-1.5.8): when a moss makes gemmae (a running maximum of G_moss, none inside a mat) and
// spores (G_moss ≥ spore_G, growing, on a rain day), where they start (eqs 3.22 and 3.23, drawn
// from the project's seeded Pcg32), when a seed germinates, waits or expires (eq 3.24), and the
// rules between a seed and the moss centres near it: resting on a moss it touches, falling along
// −y onto a moss, and the contest for an occupied place. Pure functions of a moss and its
// neighbours' values, deterministic math only. Does not: find neighbours (geom::PointIndex;
// MatBuckets only answers RestOnMoss and FallOntoMosses faster), touch a mesh (snapping to a face,
// falling onto a face, back faces, soil cells: the run decides those with the mesh and compares
// heights with FallOntoMosses), keep the seed pool or the caps, or know a day number.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "geom/radius_grid.h"
#include "moss/moss.h"
#include "moss/moss_params.h"
#include "random/pcg32.h"

namespace niwa::moss {

// The two kinds of seed (種子): a gemma (無性芽, vegetative, eq 3.22) and a spore (胞子, eq 3.23).
enum class SeedKind : int { kGemma = 0, kSpore = 1 };

// The life-cycle rows of the moss table the functions below read (moss_params.h).
struct LifeRules {
  double s;                     // moss size [m] (moss_size)
  double gemma_step;            // a gemma each time G_moss rises by this
  double spore_G;               // G_moss a growing moss needs to make spores
  double L_spore_0, L_spore_1;  // spore germination window [day] (eq 3.24: 60, 365)
  double L_gemma_0, L_gemma_1;  // gemma germination window [day] (eq 3.24: −60, 60)
  double k;                     // parent-gemma distance [m] (eq 3.22)
  double l;                     // parent-spore distance [m] (eq 3.23)
  int interior_count;           // this many others within interior_radius·s: inside a mat
  double interior_radius;       // in s
  double overlap;               // a seed closer than overlap·s to a moss centre contests its place
};
LifeRules LifeRulesOf(const MossParams& params);

// ---- gemmae (§3.6, eq 3.22)

// How many gemmae a moss makes today: one for each multiple of gemma_step that its total growth
// G_moss has passed above its running maximum `*G_max` (spec §4.20: a fall and a rise again make
// none until the old maximum is passed). Updates *G_max. Inside a mat (`inside_mat`, §3.8) the
// count is 0, but the maximum still moves (the gemma is not made, not postponed).
int GemmaeDue(double G_moss, double gemma_step, bool inside_mat, double* G_max);

// §3.8: a moss is inside a mat when at least interior_count other mosses have their centres within
// interior_radius·s (distance ≤, as geom::PointIndex::WithinRadius) of its centre. `others` are
// the other mosses' centres (the moss itself excluded by the caller).
bool InsideMat(const glm::dvec3& centre, const std::vector<glm::dvec3>& others,
               const LifeRules& rules);

// A uniform random unit vector (the I of eq 3.22): cos of the polar angle z = 1 − 2u_1, azimuth
// 2πu_2, two draws of `rng` in that order.
glm::dvec3 RandomUnitVector(Pcg32* rng);

// Eq 3.22: the gemma's start B = M + k·I, M the parent's centre, I = RandomUnitVector.
glm::dvec3 GemmaStart(const glm::dvec3& parent, double k, Pcg32* rng);

// ---- spores (§3.6, eq 3.23)

// A moss makes one spore today when G_moss ≥ spore_G, it is growing today (D > 0) and the day
// allows spores (spec §4.19: a rain day, P_i > 0).
bool MakesSpore(double G_moss, bool growing, bool rain_day, double spore_G);

// The I_N of eq 3.23: a unit vector whose angle φ to the unit face normal N is in 0° < φ < 45° or
// 135° < φ < 180°, uniform over that solid angle: the cone is picked and cos φ drawn from one draw
// (taken at the middle of its 2⁻³² step, so φ never reaches 0°, 45°, 135° or 180°), the azimuth
// about N from a second.
glm::dvec3 SporeDirection(const glm::dvec3& N, Pcg32* rng);

// Eq 3.23: the spore's start Q = M + l·I_N.
glm::dvec3 SporeStart(const glm::dvec3& parent, const glm::dvec3& N, double l, Pcg32* rng);

// ---- germination (§3.6, eq 3.24)

// G·g(L, L_0, L_1, 1) of eq 3.24: the seed's species fitness G at its place times the range score
// of its age L [days since it was made] over its kind's window.
double GerminationScore(double G, double L, SeedKind kind, const LifeRules& rules);

enum class SeedFate : int {
  kWaits = 0,       // not yet (or the moss count is at its cap)
  kGerminates = 1,  // eq 3.24 holds and there is room
  kExpires = 2,     // past its window's centre with g(L) ≤ τ_b: it can never germinate (G ≤ 1)
};
// One day of a waiting seed: eq 3.24 against the species' τ_b; at the cap (`at_cap`) a seed that
// would germinate waits (spec §1.5.8).
SeedFate SeedDay(double G, double L, SeedKind kind, double tau_b, bool at_cap,
                 const LifeRules& rules);
// g(L, L_0, L_1, 1) of eq 3.24 alone: the window's score of a seed of age L. When it is at most τ_b
// no G in [0, 1] (FitnessOf's range) can make G·g exceed τ_b (G·g ≤ g, rounding kept), so SeedDay
// gives the fate of G = 0 for every G: the run then skips the seed's gather and fitness.
double SeedWindowScore(double L, SeedKind kind, const LifeRules& rules);
// SeedDay with the window's score g = SeedWindowScore(L, kind, rules) given (the run looks it up
// by the seed's age and kind, once a run): the same fate, G·g and g ≤ τ_b as SeedDay works out.
SeedFate SeedDayOfScore(double G, double g, double L, SeedKind kind, double tau_b, bool at_cap,
                        const LifeRules& rules);

// ---- seeds among mosses (§3.3, §3.6; spec §1.5.6-1.5.7)

// The contact distance between a seed and a moss: s, with a relative slack of 1e-9 so that a seed
// placed exactly s from a centre (a gemma with k = s, a seed rested by RestOnMoss) touches it
// whatever the rounding.
double ContactDistance(const LifeRules& rules);

// A seed resting on a moss it touches.
struct MossRest {
  bool touches = false;
  uint32_t moss = 0;    // index into the centres
  glm::dvec3 position;  // where the seed rests
};
// The nearest centre within ContactDistance of `seed` (ties: the lower index). A seed at least
// overlap·s from it is moved out along the line between the centres to exactly s (the spec's
// "rests on it, centre s from that moss"); a closer one stays where it is (it is where a moss
// already is: Occupants and WinsPlace decide); a seed exactly at the centre stays too.
MossRest RestOnMoss(const glm::dvec3& seed, const std::vector<glm::dvec3>& centres,
                    const LifeRules& rules);

// RestOnMoss's last step, given its nearest centre `moss` at squared distance d2 (for a caller that
// found it through buckets with the same distances and tie rule): touches, and the position.
MossRest RestedOn(const glm::dvec3& seed, const std::vector<glm::dvec3>& centres, uint32_t moss,
                  double d2, const LifeRules& rules);

// A seed falling along −y from `seed` onto moss spheres: the first centre c it meets is the one
// with horizontal distance d ≤ s whose contact height c.y + √(s² − d²) is highest and not above
// seed.y (ties: the lower index); it rests there, s from c. `touches` false: no moss below (the run
// then lets it fall to the mesh, or compares this height with the mesh's hit: the higher wins).
MossRest FallOntoMosses(const glm::dvec3& seed, const std::vector<glm::dvec3>& centres,
                        const LifeRules& rules);

// The centres a seed may rest on in buckets (geom::RadiusGrid), for many seeds a day: RestOnMoss's
// nearest within ContactDistance and FallOntoMosses's highest within s across, by the very
// distances (a bucket's ((dx² + dy²) + dz²) of the centre minus the seed is the same bits as the
// seed minus the centre; with every y at 0 it is the fall's dx² + dz²) and the same tie rule (the
// lower index), visiting the centres near the seed instead of all of them. `centres` must outlive
// it; `max_buckets` as RadiusGrid's.
class MatBuckets {
 public:
  MatBuckets(const std::vector<glm::dvec3>& centres, const LifeRules& rules,
             std::size_t max_buckets);
  MossRest Rest(const glm::dvec3& seed, const LifeRules& rules) const;  // RestOnMoss's answer
  MossRest Fall(const glm::dvec3& seed, const LifeRules& rules) const;  // FallOntoMosses's answer

 private:
  const std::vector<glm::dvec3>* centres_;
  geom::RadiusGrid near_;   // the centres, buckets of ContactDistance
  geom::RadiusGrid below_;  // (x, 0, z) of the centres, buckets of s
};

// The priority of a moss in a contest for a place (spec §4.22: "by species and growth"):
// α_g·(1 + max(G_moss, 0)); a seed has G_moss 0.
double PlacePriority(const SpeciesRanges& species, double G_moss);

// The mosses whose centres are closer than overlap·s (strictly) to `position`, in index order.
std::vector<uint32_t> Occupants(const glm::dvec3& position, const std::vector<glm::dvec3>& centres,
                                const LifeRules& rules);

// Whether a seed (or a just-germinated moss) of priority `seed_priority` takes a place held by
// occupants of the given priorities: it must be higher than each of theirs (ties keep the
// incumbent); if it wins every occupant vanishes, else the seed does. No occupants: it stays.
bool WinsPlace(double seed_priority, const std::vector<double>& occupant_priorities);

}  // namespace niwa::moss

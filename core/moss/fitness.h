// A moss's daily fitness, growth and death (Nomura 2010 §3.6 after Ogasawara et al.;
// ../shared/specs/moss.md §1.5.1-1.5.3): the range score s (eq 3.18), its tolerance form g (eq
// 3.19, clamped to [0, 1] by default or the normalised form, spec §4.14), the fitness G from
// surface temperature, humidity and light (eq 3.17), the day's growth D (eq 3.20) and the total
// G_moss (eq 3.21) with the death rule. Pure functions, deterministic math only. Does not: find
// T_s, rh_s or S (soil.h, the photon pass), make gemmae or spores, germinate seeds (eqs 3.22-3.24),
// place mosses or know a day number.
#pragma once

#include <cstdint>
#include <vector>

#include "moss/moss.h"
#include "moss/moss_params.h"

namespace niwa::moss {

// Eq 3.18: exp{−4·log 2/(x_1 − x_0)²·(x − (x_1 + x_0)/2)²}: 1 at the range's centre, 0.5 at
// x_0 and x_1 (natural log; needs x_0 ≠ x_1).
double RangeScore(double x, double x_0, double x_1);

// Eq 3.19 on a score s in [0, 1] with tolerance n in (0, 1]: 1/2 + (s − 1/2)^n above 1/2,
// 1/2 − (1/2 − s)^n at or below. For n < 1 it leaves [0, 1] (n 0.5: 1.2071 at s = 1); kClamped
// clamps it to [0, 1] (the default), kNormalized is 1/2 ± (1/2)·|2s − 1|^n (spec §4.14).
double Tolerance(double s, double n, GForm form);
// g(x, x_0, x_1, n) of eq 3.19: Tolerance(RangeScore(x, x_0, x_1), n, form).
double Suitability(double x, double x_0, double x_1, double n, GForm form);

// Eq 3.17's three factors and their product G.
struct Fitness {
  double g_T;   // g(T_s, T_0, T_1, n_T)
  double g_rh;  // g(rh_s, rh_0, rh_1, n_rh)
  double g_S;   // g(S, S_0, S_1, n_S)
  double G;     // g_T·g_rh·g_S
};
// Eq 3.17 for one species at a place with surface temperature T_s [K], surface humidity rh_s and
// light S [W/m²].
Fitness FitnessOf(const SpeciesRanges& species, double T_s, double rh_s, double S, GForm form);

// FitnessOf's G through a memo of each factor (a run's mosses and seeds ask the same T_s and rh_s
// of a cell kept from yesterday, and the few light values a handful of equal photons give, day
// after day): each factor is Suitability of its input, looked up by the input's bits in a
// direct-mapped table per species and variable, and worked out (and stored) on a miss. The same
// bits as FitnessOf(...).G (the same functions on the same inputs, multiplied in the same order).
// The species' ranges and the form must stay those of the first call (one run's table).
class FitnessMemo {
 public:
  double G(Species species, const SpeciesRanges& ranges, double T_s, double rh_s, double S,
           GForm form);
  // G's first product g_T·g_rh (the same factors and bits): G is it times g_S in [0, 1], so G is
  // at most it (rounding is monotone), whatever the light.
  double TemperatureHumidity(Species species, const SpeciesRanges& ranges, double T_s, double rh_s,
                             GForm form);

 private:
  static constexpr int kSlots = 1024;  // a power of two, per species and variable
  struct Slot {
    uint64_t bits = 0;
    double value = 0;
    bool used = false;
  };
  double Factor(int table, double x, double x_0, double x_1, double n, GForm form);
  std::vector<Slot> slots_;
};

// Eq 3.20: the day's growth D = α_g·(G − τ_g) (growing when D > 0, declining when D < 0).
double DailyGrowth(const SpeciesRanges& species, double G);

// A moss's growth so far: G_moss (eq 3.21, the sum of its D_i since germination) and its days.
struct MossGrowth {
  double G_moss = 0;
  int days = 0;
};
// One day: adds D to G_moss (eq 3.21) and says whether the moss dies today (§3.6: G_moss below τ_d
// while declining, D < 0; a new moss, G_moss 0 < τ_d, dies on its first declining day).
struct GrowthDay {
  double D;
  bool growing;  // D > 0
  bool dies;
};
GrowthDay AdvanceGrowth(const SpeciesRanges& species, double G, MossGrowth* growth);

}  // namespace niwa::moss

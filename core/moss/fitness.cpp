// A moss's fitness, growth and death: eqs 3.17-3.21 of Nomura 2010.
#include "moss/fitness.h"

#include <algorithm>
#include <cstring>

#include "math/det_math.h"

namespace niwa::moss {
namespace {

// x^n for x ≥ 0 and n > 0 with det_math (0^n = 0).
double FitnessPow(double x, double n) {
  if (n == 1.0) return x;
  if (x <= 0.0) return 0.0;
  return det::Exp(n * det::Log(x));
}

}  // namespace

double RangeScore(double x, double x_0, double x_1) {
  // moss eq. 3.18 (log is the natural logarithm: s = 0.5 at x_0 and x_1).
  const double width = x_1 - x_0;
  const double off = x - (x_1 + x_0) / 2.0;
  return det::Exp(-4.0 * det::kLn2 / (width * width) * (off * off));
}

double Tolerance(double s, double n, GForm form) {
  if (form == GForm::kNormalized) {
    // Spec §4.14's option: the same shape kept inside [0, 1].
    const double half = 0.5 * FitnessPow(std::min(1.0, 2.0 * std::abs(s - 0.5)), n);
    return s > 0.5 ? 0.5 + half : 0.5 - half;
  }
  // n = 1 is g = s (the thesis: 正規分布と相似); returned as is, since 1/2 − (1/2 − s) loses the
  // small scores far outside a range to rounding.
  if (n == 1.0) return s;
  // moss eq. 3.19, clamped to [0, 1] (spec §4.14; docs/moss-model.md).
  const double g = s > 0.5 ? 0.5 + FitnessPow(s - 0.5, n) : 0.5 - FitnessPow(0.5 - s, n);
  return std::clamp(g, 0.0, 1.0);
}

double Suitability(double x, double x_0, double x_1, double n, GForm form) {
  return Tolerance(RangeScore(x, x_0, x_1), n, form);
}

Fitness FitnessOf(const SpeciesRanges& sp, double T_s, double rh_s, double S, GForm form) {
  Fitness f;
  f.g_T = Suitability(T_s, sp.T_0, sp.T_1, sp.n_T, form);
  f.g_rh = Suitability(rh_s, sp.rh_0, sp.rh_1, sp.n_rh, form);
  f.g_S = Suitability(S, sp.S_0, sp.S_1, sp.n_S, form);
  f.G = f.g_T * f.g_rh * f.g_S;  // moss eq. 3.17
  return f;
}

double FitnessMemo::Factor(int table, double x, double x_0, double x_1, double n, GForm form) {
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  // Fibonacci hashing of the bits (a hint only: a slot is used when its bits match).
  const std::size_t k = static_cast<std::size_t>(table) * kSlots +
                        static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 54);
  Slot& slot = slots_[k];
  if (slot.used && slot.bits == bits) return slot.value;
  slot.bits = bits;
  slot.value = Suitability(x, x_0, x_1, n, form);
  slot.used = true;
  return slot.value;
}

double FitnessMemo::G(Species species, const SpeciesRanges& sp, double T_s, double rh_s, double S,
                      GForm form) {
  static_assert(kSlots == 1024, "the hash keeps 10 bits");
  if (slots_.empty()) slots_.resize(static_cast<std::size_t>(kSpeciesCount) * 3 * kSlots);
  const int t = 3 * static_cast<int>(species);
  const double g_T = Factor(t, T_s, sp.T_0, sp.T_1, sp.n_T, form);
  const double g_rh = Factor(t + 1, rh_s, sp.rh_0, sp.rh_1, sp.n_rh, form);
  const double g_S = Factor(t + 2, S, sp.S_0, sp.S_1, sp.n_S, form);
  return g_T * g_rh * g_S;  // moss eq. 3.17, FitnessOf's product
}

double FitnessMemo::TemperatureHumidity(Species species, const SpeciesRanges& sp, double T_s,
                                        double rh_s, GForm form) {
  if (slots_.empty()) slots_.resize(static_cast<std::size_t>(kSpeciesCount) * 3 * kSlots);
  const int t = 3 * static_cast<int>(species);
  const double g_T = Factor(t, T_s, sp.T_0, sp.T_1, sp.n_T, form);
  const double g_rh = Factor(t + 1, rh_s, sp.rh_0, sp.rh_1, sp.n_rh, form);
  return g_T * g_rh;  // moss eq. 3.17's first product
}

double DailyGrowth(const SpeciesRanges& sp, double G) {
  return sp.alpha_g * (G - sp.tau_g);  // moss eq. 3.20
}

GrowthDay AdvanceGrowth(const SpeciesRanges& sp, double G, MossGrowth* growth) {
  GrowthDay day;
  day.D = DailyGrowth(sp, G);
  growth->G_moss += day.D;  // moss eq. 3.21
  ++growth->days;
  day.growing = day.D > 0;
  // §3.6: a declining moss whose total growth is below τ_d dies.
  day.dies = day.D < 0 && growth->G_moss < sp.tau_d;
  return day;
}

}  // namespace niwa::moss

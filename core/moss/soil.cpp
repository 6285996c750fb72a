// One soil cell's heat and water: eqs 3.2-3.16 of Nomura 2010 in the thesis's order.
#include "moss/soil.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "math/det_math.h"
#include "params/param_text.h"

namespace niwa::moss {
namespace {

using P = MossParam;
constexpr double kLn10 = 2.30258509299404568402;
constexpr double kSecondsPerDay = 24.0 * 60.0 * 60.0;

// x^y for x ≥ 0 with det_math (0^y = 0 for y > 0, x^0 = 1).
double SoilPow(double x, double y) {
  if (y == 0.0) return 1.0;
  if (x <= 0.0) return 0.0;
  return det::Exp(y * det::Log(x));
}

}  // namespace

SoilConstants SoilConstantsOf(const MossParams& p) {
  SoilConstants k;
  k.sigma = p.Get(P::kSigma);
  k.p = p.Get(P::kP);
  k.ref = p.Get(P::kRef);
  k.D_ATM = p.Get(P::kDAtm);
  k.iota = p.Get(P::kIota);
  k.rho = p.Get(P::kRho);
  k.cp_rho = p.Get(P::kCpRho);
  k.C_Hmin = p.Get(P::kCHMin);
  k.C_Hmax = p.Get(P::kCHMax);
  k.delta_form = static_cast<DeltaForm>(p.GetInt(P::kDeltaForm));
  k.longwave = static_cast<Longwave>(p.GetInt(P::kLongwave));
  return k;
}

Weather ClimateOf(const MossParams& p) {
  return {p.Get(P::kT), p.Get(P::kRh), p.Get(P::kU), p.Get(P::kN), p.Get(P::kN0), 0.0};
}

double EvenRainOfDay(int day, double P_year, int P_days) {
  if (P_days <= 0 || day < 1) return 0.0;
  const long long now = static_cast<long long>(day) * P_days / 365;
  const long long before = static_cast<long long>(day - 1) * P_days / 365;
  return now > before ? P_year / P_days : 0.0;
}

Status CheckSoilCell(const SoilCell& c) {
  if (!(c.S >= 0 && c.S <= 1e6))
    return Status::Error("S", FormatNumber(c.S) + " is out of range; must be a number in [0, 1e6]");
  if (!(c.m_over_M >= 0 && c.m_over_M <= 1))
    return Status::Error("m_over_M",
                         FormatNumber(c.m_over_M) + " is out of range; must be a number in [0, 1]");
  if (!(c.theta >= 0 && c.theta <= c.law.theta_SAT)) {
    return Status::Error("theta", FormatNumber(c.theta) +
                                      " is out of range; must be a number in [0, theta_SAT = " +
                                      FormatNumber(c.law.theta_SAT) +
                                      "] (the bucket is full at "
                                      "theta_SAT, eqs 3.7-3.8)");
  }
  if (!(c.V_sky >= 0 && c.V_sky <= 1))
    return Status::Error("V_sky",
                         FormatNumber(c.V_sky) + " is out of range; must be a number in [0, 1]");
  return Status::Ok();
}

SoilWeatherTerms SoilWeatherTermsOf(const SoilConstants& k, const Weather& w) {
  SoilWeatherTerms d;
  const double T = w.T;
  // Sunshine ratio 日照率 A = N / N_0 (§3.5.1).
  d.A = w.N / w.N_0;
  // moss eq. 3.2: the cloud effect on the sky's longwave.
  d.C = 0.826 * d.A * d.A * d.A - 1.234 * d.A * d.A + 1.135 * d.A + 0.298;
  d.sigma_T4 = k.sigma * T * T * T * T;
  // moss eq. 3.3: longwave from the sky.
  d.L_sky = d.sigma_T4 * (1.0 - 0.26 * d.C);
  // moss eq. 3.12: Tetens, e_SAT in hPa with T in K.
  d.e_SAT = 6.1078 * det::Exp(kLn10 * (7.5 * (T - 273.15) / (T - 35.85)));
  // moss eq. 3.13: saturation specific humidity at T.
  d.q_SAT = (0.622 * d.e_SAT / k.p) / (1.0 - 0.378 * d.e_SAT / k.p);
  // moss eq. 3.15: Δ = dq_SAT/dT, T in °C here. The thesis prints 6.1078 where e_SAT(T) belongs
  // (Clausius-Clapeyron; spec §4.12): corrected by default, literal as delta_form = 1.
  const double t_C = T - 273.15;
  const double e_factor = k.delta_form == DeltaForm::kLiteral ? 6.1078 : d.e_SAT;
  const double de_dT = e_factor * (2500.0 - 2.4 * t_C) / (0.4615 * (273.15 + t_C) * (273.15 + t_C));
  const double dq_de = 0.622 * k.p / ((k.p - 0.378 * d.e_SAT) * (k.p - 0.378 * d.e_SAT));
  d.Delta = de_dT * dq_de;
  // moss eq. 3.11's linear emission term.
  d.four_sigma_T3 = 4.0 * k.sigma * T * T * T;
  return d;
}

SoilTerms SoilEnergyBalance(const SoilConstants& k, const Weather& w, const SoilCell& cell) {
  return SoilEnergyBalance(k, w, SoilWeatherTermsOf(k, w), cell);
}

SoilTerms SoilEnergyBalance(const SoilConstants& k, const Weather& w, const SoilWeatherTerms& day,
                            const SoilCell& cell) {
  SoilTerms t;
  const double T = w.T;
  t.A = day.A;  // §3.5.1 (SoilWeatherTermsOf)
  t.C = day.C;  // moss eq. 3.2
  t.sigma_T4 = day.sigma_T4;
  // moss eq. 3.3: longwave from the sky. The sky-view mode (spec §3.1, docs/moss-model.md) sees the
  // sky over the fraction V_sky of the cell's hemisphere and surfaces at air temperature elsewhere.
  const double L_sky = day.L_sky;
  t.L = k.longwave == Longwave::kSkyView ? cell.V_sky * L_sky + (1.0 - cell.V_sky) * t.sigma_T4
                                         : L_sky;
  // moss eq. 3.4: heat reaching the surface.
  t.R = (1.0 - k.ref) * cell.S + t.L;
  // moss eq. 3.5: bulk transfer coefficient, raised by dense moss.
  t.C_H = k.C_Hmin + (k.C_Hmax - k.C_Hmin) * cell.m_over_M;
  // moss eq. 3.8: θ = O_i / h (the bucket gives it; AdvanceSoilDay).
  t.theta = cell.theta;
  // moss eq. 3.9: the dry-layer law of the geology.
  t.F = cell.law.F_1 * SoilPow(cell.law.theta_SAT - cell.theta, cell.law.F_2);
  // moss eq. 3.10: evaporation efficiency.
  t.beta = 1.0 / (1.0 + t.C_H * w.U * t.F / k.D_ATM);
  t.e_SAT = day.e_SAT;  // moss eq. 3.12
  t.q_SAT = day.q_SAT;  // moss eq. 3.13
  t.Delta = day.Delta;  // moss eq. 3.15
  // moss eq. 3.11: the linearised surface energy balance.
  const double latent = k.iota * k.rho * t.beta * t.C_H * w.U;  // ιρβC_H U
  const double sensible = k.cp_rho * t.C_H * w.U;               // c_P ρ C_H U
  const double four_sigma_T3 = day.four_sigma_T3;
  t.dT = (t.R - t.sigma_T4 - latent * (t.q_SAT * (1.0 - w.rh))) /
         (four_sigma_T3 + sensible + latent * t.Delta);
  t.T_s = T + t.dT;
  t.H = sensible * t.dT;
  // moss eq. 3.14: latent heat (negative: dew).
  t.iota_E = latent * (t.q_SAT * (1.0 - w.rh) + t.Delta * t.dT);
  t.E = t.iota_E / k.iota;
  t.E_mm_day = kSecondsPerDay * t.E;
  // moss eq. 3.16: surface relative humidity.
  t.rh_s = t.beta + w.rh * t.q_SAT * (1.0 - t.beta) / (t.q_SAT + t.Delta * t.dT);
  // Fig 3.2's balance R -> ιE + H + σT_s⁴, linearised (eq 3.11) and at the true emission.
  t.residual_linear = t.R - (t.sigma_T4 + four_sigma_T3 * t.dT) - t.H - t.iota_E;
  const double T_s2 = t.T_s * t.T_s;
  t.residual_nonlinear = t.R - k.sigma * T_s2 * T_s2 - t.H - t.iota_E;
  return t;
}

Bucket MakeBucket(double h, const GeologyLaw& law, double O_start) {
  const double O_SAT = h * law.theta_SAT;  // moss eq. 3.7
  return {h, O_SAT, O_start * O_SAT};
}

SoilDay AdvanceSoilDay(const SoilConstants& k, const Weather& w, const GeologyLaw& law, double S,
                       double m_over_M, double V_sky, Bucket* b) {
  return AdvanceSoilDay(k, w, SoilWeatherTermsOf(k, w), law, S, m_over_M, V_sky, b);
}

SoilDay AdvanceSoilDay(const SoilConstants& k, const Weather& w, const SoilWeatherTerms& weather,
                       const GeologyLaw& law, double S, double m_over_M, double V_sky, Bucket* b) {
  SoilDay day;
  // moss eq. 3.6, rain first: water above O_SAT runs off.
  b->O += w.P;
  day.runoff = std::max(0.0, b->O - b->O_SAT);
  b->O = std::min(b->O, b->O_SAT);
  SoilCell cell;
  cell.law = law;
  cell.S = S;
  cell.m_over_M = m_over_M;
  cell.theta = std::min(b->O / b->h, law.theta_SAT);  // moss eq. 3.8
  cell.V_sky = V_sky;
  day.terms = SoilEnergyBalance(k, w, weather, cell);
  // moss eq. 3.6, evaporation out (dew in), kept within the bucket.
  b->O = std::clamp(b->O - kSecondsPerDay * day.terms.E, 0.0, b->O_SAT);
  return day;
}

namespace {
bool SameBits(double a, double b) {
  uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}
}  // namespace

SoilCellDay AdvanceSoilDayKept(const SoilConstants& k, const Weather& w,
                               const SoilWeatherTerms& weather, const GeologyLaw& law, double S,
                               double m_over_M, double V_sky, Bucket* b, SoilMemo* memo) {
  // moss eq. 3.6, rain first: water above O_SAT runs off (AdvanceSoilDay's steps).
  b->O += w.P;
  b->O = std::min(b->O, b->O_SAT);
  const double theta = std::min(b->O / b->h, law.theta_SAT);  // moss eq. 3.8
  if (!(memo->S >= 0) || !SameBits(memo->S, S) || !SameBits(memo->m_over_M, m_over_M) ||
      !SameBits(memo->theta, theta)) {
    SoilCell cell;
    cell.law = law;
    cell.S = S;
    cell.m_over_M = m_over_M;
    cell.theta = theta;
    cell.V_sky = V_sky;
    const SoilTerms terms = SoilEnergyBalance(k, w, weather, cell);
    *memo = {S, m_over_M, theta, terms.T_s, terms.rh_s, terms.E};
  }
  // moss eq. 3.6, evaporation out (dew in), kept within the bucket.
  b->O = std::clamp(b->O - kSecondsPerDay * memo->E, 0.0, b->O_SAT);
  return {memo->T_s, memo->rh_s, theta};
}

}  // namespace niwa::moss

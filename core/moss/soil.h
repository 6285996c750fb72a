// One soil cell's heat and water for one day (Nomura 2010 §3.5 after Kondo 1994 and Manabe's bucket
// model; ../shared/specs/moss.md §1.4): sky longwave (eqs 3.2-3.4), bulk transfer under moss (3.5),
// the bucket and its evaporation efficiency (3.6-3.10), the linearised surface energy balance
// (3.11-3.15, eq 3.15 corrected by default, literal as an option) and the surface humidity (3.16),
// each term named as in the thesis. Pure functions of their inputs, deterministic math only.
// Does not: find a cell's light S, its mosses m or its sky view (the photon pass and the scene),
// place cells on a mesh, or know a day number (the run gives each day's weather).
#pragma once

#include "base/status.h"
#include "moss/moss.h"
#include "moss/moss_params.h"

namespace niwa::moss {

// The constants of tables 3.5 and 3.6 and §3.5.2, and the two model choices (moss_params.h).
struct SoilConstants {
  double sigma;   // σ [W m⁻² K⁻⁴]
  double p;       // air pressure [hPa]
  double ref;     // albedo
  double D_ATM;   // vapour diffusivity [m² s⁻¹]
  double iota;    // ι, latent heat of vaporisation [J/kg]
  double rho;     // ρ, air density [kg/m³]
  double cp_rho;  // c_P·ρ [J K⁻¹ m⁻³]
  double C_Hmin, C_Hmax;
  DeltaForm delta_form = DeltaForm::kCorrected;
  Longwave longwave = Longwave::kThesis;
};
SoilConstants SoilConstantsOf(const MossParams& params);

// One day's weather (table 3.1's inputs, daily means).
struct Weather {
  double T;    // air temperature [K]
  double rh;   // relative humidity [-]
  double U;    // wind speed [m/s]
  double N;    // sunshine hours [h]
  double N_0;  // possible sunshine hours [h]
  double P;    // rain of the day, P_i [mm]
};
// The constant climate of table 4.3 on a dry day (P = 0); RainOfDay gives a day's P_i.
Weather ClimateOf(const MossParams& params);
// P_i of day i ≥ 1 of the constant climate with rain days spaced evenly (spec §1.6: day i rains
// iff floor(i·P_d/365) > floor((i − 1)·P_d/365)), P_i = P / P_d on a rain day, else 0.
double EvenRainOfDay(int day, double P_year, int P_days);

// What one cell brings to the balance besides the weather.
struct SoilCell {
  GeologyLaw law;       // table 3.4 of the cell's geology
  double S = 0;         // light (日射量) [W/m²]
  double m_over_M = 0;  // m/M of eq 3.5, in [0, 1]
  double theta = 0;     // volumetric water content θ (eq 3.8), in [0, θ_SAT]
  double V_sky = 1;     // sky view, in [0, 1]; read by the sky-view longwave only
};
// Ok, or the error naming the cell's field ("S", "m_over_M", "theta", "V_sky") and its range.
Status CheckSoilCell(const SoilCell& cell);

// Every term of eqs 3.2-3.16 for one cell and day, named as in the thesis.
struct SoilTerms {
  double A;         // sunshine ratio N / N_0
  double C;         // eq 3.2: cloud effect on the sky's longwave
  double sigma_T4;  // σT⁴ [W/m²] at the air temperature
  double L;         // eq 3.3 (or its sky-view weighting): longwave from the sky [W/m²]
  double R;         // eq 3.4: heat reaching the surface [W/m²]
  double C_H;       // eq 3.5: bulk transfer coefficient
  double theta;     // eq 3.8 (the cell's θ)
  double F;         // eq 3.9: dry-layer term F(θ) [m]
  double beta;      // eq 3.10: evaporation efficiency β
  double e_SAT;     // eq 3.12: saturation vapour pressure at T [hPa]
  double q_SAT;     // eq 3.13: saturation specific humidity at T [kg/kg]
  double Delta;     // eq 3.15: dq_SAT/dT [1/K]
  double dT;        // eq 3.11: δT = T_s − T [K]
  double T_s;       // surface temperature [K]
  double H;         // sensible heat c_P·ρ·C_H·U·δT [W/m²] (fig 3.2)
  double iota_E;    // eq 3.14: latent heat ιE [W/m²] (negative: dew)
  double E;         // evaporation ιE / ι [kg m⁻² s⁻¹]
  double E_mm_day;  // 24·60·60·E [mm/day], the bucket's loss of eq 3.6
  double rh_s;      // eq 3.16: surface relative humidity (may exceed 1)
  // R − (σT⁴ + 4σT³δT) − H − ιE: zero but for rounding (eq 3.11 solves it).
  double residual_linear;
  // R − σT_s⁴ − H − ιE: the linearisation's error (fig 3.2's balance at the true emission).
  double residual_nonlinear;
};

// The terms of eqs 3.2-3.15 that read only the day's weather and the constants, not the cell: the
// same for every cell of a day, so the run works them out once a day (their exp and divisions
// were a third of the soil's work). SoilEnergyBalance with them gives the same bits as without.
struct SoilWeatherTerms {
  double A, C, sigma_T4;  // SoilTerms' A, C, sigma_T4
  double L_sky;           // eq 3.3 under the open sky [W/m²]
  double e_SAT, q_SAT, Delta;
  double four_sigma_T3;  // 4σT³, eq 3.11's linear emission [W m⁻² K⁻¹]
};
SoilWeatherTerms SoilWeatherTermsOf(const SoilConstants& k, const Weather& w);

// Eqs 3.2-3.16 in the thesis's order (§3.7) for one cell and day; the cell must pass
// CheckSoilCell and the weather hold the table's ranges.
SoilTerms SoilEnergyBalance(const SoilConstants& k, const Weather& w, const SoilCell& cell);
// The same with the day's weather terms given (day = SoilWeatherTermsOf(k, w)).
SoilTerms SoilEnergyBalance(const SoilConstants& k, const Weather& w, const SoilWeatherTerms& day,
                            const SoilCell& cell);

// The bucket of one cell (eqs 3.6-3.8): depth h [mm] and water O [mm], O_SAT = h·θ_SAT.
struct Bucket {
  double h;      // soil depth [mm]
  double O_SAT;  // eq 3.7: capacity [mm]
  double O;      // water [mm], in [0, O_SAT]
};
// A bucket of depth h with law's θ_SAT, holding O_start·O_SAT (spec §4.10: 0.5).
Bucket MakeBucket(double h, const GeologyLaw& law, double O_start);

// One day of one cell in the spec's order (§1.4; equal to eq 3.6 when no clamp acts): rain in,
// runoff above O_SAT, θ = O/h, the balance, evaporation out, O clamped to [0, O_SAT].
struct SoilDay {
  SoilTerms terms;
  double runoff;  // rain above O_SAT that ran off [mm]
};
SoilDay AdvanceSoilDay(const SoilConstants& k, const Weather& w, const GeologyLaw& law, double S,
                       double m_over_M, double V_sky, Bucket* bucket);
// The same with the day's weather terms given (day = SoilWeatherTermsOf(k, w)): the same bits.
SoilDay AdvanceSoilDay(const SoilConstants& k, const Weather& w, const SoilWeatherTerms& day,
                       const GeologyLaw& law, double S, double m_over_M, double V_sky,
                       Bucket* bucket);

// A cell's last balance, keyed by its inputs: the balance (eqs 3.2-3.16) is a pure function of S,
// m/M and θ after the rain, the cell's law and sky view, the constants and the day's weather, so a
// day whose weather and inputs are the last day's, bit for bit, has the last day's T_s, rh_s and E
// (most of the thesis's cells are dark and saturated day after day). S < 0: nothing kept.
struct SoilMemo {
  double S = -1, m_over_M = -1, theta = -1;
  double T_s = 0, rh_s = 0, E = 0;
};
// The run's day of one cell: AdvanceSoilDay's bucket steps, with the balance taken from *memo when
// its inputs are the memo's bits, else worked out and kept there. The caller gives memos of the
// same cell, law, sky view and constants, and resets them (SoilMemo{}) when the weather's fields
// but P differ from the day they were kept on. The same bucket, T_s, rh_s and θ as AdvanceSoilDay.
struct SoilCellDay {
  double T_s, rh_s, theta;
};
SoilCellDay AdvanceSoilDayKept(const SoilConstants& k, const Weather& w,
                               const SoilWeatherTerms& day, const GeologyLaw& law, double S,
                               double m_over_M, double V_sky, Bucket* bucket, SoilMemo* memo);

}  // namespace niwa::moss

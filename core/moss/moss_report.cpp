// The moss study's JSON reports; see moss_report.h.
#include "moss/moss_report.h"

#include <utility>

#include "moss/fitness.h"
#include "moss/moss_params.h"

namespace niwa::moss {

nlohmann::ordered_json SoilReport(const MossState& state, Geology geology, const SoilCell& cell) {
  const SoilConstants k = SoilConstantsOf(state.params);
  const Weather w = ClimateOf(state.params);
  const SoilTerms t = SoilEnergyBalance(k, w, cell);
  nlohmann::ordered_json j;
  j["preset"] = state.preset;
  j["geology"] = GeologyName(geology);
  j["delta_form"] = k.delta_form == DeltaForm::kLiteral ? "literal" : "corrected";
  j["longwave"] = k.longwave == Longwave::kSkyView ? "sky-view" : "thesis";
  j["T"] = w.T;
  j["rh"] = w.rh;
  j["U"] = w.U;
  j["S"] = cell.S;
  j["m_over_M"] = cell.m_over_M;
  j["V_sky"] = cell.V_sky;
  j["theta_SAT"] = cell.law.theta_SAT;
  j["A"] = t.A;                // N / N_0
  j["C"] = t.C;                // eq 3.2
  j["sigma_T4"] = t.sigma_T4;  // σT⁴
  j["L"] = t.L;                // eq 3.3
  j["R"] = t.R;                // eq 3.4
  j["C_H"] = t.C_H;            // eq 3.5
  j["theta"] = t.theta;        // eq 3.8
  j["F"] = t.F;                // eq 3.9
  j["beta"] = t.beta;          // eq 3.10
  j["e_SAT"] = t.e_SAT;        // eq 3.12
  j["q_SAT"] = t.q_SAT;        // eq 3.13
  j["Delta"] = t.Delta;        // eq 3.15
  j["dT"] = t.dT;              // eq 3.11
  j["T_s"] = t.T_s;
  j["H"] = t.H;
  j["iota_E"] = t.iota_E;  // eq 3.14
  j["E"] = t.E;
  j["E_mm_day"] = t.E_mm_day;  // eq 3.6's loss
  j["rh_s"] = t.rh_s;          // eq 3.16
  j["latent_share"] = t.iota_E + t.H != 0 ? t.iota_E / (t.iota_E + t.H) : 0.0;
  j["residual_linear"] = t.residual_linear;
  j["residual_nonlinear"] = t.residual_nonlinear;
  return j;
}

nlohmann::ordered_json FitnessReport(const MossState& state, const std::vector<Species>& which,
                                     double T_s, double rh_s, double S) {
  const GForm form = static_cast<GForm>(state.params.GetInt(MossParam::kGForm));
  nlohmann::ordered_json j;
  j["preset"] = state.preset;
  j["g_form"] = form == GForm::kNormalized ? "normalized" : "clamped";
  j["T_s"] = T_s;
  j["rh_s"] = rh_s;
  j["S"] = S;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (Species s : which) {
    const SpeciesRanges r = SpeciesOf(state.params, s);
    const Fitness f = FitnessOf(r, T_s, rh_s, S, form);
    const double D = DailyGrowth(r, f.G);
    nlohmann::ordered_json e;
    e["species"] = SpeciesName(s);
    e["s_T"] = RangeScore(T_s, r.T_0, r.T_1);  // eq 3.18
    e["g_T"] = f.g_T;                          // eq 3.19
    e["s_rh"] = RangeScore(rh_s, r.rh_0, r.rh_1);
    e["g_rh"] = f.g_rh;
    e["s_S"] = RangeScore(S, r.S_0, r.S_1);
    e["g_S"] = f.g_S;
    e["G"] = f.G;  // eq 3.17
    e["D"] = D;    // eq 3.20
    e["growing"] = D > 0;
    list.push_back(std::move(e));
  }
  j["species"] = std::move(list);
  return j;
}

}  // namespace niwa::moss

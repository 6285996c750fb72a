// The 4-layer model's radial layout over time (paper 003 §4.1, Fig. 7; ../shared/specs/bark.md
// §1.7): the inner layer I grows linearly (constant ring width), r_I(t) = R_o + ΔR·t/T; within a
// cycle (τ = (t mod T)/T) the intermediate layer M2 thickens 0 → D on it, M1 and the surface S
// (thickness D each) ride outside; at every t = kT the roles move one step outward (M2 → M1 →
// S, the old S shed, a new M2 born at r_I with thickness 0). Each layer is named by the cycle that
// bore it, so a layer's boundaries are continuous through the role exchange. Does not: simulate
// the layers' springs, peeling or shedding (the 4-layer mechanics: a later slice).
#pragma once

#include <string>
#include <vector>

#include "bark/bark_params.h"

namespace niwa::bark {

struct LayerRadii {
  double t = 0;                              // s
  int cycle = 0;                             // k = ⌊t/T⌋
  double tau = 0;                            // (t mod T)/T
  double r_inner = 0;                        // r_I: the inner layer's outer radius (cm)
  double m2_out = 0, m1_out = 0, s_out = 0;  // outer radii of M2, M1, S (M2 starts at r_I)
  int born_m2 = 0, born_m1 = 0, born_s = 0;  // the cycle that bore the layer in each role
};

// The layout at time t for initial radius R_o, inner growth ΔR per period T and thickness D.
LayerRadii LayerRadiiAt(double t, double r_o, double delta_r, double d, double period);

// Samples of `cycles` periods, `per_cycle` a period, from t = 0 to cycles·T inclusive; at each
// t = kT (k ≥ 1) two rows: the layout just before the exchange (τ = 1, roles of cycle k−1) and
// just after (τ = 0, cycle k). R_o from the lattice rows (N_R, L_o), ΔR = dR·R_o, D, T.
std::vector<LayerRadii> LayerTimeline(const BarkParams& params, int cycles, int per_cycle);

// The timeline as CSV: t,cycle,tau,r_I,M2_out,M1_out,S_out,born_M2,born_M1,born_S.
std::string LayerTimelineCsv(const std::vector<LayerRadii>& rows);

}  // namespace niwa::bark

// Fig. 7's radial layout of the 4-layer model, as equations.
#include "bark/layers.h"

#include <cmath>

#include "bark/lattice.h"
#include "params/param_text.h"

namespace niwa::bark {
namespace {

// The layout of cycle k at phase τ (τ = 1 is the cycle's end, before its role exchange).
LayerRadii LayoutOf(int k, double tau, double r_o, double delta_r, double d, double period) {
  LayerRadii r;
  r.cycle = k;
  r.tau = tau;
  r.t = (k + tau) * period;
  r.r_inner = r_o + delta_r * (k + tau);
  r.m2_out = r.r_inner + d * tau;
  r.m1_out = r.m2_out + d;
  r.s_out = r.m1_out + d;
  r.born_m2 = k;
  r.born_m1 = k - 1;
  r.born_s = k - 2;
  return r;
}

}  // namespace

LayerRadii LayerRadiiAt(double t, double r_o, double delta_r, double d, double period) {
  const int k = static_cast<int>(std::floor(t / period));
  return LayoutOf(k, t / period - k, r_o, delta_r, d, period);
}

std::vector<LayerRadii> LayerTimeline(const BarkParams& p, int cycles, int per_cycle) {
  Lattice geometry;
  geometry.n_r = p.GetInt(BarkParam::kNR);
  geometry.l_o = p.Get(BarkParam::kLo);
  const double r_o = geometry.radius();
  const double delta_r = p.Get(BarkParam::kDeltaR) * r_o;
  const double d = p.Get(BarkParam::kD) * p.Get(BarkParam::kCork);  // d_c
  const double period = p.Get(BarkParam::kT);
  std::vector<LayerRadii> rows;
  for (int k = 0; k < cycles; ++k) {
    for (int q = 0; q < per_cycle; ++q)
      rows.push_back(LayoutOf(k, static_cast<double>(q) / per_cycle, r_o, delta_r, d, period));
    rows.push_back(LayoutOf(k, 1.0, r_o, delta_r, d, period));  // before the exchange
  }
  rows.push_back(LayoutOf(cycles, 0.0, r_o, delta_r, d, period));  // after the last one
  return rows;
}

std::string LayerTimelineCsv(const std::vector<LayerRadii>& rows) {
  std::string out = "t,cycle,tau,r_I,M2_out,M1_out,S_out,born_M2,born_M1,born_S\n";
  for (const LayerRadii& r : rows) {
    out += FormatNumber(r.t) + "," + std::to_string(r.cycle) + "," + FormatNumber(r.tau) + "," +
           FormatNumber(r.r_inner) + "," + FormatNumber(r.m2_out) + "," + FormatNumber(r.m1_out) +
           "," + FormatNumber(r.s_out) + "," + std::to_string(r.born_m2) + "," +
           std::to_string(r.born_m1) + "," + std::to_string(r.born_s) + "\n";
  }
  return out;
}

}  // namespace niwa::bark

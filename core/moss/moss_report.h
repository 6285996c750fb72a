// The moss study's JSON reports: one soil cell's day (every term of eqs 3.2-3.16) and one place's
// fitness (eqs 3.17-3.20), the objects `niwa moss soil|fitness` print and the page will show.
// Does not: parse flags or read files (the front ends do) or check the state (CheckMossParams and
// CheckSoilCell do, before these are called).
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "moss/moss.h"
#include "moss/moss_state.h"
#include "moss/soil.h"

namespace niwa::moss {

// The state's preset and forms, the day's weather, the cell, every term of eqs 3.2-3.16, the
// latent share and the energy balance's residuals, in that order.
nlohmann::ordered_json SoilReport(const MossState& state, Geology geology, const SoilCell& cell);

// The state's preset and g form, the place, and for each species in `which` the s and g of each
// factor (eqs 3.18-3.19), G (eq 3.17), the day's growth D (eq 3.20) and whether it grows.
nlohmann::ordered_json FitnessReport(const MossState& state, const std::vector<Species>& which,
                                     double T_s, double rh_s, double S);

}  // namespace niwa::moss

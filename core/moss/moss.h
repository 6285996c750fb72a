// The moss study's small types (Nomura 2010, paper 001; docs/moss-model.md,
// ../shared/specs/moss.md): geologies and species of the thesis's tables 3.4 and 4.2, a species'
// fitness ranges, one day's weather. Does not: hold values (moss_params.h has the table), compute
// anything (soil.h, fitness.h) or know a mesh.
#pragma once

#include <array>

namespace niwa::moss {

// The three geologies of fig 3.1 / table 3.4 (腐植土, 砂質土, アスファルト).
enum class Geology : int { kHumus = 0, kSandy = 1, kAsphalt = 2 };
constexpr int kGeologyCount = 3;
const char* GeologyName(Geology geology);  // "humus", "sandy", "asphalt"
// The geology named `name`; false when unknown.
bool GeologyFromName(const char* name, Geology* geology);

// The three species of table 4.2: ギンゴケ (Bryum argenteum), ハイゴケ (Hypnum plumaeforme),
// スギゴケ (Polytrichum).
enum class Species : int { kGingoke = 0, kHaigoke = 1, kSugigoke = 2 };
constexpr int kSpeciesCount = 3;
const char* SpeciesName(Species species);  // "gingoke", "haigoke", "sugigoke"
bool SpeciesFromName(const char* name, Species* species);

// Table 3.4: the dry-layer law F(θ) = F_1·(θ_SAT − θ)^F_2 of one geology (eq 3.9) and its
// saturated water content.
struct GeologyLaw {
  double F_1;        // m
  double F_2;        // -
  double theta_SAT;  // -
};

// Table 4.2: one species' ranges and tolerances (eqs 3.17-3.19) and its growth constants
// (eq 3.20, germination 3.24, death).
struct SpeciesRanges {
  double T_0, T_1, n_T;     // surface temperature range [K] and tolerance
  double rh_0, rh_1, n_rh;  // surface humidity range [-] and tolerance
  double S_0, S_1, n_S;     // light range [W/m²] and tolerance
  double alpha_g;           // growth coefficient α_g
  double tau_g;             // growth threshold τ_g
  double tau_b;             // germination threshold τ_b
  double tau_d;             // death threshold τ_d
};

}  // namespace niwa::moss

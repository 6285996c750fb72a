// The moss table (tables 3.4-3.6, 4.2, 4.3 of Nomura 2010 and the spec's chosen values), its
// presets and the typed views the soil and fitness models read.
#include "moss/moss_params.h"

#include <cstring>

#include "params/embedded_presets.h"
#include "params/param_text.h"

namespace niwa::moss {
namespace {

using P = MossParam;
constexpr int Id(P p) { return static_cast<int>(p); }
constexpr int kFirst = static_cast<int>(P::kSpeciesFirst);
constexpr Stage kGrow = Stage::kGrow;

// A species row (table 4.2): every one is a growth row.
ParamSpec Row(int id, const char* key, const char* symbol, const char* unit, double value,
              double min, double max, const char* group, const char* help) {
  return {id, key, symbol, unit, value, min, max, false, group, kGrow, help};
}

std::vector<ParamSpec> Rows() {
  return {
      // ------------------------------------------------ climate (table 4.3)
      {Id(P::kT), "T", "T", "K", 288.15, 233.15, 323.15, false, "climate", kGrow,
       "Daily mean air temperature (table 4.3: 288.15; fig 4.3's right half: 293.15)."},
      {Id(P::kRh), "rh", "rh", "", 0.73, 0, 1, false, "climate", kGrow,
       "Daily mean relative humidity of the air (table 4.3)."},
      {Id(P::kPYear), "P_year", "P", "mm/yr", 1861.2, 0, 20000, false, "climate", kGrow,
       "Yearly precipitation (table 4.3); each rain day gets P / P_d."},
      {Id(P::kPDays), "P_days", "P_d", "day/yr", 180, 0, 365, true, "climate", kGrow,
       "Rain days a year (table 4.3), spaced evenly unless rain_random is 1."},
      {Id(P::kU), "U", "U", "m/s", 0.2, 0, 50, false, "climate", kGrow,
       "Daily mean wind speed (table 4.3)."},
      {Id(P::kN0), "N0", "N_0", "h", 8.0, 0.1, 24, false, "climate", kGrow,
       "Possible sunshine hours 可照時間 (table 4.3); sunshine ratio A = N / N_0."},
      {Id(P::kN), "N", "N", "h", 6.0, 0, 24, false, "climate", kGrow,
       "Sunshine hours 日照時間 (table 4.3); at most N_0."},
      {Id(P::kSunAltitude), "sun_altitude", "", "deg", 90, 1, 90, false, "climate", kGrow,
       "Sun incidence angle 太陽の入射角 (table 4.3: 90 = zenith)."},
      {Id(P::kSunAzimuth), "sun_azimuth", "", "deg", 90, -180, 180, false, "climate", kGrow,
       "Sun azimuth from +x towards +z (+z is south, core/light); no effect at the zenith."},
      {Id(P::kRainRandom), "rain_random", "", "", 0, 0, 1, true, "climate", kGrow,
       "0: rain days evenly spaced; 1: each day rains with probability P_d / 365 (seeded)."},
      // ------------------------------------------------ soil (eqs 3.2-3.16, table 3.4)
      {Id(P::kHumusF1), "humus_F1", "F_1", "m", 2.16e2, 0, 1e12, false, "soil", kGrow,
       "Humus 腐植土: dry-layer law F(θ) = F_1·(θ_SAT − θ)^F_2 (eq 3.9, table 3.4)."},
      {Id(P::kHumusF2), "humus_F2", "F_2", "", 10.0, 0, 100, false, "soil", kGrow,
       "Humus: the exponent F_2 of eq 3.9 (table 3.4)."},
      {Id(P::kHumusThetaSat), "humus_theta_sat", "θ_SAT", "", 0.490, 0.001, 1, false, "soil", kGrow,
       "Humus: saturated volumetric water content (table 3.4)."},
      {Id(P::kSandyF1), "sandy_F1", "F_1", "m", 8.32e5, 0, 1e12, false, "soil", kGrow,
       "Sandy soil 砂質土: F_1 of eq 3.9 (table 3.4)."},
      {Id(P::kSandyF2), "sandy_F2", "F_2", "", 16.6, 0, 100, false, "soil", kGrow,
       "Sandy soil: F_2 of eq 3.9 (table 3.4)."},
      {Id(P::kSandyThetaSat), "sandy_theta_sat", "θ_SAT", "", 0.392, 0.001, 1, false, "soil", kGrow,
       "Sandy soil: saturated volumetric water content (table 3.4)."},
      {Id(P::kAsphaltF1), "asphalt_F1", "F_1", "m", 7.25e7, 0, 1e12, false, "soil", kGrow,
       "Asphalt アスファルト: F_1 of eq 3.9 (table 3.4, assumed by the author)."},
      {Id(P::kAsphaltF2), "asphalt_F2", "F_2", "", 19.4, 0, 100, false, "soil", kGrow,
       "Asphalt: F_2 of eq 3.9 (table 3.4)."},
      {Id(P::kAsphaltThetaSat), "asphalt_theta_sat", "θ_SAT", "", 0.012, 0.001, 1, false, "soil",
       kGrow, "Asphalt: saturated volumetric water content (table 3.4)."},
      {Id(P::kHMax), "h_max", "h", "mm", 1000, 1, 100000, false, "soil", kGrow,
       "Soil depth cap: a deeper cell counts as this deep (§3.5.3: 1000)."},
      {Id(P::kHWall), "h_wall", "h", "mm", 1, 0.001, 1000, false, "soil", kGrow,
       "Soil depth of a wall side with no soil along y (§3.5.3: 1)."},
      {Id(P::kOStart), "O_start", "O_0/O_SAT", "", 0.5, 0, 1, false, "soil", kGrow,
       "Bucket water on day 0 as a share of O_SAT (not in the thesis; spec §4.10)."},
      {Id(P::kCHMin), "CH_min", "C_Hmin", "", 0.0015, 0, 0.1, false, "soil", kGrow,
       "Bulk transfer coefficient of bare soil (eq 3.5, §3.5.2)."},
      {Id(P::kCHMax), "CH_max", "C_Hmax", "", 0.0030, 0, 0.1, false, "soil", kGrow,
       "Bulk transfer coefficient under dense moss (eq 3.5); at least CH_min."},
      {Id(P::kRCH), "r_CH", "", "m", 0.05, 0.001, 1, false, "soil", kGrow,
       "Radius of the neighbourhood whose mosses m count in eq 3.5 (spec §4.17)."},
      {Id(P::kMCH), "M_CH", "M", "", 79, 1, 100000, true, "soil", kGrow,
       "Most mosses in that neighbourhood, M of eq 3.5 (round(π r_CH² / s²) = 79)."},
      {Id(P::kDeltaForm), "delta_form", "Δ", "", 0, 0, 1, true, "soil", kGrow,
       "Eq 3.15: 0 corrected (e_SAT(T) where the thesis prints 6.1078), 1 literal (spec §4.12)."},
      {Id(P::kLongwave), "longwave", "L", "", 0, 0, 1, true, "soil", kGrow,
       "0 thesis: eq 3.3 on every cell; 1 sky-view: V·L + (1 − V)·σT⁴ (spec §3.1)."},
      // ------------------------------------------------ constants (tables 3.5, 3.6)
      {Id(P::kSigma), "sigma", "σ", "W m⁻² K⁻⁴", 5.67e-8, 1e-9, 1e-6, false, "constants", kGrow,
       "Stefan-Boltzmann constant (table 3.5)."},
      {Id(P::kP), "p", "p", "hPa", 1013, 300, 1100, false, "constants", kGrow,
       "Air pressure (table 3.5)."},
      {Id(P::kRef), "ref", "ref", "", 0.2, 0, 1, false, "constants", kGrow,
       "Albedo アルベート係数 (table 3.5, eq 3.4)."},
      {Id(P::kDAtm), "D_ATM", "D_ATM", "m²/s", 2.54e-5, 1e-7, 1e-3, false, "constants", kGrow,
       "Molecular diffusivity of water vapour at 20 °C (table 3.6, printed m⁻²·s⁻¹)."},
      {Id(P::kIota), "iota", "ι", "J/kg", 2.543e6, 1e5, 1e7, false, "constants", kGrow,
       "Latent heat of vaporisation at 20 °C (table 3.6; 2.453e6 is the textbook value, spec "
       "§4.13)."},
      {Id(P::kRho), "rho", "ρ", "kg/m³", 1.19, 0.1, 10, false, "constants", kGrow,
       "Air density at 20 °C (table 3.6)."},
      {Id(P::kCpRho), "cp_rho", "c_P·ρ", "J K⁻¹ m⁻³", 1.21e3, 1, 1e5, false, "constants", kGrow,
       "Volumetric heat capacity of air at 20 °C (table 3.6)."},
      // ------------------------------------------------ light (§3.4, §3.5.1)
      {Id(P::kPhotons), "photons", "", "", 8192, 0, 1048576, true, "light", kGrow,
       "Photons emitted a day (accepted emissions; §3.8: 8,192)."},
      {Id(P::kIndirect), "indirect", "", "", 1, 0, 1, true, "light", kGrow,
       "1: photons bounce (fig 4.1); 0: first hits only, no sky photons (fig 4.2)."},
      {Id(P::kRhoMesh), "rho_mesh", "", "", 0.5, 0, 1, false, "light", kGrow,
       "Reflectance of the land: the chance a photon is reflected (§3.4's example: 0.5)."},
      {Id(P::kRhoMoss), "rho_moss", "", "", 0.2, 0, 1, false, "light", kGrow,
       "Reflectance of a moss (not given in the thesis; spec §4.5)."},
      {Id(P::kMaxBounces), "max_bounces", "", "", 16, 0, 64, true, "light", kGrow,
       "Most diffuse bounces of one photon."},
      {Id(P::kRGather), "r_gather", "", "m", 0.10, 0.001, 10, false, "light", kGrow,
       "Photon gather radius: photons within it light a cell or a moss (§3.5.1, spec §4.6)."},
      {Id(P::kIBeam), "I_beam", "", "W/m²", 1000, 0, 2000, false, "light", kGrow,
       "Beam irradiance while sunny: S_sun = I_beam·N / 24 (spec §4.4)."},
      {Id(P::kSSky), "S_sky", "", "W/m²", 0, 0, 1000, false, "light", kGrow,
       "Diffuse sky irradiance on open ground (extension; 68 in nomura2010-sky, spec §3.1)."},
      {Id(P::kSunDistance), "sun_distance", "", "R", 10, 1.5, 1000, false, "light", kGrow,
       "Distance of the sun's square from the scene centre, in scene radii R."},
      {Id(P::kSunSize), "sun_size", "", "R", 0.5, 0.001, 10, false, "light", kGrow,
       "Side of the sun's square light, in scene radii R."},
      {Id(P::kSunPath), "sun_path", "", "", 0, 0, 1, true, "light", kGrow,
       "0 fixed: one sun position; 1 arc: photons spread over the day's arc (spec §1.3)."},
      {Id(P::kLightSmoothingDays), "light_smoothing_days", "", "day", 0, 0, 365, false, "light",
       kGrow, "Days of an exponential mean of each S over days (0: none, the thesis)."},
      // ------------------------------------------------ life cycle (§3.3, §3.6, §3.8)
      {Id(P::kGForm), "g_form", "g", "", 0, 0, 1, true, "life", kGrow,
       "Eq 3.19 for n < 1: 0 clamped to [0, 1]; 1 normalised 1/2 ± (1/2)|2s − 1|^n (spec §4.14)."},
      {Id(P::kMaxMosses), "max_mosses", "", "", 16384, 1, 1048576, true, "life", kGrow,
       "Most living mosses (§3.8: 16,384)."},
      {Id(P::kSeedCap), "seed_cap", "", "", 16384, 0, 1048576, true, "life", kGrow,
       "Most waiting seeds (gemmae and spores); more are dropped and counted."},
      {Id(P::kNInit), "n_init", "", "", 64, 0, 16384, true, "life", kGrow,
       "Mosses placed at random on day 0, species uniform."},
      {Id(P::kImmigrationDays), "immigration_days", "", "day", 10, 0, 3650, true, "life", kGrow,
       "One outside spore lands every this many days (0: none; §3.3)."},
      {Id(P::kMossSize), "moss_size", "s", "m", 0.01, 0.001, 0.1, false, "life", kGrow,
       "Moss model size: a sphere of this diameter blocks light (§4.1: 1 cm)."},
      {Id(P::kGemmaStep), "gemma_step", "", "", 0.5, 0.01, 100, false, "life", kGrow,
       "A gemma each time G_moss rises by this (§3.6: 0.5)."},
      {Id(P::kSporeG), "spore_G", "", "", 2.0, 0, 1000, false, "life", kGrow,
       "G_moss a growing moss needs to make spores (§3.6: 2.0)."},
      {Id(P::kLSpore0), "L_spore_0", "L_0", "day", 60, -3650, 3650, false, "life", kGrow,
       "Spore germination window start (eq 3.24: 60)."},
      {Id(P::kLSpore1), "L_spore_1", "L_1", "day", 365, -3650, 3650, false, "life", kGrow,
       "Spore germination window end (eq 3.24: 365)."},
      {Id(P::kLGemma0), "L_gemma_0", "L_0", "day", -60, -3650, 3650, false, "life", kGrow,
       "Gemma germination window start (eq 3.24: −60)."},
      {Id(P::kLGemma1), "L_gemma_1", "L_1", "day", 60, -3650, 3650, false, "life", kGrow,
       "Gemma germination window end (eq 3.24: 60)."},
      {Id(P::kKGemma), "k_gemma", "k", "m", 0.01, 0, 1, false, "life", kGrow,
       "Parent-gemma distance k of eq 3.22 (not given; spec §4.18)."},
      {Id(P::kLSporeDistance), "l_spore", "l", "m", 0.10, 0, 10, false, "life", kGrow,
       "Parent-spore distance l of eq 3.23 (not given; spec §4.18)."},
      {Id(P::kInteriorCount), "interior_count", "", "", 6, 1, 100, true, "life", kGrow,
       "A moss with this many others within interior_radius is inside a mat: no gemmae (§3.8)."},
      {Id(P::kInteriorRadius), "interior_radius", "", "s", 1.5, 0.5, 10, false, "life", kGrow,
       "The mat test's radius, in moss sizes s."},
      {Id(P::kOverlap), "overlap", "", "s", 0.9, 0, 2, false, "life", kGrow,
       "A seed closer than this (in s) to a moss competes for its place (§3.6)."},
      {Id(P::kSoilEdge), "soil_edge", "", "m", 0.075, 0.005, 10, false, "life", kGrow,
       "Longest edge of a soil cell: the mesh's triangles are split until none is longer."},
      // ------------------------------------------------ species (table 4.2)
      Row(kFirst + 0, "gingoke_T0", "T_0", "K", 274.15, 200, 350, "gingoke",
          "Lowest surface temperature T_s of the range (g = 0.5 there, eqs 3.18-3.19)."),
      Row(kFirst + 1, "gingoke_T1", "T_1", "K", 299.15, 200, 350, "gingoke",
          "Highest surface temperature of the range; T_0 < T_1."),
      Row(kFirst + 2, "gingoke_nT", "n_T", "", 1, 0.01, 1, "gingoke",
          "Temperature tolerance n (eq 3.19): larger is a gentler fall outside the range; 1 gives "
          "g = s."),
      Row(kFirst + 3, "gingoke_rh0", "rh_0", "", 0.8, 0, 2, "gingoke",
          "Lowest surface humidity rh_s of the range."),
      Row(kFirst + 4, "gingoke_rh1", "rh_1", "", 1.2, 0, 2, "gingoke",
          "Highest surface humidity of the range; rh_0 < rh_1 (rh_s may exceed 1, eq 3.16)."),
      Row(kFirst + 5, "gingoke_nrh", "n_rh", "", 0.5, 0.01, 1, "gingoke",
          "Humidity tolerance n (eq 3.19)."),
      Row(kFirst + 6, "gingoke_S0", "S_0", "W/m²", 0, 0, 1000, "gingoke",
          "Lowest light S of the range (0: darkness scores g_S = 0.5)."),
      Row(kFirst + 7, "gingoke_S1", "S_1", "W/m²", 60, 0, 1000, "gingoke",
          "Highest light of the range; S_0 < S_1."),
      Row(kFirst + 8, "gingoke_nS", "n_S", "", 1, 0.01, 1, "gingoke",
          "Light tolerance n (eq 3.19)."),
      Row(kFirst + 9, "gingoke_alpha_g", "α_g", "1/day", 0.3, 0, 10, "gingoke",
          "Growth coefficient: D = α_g·(G − τ_g) a day (eq 3.20)."),
      Row(kFirst + 10, "gingoke_tau_g", "τ_g", "", 0.1, 0, 1, "gingoke",
          "Growth threshold: the moss grows on a day with G > τ_g (eq 3.20)."),
      Row(kFirst + 11, "gingoke_tau_b", "τ_b", "", 0.4, 0, 1, "gingoke",
          "Germination threshold: a seed germinates when G·g(L, L_0, L_1, 1) > τ_b (eq 3.24)."),
      Row(kFirst + 12, "gingoke_tau_d", "τ_d", "", 0.1, 0, 100, "gingoke",
          "Death threshold: a declining moss with G_moss < τ_d dies (§3.6)."),
      Row(kFirst + 13, "haigoke_T0", "T_0", "K", 276.15, 200, 350, "haigoke",
          "Lowest surface temperature T_s of the range (g = 0.5 there, eqs 3.18-3.19)."),
      Row(kFirst + 14, "haigoke_T1", "T_1", "K", 295.15, 200, 350, "haigoke",
          "Highest surface temperature of the range; T_0 < T_1."),
      Row(kFirst + 15, "haigoke_nT", "n_T", "", 1, 0.01, 1, "haigoke",
          "Temperature tolerance n (eq 3.19): larger is a gentler fall outside the range; 1 gives "
          "g = s."),
      Row(kFirst + 16, "haigoke_rh0", "rh_0", "", 0.9, 0, 2, "haigoke",
          "Lowest surface humidity rh_s of the range."),
      Row(kFirst + 17, "haigoke_rh1", "rh_1", "", 1.1, 0, 2, "haigoke",
          "Highest surface humidity of the range; rh_0 < rh_1 (rh_s may exceed 1, eq 3.16)."),
      Row(kFirst + 18, "haigoke_nrh", "n_rh", "", 0.5, 0.01, 1, "haigoke",
          "Humidity tolerance n (eq 3.19)."),
      Row(kFirst + 19, "haigoke_S0", "S_0", "W/m²", 0, 0, 1000, "haigoke",
          "Lowest light S of the range (0: darkness scores g_S = 0.5)."),
      Row(kFirst + 20, "haigoke_S1", "S_1", "W/m²", 40, 0, 1000, "haigoke",
          "Highest light of the range; S_0 < S_1."),
      Row(kFirst + 21, "haigoke_nS", "n_S", "", 1, 0.01, 1, "haigoke",
          "Light tolerance n (eq 3.19)."),
      Row(kFirst + 22, "haigoke_alpha_g", "α_g", "1/day", 0.25, 0, 10, "haigoke",
          "Growth coefficient: D = α_g·(G − τ_g) a day (eq 3.20)."),
      Row(kFirst + 23, "haigoke_tau_g", "τ_g", "", 0.1, 0, 1, "haigoke",
          "Growth threshold: the moss grows on a day with G > τ_g (eq 3.20)."),
      Row(kFirst + 24, "haigoke_tau_b", "τ_b", "", 0.35, 0, 1, "haigoke",
          "Germination threshold: a seed germinates when G·g(L, L_0, L_1, 1) > τ_b (eq 3.24)."),
      Row(kFirst + 25, "haigoke_tau_d", "τ_d", "", 0.15, 0, 100, "haigoke",
          "Death threshold: a declining moss with G_moss < τ_d dies (§3.6)."),
      Row(kFirst + 26, "sugigoke_T0", "T_0", "K", 278.15, 200, 350, "sugigoke",
          "Lowest surface temperature T_s of the range (g = 0.5 there, eqs 3.18-3.19)."),
      Row(kFirst + 27, "sugigoke_T1", "T_1", "K", 297.15, 200, 350, "sugigoke",
          "Highest surface temperature of the range; T_0 < T_1."),
      Row(kFirst + 28, "sugigoke_nT", "n_T", "", 1, 0.01, 1, "sugigoke",
          "Temperature tolerance n (eq 3.19): larger is a gentler fall outside the range; 1 gives "
          "g = s."),
      Row(kFirst + 29, "sugigoke_rh0", "rh_0", "", 0.85, 0, 2, "sugigoke",
          "Lowest surface humidity rh_s of the range."),
      Row(kFirst + 30, "sugigoke_rh1", "rh_1", "", 1.15, 0, 2, "sugigoke",
          "Highest surface humidity of the range; rh_0 < rh_1 (rh_s may exceed 1, eq 3.16)."),
      Row(kFirst + 31, "sugigoke_nrh", "n_rh", "", 1, 0.01, 1, "sugigoke",
          "Humidity tolerance n (eq 3.19)."),
      Row(kFirst + 32, "sugigoke_S0", "S_0", "W/m²", 0, 0, 1000, "sugigoke",
          "Lowest light S of the range (0: darkness scores g_S = 0.5)."),
      Row(kFirst + 33, "sugigoke_S1", "S_1", "W/m²", 50, 0, 1000, "sugigoke",
          "Highest light of the range; S_0 < S_1."),
      Row(kFirst + 34, "sugigoke_nS", "n_S", "", 1, 0.01, 1, "sugigoke",
          "Light tolerance n (eq 3.19)."),
      Row(kFirst + 35, "sugigoke_alpha_g", "α_g", "1/day", 0.3, 0, 10, "sugigoke",
          "Growth coefficient: D = α_g·(G − τ_g) a day (eq 3.20)."),
      Row(kFirst + 36, "sugigoke_tau_g", "τ_g", "", 0.075, 0, 1, "sugigoke",
          "Growth threshold: the moss grows on a day with G > τ_g (eq 3.20)."),
      Row(kFirst + 37, "sugigoke_tau_b", "τ_b", "", 0.37, 0, 1, "sugigoke",
          "Germination threshold: a seed germinates when G·g(L, L_0, L_1, 1) > τ_b (eq 3.24)."),
      Row(kFirst + 38, "sugigoke_tau_d", "τ_d", "", 0.12, 0, 100, "sugigoke",
          "Death threshold: a declining moss with G_moss < τ_d dies (§3.6)."),
  };
}

}  // namespace

const char* GeologyName(Geology geology) {
  static const char* names[] = {"humus", "sandy", "asphalt"};
  return names[static_cast<int>(geology)];
}
bool GeologyFromName(const char* name, Geology* geology) {
  for (int i = 0; i < kGeologyCount; ++i) {
    if (std::strcmp(name, GeologyName(static_cast<Geology>(i))) == 0) {
      *geology = static_cast<Geology>(i);
      return true;
    }
  }
  return false;
}
const char* SpeciesName(Species species) {
  static const char* names[] = {"gingoke", "haigoke", "sugigoke"};
  return names[static_cast<int>(species)];
}
bool SpeciesFromName(const char* name, Species* species) {
  for (int i = 0; i < kSpeciesCount; ++i) {
    if (std::strcmp(name, SpeciesName(static_cast<Species>(i))) == 0) {
      *species = static_cast<Species>(i);
      return true;
    }
  }
  return false;
}

MossParam SpeciesRow(Species species, int column) {
  return static_cast<MossParam>(kFirst + static_cast<int>(species) * kSpeciesColumns + column);
}

const ParamTable& MossTable() {
  static const ParamTable table("moss", Rows(),
                                {{"climate", "Climate (table 4.3)"},
                                 {"soil", "Soil heat and water (eqs 3.2-3.16, table 3.4)"},
                                 {"constants", "Constants (tables 3.5, 3.6)"},
                                 {"light", "Light: photon map (§3.4)"},
                                 {"life", "Life cycle (§3.3, §3.6)"},
                                 {"gingoke", "ギンゴケ gingoke (table 4.2)"},
                                 {"haigoke", "ハイゴケ haigoke (table 4.2)"},
                                 {"sugigoke", "スギゴケ sugigoke (table 4.2)"}});
  return table;
}

const ParamTable& TableOf(MossParam) { return MossTable(); }

GeologyLaw GeologyLawOf(const MossParams& p, Geology geology) {
  switch (geology) {
    case Geology::kSandy:
      return {p.Get(P::kSandyF1), p.Get(P::kSandyF2), p.Get(P::kSandyThetaSat)};
    case Geology::kAsphalt:
      return {p.Get(P::kAsphaltF1), p.Get(P::kAsphaltF2), p.Get(P::kAsphaltThetaSat)};
    case Geology::kHumus:
    default:
      return {p.Get(P::kHumusF1), p.Get(P::kHumusF2), p.Get(P::kHumusThetaSat)};
  }
}

SpeciesRanges SpeciesOf(const MossParams& p, Species species) {
  double v[kSpeciesColumns];
  for (int c = 0; c < kSpeciesColumns; ++c) v[c] = p.Get(SpeciesRow(species, c));
  return {v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12]};
}

namespace {

// {row, "x is not below other = y; must be ..."} when lower >= upper.
Status Below(const MossParams& p, MossParam lower, MossParam upper) {
  const double a = p.Get(lower), b = p.Get(upper);
  if (a < b) return Status::Ok();
  const char* key = MossTable().row(static_cast<std::size_t>(lower)).key;
  const char* other = MossTable().row(static_cast<std::size_t>(upper)).key;
  return Status::Error(key, FormatNumber(a) + " is not below " + other + " = " + FormatNumber(b) +
                                "; must be less than " + other);
}

}  // namespace

Status CheckMossParams(const MossParams& p) {
  if (p.Get(P::kN) > p.Get(P::kN0)) {
    return Status::Error("N", FormatNumber(p.Get(P::kN)) +
                                  " is over N0 = " + FormatNumber(p.Get(P::kN0)) +
                                  "; must be a number in [0, N0] (sunshine ratio A = N / N0)");
  }
  if (p.Get(P::kCHMin) > p.Get(P::kCHMax)) {
    return Status::Error("CH_min", FormatNumber(p.Get(P::kCHMin)) +
                                       " is over CH_max = " + FormatNumber(p.Get(P::kCHMax)) +
                                       "; must be a number in [0, CH_max]");
  }
  for (int s = 0; s < kSpeciesCount; ++s) {
    const Species species = static_cast<Species>(s);
    for (int c : {0, 3, 6}) {  // T_0 < T_1, rh_0 < rh_1, S_0 < S_1
      NIWA_RETURN_IF_ERROR(Below(p, SpeciesRow(species, c), SpeciesRow(species, c + 1)));
    }
  }
  NIWA_RETURN_IF_ERROR(Below(p, P::kLSpore0, P::kLSpore1));
  return Below(p, P::kLGemma0, P::kLGemma1);
}

namespace {

// core/moss/presets/moss_presets.json (embedded by the one step; docs/moss-model.md), read once.
const std::vector<ListedPreset>& Presets() {
  static const std::vector<ListedPreset> presets = StudyPresetLists("moss", MossTable());
  return presets;
}

}  // namespace

const std::vector<std::string>& MossPresetNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const ListedPreset& p : Presets()) n.push_back(p.name);
    return n;
  }();
  return names;
}

std::string MossPresetSource(std::string_view name) {
  for (const ListedPreset& p : Presets())
    if (name == p.name) return p.source;
  return "";
}

std::vector<std::pair<std::string, double>> MossPresetValues(std::string_view name) {
  for (const ListedPreset& p : Presets())
    if (name == p.name) return p.values;
  return {};
}

Result<MossParams> MossPreset(std::string_view name) {
  for (const ListedPreset& preset : Presets()) {
    if (name != preset.name) continue;
    MossParams params;
    for (const auto& [key, value] : preset.values)
      NIWA_RETURN_IF_ERROR(params.Set(*MossTable().Find(key), value));
    return params;
  }
  std::string names;
  for (const std::string& n : MossPresetNames()) names += (names.empty() ? "" : " or ") + n;
  return Status::Error("preset", "'" + std::string(name) + "' is unknown; must be " + names);
}

}  // namespace niwa::moss

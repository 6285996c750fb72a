// The bark study's calibration: a grid over the calibratable rows, scored against Table 3 (2-layer)
// or the peel share (4-layer).
#include "bark/calibrate.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "bark/bark_run.h"
#include "params/param_text.h"
#include "params/strict_number.h"

namespace niwa::bark {
namespace {

constexpr double kMeanTolerance = 0.25, kMaxTolerance = 0.4;  // spec §4.1 level B

std::string KeyList(std::string_view model) {
  std::string out;
  const std::vector<std::string>& keys = CalibratableKeys(model);
  for (std::size_t i = 0; i < keys.size(); ++i)
    out += (i == 0 ? "" : i + 1 == keys.size() ? " or " : ", ") + keys[i];
  return out;
}

// |ours/paper − 1| / tolerance: at most 1 inside the bar.
double Deviation(double ours, double paper, double tolerance) {
  return std::fabs(ours / paper - 1.0) / tolerance;
}

struct Scored {
  nlohmann::ordered_json measures;
  double score = 0, tie = 0;  // the worst deviation; the sum of squared deviations
  nlohmann::ordered_json parts;
};

// `state`'s run with `seed`, grown through all its cycles (one candidate's run at one seed).
Result<BarkRun> GrownWithSeed(const BarkState& state, uint64_t seed, const Budget& budget) {
  BarkState s = state;
  s.seed = seed;
  Result<BarkRun> run = BarkRun::Start(s, budget);
  if (!run.ok()) return run.status();
  NIWA_RETURN_IF_ERROR(run->Advance({}));
  return run;
}

// The 2-layer measures over the seeds and their deviations from the paper's row. The score reads
// the paper's measure, the crack spacing along scan lines (regions.h Spacing; docs/bark-model.md
// choice 10a), as `niwa bark table3`'s level_b_spacing does: the seeds' means of the lines' mean
// and largest spacing around (width) and along (height); camphor's "(>20)" is met when some line
// along the trunk crosses no horizontal crack at some seed. The plates' extents (choice 8) are
// printed beside them, not scored.
Result<Scored> ScoreTwoLayer(const BarkState& state, const CalibrateRequest& r,
                             const Budget& budget) {
  const PaperTable3Row* paper = PaperTable3(state.species);
  double mean_w = 0, mean_h = 0, max_w = 0, max_h = 0, plate_mean_w = 0, plate_mean_h = 0,
         plate_max_w = 0, plate_max_h = 0, icpt_w = 0, icpt_h = 0, vertical = 0, closed = 0;
  int strips = 0, open_along = 0;
  const double n = static_cast<double>(r.last_seed - r.first_seed + 1);
  for (uint64_t seed = r.first_seed; seed <= r.last_seed; ++seed) {
    Result<BarkRun> run = GrownWithSeed(state, seed, budget);
    if (!run.ok()) return run.status();
    const CrackMeasures& c = run->cracks();
    mean_w += c.spacing_width.mean / n;
    mean_h += c.spacing_height.mean / n;
    max_w += c.spacing_width.max / n;
    max_h += c.spacing_height.max / n;
    open_along += c.spacing_height.open;
    plate_mean_w += c.mean_width / n;
    plate_mean_h += c.mean_height / n;
    plate_max_w += c.max_width / n;
    plate_max_h += c.max_height / n;
    icpt_w += c.intercept_width / n;
    icpt_h += c.intercept_height / n;
    vertical += c.vertical_crack_share / n;
    closed += c.closed_fraction / n;
    strips += c.strips;
  }
  Scored out;
  out.measures = {{"mean_w", mean_w},
                  {"mean_h", mean_h},
                  {"max_w", max_w},
                  {"max_h", max_h},
                  {"open_lines_h", open_along},
                  {"plates",
                   {{"mean_w", plate_mean_w},
                    {"mean_h", plate_mean_h},
                    {"max_w", plate_max_w},
                    {"max_h", plate_max_h},
                    {"strips", strips}}},
                  {"intercept_w", icpt_w},
                  {"intercept_h", icpt_h},
                  {"vertical_crack_share", vertical},
                  {"closed_fraction", closed}};
  const double d_mw = Deviation(mean_w, paper->mean_w, kMeanTolerance);
  const double d_mh = Deviation(mean_h, paper->mean_h, kMeanTolerance);
  const double d_xw = Deviation(max_w, paper->max_w, kMaxTolerance);
  // "(>20)": a line along the trunk crossing no horizontal crack at some seed; else over 1 by the
  // shortfall of the largest spacing from the patch.
  const double h_o = state.params.Get(BarkParam::kLo) * state.params.GetInt(BarkParam::kNH);
  const double d_xh = paper->max_h > 0 ? Deviation(max_h, paper->max_h, kMaxTolerance)
                      : open_along > 0 ? 0.0
                                       : 1.0 + std::max(0.0, 1.0 - max_h / h_o);
  const double means = std::max(d_mw, d_mh), maxima = std::max(d_xw, d_xh);
  out.score = std::max(means, maxima);
  out.tie = d_mw * d_mw + d_mh * d_mh + d_xw * d_xw + d_xh * d_xh;
  out.parts = {{"mean_w", d_mw}, {"mean_h", d_mh}, {"max_w", d_xw},
               {"max_h", d_xh},  {"means", means}, {"maxima", maxima}};
  return out;
}

// The 4-layer measures: the share of S peeled by each cycle's end (cycles after the first, the
// crack-free start), S's visible share there, S→M1 bonds broken a cycle, the area shed.
Result<Scored> ScoreFourLayer(const BarkState& state, const CalibrateRequest& r,
                              const Budget& budget) {
  const int cycles = state.params.GetInt(BarkParam::kCycles);
  double peeled_sum = 0, peeled_min = 1, exposed_s = 0, bonds = 0, shed = 0;
  int counted = 0;
  const double n = static_cast<double>(r.last_seed - r.first_seed + 1);
  for (uint64_t seed = r.first_seed; seed <= r.last_seed; ++seed) {
    Result<BarkRun> run = GrownWithSeed(state, seed, budget);
    if (!run.ok()) return run.status();
    const std::vector<BarkSample>& rows = run->samples();
    int bonds_before = 0;
    for (int c = 0; c < cycles; ++c) {
      // The cycle's end, before its exchange: the first row with c exchanges at t = (c + 1)·T.
      const auto end = std::find_if(rows.begin(), rows.end(), [&](const BarkSample& x) {
        return x.exchanges == c && x.cycle == c + 1;
      });
      if (end == rows.end()) continue;
      if (c >= 1) {
        peeled_sum += end->peeled;
        peeled_min = std::min(peeled_min, end->peeled);
        exposed_s += end->exposed[0];
        bonds += end->bonds_broken - bonds_before;
        ++counted;
      }
      bonds_before = end->bonds_broken;
    }
    shed += run->layers().shed_nodes * run->mechanics().node_area / n;
  }
  Scored out;
  const double k = std::max(1, counted);
  const double peeled = peeled_sum / k;
  if (counted == 0) peeled_min = 0;
  out.measures = {{"peeled_share", peeled},
                  {"peeled_share_least", peeled_min},
                  {"exposed_S", exposed_s / k},
                  {"bonds_per_cycle", bonds / k},
                  {"shed_area", shed}};
  const double d_band = std::fabs(peeled - kPeelShareCentre) / kPeelShareHalfWidth;
  const double d_every =
      peeled_min >= kPeelShareLeast ? 0.0 : 1.0 + (kPeelShareLeast - peeled_min) / kPeelShareLeast;
  out.score = std::max(d_band, d_every);
  out.tie = d_band * d_band + d_every * d_every;
  out.parts = {{"peeled_share", d_band}, {"every_cycle", d_every}};
  return out;
}

}  // namespace

std::vector<double> CalibrateAxis::Values() const {
  std::vector<double> v;
  for (int k = 0; k < points; ++k) {
    // Rounded to 1e-12 so 0.1 + 0.1·2 prints as 0.3 (the rows calibrated lie within [0, 100]).
    const double x = points == 1 ? lo : lo + (hi - lo) * k / (points - 1);
    v.push_back(std::round(x * 1e12) / 1e12);
  }
  return v;
}

const std::vector<std::string>& CalibratableKeys(std::string_view model) {
  static const std::vector<std::string> two = {"dH", "dR", "D"};
  static const std::vector<std::string> four = {"kappa_h", "gamma", "A", "eta"};
  return model == "4layer" ? four : two;
}

std::vector<CalibrateAxis> DefaultCalibrateAxes(std::string_view model) {
  if (model == "4layer")
    return {{"kappa_h", 0.03, 0.3, 4}, {"gamma", 0.25, 1.0, 2}, {"A", 2.0, 8.0, 2}};
  return {{"dH", 0.020, 0.050, 7}};
}

Result<CalibrateAxis> ParseCalibrateAxis(std::string_view text, std::string_view model) {
  const std::string form = "'" + std::string(text).substr(0, 60) +
                           "' must be KEY=LO:HI:N or KEY=V, KEY one of " + KeyList(model);
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) return Status::Error("vary", form);
  CalibrateAxis axis;
  axis.key = std::string(text.substr(0, eq));
  const std::vector<std::string>& keys = CalibratableKeys(model);
  if (std::find(keys.begin(), keys.end(), axis.key) == keys.end())
    return Status::Error("vary", "'" + axis.key.substr(0, 40) + "' is not calibrated in the " +
                                     std::string(model) + " model; must be " + KeyList(model));
  const ParamSpec& row = BarkTable().row(*BarkTable().Find(axis.key));
  std::vector<std::string_view> parts;
  std::string_view rest = text.substr(eq + 1);
  for (;;) {
    const std::size_t colon = rest.find(':');
    parts.push_back(rest.substr(0, colon));
    if (colon == std::string_view::npos) break;
    rest = rest.substr(colon + 1);
  }
  if (parts.size() != 1 && parts.size() != 3) return Status::Error("vary", form);
  const std::string& field = axis.key;
  Result<double> lo = ParseStrictNumber(field, parts[0], row.min_value, row.max_value, false);
  if (!lo.ok()) return lo.status().Within("vary");
  axis.lo = axis.hi = *lo;
  if (parts.size() == 3) {
    Result<double> hi = ParseStrictNumber(field, parts[1], *lo, row.max_value, false);
    if (!hi.ok()) return hi.status().Within("vary");
    Result<double> points =
        ParseStrictNumber(field + " points", parts[2], 1, kMaxCalibratePoints, true);
    if (!points.ok()) return points.status().Within("vary");
    axis.hi = *hi;
    axis.points = static_cast<int>(*points);
  }
  return axis;
}

namespace {

// The grid point g's state (the first axis slowest), its values as JSON; map_size 256 (no maps are
// drawn, so the estimate counts none of the table's default 1024).
BarkState GridPoint(const CalibrateRequest& r, int g, nlohmann::ordered_json* values) {
  BarkState s = r.base;
  (void)s.params.Set(BarkParam::kMapSize, 256);
  std::vector<std::size_t> index(r.vary.size());
  for (std::size_t i = r.vary.size(); i-- > 0;) {  // the last axis fastest
    const int points = r.vary[i].points;
    index[i] = static_cast<std::size_t>(g % points);
    g /= points;
  }
  for (std::size_t i = 0; i < r.vary.size(); ++i) {
    const double v = r.vary[i].Values()[index[i]];
    (void)s.params.Set(*BarkTable().Find(r.vary[i].key), v);  // in range: checked by the caller
    if (values) (*values)[r.vary[i].key] = v;
  }
  return s;
}

int GridSize(const CalibrateRequest& r) {
  int grid = 1;
  for (const CalibrateAxis& a : r.vary)
    grid *= std::max(1, std::min(a.points, kMaxCalibratePoints));
  return grid;
}

}  // namespace

Estimate EstimateCalibrate(const CalibrateRequest& r) {
  const double seeds = static_cast<double>(r.last_seed - r.first_seed + 1);
  const int grid = GridSize(r);
  Estimate e;
  std::string what;
  for (int g = 0; g < grid; ++g) {
    const Estimate one = EstimateBarkRun(GridPoint(r, g, nullptr));
    e.memory_bytes = std::max(e.memory_bytes, one.memory_bytes);  // one run at a time
    e.seconds += one.seconds * seeds;
    if (g == 0) what = one.what;
  }
  e.what = "the calibration (" + FormatCount(grid) + " grid points x " + FormatCount(seeds) +
           " seeds of " + what + ")";
  return e;
}

Result<std::string> CalibrateJson(const CalibrateRequest& r, const Budget& budget) {
  const bool four = r.base.model == "4layer";
  NIWA_RETURN_IF_ERROR(CheckBarkState(r.base));
  if (!four && !PaperTable3(r.base.species))
    return Status::Error(
        "species", "'" + r.base.species + "' is not in Table 3; must be camphor, tallow or pine");
  if (four && r.base.params.GetInt(BarkParam::kCycles) < 2)
    return Status::Error("cycles", std::to_string(r.base.params.GetInt(BarkParam::kCycles)) +
                                       " is too few to calibrate peeling; must be at least 2 "
                                       "(the first cycle starts crack free)");
  if (r.first_seed > r.last_seed || r.last_seed - r.first_seed >= kMaxCalibrateRuns)
    return Status::Error("seeds", "must be A-B with A <= B and at most " +
                                      std::to_string(kMaxCalibrateRuns) + " seeds");
  if (r.vary.empty())
    return Status::Error("vary", "nothing to vary; must name " + KeyList(r.base.model));
  double grid = 1;
  for (std::size_t i = 0; i < r.vary.size(); ++i) {
    const CalibrateAxis& a = r.vary[i];
    const std::vector<std::string>& keys = CalibratableKeys(r.base.model);
    if (std::find(keys.begin(), keys.end(), a.key) == keys.end())
      return Status::Error("vary", "'" + a.key + "' is not calibrated in the " + r.base.model +
                                       " model; must be " + KeyList(r.base.model));
    for (std::size_t j = 0; j < i; ++j)
      if (r.vary[j].key == a.key)
        return Status::Error("vary", "'" + a.key + "' is varied twice; must be named once");
    const ParamSpec& row = BarkTable().row(*BarkTable().Find(a.key));
    if (a.points < 1 || a.points > kMaxCalibratePoints || a.hi < a.lo || a.lo < row.min_value ||
        a.hi > row.max_value)
      return Status::Error("vary",
                           a.key + ": must have 1 to 9 points, lo <= hi, both " + RangeText(row));
    grid *= a.points;
  }
  const double runs = grid * static_cast<double>(r.last_seed - r.first_seed + 1);
  if (runs > kMaxCalibrateRuns)
    return Status::Error("vary", FormatCount(runs) +
                                     " runs (grid points × seeds); must be at most " +
                                     std::to_string(kMaxCalibrateRuns));
  NIWA_RETURN_IF_ERROR(
      CheckEstimate(EstimateCalibrate(r), budget, "lower the points, the seeds, N_R or N_H"));

  nlohmann::ordered_json candidates = nlohmann::ordered_json::array();
  int best = -1, best_means = -1;
  double best_score = 0, best_tie = 0, best_means_score = 0;
  const int points = static_cast<int>(grid);
  for (int g = 0; g < points; ++g) {
    nlohmann::ordered_json values;
    const BarkState s = GridPoint(r, g, &values);
    NIWA_RETURN_IF_ERROR(CheckBarkState(s));
    Result<Scored> scored = four ? ScoreFourLayer(s, r, budget) : ScoreTwoLayer(s, r, budget);
    if (!scored.ok()) return scored.status();
    if (best < 0 || scored->score < best_score ||
        (scored->score == best_score && scored->tie < best_tie)) {
      best = g;
      best_score = scored->score;
      best_tie = scored->tie;
    }
    if (!four) {
      const double m = scored->parts["means"].get<double>();
      if (best_means < 0 || m < best_means_score) {
        best_means = g;
        best_means_score = m;
      }
    }
    candidates.push_back({{"values", values},
                          {"measures", scored->measures},
                          {"deviations", scored->parts},
                          {"score", scored->score}});
  }

  nlohmann::ordered_json j;
  j["species"] = r.base.species;
  j["model"] = r.base.model;
  j["size"] = {r.base.params.GetInt(BarkParam::kNR), r.base.params.GetInt(BarkParam::kNH)};
  if (four) j["cycles"] = r.base.params.GetInt(BarkParam::kCycles);
  j["seeds"] = {r.first_seed, r.last_seed};
  nlohmann::ordered_json vary = nlohmann::ordered_json::array();
  for (const CalibrateAxis& a : r.vary) vary.push_back({{"key", a.key}, {"values", a.Values()}});
  j["vary"] = vary;
  if (four) {
    j["target"] = {
        {"peeled_share",
         {kPeelShareCentre - kPeelShareHalfWidth, kPeelShareCentre + kPeelShareHalfWidth}},
        {"peeled_share_least", kPeelShareLeast}};
  } else {
    const PaperTable3Row* p = PaperTable3(r.base.species);
    j["target"] = {{"mean", {p->mean_w, p->mean_h}},
                   {"max",
                    {p->max_w, p->max_h > 0 ? nlohmann::ordered_json(p->max_h)
                                            : nlohmann::ordered_json(">H")}},
                   {"tolerance", {{"mean", kMeanTolerance}, {"max", kMaxTolerance}}}};
  }
  j["runs"] = static_cast<int>(runs);
  j["candidates"] = candidates;
  const nlohmann::ordered_json& b = candidates[static_cast<std::size_t>(best)];
  j["best"] = b;
  if (four) {
    j["meets"] = {{"peel", b["score"].get<double>() <= 1.0}};
  } else {
    j["meets"] = {{"means", b["deviations"]["means"].get<double>() <= 1.0},
                  {"maxima", b["deviations"]["maxima"].get<double>() <= 1.0}};
    j["best_means"] = candidates[static_cast<std::size_t>(best_means)];
  }
  return j.dump();
}

}  // namespace niwa::bark

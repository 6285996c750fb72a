// Simulated bark per trunk in the garden (see garden_bark.h).
#include "compose/garden_bark.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "bark/bark_params.h"
#include "bark/bark_run.h"
#include "bark/bark_state.h"
#include "compose/garden_params.h"
#include "params/param_text.h"

namespace niwa::compose {
namespace {

using bark::BarkParam;

// The tallest a bark map can be (rows; bark_run's estimate takes the same).
constexpr double kMaxMapRows = 4096;
// Bytes of the three maps' PNGs per pixel, at most (RGBA, barely compressed), and seconds to copy
// them into the .glb.
constexpr double kMapPngBytesPerPixel = 3 * 4;
constexpr double kGlbSecondsPerByte = 1e-8;

}  // namespace

std::string GardenBarkSpecies(const std::string& tree_preset) {
  static const std::map<std::string, std::string> kBark = {
      {"pine", "pine"},       {"sakura", "tallow"},          {"sakura-thesis", "tallow"},
      {"weeping", "tallow"},  {"keyaki", "tallow"},          {"keyaki-thesis", "tallow"},
      {"tsutsuji", "tallow"}, {"tsutsuji-thesis", "tallow"}, {"maple", "camphor"},
      {"ginkgo", "camphor"},
  };
  const auto it = kBark.find(tree_preset);
  return it == kBark.end() ? std::string("camphor") : it->second;
}

int GardenBarks::simulated() const {
  int n = 0;
  for (const GardenBark& b : trees) n += b.frame ? 1 : 0;
  return n;
}

Result<GardenBarks> StartGardenBarks(const GardenState& state,
                                     const std::vector<std::string>& species) {
  GardenBarks barks;
  barks.on = state.params.GetBool(GardenParam::kBark);
  barks.map_size = state.params.GetInt(GardenParam::kBarkMapSize);
  if (!barks.on) return barks;
  BarkOnTreeOptions options;
  options.map_size = barks.map_size;
  NIWA_RETURN_IF_ERROR(CheckBarkOnTreeOptions(options));
  for (const std::string& s : species) {
    GardenBark b;
    b.species = GardenBarkSpecies(s);
    for (int k = 0; k < 2; ++k) b.trunk[k].height_m = kGardenBarkHeights[k];
    barks.trees.push_back(std::move(b));
  }
  return barks;
}

Estimate GardenBarkLeastEstimate(const GardenBarks& barks) {
  Estimate total;
  if (!barks.on) return total;
  for (const GardenBark& b : barks.trees) {
    bark::BarkState s;
    if (!bark::SetBarkSpecies(b.species, &s).ok()) continue;
    if (!s.params.Set(BarkParam::kNR, 8).ok() || !s.params.Set(BarkParam::kCycles, 1).ok() ||
        !s.params.Set(BarkParam::kMapSize, barks.map_size).ok())
      continue;
    const Estimate e = bark::EstimateBarkRun(s);
    // The runs follow one another: their times add, their memory is one run's.
    total.seconds += e.seconds;
    total.memory_bytes = std::max(total.memory_bytes, e.memory_bytes);
  }
  total.what = "the simulated bark of " + FormatCount(static_cast<double>(barks.trees.size())) +
               " distinct trees (at least; maps " + std::to_string(barks.map_size) + " px wide)";
  return total;
}

void RecordGardenTrunk(const Tree& tree, std::size_t g, GardenBarks* barks) {
  if (!barks->on || g >= barks->trees.size()) return;
  for (TrunkHistory& h : barks->trees[g].trunk) RecordTrunkYear(tree, &h);
}

Status GrowGardenBarks(const std::vector<const Tree*>& trees, const std::vector<uint64_t>& seeds,
                       const Budget& left, const run::Observer& observer, GardenBarks* barks,
                       std::string* truncated_by) {
  if (!barks->on) return Status::Ok();
  const auto t0 = std::chrono::steady_clock::now();
  double seconds_used = 0;
  // Barks whose states are the same (species, seed, lattice, cycles, dR: trees of one species,
  // seed and thin trunk often reach the same ceiling and N_R) are one run: the same state gives the
  // same bytes.
  std::map<std::string, std::shared_ptr<const BarkFrame>> runs;
  const double n = static_cast<double>(barks->trees.size());
  for (std::size_t g = 0; g < barks->trees.size() && g < trees.size(); ++g) {
    if (observer && !observer({"bark", static_cast<double>(g), n})) return run::CancelledStatus();
    GardenBark& b = barks->trees[g];
    // Breast height when the trunk reached it the year before the last, else near the foot.
    const TrunkHistory* history = nullptr;
    for (const TrunkHistory& h : b.trunk) {
      if (history == nullptr && BarkHeights(h).max >= h.height_m) history = &h;
    }
    if (history == nullptr) {
      b.procedural_why = "the trunk grew " + std::to_string(b.trunk[1].years.size()) +
                         " year(s) and did not reach " + FormatNumber(kGardenBarkHeights[1]) +
                         " m the year before the last";
      continue;
    }
    BarkOnTreeOptions options;
    options.species = b.species;
    options.map_size = barks->map_size;
    options.seed = seeds[g];
    Result<BarkOnTreePlan> plan = PlanBarkOnTree(*history, options);
    if (!plan.ok()) {
      b.procedural_why = plan.status().Line();
      continue;
    }
    const std::string key = bark::EncodeBarkHash(plan->state);
    if (const auto it = runs.find(key); it != runs.end()) {
      b.height_m = history->height_m;
      b.plan = std::move(plan).value();
      b.frame = it->second;
      continue;
    }
    Budget mine = left;
    mine.seconds = left.seconds - seconds_used;
    const Estimate e = OldBarkEstimate(*plan);
    const bool over_time = e.seconds > mine.seconds;
    if (over_time || e.memory_bytes > static_cast<double>(mine.memory_bytes)) {
      const std::string& limit = over_time ? left.seconds_limit : left.memory_limit;
      b.procedural_why = "over the budget";
      if (truncated_by->empty())
        *truncated_by =
            "bark: " + TruncatedLine(limit, "before distinct tree " + std::to_string(g),
                                     "the trees, the ivy and the barks before it "
                                     "used the garden's budget",
                                     "set bark 0, or lower bark_map_size" + RaiseHint(limit));
      continue;
    }
    Result<BarkFrame> frame = GrowOldBark(*plan, mine);
    if (!frame.ok()) return frame.status();
    seconds_used += e.seconds;
    // The page's pixels are not kept: the .glb takes the PNGs.
    frame->colour_pixels = {};
    frame->normal_pixels = {};
    b.height_m = history->height_m;
    b.plan = std::move(plan).value();
    b.frame = std::make_shared<const BarkFrame>(std::move(frame).value());
    runs[key] = b.frame;
    ++barks->runs;
  }
  barks->grown = true;
  barks->ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return Status::Ok();
}

void WrapGardenBarkUvs(const Tree& tree, const BarkFrame& frame, std::vector<LodMesh>* levels) {
  for (LodMesh& level : *levels) {
    if (level.parts.bark.indices.empty()) continue;
    level.parts.bark.uvs = WrapBarkUvs(tree, level.parts, frame);
  }
}

void DressGardenBark(const BarkFrame& frame, gltf::Document* tree_doc) {
  for (gltf::Material& m : tree_doc->materials) {
    if (m.name != "bark") continue;
    DressBarkMaterial(frame, "bark", &m, tree_doc);
    m.base_color_factor = {1, 1, 1, 1};
  }
}

Estimate GardenBarkExportEstimate(const GardenBarks& barks) {
  Estimate e;
  if (!barks.on) return e;
  for (const GardenBark& b : barks.trees) {
    // Before the barks are run, the tallest maps; after, their PNGs.
    const double bytes = b.frame ? static_cast<double>(b.frame->base_colour.size() +
                                                       b.frame->normal.size() + b.frame->orm.size())
                                 : barks.map_size * kMaxMapRows * kMapPngBytesPerPixel;
    e.memory_bytes += 2 * bytes;  // the document's copy and the .glb's
    e.seconds += bytes * kGlbSecondsPerByte;
  }
  e.what = "the simulated barks' maps";
  return e;
}

std::string GardenBarksJson(const GardenBarks& barks) {
  if (!barks.on) return "";
  nlohmann::ordered_json j;
  j["simulated"] = barks.simulated();
  j["procedural"] = static_cast<int>(barks.trees.size()) - barks.simulated();
  j["runs"] = barks.runs;
  j["map_size"] = barks.map_size;
  nlohmann::ordered_json by_species = nlohmann::ordered_json::object();
  nlohmann::ordered_json trees = nlohmann::ordered_json::array();
  for (const GardenBark& b : barks.trees) {
    if (!b.frame) {
      trees.push_back({{"species", b.species}, {"procedural", b.procedural_why}});
      continue;
    }
    by_species[b.species] = by_species.value(b.species, 0) + 1;
    const BarkOnTreePlan& p = b.plan;
    trees.push_back({{"species", b.species},
                     {"height_m", b.height_m},
                     {"years", {p.first_year, p.last_year}},
                     {"radii_cm", p.radii_cm},
                     {"N_R", p.state.params.GetInt(BarkParam::kNR)},
                     {"dR", p.state.params.Get(BarkParam::kDeltaR)},
                     {"tile_cm", {b.frame->tile_width_m * 100, b.frame->tile_height_m * 100}},
                     {"hash", b.frame->hash}});
  }
  j["species"] = by_species;
  j["trees"] = trees;
  return j.dump();
}

}  // namespace niwa::compose

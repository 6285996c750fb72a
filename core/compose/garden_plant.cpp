// The garden's planting rules (see garden_plant.h).
#include "compose/garden_plant.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "random/pcg32.h"

namespace niwa::compose {
namespace {

// The Poisson grid: cells of side spacing/√2 hold at most one trunk each, so a dart reads the
// 5 × 5 cells around its own.
class SpacingGrid {
 public:
  SpacingGrid(double size, double spacing) : size_(size), spacing_(spacing) {
    cell_ = spacing / std::sqrt(2.0);
    n_ = std::max(1, static_cast<int>(std::ceil(size / cell_)));
    slots_.assign(static_cast<std::size_t>(n_) * n_, -1);
  }
  bool Free(double x, double z, const std::vector<PlacedTree>& trees) const {
    const int ci = Index(x), cj = Index(z);
    for (int j = std::max(0, cj - 2); j <= std::min(n_ - 1, cj + 2); ++j)
      for (int i = std::max(0, ci - 2); i <= std::min(n_ - 1, ci + 2); ++i) {
        const int t = slots_[static_cast<std::size_t>(j) * n_ + i];
        if (t < 0) continue;
        const double dx = trees[t].x - x, dz = trees[t].z - z;
        if (dx * dx + dz * dz < spacing_ * spacing_) return false;
      }
    return true;
  }
  // Hand-placed trees may share a cell: those are checked by brute force (few of them).
  void Put(double x, double z, int tree) {
    int& slot = slots_[static_cast<std::size_t>(Index(z)) * n_ + Index(x)];
    if (slot < 0) slot = tree;
  }

 private:
  int Index(double v) const {
    return std::clamp(static_cast<int>((v + size_ / 2) / cell_), 0, n_ - 1);
  }
  double size_, spacing_, cell_;
  int n_;
  std::vector<int> slots_;
};

}  // namespace

Result<Planting> PlantGarden(const GardenState& state, const GardenScene& scene) {
  Planting out;
  const GardenGround& g = scene.ground;
  for (std::size_t i = 0; i < state.plants.size(); ++i) {
    const GardenPlant& p = state.plants[i];
    for (std::size_t k = 0; k < scene.objects.size(); ++k)
      if (scene.objects[k].Covers(p.x, p.z, kTrunkClearance))
        return Status::Error("plants[" + std::to_string(i) + "].pos",
                             "[" + FormatNumber(p.x) + ", " + FormatNumber(p.z) +
                                 "] is inside objects[" + std::to_string(k) + "] (" +
                                 scene.objects[k].kind + "); a tree must stand at least " +
                                 FormatNumber(kTrunkClearance) + " m outside an object");
    out.trees.push_back(
        {p.species, p.seed, p.age, p.x, g.HeightAt(p.x, p.z), p.z, p.rot, static_cast<int>(i)});
  }
  PlantingReport& r = out.report;
  r.by_hand = static_cast<long>(out.trees.size());
  const double size = state.params.Get(GardenParam::kSize);
  const double density = state.params.Get(GardenParam::kDensity);
  const double target = std::round(density * size * size);
  if (target > kMaxRuleTrees)
    return Status::Error("density", FormatNumber(density) + " asks for " + FormatCount(target) +
                                        " trees over " + FormatNumber(size) + " m²; at most " +
                                        FormatCount(kMaxRuleTrees) + " (lower density or size)");
  r.target = static_cast<long>(target);
  if (r.target == 0) return out;
  image::Rgba8Image mask;
  if (!state.mask_png.empty()) {
    Result<image::Rgba8Image> img = DecodeGardenMask(state.mask_name, state.mask_png);
    if (!img.ok()) return img.status();
    mask = std::move(*img);
  }
  const double spacing = state.params.Get(GardenParam::kSpacing);
  const double alt_min = state.params.Get(GardenParam::kAltMin);
  const double alt_max = state.params.Get(GardenParam::kAltMax);
  const double slope_max = state.params.Get(GardenParam::kSlopeMax);
  const int variants = state.params.GetInt(GardenParam::kVariants);
  double total_weight = 0;
  for (const SpeciesWeight& w : state.mix) total_weight += w.weight;
  SpacingGrid grid(size, spacing);
  for (std::size_t t = 0; t < out.trees.size(); ++t)
    grid.Put(out.trees[t].x, out.trees[t].z, static_cast<int>(t));
  Pcg32 rng(static_cast<uint64_t>(state.params.Get(GardenParam::kPlantSeed)), 0x67617264656eULL);
  const long darts = r.target * kDartsPerTree;
  const std::size_t hand = out.trees.size();
  while (r.candidates < darts && r.by_rule < r.target) {
    ++r.candidates;
    const double x = rng.Uniform(-size / 2, size / 2), z = rng.Uniform(-size / 2, size / 2);
    const double keep =
        rng.Uniform();  // drawn for every dart: the sequence never depends on a mask
    if (!mask.pixels.empty()) {
      const int px = std::clamp(static_cast<int>((x / size + 0.5) * mask.width), 0, mask.width - 1);
      const int py =
          std::clamp(static_cast<int>((z / size + 0.5) * mask.height), 0, mask.height - 1);
      const unsigned char* c = mask.At(px, py);
      const double luminance = (0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]) / 255.0;
      if (keep >= luminance) {
        ++r.refused_mask;
        continue;
      }
    }
    const double y = g.HeightAt(x, z);
    if (y < alt_min || y > alt_max) {
      ++r.refused_altitude;
      continue;
    }
    if (g.SlopeAt(x, z) > slope_max) {
      ++r.refused_slope;
      continue;
    }
    bool on_object = false;
    for (const PlacedObject& o : scene.objects)
      on_object = on_object || o.Covers(x, z, kTrunkClearance);
    if (on_object) {
      ++r.refused_object;
      continue;
    }
    bool free = grid.Free(x, z, out.trees);
    for (std::size_t t = 0; free && t < hand; ++t) {
      const double dx = out.trees[t].x - x, dz = out.trees[t].z - z;
      free = dx * dx + dz * dz >= spacing * spacing;
    }
    if (!free) {
      ++r.refused_spacing;
      continue;
    }
    double pick = rng.Uniform() * total_weight;
    std::size_t s = 0;
    while (s + 1 < state.mix.size() && pick >= state.mix[s].weight) pick -= state.mix[s++].weight;
    const uint64_t variant =
        1 + std::min<uint64_t>(variants - 1, static_cast<uint64_t>(rng.Uniform() * variants));
    const double rot = rng.Uniform(0, 360);
    grid.Put(x, z, static_cast<int>(out.trees.size()));
    out.trees.push_back({state.mix[s].species, variant, 0, x, y, z, rot, -1});
    ++r.by_rule;
  }
  return out;
}

std::string PlantingJson(const Planting& planting) {
  nlohmann::ordered_json j;
  j["trees"] = nlohmann::ordered_json::array();
  for (const PlacedTree& t : planting.trees)
    j["trees"].push_back({{"species", t.species},
                          {"seed", t.seed},
                          {"age", t.age},
                          {"pos", {t.x, t.y, t.z}},
                          {"rot", t.rot},
                          {"hand", t.hand}});
  const PlantingReport& r = planting.report;
  j["report"] = {{"target", r.target},
                 {"candidates", r.candidates},
                 {"by_hand", r.by_hand},
                 {"by_rule", r.by_rule},
                 {"refused",
                  {{"mask", r.refused_mask},
                   {"altitude", r.refused_altitude},
                   {"slope", r.refused_slope},
                   {"object", r.refused_object},
                   {"spacing", r.refused_spacing}}}};
  return j.dump();
}

}  // namespace niwa::compose

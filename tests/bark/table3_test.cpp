// Table 3's orderings (spec §4.1) from the 2-layer model on a 64 × 64 patch, seeds 1-2, the means
// over the seeds: level A (one height growth, dH = 0.03, for all three species) and level B (the
// presets' per-species growth). The paper's numbers themselves (level B, 128 × 64, seeds 1-5) are
// measured by scripts/figures bark table3 (docs/FIGURES.md); these are the orderings the three
// species' Table 2 constants must give.
#include <gtest/gtest.h>

#include <map>
#include <string>

#include "bark/bark_run.h"

namespace niwa::bark {
namespace {

struct Measured {
  double vertical = 0, mean_w = 0, mean_h = 0, intercept_h = 0, closed = 0;
  double spacing_w = 0, spacing_h = 0;  // crack spacing along scan lines (the paper's measure)
};

Measured Grow(const std::string& species, bool level_a) {
  Measured m;
  const int seeds = 2;
  for (int seed = 1; seed <= seeds; ++seed) {
    BarkState s;
    EXPECT_TRUE(SetBarkSpecies(species, &s).ok());
    EXPECT_TRUE(SetBarkSize("64x64", &s).ok());
    EXPECT_TRUE(SetBarkSeed(seed, &s).ok());
    if (level_a) {  // one growth for all: dH 0.03 and Table 1's dR and D (tallow's preset differs)
      EXPECT_TRUE(s.params.Set(BarkParam::kDeltaH, 0.03).ok());
      EXPECT_TRUE(s.params.Set(BarkParam::kDeltaR, 0.021).ok());
      EXPECT_TRUE(s.params.Set(BarkParam::kD, 1.0).ok());
    }
    Result<BarkRun> run = BarkRun::Start(s, Budget{});
    EXPECT_TRUE(run.ok());
    EXPECT_TRUE(run->Advance({}).ok());
    const CrackMeasures& c = run->cracks();
    m.vertical += c.vertical_crack_share / seeds;
    m.mean_w += c.mean_width / seeds;
    m.mean_h += c.mean_height / seeds;
    m.intercept_h += c.intercept_height / seeds;
    m.closed += c.closed_fraction / seeds;
    m.spacing_w += c.spacing_width.mean / seeds;
    m.spacing_h += c.spacing_height.mean / seeds;
  }
  return m;
}

TEST(Table3, LevelAOneGrowthForAllSpecies) {
  const Measured camphor = Grow("camphor", true), tallow = Grow("tallow", true),
                 pine = Grow("pine", true);
  // Vertical cracks: camphor's the most (note *1).
  EXPECT_GT(camphor.vertical, tallow.vertical);
  EXPECT_GT(camphor.vertical, pine.vertical);
  // Width: pine's plates at least 1.25× tallow's and camphor's.
  EXPECT_GE(pine.mean_w, 1.25 * tallow.mean_w);
  EXPECT_GE(pine.mean_w, 1.25 * camphor.mean_w);
  // Height (the crack spacing along the trunk): camphor > pine > tallow.
  EXPECT_GT(camphor.intercept_h, pine.intercept_h);
  EXPECT_GT(pine.intercept_h, tallow.intercept_h);
  // On the crack spacing along scan lines (docs/bark-model.md choice 10a): the same height order,
  // and camphor's spacing at least 1.3x as elongated as tallow's (the plates' extents miss this
  // one: docs/FIGURES.md, Table 3 level A).
  EXPECT_GT(camphor.spacing_h, pine.spacing_h);
  EXPECT_GT(pine.spacing_h, tallow.spacing_h);
  EXPECT_GE(camphor.spacing_h / camphor.spacing_w, 1.3 * tallow.spacing_h / tallow.spacing_w);
}

TEST(Table3, LevelBPerSpeciesGrowth) {
  const Measured camphor = Grow("camphor", false), tallow = Grow("tallow", false),
                 pine = Grow("pine", false);
  EXPECT_GE(camphor.vertical, 0.85);
  EXPECT_GT(camphor.vertical, tallow.vertical);
  EXPECT_GT(camphor.vertical, pine.vertical);
  // Plate height: camphor > pine > tallow (Table 3: 11.6 > 4.28 > 3.02).
  EXPECT_GT(camphor.mean_h, pine.mean_h);
  EXPECT_GT(pine.mean_h, tallow.mean_h);
  // Camphor's plates are long: height/width at least 1.3× tallow's (the paper's 7.3 against 1.8).
  EXPECT_GE(camphor.mean_h / camphor.mean_w, 1.3 * tallow.mean_h / tallow.mean_w);
  // Tallow's cracks close regions (note *2) at least as often as camphor's.
  EXPECT_GE(tallow.closed, camphor.closed);
}

}  // namespace
}  // namespace niwa::bark

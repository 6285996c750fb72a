// The terrain figure presets, read from core/terrain/presets/figure_presets.json through the one
// embed step, are the paper's figure settings (docs/terrain-model.md; held in C++ before the move).
#include <gtest/gtest.h>

#include "terrain/terrain_params.h"

namespace niwa::terrain {
namespace {

using P = TerrainParam;
using V = std::vector<std::pair<TerrainParam, double>>;

TEST(TerrainPresets, TheFiguresInThePapersOrderWithTheirValues) {
  const std::vector<FigurePreset>& presets = FigurePresets();
  const std::vector<std::string> names = {"fig9a",  "fig9b",  "fig9c",  "fig10a", "fig10b",
                                          "fig13a", "fig13b", "fig13c", "fig14a", "fig14b",
                                          "fig14c", "fig15",  "fig16"};
  ASSERT_EQ(presets.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(presets[i].name, names[i]);
    EXPECT_FALSE(presets[i].caption.empty()) << names[i];
  }
  EXPECT_EQ(presets[1].values, (V{{P::kMethod, 0}, {P::kJoin, 1}, {P::kC, 1.4}}));
  EXPECT_EQ(presets[4].values, (V{{P::kMethod, 0}, {P::kJoin, 3}, {P::kC, 1.6}}));
  EXPECT_EQ(presets[7].values, (V{{P::kMethod, 1},
                                  {P::kJoin, 3},
                                  {P::kC, 1.4},
                                  {P::kD2, 0.3},
                                  {P::kThetaMin, 0},
                                  {P::kThetaMax, 30}}));
  EXPECT_EQ(presets[8].values,
            (V{{P::kMethod, 2}, {P::kJoin, 3}, {P::kC, 1.4}, {P::kF0, 64}, {P::kNfft, 1024}}));
  EXPECT_EQ(presets[12].values, (V{{P::kMethod, 3},
                                   {P::kJoin, 3},
                                   {P::kC, 3},
                                   {P::kD2, 0.5},
                                   {P::kThetaMin, 20},
                                   {P::kThetaMax, 40},
                                   {P::kF0, 256},
                                   {P::kNfft, 1024}}));
  EXPECT_EQ(presets[12].caption, "improved method: d' = 3d, d'' = 0.5d, θ in (20°, 40°), f0 = 256");
}

TEST(TerrainPresets, MethodNamesPickTheirFigure) {
  TerrainParams a, b;
  ASSERT_TRUE(ApplyPreset("improved", &a).ok());
  ASSERT_TRUE(ApplyPreset("fig16", &b).ok());
  EXPECT_EQ(a.Get(P::kC), 3);
  EXPECT_EQ(a.Get(P::kThetaMax), b.Get(P::kThetaMax));
  EXPECT_EQ(ApplyPreset("fig99", &a).field(), "preset");
}

}  // namespace
}  // namespace niwa::terrain

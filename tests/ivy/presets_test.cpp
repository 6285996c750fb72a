// The ivy presets, read from core/ivy/presets/ivy_presets.json through the one embed step, are the
// values docs/ivy-model.md gives (and that ivy_params.cpp held in C++ before the move).
#include <gtest/gtest.h>

#include "ivy/ivy_params.h"
#include "params/embedded_presets.h"

namespace niwa {
namespace {

TEST(IvyPresets, ReadFromTheEmbeddedListInItsOrder) {
  const std::vector<std::string> names = {"paper", "literal", "improved", "metric", "artist"};
  EXPECT_EQ(IvyPresetNames(), names);
  using V = std::vector<std::pair<std::string, double>>;
  EXPECT_EQ(IvyPresetOverrides("paper"), V{});
  EXPECT_EQ(IvyPresetOverrides("literal"), (V{{"kappa", 0}, {"lambda", 1}}));
  EXPECT_EQ(IvyPresetOverrides("improved"),
            (V{{"max_bend", 60}, {"avoid", 10}, {"candidates", 32}, {"body", 1}}));
  // metric is a scale, not lengths (issue 31 item 4): the paper's rows at 1000 px per unit.
  EXPECT_EQ(IvyPresetOverrides("metric"), (V{{"scale", 1000}}));
  // artist (issue 31 item 5): beyond the paper; its own rows are 0 in every other preset.
  EXPECT_EQ(IvyPresetOverrides("artist"), (V{{"g_min", -1},
                                             {"hang", 8},
                                             {"max_bend", 90},
                                             {"avoid", 20},
                                             {"candidates", 32},
                                             {"body", 1},
                                             {"leaf_light", 1},
                                             {"w_grav", 0.5},
                                             {"t2", 0.5},
                                             {"leaf_size", 75},
                                             {"leaf_spacing", 50}}));
  for (const char* other : {"paper", "literal", "improved", "metric"}) {
    EXPECT_EQ(IvyPreset(other)->Get(IvyParam::kHang), 0) << other;
    EXPECT_EQ(IvyPreset(other)->Get(IvyParam::kLeafLight), 0) << other;
    EXPECT_EQ(IvyPreset(other)->Get(IvyParam::kGMin), 0) << other;
    EXPECT_EQ(IvyPreset(other)->Get(IvyParam::kLeafSpacing), 0) << other;
  }
  Result<IvyParams> metric = IvyPreset("metric");
  ASSERT_TRUE(metric.ok());
  EXPECT_EQ(metric->Get(IvyParam::kL), 50);
  EXPECT_EQ(metric->Get(IvyParam::kScale), 1000);
  EXPECT_FALSE(IvyPreset("nope").ok());
}

TEST(IvyPresets, EveryListedPresetHasItsSource) {
  Result<std::vector<ListedPreset>> listed = ReadPresetLists("ivy", IvyTable());
  ASSERT_TRUE(listed.ok()) << listed.status().Line();
  ASSERT_EQ(listed->size(), 5u);
  for (const ListedPreset& p : *listed) EXPECT_FALSE(p.source.empty()) << p.name;
}

}  // namespace
}  // namespace niwa

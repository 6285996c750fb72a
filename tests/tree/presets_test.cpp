// Tests that the preset files load and carry the values of thesis table 2.2.
#include "tree/presets.h"

#include <gtest/gtest.h>

namespace niwa {
namespace {

TEST(Presets, ThesisSpeciesLoadWithTable22Values) {
  ASSERT_NE(FindPreset("binary"), nullptr);
  ASSERT_NE(FindPreset("sakura-thesis"), nullptr);
  ASSERT_NE(FindPreset("keyaki-thesis"), nullptr);
  ASSERT_NE(FindPreset("tsutsuji-thesis"), nullptr);
  EXPECT_EQ(FindPreset("nope"), nullptr);
  const TreeParams& binary = FindPreset("binary")->params;
  EXPECT_EQ(binary.Get(ParamId::kPsiT), -10);
  EXPECT_EQ(binary.Get(ParamId::kPTlS), 0.3);
  EXPECT_EQ(binary.Get(ParamId::kHBD), 2);
  const TreeParams& sakura = FindPreset("sakura-thesis")->params;
  EXPECT_EQ(sakura.Get(ParamId::kNLow), 6);
  EXPECT_EQ(sakura.Get(ParamId::kNHigh), 25);
  EXPECT_EQ(sakura.Get(ParamId::kPhi), 0.4);
  EXPECT_EQ(sakura.Get(ParamId::kThetaBmaxB), 20);
  const TreeParams& keyaki = FindPreset("keyaki-thesis")->params;
  EXPECT_EQ(keyaki.Get(ParamId::kThetaN), 6);
  EXPECT_EQ(keyaki.Get(ParamId::kSympodial), 1);
  EXPECT_EQ(keyaki.Get(ParamId::kPLOld), 0.7);
  const TreeParams& tsutsuji = FindPreset("tsutsuji-thesis")->params;
  EXPECT_EQ(tsutsuji.Get(ParamId::kBTl), 3);
  EXPECT_EQ(tsutsuji.Get(ParamId::kDeltaD), 0.8);
  EXPECT_EQ(PresetNames().find("binary"), 0u);
}

}  // namespace
}  // namespace niwa

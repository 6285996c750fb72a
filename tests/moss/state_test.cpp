// The moss state's preset and share-link hash: preset first, rows clamped with a notice, repeated
// and unknown keys refused, the prefix of a composed page, and encode -> apply round trips.
#include <gtest/gtest.h>

#include "moss/moss_state.h"

namespace niwa::moss {
namespace {

TEST(MossState, HashAppliesThePresetFirstThenTheRows) {
  MossState state;
  std::vector<std::string> notices;
  ApplyMossHash("T=293.15&preset=nomura2010-sky", "", &state, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(state.preset, "nomura2010-sky");
  EXPECT_EQ(state.params.Get(MossParam::kT), 293.15);
  EXPECT_EQ(state.params.Get(MossParam::kSSky), 68.0);
  EXPECT_EQ(EncodeMossHash(state), "preset=nomura2010-sky&T=293.15");
}

TEST(MossState, BadKeysAndValuesGiveNotices) {
  MossState state;
  std::vector<std::string> notices;
  ApplyMossHash("rh=2&preset=nope&zz=1", "", &state, &notices);
  ASSERT_EQ(notices.size(), 3u);
  EXPECT_NE(notices[0].find("preset: 'nope' is unknown; must be nomura2010 or nomura2010-sky"),
            std::string::npos);
  EXPECT_NE(notices[1].find("rh"), std::string::npos);  // clamped into [0, 1]
  EXPECT_EQ(state.params.Get(MossParam::kRh), 1.0);
  EXPECT_EQ(notices[2], "unknown key 'zz' dropped");
  notices.clear();
  MossState fresh;
  ApplyMossHash("T=290&T=291", "", &fresh, &notices);
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_NE(notices[0].find("T: given 2 times"), std::string::npos);
  EXPECT_EQ(fresh.params.Get(MossParam::kT), 288.15);  // refused whole
}

TEST(MossState, PrefixedKeysOnAComposedPage) {
  MossState state;
  std::vector<std::string> notices;
  ApplyMossHash("moss.gingoke_tau_d=0.2&ivy.steps=3", "moss.", &state, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(state.params.Get(SpeciesRow(Species::kGingoke, 12)), 0.2);
  const std::string hash = EncodeMossHash(state, "moss.");
  EXPECT_EQ(hash, "moss.preset=nomura2010&moss.gingoke_tau_d=0.2");
  MossState back;
  ApplyMossHash(hash, "moss.", &back, &notices);
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(static_cast<const ParamSet&>(back.params), static_cast<const ParamSet&>(state.params));
  EXPECT_EQ(SetMossPreset("x", &back).field(), "preset");
}

}  // namespace
}  // namespace niwa::moss

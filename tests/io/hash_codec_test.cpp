// Tests of the generic share-link hash codec: splitting, percent-decoding, printable notices and
// clamp-with-notice over a table's rows (the tree table here; a second table in tests/params).
#include "io/hash_codec.h"

#include <gtest/gtest.h>

#include "tree/tree_params.h"

namespace niwa {
namespace {

TEST(HashCodec, SplitsDecodesAndSkipsEmptyItems) {
  HashPairs pairs = SplitHash("#a=1&&b=%3Cx%3E&c&d=two+words&e=%zz&=v");
  ASSERT_EQ(pairs.size(), 6u);
  EXPECT_EQ(pairs[0], (std::pair<std::string, std::string>{"a", "1"}));
  EXPECT_EQ(pairs[1].second, "<x>");
  EXPECT_EQ(pairs[2], (std::pair<std::string, std::string>{"c", ""}));
  EXPECT_EQ(pairs[3].second, "two words");
  EXPECT_EQ(pairs[4].second, "%zz");  // not a %XX escape: kept as given
  EXPECT_EQ(pairs[5].first, "");
  EXPECT_TRUE(SplitHash("").empty());
  EXPECT_TRUE(SplitHash("#").empty());
  // Past kMaxHashLength the rest is ignored.
  std::string long_hash = "a=" + std::string(kMaxHashLength, '1') + "&b=2";
  ASSERT_EQ(SplitHash(long_hash).size(), 1u);
  EXPECT_EQ(PercentDecode("%41%62c%2"), "Abc%2");
}

TEST(HashCodec, PrintableDropsMarkupAndControlAndIsShort) {
  EXPECT_EQ(Printable("ok text"), "ok text");
  EXPECT_EQ(Printable("<img src='x'>&\"\n\x01"), "?img src=?x??????");
  EXPECT_EQ(Printable(std::string(100, 'a')).size(), 40u);
}

TEST(HashCodec, RowsAreClampedRoundedOrDroppedWithOneNoticeEach) {
  TreeParams params;
  std::vector<std::string> notices;
  EXPECT_TRUE(ApplyHashParam("gamma", "0.3", "", &params, &notices));
  EXPECT_TRUE(notices.empty());
  EXPECT_EQ(params.Get(TreeParam::kGamma), 0.3);
  EXPECT_TRUE(ApplyHashParam("gamma", "5", "", &params, &notices));
  EXPECT_EQ(params.Get(TreeParam::kGamma), 1.0);
  EXPECT_TRUE(ApplyHashParam("N_high", "2.6", "", &params, &notices));
  EXPECT_EQ(params.Get(TreeParam::kNHigh), 3.0);
  EXPECT_TRUE(ApplyHashParam("alpha_t", "<b>", "", &params, &notices));
  EXPECT_FALSE(ApplyHashParam("nope", "1", "", &params, &notices));
  EXPECT_FALSE(ApplyHashParam("gamma", "1", "tree.", &params, &notices));  // prefix missing
  ASSERT_EQ(notices.size(), 3u);
  EXPECT_EQ(notices[0], "gamma: clamped to 1, must be a number in [0, 1]");
  EXPECT_EQ(notices[1], "N_high: clamped to 3, must be a whole number in [1, 100]");
  EXPECT_EQ(notices[2], "alpha_t: '?b?' dropped, must be a number in [0, 1]");
  TreeParams base;
  EXPECT_EQ(EncodeChangedParams(params, base), "&gamma=1&N_high=3");
  EXPECT_EQ(EncodeChangedParams(params, base, "tree."), "&tree.gamma=1&tree.N_high=3");
  EXPECT_EQ(EncodeChangedParams(base, base), "");
}

}  // namespace
}  // namespace niwa

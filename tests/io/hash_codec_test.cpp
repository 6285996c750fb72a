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
  EXPECT_EQ(PercentDecode("%41%62c%2"), "Abc%2");
}

// Issue 16 item 4: a hash over the maximum is refused whole with one notice, never cut (cutting
// could read "...&years=10" as years=1); at the maximum it is read.
TEST(HashCodec, HashOverTheMaximumIsRefusedNotCut) {
  std::vector<std::string> notices;
  std::string at_limit = "a=" + std::string(kMaxHashLength - 6, '1') + "&b=2";
  ASSERT_EQ(at_limit.size(), kMaxHashLength);
  EXPECT_EQ(SplitHash(at_limit, &notices).size(), 2u);
  EXPECT_TRUE(notices.empty());
  std::string over = at_limit + "0";
  EXPECT_TRUE(SplitHash(over, &notices).empty());
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0], "hash: 16385 characters; the limit is 16384, nothing was read");
}

// Issue 34: a repeated key refuses the whole link (it used to be read with "the last value is
// used", so a page took what the CLI refused); repeatable keys (the tree's prunes) may repeat.
TEST(HashCodec, RepeatedKeysRefuseTheLinkUnlessRepeatable) {
  std::vector<std::string> notices;
  HashPairs pairs =
      SplitHash("seed=1&years=2&seed=3&prune=1:b2&prune=2:b3&seed=4", &notices, {"prune"});
  EXPECT_TRUE(pairs.empty());
  ASSERT_EQ(notices.size(), 1u);
  EXPECT_EQ(notices[0], "seed: given 3 times; must be given once, nothing was read");
  notices.clear();
  EXPECT_TRUE(SplitHash("builtin=disk&builtin=lobes7&d=5&d=50", &notices).empty());
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_EQ(notices[1], "d: given 2 times; must be given once, nothing was read");
  notices.clear();
  EXPECT_EQ(SplitHash("years=2&prune=1:b2&prune=2:b3", &notices, {"prune"}).size(), 3u);
  EXPECT_TRUE(notices.empty());
}

// Decoded values written back are encoded again: "5&mode=full" cannot become a key of its own.
TEST(HashCodec, PercentEncodeRoundTripsAndCannotInjectKeys) {
  const std::string hostile = "5&mode=full#x%20y+z\x1b<>";
  std::string encoded = PercentEncode(hostile);
  EXPECT_EQ(encoded.find_first_of("&=#+<> "), std::string::npos) << encoded;
  EXPECT_EQ(PercentDecode(encoded), hostile);
  HashPairs pairs = SplitHash("wind_speed=" + encoded);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].second, hostile);
  EXPECT_EQ(PercentEncode("a-b_c.d~1:2,3"), "a-b_c.d~1:2,3");
}

TEST(HashCodec, PrintableEscapesControlAndMarkupAndIsShort) {
  EXPECT_EQ(Printable("ok text"), "ok text");
  EXPECT_EQ(Printable("<img src='x'>&"), "\\x3cimg src=\\x27x\\x27\\x3e\\x26");
  EXPECT_EQ(Printable("a\x1b[31mb\n"), "a\\x1b[31mb\\x0a");
  EXPECT_EQ(Printable(std::string(100, 'a')), std::string(60, 'a') + "...");
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
  EXPECT_EQ(notices[2], "alpha_t: '\\x3cb\\x3e' dropped, must be a number in [0, 1]");
  TreeParams base;
  EXPECT_EQ(EncodeChangedParams(params, base), "&gamma=1&N_high=3");
  EXPECT_EQ(EncodeChangedParams(params, base, "tree."), "&tree.gamma=1&tree.N_high=3");
  EXPECT_EQ(EncodeChangedParams(base, base), "");
}

}  // namespace
}  // namespace niwa

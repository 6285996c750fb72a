// Tests of prune text (YEAR:bID, YEAR:sinceY) and of the reason a prune cut nothing.
#include "tree/prune.h"

#include <gtest/gtest.h>

#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

TEST(Prune, ParsesBranchAndSinceFormsAndFormatsThemBack) {
  Result<Prune> branch = ParsePrune("12:b42");
  ASSERT_TRUE(branch.ok());
  EXPECT_EQ(branch->year, 12);
  EXPECT_EQ(branch->branch, 42);
  EXPECT_EQ(branch->since_year, -1);
  EXPECT_EQ(FormatPrune(*branch), "12:b42");
  Result<Prune> bare = ParsePrune("3:7");  // the id without its 'b'
  ASSERT_TRUE(bare.ok());
  EXPECT_EQ(FormatPrune(*bare), "3:b7");
  Result<Prune> since = ParsePrune("10:since7");
  ASSERT_TRUE(since.ok());
  EXPECT_EQ(since->year, 10);
  EXPECT_EQ(since->branch, -1);
  EXPECT_EQ(since->since_year, 7);
  EXPECT_EQ(FormatPrune(*since), "10:since7");
  EXPECT_TRUE(ParsePrune("100:b0").ok());
}

TEST(Prune, BadTextIsOneLineNamingTheFormAndTheYearRange) {
  for (const char* text : {"", "12", ":b1", "0:b1", "101:b1", "2.5:b1", "3:", "3:x", "3:b", "3:b-1",
                           "3:b1.5", "3:since0", "3:since101", "3:sincex", "a:b1"}) {
    Result<Prune> prune = ParsePrune(text);
    ASSERT_FALSE(prune.ok()) << text;
    EXPECT_EQ(prune.status().field(), "prune");
    EXPECT_EQ(prune.status().message(), "'" + std::string(text) +
                                            "' must be YEAR:bID or YEAR:sinceY with YEAR in [1, "
                                            "100]");
  }
  // Hostile text is shown printable and short.
  Result<Prune> hostile = ParsePrune("<script>alert(1)</script>:b1");
  ASSERT_FALSE(hostile.ok());
  EXPECT_EQ(hostile.status().Line().find('<'), std::string::npos);
}

TEST(Prune, IdleReasonNamesThePrune) {
  GrowRequest r;
  r.preset = "binary";
  r.params = FindPreset("binary")->params;
  r.years = 4;
  Tree tree = GrowTree(r);
  EXPECT_TRUE(IdlePruneReason({4, 0, -1}, tree).ok());
  Status late = IdlePruneReason({5, 0, -1}, tree);
  EXPECT_EQ(late.field(), "5:b0");
  EXPECT_EQ(late.Line(), "5:b0: year 5 is after the last year grown (4)");
  EXPECT_EQ(IdlePruneReason({2, -1, 3}, tree).Line(),
            "2:since3: nothing had grown since year 3 by year 2");
}

}  // namespace
}  // namespace niwa

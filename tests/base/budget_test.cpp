// core/base/budget: byte sizes read and written, and the one-line refusal naming the limit.
#include "base/budget.h"

#include <gtest/gtest.h>

namespace niwa {
namespace {

TEST(Budget, ParsesSizes) {
  uint64_t b = 0;
  ASSERT_TRUE(ParseBytes("4G", &b));
  EXPECT_EQ(b, uint64_t{4} << 30);
  ASSERT_TRUE(ParseBytes("512MB", &b));
  EXPECT_EQ(b, uint64_t{512} << 20);
  ASSERT_TRUE(ParseBytes("1000", &b));
  EXPECT_EQ(b, 1000u);
  for (const char* bad :
       {"", "G", "-4G", "4.5G", "4 G", "4X", "0x10", "1234567890123456", "9999999T"})
    EXPECT_FALSE(ParseBytes(bad, &b)) << bad;
}

TEST(Budget, FormatsSizes) {
  EXPECT_EQ(FormatBytes(double(uint64_t{2} << 30)), "2 GB");
  EXPECT_EQ(FormatBytes(1.5 * 1024 * 1024), "1.5 MB");
  EXPECT_EQ(FormatBytes(100), "100 B");
}

TEST(Budget, RefusesNamingTheLimit) {
  Budget budget;  // 2 GB, 60 s, its limits named by their state fields (no flag words in core)
  Estimate fits{1e9, 10, "work"};
  EXPECT_TRUE(CheckEstimate(fits, budget, "lower x").ok());
  Status memory = CheckEstimate({3.0 * (1 << 30), 1, "writing the .json"}, budget, "lower years");
  EXPECT_EQ(memory.Line(),
            "max_memory: writing the .json needs about 3 GB, more than the 2 GB allowed; lower "
            "years");
  Status time = CheckEstimate({1, 61, "swaying"}, budget, "lower duration");
  EXPECT_EQ(time.field(), "max_seconds");
  // A front end names the limits with its words, and a flag gets its raise hint (the CLI).
  budget.memory_limit = "--max-memory";
  EXPECT_EQ(
      CheckEstimate({3.0 * (1 << 30), 1, "writing the .json"}, budget, "lower --years").Line(),
      "--max-memory: writing the .json needs about 3 GB, more than the 2 GB allowed; lower "
      "--years (or raise --max-memory)");
  EXPECT_EQ((fits + Estimate{1, 2, "more"}).what, "work and more");
}

}  // namespace
}  // namespace niwa

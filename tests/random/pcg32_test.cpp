// Tests of the project's PCG32 generator against the reference sequence of pcg-c-basic.
#include "random/pcg32.h"

#include <gtest/gtest.h>

namespace niwa {
namespace {

TEST(Pcg32, MatchesReferenceSequenceForSeed42Stream54) {
  // pcg32-demo (pcg-c-basic) output for pcg32_srandom_r(&rng, 42u, 54u).
  Pcg32 rng(42u, 54u);
  const uint32_t expected[] = {0xa15c02b7, 0x7b47f409, 0xba1d3330,
                               0x83d2f293, 0xbfa4784b, 0xcbed606e};
  for (uint32_t value : expected) EXPECT_EQ(rng.NextU32(), value);
}

TEST(Pcg32, UniformStaysInUnitIntervalAndIsRoughlyFlat) {
  Pcg32 rng(7);
  int buckets[10] = {};
  for (int i = 0; i < 100000; ++i) {
    double u = rng.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++buckets[static_cast<int>(u * 10)];
  }
  for (int count : buckets) EXPECT_NEAR(count, 10000, 500);
}

TEST(Pcg32, BernoulliEdgesAndSeedsDiffer) {
  Pcg32 a(1), b(2);
  EXPECT_FALSE(a.Bernoulli(0.0));
  EXPECT_TRUE(a.Bernoulli(1.0));
  EXPECT_NE(a.NextU32(), b.NextU32());
}

}  // namespace
}  // namespace niwa

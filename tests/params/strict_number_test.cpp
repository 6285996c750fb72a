// Tests of the one strict number parser (params/strict_number): the grammar against a brute-force
// twin (std::regex of the same grammar) on random text, and the one-line errors naming the field.
#include "params/strict_number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include "random/pcg32.h"

namespace niwa {
namespace {

TEST(StrictNumber, DecimalOnly) {
  EXPECT_EQ(ParseDecimal("0"), 0.0);
  EXPECT_EQ(ParseDecimal("-0"), 0.0);
  EXPECT_EQ(ParseDecimal("0.5"), 0.5);
  EXPECT_EQ(ParseDecimal("10"), 10.0);
  EXPECT_EQ(ParseDecimal("1e-05"), 1e-5);  // printf's exponent keeps its zero
  EXPECT_EQ(ParseDecimal("+5"), 5.0);
  EXPECT_EQ(ParseDecimal("-0.5"), -0.5);
  EXPECT_EQ(ParseDecimal(".5"), 0.5);
  EXPECT_EQ(ParseDecimal("5."), 5.0);
  EXPECT_EQ(ParseDecimal("1e3"), 1000.0);
  EXPECT_EQ(ParseDecimal("1E-3"), 0.001);
  for (const char* bad :
       {"",      " ",        "0x10", "0X1p3", "0x1p3", "1p3", "inf",   "-inf",  "nan",
        "NaN",   "infinity", "1e",   "1e+",   "e5",    ".",   "+",     "-",     "--5",
        "+-5",   "1.2.3",    " 5",   "5 ",    "5\n",   "5,0", "1_000", "1e400", "-1e400",
        "0b101", "\x1b",     "010",  "-01",   "+007",  "00",  "00.5",  "-00.5", "0010e2"}) {
    EXPECT_FALSE(ParseDecimal(bad).has_value()) << bad;
  }
  EXPECT_FALSE(ParseDecimal(std::string(kMaxNumberText + 1, '1')).has_value());  // refused, not cut
  EXPECT_TRUE(ParseDecimal(std::string(kMaxNumberText - 5, '1') + "e-40").has_value());
}

// The twin: the grammar written as a regex; random strings over the number alphabet (plus a few
// hostile characters) must be accepted by both or by neither, and accepted ones must be finite.
TEST(StrictNumber, MatchesItsRegexTwinOnRandomText) {
  const std::regex grammar(R"([+-]?((0|[1-9][0-9]*)(\.[0-9]*)?|\.[0-9]+)([eE][+-]?[0-9]+)?)");
  const std::string alphabet = "0123456789+-.eE x";
  Pcg32 rng(16, 4);
  int accepted = 0;
  for (int n = 0; n < 20000; ++n) {
    std::string text;
    const uint32_t length = rng.NextU32() % 9u;
    for (uint32_t i = 0; i < length; ++i) {
      text += alphabet[rng.NextU32() % static_cast<uint32_t>(alphabet.size())];
    }
    const bool twin = std::regex_match(text, grammar);
    std::optional<double> value = ParseDecimal(text);
    // The twin does not know finiteness: "9e999" matches it but overflows.
    if (twin && !value) {
      EXPECT_TRUE(text.find_first_of("eE") != std::string::npos) << text;
      continue;
    }
    EXPECT_EQ(value.has_value(), twin) << "'" << text << "'";
    if (value) {
      EXPECT_TRUE(std::isfinite(*value));
      ++accepted;
    }
  }
  EXPECT_GT(accepted, 1000);  // the sample reached the accepting side often
}

TEST(StrictNumber, ErrorsNameTheFieldAndTheRange) {
  EXPECT_EQ(ParseStrictNumber("--years", "", 0, 100, true).status().Line(),
            "--years: empty; must be a whole number in [0, 100]");
  EXPECT_EQ(ParseStrictNumber("--years", "0x10", 0, 100, true).status().Line(),
            "--years: '0x10' is not a decimal number; must be a whole number in [0, 100]");
  // Not a number with or without its zeros: said so, not "leading zero" (tests/cli/strict_input).
  EXPECT_EQ(ParseStrictNumber("steps", "010x", 0, 10000, true).status().Line(),
            "steps: '010x' is not a decimal number; must be a whole number in [0, 10000]");
  // Issue 34: "010" was read as ten; it is refused as octal-looking, naming field and range.
  EXPECT_EQ(ParseStrictNumber("res", "010", 8, 4096, true).status().Line(),
            "res: '010' has a leading zero (octal in some tools); must be a whole number in [8, "
            "4096]");
  EXPECT_EQ(ParseStrictNumber("d", "-01", -5, 5, false).status().Line(),
            "d: '-01' has a leading zero (octal in some tools); must be a number in [-5, 5]");
  EXPECT_EQ(ParseStrictNumber("--years", "101", 0, 100, true).status().Line(),
            "--years: 101 is out of range; must be a whole number in [0, 100]");
  EXPECT_EQ(
      ParseStrictNumber("--seed", "-18446744073709551615", 0, 4294967295.0, true).status().Line(),
      "--seed: -1.8446744073709552e+19 is out of range; must be a whole number in [0, "
      "4294967295]");
  Result<double> ok = ParseStrictNumber("--wind", "7.5", 0, 100, false);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(*ok, 7.5);
  // A hostile value is echoed escaped and short.
  std::string line =
      ParseStrictNumber("x", "\x1b[31m" + std::string(500, 'z'), 0, 1, false).status().Line();
  EXPECT_EQ(line.find('\x1b'), std::string::npos);
  EXPECT_NE(line.find("\\x1b[31m"), std::string::npos);
  EXPECT_LT(line.size(), 140u) << line;
}

}  // namespace
}  // namespace niwa

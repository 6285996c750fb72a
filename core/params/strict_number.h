// The one strict number parser of every CLI flag, share-link hash value and params JSON string:
// decimal text only, checked against an allowed range, as a Result.
// Does not: accept hex ("0x10", "0x1p3"), leading zeros ("010"), inf/nan, empty text, spaces or
// junk around the number, or wrap out-of-range integers; it knows no table or flag (callers name
// the field).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "base/status.h"

namespace niwa {

// Longest number text read (longer text is refused, not cut).
constexpr std::size_t kMaxNumberText = 64;

// The grammar: [+-]? (W ('.' D*)? | '.' D+) ([eE] [+-]? D+)?  with D a decimal digit and W a
// whole part without a leading zero ("0", "0.5", "10", but not "010", "-01" or "00.5": other tools
// read "010" as octal eight; the exponent's digits may start with 0, as printf's "1e-05"). Nullopt
// when the text does not match or the value is not finite.
std::optional<double> ParseDecimal(std::string_view text);

// The whole part has more than one digit and starts with 0 ("010", "-01", "00.5").
bool HasLeadingZero(std::string_view text);
// Why text is no number, for the one-line errors: "'010' has a leading zero (octal in some
// tools)" or "'0x10' is not a decimal number".
std::string NotDecimalWhy(std::string_view text);

// The number in text, required to lie in [min, max] (and be whole when integer). Errors, all naming
// field and the range: "empty; must be a whole number in [0, 100]", "'0x10' is not a decimal
// number; must be ...", "101 is out of range; must be ...".
Result<double> ParseStrictNumber(std::string_view field, std::string_view text, double min,
                                 double max, bool integer);

}  // namespace niwa

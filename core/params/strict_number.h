// The one strict number parser of every CLI flag, share-link hash value and params JSON string:
// decimal text only, checked against an allowed range, as a Result.
// Does not: accept hex ("0x10", "0x1p3"), inf/nan, empty text, spaces or junk around the number,
// or wrap out-of-range integers; it knows no table or flag (callers name the field).
#pragma once

#include <optional>
#include <string_view>

#include "base/status.h"

namespace niwa {

// Longest number text read (longer text is refused, not cut).
constexpr std::size_t kMaxNumberText = 64;

// The grammar: [+-]? (D+ ('.' D*)? | '.' D+) ([eE] [+-]? D+)?  with D a decimal digit. Leading
// zeros are decimal ("010" is ten). Nullopt when the text does not match or the value is not
// finite.
std::optional<double> ParseDecimal(std::string_view text);

// The number in text, required to lie in [min, max] (and be whole when integer). Errors, all naming
// field and the range: "empty; must be a whole number in [0, 100]", "'0x10' is not a decimal
// number; must be ...", "101 is out of range; must be ...".
Result<double> ParseStrictNumber(std::string_view field, std::string_view text, double min,
                                 double max, bool integer);

}  // namespace niwa

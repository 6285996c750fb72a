// Number text and range checks shared by every parameter table and every CLI flag.
// Does not: know any table's rows; it only formats, parses and checks single values.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "base/status.h"

namespace niwa {

// "a number in [0, 1]" or "a whole number in [1, 100]": the allowed range in words.
std::string RangeText(double min_value, double max_value, bool integer);
// Ok when value lies in [min, max] (and is whole when integer), else the Status
// {field, "1.5 is out of range; must be a number in [0, 1]"}. The one range check of every table
// and flag.
Status CheckValue(std::string_view field, double value, double min_value, double max_value,
                  bool integer);
// Shortest text that parses back to exactly the same double.
std::string FormatNumber(double value);
// Strict number parser: the whole text must be a finite decimal number (params/strict_number.h
// ParseDecimal, the one grammar).
std::optional<double> ParseNumber(std::string_view text);

}  // namespace niwa

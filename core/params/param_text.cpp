// Number text and range checks of the parameter tables and CLI flags.
#include "params/param_text.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "params/strict_number.h"

namespace niwa {

std::string FormatNumber(double value) {
  char buffer[32];
  if (std::floor(value) == value && std::fabs(value) < 1e15) {
    std::snprintf(buffer, sizeof buffer, "%.0f", value);  // whole numbers without exponent
    return buffer;
  }
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
    if (std::strtod(buffer, nullptr) == value) break;
  }
  return buffer;
}

std::string RangeText(double min_value, double max_value, bool integer) {
  return std::string(integer ? "a whole number" : "a number") + " in [" + FormatNumber(min_value) +
         ", " + FormatNumber(max_value) + "]";
}

Status CheckValue(std::string_view field, double value, double min_value, double max_value,
                  bool integer) {
  bool whole = std::floor(value) == value;
  if (std::isfinite(value) && value >= min_value && value <= max_value && (!integer || whole)) {
    return Status::Ok();
  }
  return Status::Error(std::string(field),
                       (std::isfinite(value) ? FormatNumber(value) : std::string("value")) +
                           " is out of range; must be " + RangeText(min_value, max_value, integer));
}

std::optional<double> ParseNumber(std::string_view text) { return ParseDecimal(text); }

}  // namespace niwa

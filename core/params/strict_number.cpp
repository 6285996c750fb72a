// The strict decimal number parser shared by the CLI, the hash codec and the params JSON reader.
#include "params/strict_number.h"

#include <cmath>
#include <cstdlib>
#include <string>

#include "base/echo.h"
#include "params/param_text.h"

namespace niwa {
namespace {

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// Number of decimal digits at text[i...].
std::size_t Digits(std::string_view text, std::size_t i) {
  std::size_t n = 0;
  while (i + n < text.size() && IsDigit(text[i + n])) ++n;
  return n;
}

bool MatchesGrammar(std::string_view text) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t whole = Digits(text, i);
  if (whole > 1 && text[i] == '0') return false;  // "010", "-01", "00.5": octal-looking
  i += whole;
  std::size_t fraction = 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    fraction = Digits(text, i);
    i += fraction;
  }
  if (whole == 0 && fraction == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    const std::size_t exponent = Digits(text, i);
    if (exponent == 0) return false;
    i += exponent;
  }
  return i == text.size();
}

}  // namespace

// A number the grammar would take but for its leading zeros ("010", "-01", "00.5"); "010x" is not
// a number at all and says so.
bool HasLeadingZero(std::string_view text) {
  std::size_t i = 0;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
  const std::size_t whole = Digits(text, i);
  if (whole <= 1 || text[i] != '0') return false;
  std::size_t first = i;  // the first digit kept: the leading zeros dropped, one digit left at least
  while (first + 1 < i + whole && text[first] == '0') ++first;
  std::string rest(text.substr(0, i));
  rest += text.substr(first);
  return MatchesGrammar(rest);
}

std::string NotDecimalWhy(std::string_view text) {
  return "'" + Echo(text) + "' " +
         (HasLeadingZero(text) ? "has a leading zero (octal in some tools)"
                               : "is not a decimal number");
}

std::optional<double> ParseDecimal(std::string_view text) {
  if (text.empty() || text.size() > kMaxNumberText || !MatchesGrammar(text)) return std::nullopt;
  const std::string copy(text);  // strtod needs a terminated string; the grammar left no junk
  char* end = nullptr;
  const double value = std::strtod(copy.c_str(), &end);
  if (end != copy.c_str() + copy.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

Result<double> ParseStrictNumber(std::string_view field, std::string_view text, double min,
                                 double max, bool integer) {
  const std::string range = RangeText(min, max, integer);
  if (text.empty()) return Status::Error(std::string(field), "empty; must be " + range);
  std::optional<double> value = ParseDecimal(text);
  if (!value) {
    return Status::Error(std::string(field), NotDecimalWhy(text) + "; must be " + range);
  }
  NIWA_RETURN_IF_ERROR(CheckValue(field, *value, min, max, integer));
  return *value;
}

}  // namespace niwa

// Budget checks and their one-line messages (core/base/budget.h).
#include "base/budget.h"

#include <cmath>
#include <cstdio>

namespace niwa {

std::string FormatCount(double n) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.0f", n);
  std::string digits = buffer, out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

std::string FormatBytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 4) {
    bytes /= 1024.0;
    ++unit;
  }
  char buffer[32];
  if (unit == 0 || bytes >= 100.0 || bytes == std::floor(bytes)) {
    std::snprintf(buffer, sizeof buffer, "%.0f %s", std::ceil(bytes), units[unit]);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.1f %s", std::ceil(bytes * 10.0) / 10.0, units[unit]);
  }
  return buffer;
}

std::string FormatSeconds(double seconds) {
  char buffer[32];
  if (seconds >= 100.0 || seconds == std::floor(seconds)) {
    std::snprintf(buffer, sizeof buffer, "%.0f s", std::ceil(seconds));
  } else {
    std::snprintf(buffer, sizeof buffer, "%.1f s", std::ceil(seconds * 10.0) / 10.0);
  }
  return buffer;
}

bool ParseBytes(const std::string& text, uint64_t* bytes) {
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  if (digits == 0 || digits > 15) return false;
  uint64_t value = 0;
  for (std::size_t i = 0; i < digits; ++i) value = value * 10 + uint64_t(text[i] - '0');
  std::string unit = text.substr(digits);
  if (unit.size() == 2 && (unit[1] == 'B' || unit[1] == 'b')) unit.pop_back();
  int shift = 0;
  if (unit == "k" || unit == "K") {
    shift = 10;
  } else if (unit == "m" || unit == "M") {
    shift = 20;
  } else if (unit == "g" || unit == "G") {
    shift = 30;
  } else if (unit == "t" || unit == "T") {
    shift = 40;
  } else if (!unit.empty() && unit != "B" && unit != "b") {
    return false;
  }
  if (value > (uint64_t{1} << (62 - shift))) return false;
  *bytes = value << shift;
  return true;
}

Status CheckEstimate(const Estimate& e, const Budget& budget, const std::string& change) {
  if (e.memory_bytes > static_cast<double>(budget.memory_bytes)) {
    return Status::Error(budget.memory_limit,
                         e.what + " needs about " + FormatBytes(e.memory_bytes) +
                             ", more than the " + FormatBytes(double(budget.memory_bytes)) +
                             " allowed; " + change + RaiseHint(budget.memory_limit));
  }
  if (e.seconds > budget.seconds) {
    return Status::Error(budget.seconds_limit, e.what + " takes about " + FormatSeconds(e.seconds) +
                                                   ", more than the " +
                                                   FormatSeconds(budget.seconds) + " allowed; " +
                                                   change + RaiseHint(budget.seconds_limit));
  }
  return Status::Ok();
}

std::string RaiseHint(const std::string& limit) {
  return limit.rfind("--", 0) == 0 ? " (or raise " + limit + ")" : "";
}

std::string TruncatedLine(const std::string& limit, const std::string& where,
                          const std::string& why, const std::string& change) {
  return limit + ": stopped " + where + ": " + why + "; " + change;
}

}  // namespace niwa

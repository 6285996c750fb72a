// The moss study's weather files: JSON or CSV days, checked against the table (weather.h).
#include "moss/weather.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

#include "base/echo.h"
#include "params/json_guard.h"
#include "params/param_text.h"
#include "params/strict_number.h"

namespace niwa::moss {
namespace {

constexpr const char* kWeatherNames[kWeatherFields] = {"T", "rh", "U", "N", "N0", "P"};
constexpr const char* kWeatherAllowed = "must be T, rh, U, N, N0 or P";
constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();

double* FieldOf(WeatherDay* d, int k) {
  double* fields[kWeatherFields] = {&d->T, &d->rh, &d->U, &d->N, &d->N0, &d->P};
  return fields[k];
}

int WeatherFieldIndex(const std::string& name) {
  for (int k = 0; k < kWeatherFields; ++k)
    if (name == kWeatherNames[k]) return k;
  return -1;
}

// The range of field k: its table row's, P a day's rain.
void WeatherRange(int k, double* lo, double* hi) {
  if (k == 5) {
    *lo = 0, *hi = kMaxDailyRain;
    return;
  }
  const MossParam rows[5] = {MossParam::kT, MossParam::kRh, MossParam::kU, MossParam::kN,
                             MossParam::kN0};
  const ParamSpec& spec = MossTable().row(static_cast<std::size_t>(rows[k]));
  *lo = spec.min_value, *hi = spec.max_value;
}

Status DayError(std::size_t day, const Status& status) {
  return Status::Error("weather", "day " + std::to_string(day) + ": " + status.Line());
}

// The cross-field check: N at most N0 (either from the table when the file leaves it out).
Status CheckDay(std::size_t day, const WeatherDay& d, const MossParams& params) {
  const double N = std::isnan(d.N) ? params.Get(MossParam::kN) : d.N;
  const double N0 = std::isnan(d.N0) ? params.Get(MossParam::kN0) : d.N0;
  if (N > N0)
    return DayError(day, Status::Error("N", FormatNumber(N) + " is above N0 " + FormatNumber(N0) +
                                                "; must be at most N0"));
  return Status::Ok();
}

WeatherDay EmptyDay() { return {kNoValue, kNoValue, kNoValue, kNoValue, kNoValue, kNoValue}; }

Result<std::vector<WeatherDay>> ParseWeatherCsv(const std::string& text, const MossParams& params) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
    start = end + 1;
  }
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (lines.empty())
    return Status::Error("weather", "is empty; must start with a header row such as T,rh,U,N,N0,P");
  auto split = [](const std::string& line) {
    std::vector<std::string> out;
    std::size_t from = 0;
    for (;;) {
      const std::size_t comma = line.find(',', from);
      out.push_back(
          line.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
      if (comma == std::string::npos) return out;
      from = comma + 1;
    }
  };
  const std::vector<std::string> header = split(lines[0]);
  std::vector<int> column;
  for (const std::string& name : header) {
    const int k = WeatherFieldIndex(name);
    if (k < 0)
      return Status::Error("weather", "column '" + Echo(name) + "' is unknown; " + kWeatherAllowed);
    for (int seen : column)
      if (seen == k) return Status::Error("weather", "column '" + name + "' is given twice");
    column.push_back(k);
  }
  const std::size_t days = lines.size() - 1;
  if (days < 1 || days > static_cast<std::size_t>(kMaxWeatherDays))
    return Status::Error("weather", "has " + std::to_string(days) + " days; must have 1 to " +
                                        std::to_string(kMaxWeatherDays));
  std::vector<WeatherDay> out;
  out.reserve(days);
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const std::vector<std::string> cells = split(lines[i]);
    if (cells.size() != column.size())
      return DayError(
          i, Status::Error("", "has " + std::to_string(cells.size()) + " fields; must have " +
                                   std::to_string(column.size()) + " (the header's)"));
    WeatherDay d = EmptyDay();
    for (std::size_t c = 0; c < column.size(); ++c) {
      double lo, hi;
      WeatherRange(column[c], &lo, &hi);
      Result<double> v = ParseStrictNumber(kWeatherNames[column[c]], cells[c], lo, hi, false);
      if (!v.ok()) return DayError(i, v.status());
      *FieldOf(&d, column[c]) = *v;
    }
    NIWA_RETURN_IF_ERROR(CheckDay(i, d, params));
    out.push_back(d);
  }
  return out;
}

Result<std::vector<WeatherDay>> ParseWeatherJson(const std::string& text,
                                                 const MossParams& params) {
  NIWA_RETURN_IF_ERROR(CheckJsonKeys(text, "weather").Within("weather"));
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  const char* shape = "must be {\"days\": [{\"T\": 288.15, \"rh\": 0.73, ...}, ...]}";
  if (j.is_discarded() || !j.is_object())
    return Status::Error("weather", std::string("is not a JSON object; ") + shape);
  for (auto it = j.begin(); it != j.end(); ++it)
    if (it.key() != "days")
      return Status::Error("weather", "key '" + Echo(it.key()) + "' is unknown; " + shape);
  if (!j.contains("days") || !j["days"].is_array())
    return Status::Error("weather", std::string("has no days array; ") + shape);
  const nlohmann::json& days = j["days"];
  if (days.empty() || days.size() > static_cast<std::size_t>(kMaxWeatherDays))
    return Status::Error("weather", "has " + std::to_string(days.size()) +
                                        " days; must have 1 to " + std::to_string(kMaxWeatherDays));
  std::vector<WeatherDay> out;
  out.reserve(days.size());
  for (std::size_t i = 0; i < days.size(); ++i) {
    const nlohmann::json& day = days[i];
    if (!day.is_object())
      return DayError(i + 1, Status::Error("", "is not an object; must be {\"T\": ..., ...}"));
    WeatherDay d = EmptyDay();
    for (auto it = day.begin(); it != day.end(); ++it) {
      const int k = WeatherFieldIndex(it.key());
      if (k < 0)
        return DayError(
            i + 1, Status::Error("", "'" + Echo(it.key()) + "' is unknown; " + kWeatherAllowed));
      double lo, hi;
      WeatherRange(k, &lo, &hi);
      if (!it.value().is_number())
        return DayError(i + 1,
                        Status::Error(kWeatherNames[k], "must be a number in [" + FormatNumber(lo) +
                                                            ", " + FormatNumber(hi) + "]"));
      const double v = it.value().get<double>();
      const Status in_range = CheckValue(kWeatherNames[k], v, lo, hi, false);
      if (!in_range.ok()) return DayError(i + 1, in_range);
      *FieldOf(&d, k) = v;
    }
    NIWA_RETURN_IF_ERROR(CheckDay(i + 1, d, params));
    out.push_back(d);
  }
  return out;
}

}  // namespace

Result<std::vector<WeatherDay>> ParseWeather(const std::string& text, bool csv,
                                             const MossParams& params) {
  return csv ? ParseWeatherCsv(text, params) : ParseWeatherJson(text, params);
}

Weather WeatherOfDay(const Weather& climate, const WeatherDay& day) {
  Weather w = climate;
  if (!std::isnan(day.T)) w.T = day.T;
  if (!std::isnan(day.rh)) w.rh = day.rh;
  if (!std::isnan(day.U)) w.U = day.U;
  if (!std::isnan(day.N)) w.N = day.N;
  if (!std::isnan(day.N0)) w.N_0 = day.N0;
  if (!std::isnan(day.P)) w.P = day.P;
  return w;
}

}  // namespace niwa::moss

// The moss study's daily weather from a file (spec §1.6's extension of tables 3.1 and 4.3): one row
// a day of the inputs the soil model reads each day (T, rh, U, N, N0, P), as JSON
// {"days": [{"T": 288.15, "P": 10.34}, ...]} or CSV with a header row ("T,rh,P" ...); each value
// checked against its table row's range (P, a day's rain, in [0, 2000] mm) and N against N0.
// Does not: read files (the front end gives the text), know a day number beyond the row's index
// (the run cycles the rows), or move the sun (sun_altitude and sun_azimuth stay the table's).
#pragma once

#include <string>
#include <vector>

#include "base/status.h"
#include "moss/moss_params.h"
#include "moss/soil.h"

namespace niwa::moss {

// One day of a file: a field the file leaves out is NaN (the run takes the table's value, and for
// P the table's rain: P_year over P_days, even or random).
struct WeatherDay {
  double T, rh, U, N, N0, P;
};
constexpr int kWeatherFields = 6;
constexpr int kMaxWeatherDays = 3650;   // a day a row, as days' range
constexpr double kMaxDailyRain = 2000;  // mm in one day (the world's record is ~1,825)

// The days of a weather file (`csv`: CSV, else JSON), each checked against `params`' rows (a field
// the file leaves out counts as the table's value in the N <= N0 check). Errors name "weather" and
// say where: "day 3: T 400 is out of range; must be a number in [233.15, 323.15]",
// "column 'Tmax' is unknown; must be T, rh, U, N, N0 or P", "has no days; must have 1 to 3650".
Result<std::vector<WeatherDay>> ParseWeather(const std::string& text, bool csv,
                                             const MossParams& params);

// The weather of a day: `climate` (the table's, with its rain) with the file's day over it.
Weather WeatherOfDay(const Weather& climate, const WeatherDay& day);

}  // namespace niwa::moss

// The sun and the sky for every study: the sun's direction from its altitude and azimuth or from a
// date, a time and a place, and the irradiance that falls on a surface (direct and a simple sky).
//
// Frame: y up, +x east, +z south (so -z is north; right-handed). Azimuth is measured in the
// horizontal plane from +x (east) towards +z (south), in degrees: 0 east, 90 south, ±180 west,
// -90 north. A compass bearing (from north, clockwise) is this azimuth + 90°. The tree's sun rows
// (sun_elevation, sun_azimuth) and the pages' lights use this convention.
//
// Deterministic: only det_math (no std::sin, std::cos, std::pow), so native and WASM agree bit for
// bit. Not here: shadows and occlusion (each study's own light model, e.g. tree/light), spectral or
// atmospheric models beyond the clear-sky formula below, refraction near the horizon, time zones
// and calendars beyond the Gregorian day of year.
#pragma once

#include <glm/vec3.hpp>

namespace niwa {
namespace light {

// Unit direction towards the sun at altitude (elevation above the horizon) and azimuth, in degrees
// (the convention above). Float arithmetic in a fixed order: the tree's sky uses these bits.
glm::vec3 SunDirection(float altitude_deg, float azimuth_deg);

struct SunPosition {
  double altitude_deg;  // above the horizon; negative below it (night)
  double azimuth_deg;   // the convention above, in (-180, 180]
};

// The sun's position for a declination, an hour angle (0 at local solar noon, negative in the
// morning, 15° per hour) and a latitude (north positive), all in degrees: the standard spherical
// astronomy relations (e.g. Meeus, "Astronomical Algorithms", 2nd ed. 1998, eq. 13.5-13.6) in the
// local east-north-up frame.
SunPosition SunFromHourAngle(double declination_deg, double hour_angle_deg, double latitude_deg);

// A moment and a place: Gregorian date, hours in UTC (may carry minutes as a fraction), latitude
// (north positive) and longitude (east positive) in degrees.
struct SolarTime {
  int year = 2026, month = 3, day = 20;
  double hours_utc = 12.0;
  double latitude_deg = 35.0, longitude_deg = 0.0;
};

// The sun's position at a moment and place by the algorithm of NOAA's Solar Calculator (NOAA
// Global Monitoring Laboratory, "NOAA_Solar_Calculations_day.xls", after Meeus, "Astronomical
// Algorithms", 1991): Julian centuries since J2000.0, the sun's apparent longitude and the
// obliquity give the declination and the equation of time; true solar time from longitude gives
// the hour angle; then SunFromHourAngle. Good to about 0.01° for 1800-2100 without atmospheric
// refraction (not applied: near the horizon the seen sun is up to 0.6° higher).
SunPosition SunAt(const SolarTime& when);

// Unit direction towards the sun at a position (the same as SunDirection for its angles, in double
// until the end).
glm::vec3 SunDirection(const SunPosition& position);

// Direct irradiance on a surface with unit normal: direct normal irradiance (W/m², from the sun
// disc on a plane facing it) times the cosine of incidence, zero when the sun is behind the surface
// or below the horizon (sun_direction.y <= 0).
double DirectOnSurface(const glm::vec3& sun_direction, const glm::vec3& normal,
                       double direct_normal);

// Diffuse sky irradiance on a surface with unit normal under an isotropic sky of diffuse horizontal
// irradiance diffuse_horizontal (W/m²): the fraction of the sky dome the surface sees,
// (1 + normal.y) / 2 (Liu and Jordan, Solar Energy 7(2), 1963).
double SkyOnSurface(const glm::vec3& normal, double diffuse_horizontal);

// Clear-sky direct normal irradiance (W/m²) at a sun altitude: Meinel and Meinel ("Applied Solar
// Energy", 1976), 1353 · 0.7^(AM^0.678), with the air mass AM of Kasten and Young (Applied Optics
// 28(22), 1989), 1 / (cos z + 0.50572 (96.07995 - z)^-1.6364), z the zenith angle in degrees.
// Zero at or below the horizon.
double ClearSkyDirectNormal(double altitude_deg);

// Direct plus sky on a surface: a clear sky's direct normal irradiance at the sun's altitude and
// a diffuse sky of sky_fraction of it on the horizontal (0.1 to 0.2 for a clear day).
double ClearSkyOnSurface(const glm::vec3& sun_direction, const glm::vec3& normal,
                         double sky_fraction);

}  // namespace light
}  // namespace niwa

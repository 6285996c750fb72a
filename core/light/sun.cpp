// The sun's direction and position, and irradiance on a surface (see sun.h for the frame and the
// formulas' sources).
#include "light/sun.h"

#include <cmath>

#include "math/det_math.h"
#include "math/rotation.h"

namespace niwa {
namespace light {
namespace {

constexpr double kDegree = det::kPi / 180.0;

double Pow(double base, double exponent) { return det::Exp(exponent * det::Log(base)); }

}  // namespace

glm::vec3 SunDirection(float altitude_deg, float azimuth_deg) {
  const float elevation = Radians(altitude_deg), azimuth = Radians(azimuth_deg);
  return glm::vec3(det::Cosf(elevation) * det::Cosf(azimuth), det::Sinf(elevation),
                   det::Cosf(elevation) * det::Sinf(azimuth));
}

SunPosition SunFromHourAngle(double declination_deg, double hour_angle_deg, double latitude_deg) {
  double sin_d, cos_d, sin_h, cos_h, sin_l, cos_l;
  det::SinCos(declination_deg * kDegree, &sin_d, &cos_d);
  det::SinCos(hour_angle_deg * kDegree, &sin_h, &cos_h);
  det::SinCos(latitude_deg * kDegree, &sin_l, &cos_l);
  // The unit vector towards the sun in the local east-north-up frame.
  const double east = -cos_d * sin_h;
  const double north = sin_d * cos_l - cos_d * cos_h * sin_l;
  const double up = sin_d * sin_l + cos_d * cos_h * cos_l;
  const double horizontal = std::sqrt(east * east + north * north);
  // Scene frame: x east, z south.
  return SunPosition{det::Atan2(up, horizontal) / kDegree, det::Atan2(-north, east) / kDegree};
}

SunPosition SunAt(const SolarTime& when) {
  // Julian day of the date's 0 h UTC (Meeus eq. 7.1, Gregorian calendar), then centuries since
  // J2000.0.
  int y = when.year, m = when.month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  const double a = std::floor(y / 100.0), b = 2.0 - a + std::floor(a / 4.0);
  const double julian_day = std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) +
                            when.day + b - 1524.5 + when.hours_utc / 24.0;
  const double t = (julian_day - 2451545.0) / 36525.0;
  // The sun's geometric mean longitude and anomaly, the orbit's eccentricity, the equation of
  // centre, the apparent longitude and the corrected obliquity (degrees).
  double l0 = 280.46646 + t * (36000.76983 + t * 0.0003032);
  l0 -= 360.0 * std::floor(l0 / 360.0);
  const double mean_anomaly = 357.52911 + t * (35999.05029 - 0.0001537 * t);
  const double e = 0.016708634 - t * (0.000042037 + 0.0000001267 * t);
  const double m1 = mean_anomaly * kDegree;
  const double centre = det::Sin(m1) * (1.914602 - t * (0.004817 + 0.000014 * t)) +
                        det::Sin(2.0 * m1) * (0.019993 - 0.000101 * t) +
                        det::Sin(3.0 * m1) * 0.000289;
  const double omega = (125.04 - 1934.136 * t) * kDegree;
  const double apparent_longitude = l0 + centre - 0.00569 - 0.00478 * det::Sin(omega);
  const double mean_obliquity =
      23.0 + (26.0 + (21.448 - t * (46.815 + t * (0.00059 - t * 0.001813))) / 60.0) / 60.0;
  const double obliquity = (mean_obliquity + 0.00256 * det::Cos(omega)) * kDegree;
  // Declination: asin(sin ε sin λ).
  const double sin_declination = det::Sin(obliquity) * det::Sin(apparent_longitude * kDegree);
  const double declination =
      det::Atan2(sin_declination, std::sqrt((1.0 - sin_declination) * (1.0 + sin_declination)));
  // The equation of time (minutes).
  double sin_half, cos_half;
  det::SinCos(obliquity / 2.0, &sin_half, &cos_half);
  const double v = (sin_half / cos_half) * (sin_half / cos_half);
  const double l = l0 * kDegree;
  const double equation_of_time_min =
      4.0 / kDegree *
      (v * det::Sin(2.0 * l) - 2.0 * e * det::Sin(m1) +
       4.0 * e * v * det::Sin(m1) * det::Cos(2.0 * l) - 0.5 * v * v * det::Sin(4.0 * l) -
       1.25 * e * e * det::Sin(2.0 * m1));
  const double true_solar_min =
      when.hours_utc * 60.0 + equation_of_time_min + 4.0 * when.longitude_deg;
  const double hour_angle_deg = true_solar_min / 4.0 - 180.0;
  return SunFromHourAngle(declination / kDegree, hour_angle_deg, when.latitude_deg);
}

glm::vec3 SunDirection(const SunPosition& position) {
  double sin_a, cos_a, sin_z, cos_z;
  det::SinCos(position.altitude_deg * kDegree, &sin_a, &cos_a);
  det::SinCos(position.azimuth_deg * kDegree, &sin_z, &cos_z);
  return glm::vec3(static_cast<float>(cos_a * cos_z), static_cast<float>(sin_a),
                   static_cast<float>(cos_a * sin_z));
}

double DirectOnSurface(const glm::vec3& sun_direction, const glm::vec3& normal,
                       double direct_normal) {
  if (!(sun_direction.y > 0.0f)) return 0.0;
  const double cosine = static_cast<double>(normal.x) * sun_direction.x +
                        static_cast<double>(normal.y) * sun_direction.y +
                        static_cast<double>(normal.z) * sun_direction.z;
  return cosine > 0.0 ? direct_normal * cosine : 0.0;
}

double SkyOnSurface(const glm::vec3& normal, double diffuse_horizontal) {
  return diffuse_horizontal * 0.5 * (1.0 + static_cast<double>(normal.y));
}

double ClearSkyDirectNormal(double altitude_deg) {
  if (!(altitude_deg > 0.0)) return 0.0;
  const double zenith_deg = 90.0 - altitude_deg;
  const double air_mass =
      1.0 / (det::Cos(zenith_deg * kDegree) + 0.50572 * Pow(96.07995 - zenith_deg, -1.6364));
  return 1353.0 * Pow(0.7, Pow(air_mass, 0.678));
}

double ClearSkyOnSurface(const glm::vec3& sun_direction, const glm::vec3& normal,
                         double sky_fraction) {
  const double x = sun_direction.x, y = sun_direction.y, z = sun_direction.z;
  const double altitude_deg = det::Atan2(y, std::sqrt(x * x + z * z)) / kDegree;
  const double direct_normal = ClearSkyDirectNormal(altitude_deg);
  return DirectOnSurface(sun_direction, normal, direct_normal) +
         SkyOnSurface(normal, sky_fraction * direct_normal);
}

}  // namespace light
}  // namespace niwa

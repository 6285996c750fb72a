// Tests of core/light/sun: known solar positions, the frame's conventions, the tree's sun bits, and
// irradiance against hand computations.
#include "light/sun.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>

#include "math/det_math.h"
#include "math/rotation.h"

namespace niwa {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

uint32_t Bits(float v) {
  uint32_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

// The tree's sky sun (tree/light.cpp before core/light) gives the same bits.
TEST(Sun, DirectionFromAnglesIsTheTreesFormulaBitForBit) {
  for (float el = -10.0f; el <= 90.0f; el += 0.7f) {
    for (float az = -180.0f; az <= 180.0f; az += 1.3f) {
      const float e = Radians(el), a = Radians(az);
      const glm::vec3 expected(det::Cosf(e) * det::Cosf(a), det::Sinf(e),
                               det::Cosf(e) * det::Sinf(a));
      const glm::vec3 got = light::SunDirection(el, az);
      for (int k = 0; k < 3; ++k) ASSERT_EQ(Bits(got[k]), Bits(expected[k])) << el << " " << az;
    }
  }
}

TEST(Sun, AzimuthConventionEastSouthWestNorth) {
  const glm::vec3 east = light::SunDirection(0.0f, 0.0f), south = light::SunDirection(0.0f, 90.0f);
  const glm::vec3 west = light::SunDirection(0.0f, 180.0f),
                  north = light::SunDirection(0.0f, -90.0f);
  EXPECT_NEAR(east.x, 1.0f, 1e-6f);
  EXPECT_NEAR(south.z, 1.0f, 1e-6f);
  EXPECT_NEAR(west.x, -1.0f, 1e-6f);
  EXPECT_NEAR(north.z, -1.0f, 1e-6f);
  const glm::vec3 zenith = light::SunDirection(90.0f, 37.0f);
  EXPECT_NEAR(zenith.y, 1.0f, 1e-6f);
}

TEST(Sun, HourAngleGivesTextbookPositions) {
  // Equinox noon at 35° N: altitude 90 - 35 = 55°, due south (azimuth 90).
  light::SunPosition noon = light::SunFromHourAngle(0.0, 0.0, 35.0);
  EXPECT_NEAR(noon.altitude_deg, 55.0, 1e-12);
  EXPECT_NEAR(noon.azimuth_deg, 90.0, 1e-12);
  // Equinox sunrise (hour angle -90°): on the horizon, due east; sunset due west.
  light::SunPosition rise = light::SunFromHourAngle(0.0, -90.0, 35.0);
  EXPECT_NEAR(rise.altitude_deg, 0.0, 1e-12);
  EXPECT_NEAR(rise.azimuth_deg, 0.0, 1e-12);
  light::SunPosition set = light::SunFromHourAngle(0.0, 90.0, 35.0);
  EXPECT_NEAR(std::fabs(set.azimuth_deg), 180.0, 1e-12);
  // June solstice noon at 35° N: 90 - 35 + 23.44; south of the tropic the noon sun is north.
  EXPECT_NEAR(light::SunFromHourAngle(23.44, 0.0, 35.0).altitude_deg, 78.44, 1e-12);
  light::SunPosition sydney = light::SunFromHourAngle(0.0, 0.0, -33.9);
  EXPECT_NEAR(sydney.altitude_deg, 56.1, 1e-12);
  EXPECT_NEAR(sydney.azimuth_deg, -90.0, 1e-12);
  // A general case against the spherical-astronomy formula with the platform's libm:
  // sin h = sin φ sin δ + cos φ cos δ cos H.
  for (double d : {-23.0, -5.0, 10.0, 23.4}) {
    for (double h = -170.0; h <= 170.0; h += 17.0) {
      for (double lat : {-60.0, -10.0, 0.0, 35.0, 51.5, 70.0}) {
        const double sin_alt = std::sin(lat * kDeg) * std::sin(d * kDeg) +
                               std::cos(lat * kDeg) * std::cos(d * kDeg) * std::cos(h * kDeg);
        const light::SunPosition p = light::SunFromHourAngle(d, h, lat);
        EXPECT_NEAR(p.altitude_deg, std::asin(sin_alt) / kDeg, 1e-9) << d << " " << h << " " << lat;
        // The direction is a unit vector at that altitude; morning suns are east (x > 0).
        const glm::vec3 v = light::SunDirection(p);
        EXPECT_NEAR(v.y, sin_alt, 1e-6);
        if (h < 0.0 && std::fabs(d) < 1.0) {
          EXPECT_GT(v.x, 0.0f);
        }
      }
    }
  }
}

TEST(Sun, DateAndTimeGiveKnownPositions) {
  // 2026-03-20 (the March equinox, 14:46 UTC) at local solar noon on the Greenwich meridian
  // (12:07.5 UTC: the equation of time is -7.5 min), 35° N: 55°, due south. The declination is
  // still -0.044° (0.0164° an hour before the equinox), so 54.956°.
  light::SolarTime equinox;
  equinox.year = 2026;
  equinox.month = 3;
  equinox.day = 20;
  equinox.hours_utc = 12.0 + 7.5 / 60.0;
  equinox.latitude_deg = 35.0;
  equinox.longitude_deg = 0.0;
  light::SunPosition p = light::SunAt(equinox);
  EXPECT_NEAR(p.altitude_deg, 55.0, 0.1);
  EXPECT_NEAR(p.altitude_deg, 54.956, 0.02);
  EXPECT_NEAR(p.azimuth_deg, 90.0, 0.5);
  // The June solstice noon (21 June 2026, declination 23.436°): 78.436°; the December one
  // (21 December): 90 - 35 - 23.436 = 31.564°.
  light::SolarTime june = equinox;
  june.month = 6;
  june.day = 21;
  june.hours_utc = 12.0 + 1.7 / 60.0;  // solar noon: the equation of time is -1.7 min
  EXPECT_NEAR(light::SunAt(june).altitude_deg, 78.436, 0.03);
  light::SolarTime december = equinox;
  december.month = 12;
  december.day = 21;
  december.hours_utc = 12.0 - 1.9 / 60.0;  // solar noon: +1.9 min
  EXPECT_NEAR(light::SunAt(december).altitude_deg, 31.564, 0.03);
  // Kyoto (35.0° N, 135.77° E) at local solar noon is 12:00 - 9 h 3 min UTC, give or take the
  // equation of time (+16.4 min on 3 November): the sun near its highest, due south.
  light::SolarTime kyoto = equinox;
  kyoto.month = 11;
  kyoto.day = 3;
  kyoto.longitude_deg = 135.77;
  kyoto.hours_utc = 12.0 - 135.77 / 15.0 - 16.4 / 60.0;
  p = light::SunAt(kyoto);
  EXPECT_NEAR(p.azimuth_deg, 90.0, 0.5);
  EXPECT_NEAR(p.altitude_deg, 90.0 - 35.0 - 15.1, 0.3);  // declination -15.1° on 3 November
  // Midnight is below the horizon; 09:00 local solar time is in the east half of the sky.
  light::SolarTime night = equinox;
  night.hours_utc = 0.0;
  EXPECT_LT(light::SunAt(night).altitude_deg, -40.0);
  light::SolarTime morning = equinox;
  morning.hours_utc = 9.0;
  EXPECT_GT(light::SunDirection(light::SunAt(morning)).x, 0.3f);
  // Leap years: 29 February exists and continues into 1 March.
  light::SolarTime leap = equinox;
  leap.year = 2028;
  leap.month = 2;
  leap.day = 29;
  light::SolarTime after = leap;
  after.month = 3;
  after.day = 1;
  EXPECT_LT(light::SunAt(leap).altitude_deg, light::SunAt(after).altitude_deg);
}

TEST(Sun, IrradianceMatchesHandComputation) {
  const glm::vec3 sun = light::SunDirection(60.0f, 90.0f);  // 60° up, due south
  const glm::vec3 up(0, 1, 0), south_wall(0, 0, 1), north_wall(0, 0, -1), down(0, -1, 0);
  EXPECT_NEAR(light::DirectOnSurface(sun, up, 800.0), 800.0 * std::sin(60.0 * kDeg), 1e-3);
  EXPECT_NEAR(light::DirectOnSurface(sun, south_wall, 800.0), 800.0 * 0.5, 1e-3);
  EXPECT_EQ(light::DirectOnSurface(sun, north_wall, 800.0), 0.0);
  EXPECT_EQ(light::DirectOnSurface(light::SunDirection(-5.0f, 90.0f), up, 800.0), 0.0);
  EXPECT_DOUBLE_EQ(light::SkyOnSurface(up, 100.0), 100.0);
  EXPECT_DOUBLE_EQ(light::SkyOnSurface(south_wall, 100.0), 50.0);
  EXPECT_DOUBLE_EQ(light::SkyOnSurface(down, 100.0), 0.0);
  // Meinel's clear sky with Kasten and Young's air mass, by hand with libm.
  for (double altitude : {90.0, 60.0, 30.0, 10.0, 2.0}) {
    const double z = 90.0 - altitude;
    const double am = 1.0 / (std::cos(z * kDeg) + 0.50572 * std::pow(96.07995 - z, -1.6364));
    const double dni = 1353.0 * std::pow(0.7, std::pow(am, 0.678));
    EXPECT_NEAR(light::ClearSkyDirectNormal(altitude), dni, 1e-9 * dni) << altitude;
  }
  EXPECT_NEAR(light::ClearSkyDirectNormal(90.0), 947.0, 1.0);  // the textbook ~950 W/m² at zenith
  EXPECT_EQ(light::ClearSkyDirectNormal(0.0), 0.0);
  EXPECT_EQ(light::ClearSkyDirectNormal(-20.0), 0.0);
  const double dni60 = light::ClearSkyDirectNormal(60.0);
  EXPECT_NEAR(light::ClearSkyOnSurface(sun, up, 0.15), dni60 * std::sin(60.0 * kDeg) + 0.15 * dni60,
              1e-3);
}

}  // namespace
}  // namespace niwa

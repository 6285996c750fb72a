// The shared sun (core/light/sun.h) for the pages: the direction towards the sun from its angles,
// and the sun's position at a date, time and place, so a page's light comes from core's formula.
// Does not: know GL or any study, or choose a page's default sun (web/gl/sun.js does).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include "light/sun.h"

namespace niwa {
namespace {

emscripten::val Vector(const glm::vec3& v) {
  emscripten::val out = emscripten::val::array();
  out.call<void>("push", v.x, v.y, v.z);
  return out;
}

// sunDirection(altitudeDeg, azimuthDeg) -> [x, y, z], unit, towards the sun (y up, azimuth from
// +x (east) towards +z (south)): the bits the tree's light model uses.
emscripten::val SunDirection(double altitude_deg, double azimuth_deg) {
  return Vector(
      light::SunDirection(static_cast<float>(altitude_deg), static_cast<float>(azimuth_deg)));
}

// sunAt(year, month, day, hoursUtc, latitudeDeg, longitudeDeg) -> {altitude, azimuth, direction}.
emscripten::val SunAt(int year, int month, int day, double hours_utc, double latitude_deg,
                      double longitude_deg) {
  light::SolarTime when;
  when.year = year;
  when.month = month;
  when.day = day;
  when.hours_utc = hours_utc;
  when.latitude_deg = latitude_deg;
  when.longitude_deg = longitude_deg;
  const light::SunPosition p = light::SunAt(when);
  emscripten::val out = emscripten::val::object();
  out.set("altitude", p.altitude_deg);
  out.set("azimuth", p.azimuth_deg);
  out.set("direction", Vector(light::SunDirection(p)));
  return out;
}

}  // namespace
}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_light) {
  emscripten::function("sunDirection", &niwa::SunDirection);
  emscripten::function("sunAt", &niwa::SunAt);
}

// Built-in seed contours (see seeds.h).
#include "terrain/seeds.h"

#include <algorithm>
#include <cmath>

#include "math/det_math.h"

namespace niwa::terrain {
namespace {

Ring Radial(int n, double radius, int lobes, double depth) {
  Ring r;
  for (int i = 0; i < n; ++i) {
    double s, c, s7, c7;
    det::SinCos(2 * det::kPi * i / n, &s, &c);
    det::SinCos(lobes * 2 * det::kPi * i / n, &s7, &c7);
    const double rr = radius * (1 + depth * c7);
    r.push_back({rr * c, rr * s});
  }
  return r;
}

// The valley table of "valleys": centre angle (fraction of a turn), depth (m), half-width (rad).
// Hand-set, irregular on purpose (deep and shallow, narrow and wide, unevenly spaced), so the
// mountain has many valleys of different lengths instead of lobes7's seven equal ones.
struct Valley {
  double turn, depth, half_width;
};
constexpr Valley kValleys[] = {
    {0.010, 190, 0.090}, {0.068, 95, 0.060},  {0.118, 150, 0.075}, {0.170, 80, 0.055},
    {0.222, 200, 0.095}, {0.281, 110, 0.065}, {0.330, 160, 0.080}, {0.385, 85, 0.050},
    {0.436, 180, 0.085}, {0.492, 100, 0.060}, {0.545, 140, 0.070}, {0.600, 90, 0.055},
    {0.652, 195, 0.090}, {0.708, 120, 0.065}, {0.760, 165, 0.080}, {0.812, 85, 0.050},
    {0.866, 175, 0.085}, {0.925, 105, 0.060},
};
constexpr double kValleysRadius = 400;
constexpr int kValleysSamples = 480;

// A massif of radius 400 m with a gentle two- and three-fold swell, cut by the V-shaped valleys of
// kValleys: r(φ) = R·(1 + 0.08 cos(2φ + 0.5) + 0.05 cos(3φ + 1.3)) − depth·(1 − |φ − φ_v|/w) within
// w of a valley's centre φ_v. Sampled at 480 even angles plus each valley's floor, so every V is
// sharp. Star-shaped about the origin (r > 0 everywhere), hence simple.
Ring Valleys() {
  std::vector<double> turns;
  for (int i = 0; i < kValleysSamples; ++i)
    turns.push_back(static_cast<double>(i) / kValleysSamples);
  for (const Valley& v : kValleys) turns.push_back(v.turn);
  std::sort(turns.begin(), turns.end());
  turns.erase(std::unique(turns.begin(), turns.end()), turns.end());
  Ring r;
  for (double turn : turns) {
    const double phi = 2 * det::kPi * turn;
    double s, c, s2, c2, s3, c3;
    det::SinCos(phi, &s, &c);
    det::SinCos(2 * phi + 0.5, &s2, &c2);
    det::SinCos(3 * phi + 1.3, &s3, &c3);
    double rr = kValleysRadius * (1 + 0.08 * c2 + 0.05 * c3);
    for (const Valley& v : kValleys) {
      double off = std::fabs(phi - 2 * det::kPi * v.turn);
      off = std::min(off, 2 * det::kPi - off);
      if (off < v.half_width) rr -= v.depth * (1 - off / v.half_width);
    }
    r.push_back({rr * c, rr * s});
  }
  return r;
}

}  // namespace

const std::vector<SeedInfo>& BuiltinSeeds() {
  static const std::vector<SeedInfo> seeds = {
      {"disk", "synthetic: a 256-gon of radius 200 m (the simple method grows a cone)", 20, 10, 0},
      {"dumbbell",
       "synthetic: two 200 m squares joined by a 60 m neck 30 m wide (= 1.5 d): splits into two "
       "peaks at the first shrink",
       20, 10, 0},
      {"lobes7", "synthetic: r = 300 m·(1 + 0.25 cos 7φ), 350 points: seven lobes, seven valleys",
       20, 10, 0},
      {"jacksboro",
       "real: the 800 m contour of the USGS Jacksboro fault DEM (Tennessee; public domain USGS "
       "data shipped as matplotlib's sample data, Debian python-matplotlib-data), extracted by "
       "scripts/terrain_dem_seed.py 800 (tests/data/terrain/jacksboro_800.json, DEM beside it); d "
       "= 70 m so that Δh/d = tan 16° "
       "is the DEM's mean slope inside it (15.5°)",
       70, 20, 800},
      {"valleys",
       "synthetic: a 400 m massif, r = 400 m·(1 + 0.08 cos(2φ + 0.5) + 0.05 cos(3φ + 1.3)), cut by "
       "18 V-shaped valleys 80-200 m deep and unevenly spaced (a table in seeds.cpp), 498 points: "
       "many valleys of different lengths running up the mountain",
       20, 10, 0},
  };
  return seeds;
}

Result<Ring> BuiltinSeed(const std::string& name) {
  if (name == "disk") return Radial(256, 200, 0, 0);
  if (name == "lobes7") return Radial(350, 300, 7, 0.25);
  if (name == "jacksboro") {
    static const double points[][2] = {
#include "terrain/seed_jacksboro.inc"
    };
    Ring r;
    for (const auto& p : points) r.push_back({p[0], p[1]});
    return r;
  }
  if (name == "valleys") return Valleys();
  if (name == "dumbbell") {
    return Ring{{0, 0},     {200, 0},   {200, 85},  {260, 85},  {260, 0},   {460, 0},
                {460, 200}, {260, 200}, {260, 115}, {200, 115}, {200, 200}, {0, 200}};
  }
  return Status::Error(
      "builtin", "'" + name + "' is unknown; must be disk, dumbbell, lobes7, jacksboro or valleys");
}

}  // namespace niwa::terrain

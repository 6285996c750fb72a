// Built-in seed contours (see seeds.h).
#include "terrain/seeds.h"

#include "math/det_math.h"

namespace niwa::terrain {
namespace {

constexpr double kPi = 3.14159265358979323846;

Ring Radial(int n, double radius, int lobes, double depth) {
  Ring r;
  for (int i = 0; i < n; ++i) {
    double s, c, s7, c7;
    det::SinCos(2 * kPi * i / n, &s, &c);
    det::SinCos(lobes * 2 * kPi * i / n, &s7, &c7);
    const double rr = radius * (1 + depth * c7);
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
  if (name == "dumbbell") {
    return Ring{{0, 0},     {200, 0},   {200, 85},  {260, 85},  {260, 0},   {460, 0},
                {460, 200}, {260, 200}, {260, 115}, {200, 115}, {200, 200}, {0, 200}};
  }
  return Status::Error("--builtin",
                       "'" + name + "' is unknown; must be disk, dumbbell, lobes7 or jacksboro");
}

}  // namespace niwa::terrain

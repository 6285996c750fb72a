// Terrain workloads (core/terrain, paper 002): growing a whole mountain from a seed of 125 .. 1000
// points with the improved method (warm, and the 500-point seed cold: timed once), and the
// heightfield per cell at 256² .. 1024² through segment grids, beside its brute-force twin; and the
// page's regrow path (grow, 512² heightfield, stats, flat buffers) in both builds.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "math/det_math.h"
#include "terrain/generate.h"
#include "terrain/heightfield.h"
#include "terrain/terrain_report.h"
#include "terrain/terrain_state.h"
#include "terrain/terrain_surface.h"
#include "workloads.h"

namespace niwa {
namespace {

constexpr double kPi = 3.14159265358979323846;

// lobes7's shape, r = 300 m·(1 + 0.25 cos 7φ), with n points.
terrain::Ring Lobes(int n) {
  terrain::Ring r;
  for (int i = 0; i < n; ++i) {
    double s, c, s7, c7;
    det::SinCos(2 * kPi * i / n, &s, &c);
    det::SinCos(7 * 2 * kPi * i / n, &s7, &c7);
    const double rr = 300 * (1 + 0.25 * c7);
    r.push_back({rr * c, rr * s});
  }
  return r;
}

terrain::TerrainParams Improved() {
  terrain::TerrainState s;
  (void)terrain::SetTerrainBuiltin("lobes7", &s);
  (void)terrain::SetTerrainPreset("improved", &s);
  return s.params;
}

double Checksum(const terrain::Terrain& t) {
  double sum = static_cast<double>(t.contours.size());
  for (const terrain::ContourNode& c : t.contours) sum += 1e-3 * static_cast<double>(c.ring.size());
  return sum;
}

Workload GrowWorkload(int points, bool cold) {
  Workload wl;
  wl.name = std::string("terrain/grow-improved") + (cold ? "-cold" : "") + "/seed-" +
            std::to_string(points);
  wl.note = "Grow (improved method, fig16 constants, d = 20 m) from a " + std::to_string(points) +
            "-point lobes7 seed" + (cold ? ", timed once: the first grow, no warm-up" : "");
  wl.unit = "seed point";
  wl.once = cold;
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [points, units]() -> WorkloadBody {
    auto seed = std::make_shared<terrain::Ring>(Lobes(points));
    auto params = std::make_shared<terrain::TerrainParams>(Improved());
    *units = points;
    return [seed, params]() {
      Result<terrain::Terrain> t = terrain::Grow(*seed, *params, terrain::kDefaultTerrainSeed);
      return t.ok() ? Checksum(*t) : -1.0;
    };
  };
  return wl;
}

Workload HeightfieldWorkload(int res, bool brute) {
  Workload wl;
  wl.name = std::string("terrain/heightfield") + (brute ? "-brute" : "") + "/lobes7-" +
            std::to_string(res);
  wl.note = "BuildHeightfield" + std::string(brute ? "BruteForce" : " (segment grids)") + " at " +
            std::to_string(res) + " cells a side of the 350-point lobes7 improved mountain";
  wl.unit = "cell";
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [res, brute, units]() -> WorkloadBody {
    Result<terrain::Terrain> grown =
        terrain::Grow(Lobes(350), Improved(), terrain::kDefaultTerrainSeed);
    auto t = std::make_shared<terrain::Terrain>(grown.ok() ? *grown : terrain::Terrain());
    *units = static_cast<double>(terrain::BuildHeightfield(*t, res).h.size());
    return [t, res, brute]() {
      const terrain::Heightfield hf =
          brute ? terrain::BuildHeightfieldBruteForce(*t, res) : terrain::BuildHeightfield(*t, res);
      return hf.h.empty() ? -1.0 : hf.h[hf.h.size() / 2] + static_cast<double>(hf.h.size());
    };
  };
  return wl;
}

// The page's regrow of a drawn seed (web/bindings/terrain_bindings.cpp TerrainLab::grow and
// statsJson, without JavaScript): a 120-point seed like bench/terrain_page.mjs's drawing, r = 300
// m· (1 + 0.2 cos 3φ + 0.06 sin 11φ), grown with the improved method from its state, the 512²
// heightfield, the stats object (exact checks and the link included) and the flat buffers. All the
// core work of one regrow: the page now gets the mountain before the stats (which the worker
// computes right after posting it, web/worker/terrain_handler.js), so its posted time is this
// less the stats, and it copies into recycled buffers, which this does not time.
Workload PageRegrowWorkload(int res) {
  Workload wl;
  wl.name = "terrain/page-regrow/drawn-" + std::to_string(res);
  wl.note = "The page's regrow without JavaScript: a drawn 120-point seed (improved), the " +
            std::to_string(res) + "² heightfield, the stats and the flat buffers";
  wl.unit = "cell";
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [res, units]() -> WorkloadBody {
    auto state = std::make_shared<terrain::TerrainState>();
    terrain::Ring drawn;
    for (int i = 0; i < 120; ++i) {
      double s, c, s3, c3, s11, c11;
      det::SinCos(2 * kPi * i / 120, &s, &c);
      det::SinCos(3 * 2 * kPi * i / 120, &s3, &c3);
      det::SinCos(11 * 2 * kPi * i / 120, &s11, &c11);
      const double r = 300 * (1 + 0.2 * c3 + 0.06 * s11);
      // Rounded to 1 cm, as the page rounds a drawing.
      drawn.push_back({std::round(r * c * 100) / 100, std::round(r * s * 100) / 100});
    }
    (void)terrain::SetTerrainBuiltin("lobes7", state.get());  // the page's d, Δh, h0 before
    (void)terrain::SetTerrainPreset("improved", state.get());
    (void)terrain::SetTerrainPoints(drawn, state.get());
    (void)state->params.Set(terrain::TerrainParam::kRes, res);
    auto flat = std::make_shared<terrain::SurfaceBuffers>();
    {
      Result<terrain::Terrain> t =
          terrain::Grow(*terrain::StateSeed(*state), state->params, state->seed);
      *units = t.ok() ? static_cast<double>(terrain::BuildHeightfield(*t, res).h.size()) : 0;
    }
    return [state, flat, res]() {
      Result<terrain::Terrain> t =
          terrain::Grow(*terrain::StateSeed(*state), state->params, state->seed);
      if (!t.ok()) return -1.0;
      const terrain::Heightfield hf = terrain::BuildHeightfield(*t, res);
      const terrain::TerrainStats s = terrain::ComputeStats(*t, &hf);
      const std::string stats = terrain::TerrainStatsJson(*state, *t, hf, s).dump();
      terrain::BuildSurfaceBuffers(*t, hf, flat.get());
      return static_cast<double>(stats.size()) + s.hypsometric_integral +
             static_cast<double>(flat->indices.size()) +
             flat->positions[flat->positions.size() / 2];
    };
  };
  return wl;
}

}  // namespace

std::vector<Workload> TerrainWorkloads() {
  std::vector<Workload> all;
  all.push_back(GrowWorkload(500, /*cold=*/true));
  for (int points : {125, 250, 500, 1000}) all.push_back(GrowWorkload(points, false));
  for (int res : {256, 512, 1024}) all.push_back(HeightfieldWorkload(res, false));
  all.push_back(HeightfieldWorkload(256, /*brute=*/true));
  all.push_back(PageRegrowWorkload(512));
  return all;
}

}  // namespace niwa

// Moss workloads (core/moss, paper 001; issue 29 item 6): the thesis workload (300 days, 8,192
// photons a day, `thesis` scene, cap 16,384) cold and a 30-day warm slice; one day's photon pass on
// `thesis` at 2 k .. 64 k photons (cost linear in photons); and 8,192 photons traced on `rocks`
// with rock_triangles 1 k .. 1 M (cost per 10x triangles, the goal <= 2x), the cells built as the
// run builds them (over 200,000 triangles, one cell a triangle: soil_cells.h).
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "moss/photons.h"
#include "moss/scenes.h"
#include "moss/soil_cells.h"
#include "random/pcg32.h"
#include "workloads.h"

namespace niwa {
namespace {

// A checksum of a run: mosses alive, births and the last day's stored photons.
double Checksum(const moss::MossRun& run) {
  const moss::MossWorld& w = run.world();
  double sum = static_cast<double>(w.mosses.size()) + 1e-3 * static_cast<double>(w.births);
  for (int64_t n : w.stored_by_depth) sum += 1e-6 * static_cast<double>(n);
  return sum;
}

// `days` days of the default thesis state grown from the start (scene and cells built in the body).
Workload Thesis(int days, bool once) {
  Workload wl;
  wl.name = "moss/thesis-" + std::to_string(days);
  wl.note = "MossRun::Start (scene, soil cells) and " + std::to_string(days) +
            " days on thesis, 8,192 photons a day, preset nomura2010, seed 1" +
            (once ? ", timed once" : "");
  wl.once = once;
  wl.unit = "day";
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [days, units]() -> WorkloadBody {
    *units = days;
    return [days]() {
      moss::MossState state;
      state.days = days;
      Result<moss::MossRun> run = moss::MossRun::Start(state, Budget{});
      if (!run.ok() || !run->Advance(nullptr).ok()) return -1.0;
      return Checksum(*run);
    };
  };
  return wl;
}

// The cells and light of a scene, built once; the body traces one day's photons (no mosses).
struct PhotonBench {
  moss::SoilCells cells;
  moss::PhotonLight light;
  moss::MossOccluders none;
  moss::PhotonMap map;
};

std::shared_ptr<PhotonBench> MakePhotonBench(const std::string& scene_name, int rock_triangles) {
  moss::MossState state;
  Result<moss::MossScene> scene = moss::BuildScene(scene_name, rock_triangles);
  if (!scene.ok()) return nullptr;
  moss::SoilCellOptions options;
  options.soil_edge = state.params.Get(moss::MossParam::kSoilEdge);
  Result<moss::SoilCells> cells = moss::MakeSoilCells(*scene, options);
  if (!cells.ok()) return nullptr;
  auto b = std::make_shared<PhotonBench>();
  b->cells = std::move(*cells);
  Result<moss::PhotonLight> light = moss::PhotonLightOf(state.params, b->cells);
  if (!light.ok()) return nullptr;
  b->light = *light;
  return b;
}

Workload Photons(const std::string& scene, const std::string& label, int rock_triangles,
                 int photons) {
  Workload wl;
  wl.name = "moss/photons-" + scene + "/" + label;
  wl.note = "One day's photon pass on " + scene +
            (scene == "rocks" ? " with rock_triangles " + label : "") + ": " +
            std::to_string(photons) +
            " photons traced with bounces (scene and BVH built beforehand)";
  wl.unit = "photon";
  wl.size_name = "triangles";  // traced: the soil cells
  std::shared_ptr<double> units = wl.units, size = wl.size;
  wl.prepare = [scene, rock_triangles, photons, units, size]() -> WorkloadBody {
    std::shared_ptr<PhotonBench> b = MakePhotonBench(scene, rock_triangles);
    *units = photons;
    if (b != nullptr) *size = static_cast<double>(b->cells.size());
    return [b, photons]() {
      if (b == nullptr) return -1.0;
      Pcg32 rng(1, 7);
      moss::TracePhotons(b->cells, b->none, b->light, photons, &rng, &b->map);
      double sum = 0;
      for (int64_t n : b->map.stored_by_depth) sum += static_cast<double>(n);
      return sum;
    };
  };
  return wl;
}

}  // namespace

std::vector<Workload> MossWorkloads() {
  std::vector<Workload> all;
  all.push_back(Thesis(300, true));
  all.push_back(Thesis(30, false));
  for (int k : {2048, 8192, 32768, 65536})
    all.push_back(Photons("thesis", std::to_string(k / 1024) + "k", 0, k));
  // rock_triangles 1 k, 10 k, 100 k and 1 M: the icosphere levels they round up to (1,600,
  // 25,600, 102,400 and 1,638,400 rock triangles; the ground adds ~2.9 k cells), so cost per 10x is
  // read from the slope over the traced triangles the runner prints.
  all.push_back(Photons("rocks", "1k", 1000, 8192));
  all.push_back(Photons("rocks", "10k", 10000, 8192));
  all.push_back(Photons("rocks", "100k", 100000, 8192));
  all.push_back(Photons("rocks", "1m", 1000000, 8192));
  return all;
}

}  // namespace niwa

// Moss ray workloads (issue 29 item 6: the photon tracer beside a ray-tracing library on the same
// rays): the rays of the first day's photon pass on `thesis` (8,192 photons, preset nomura2010,
// seed 1: the rays `niwa moss photons --scene thesis --rays FILE.bin` writes) cast again through
// the cells' BVH, the land query alone (geom::FirstHitWithoutNormal, as TracePhotons casts them),
// so the time per ray stands beside bench/moss_rays_peer.mjs's three-mesh-bvh on that file. The
// checksum, Σ (triangle + 1) over the rays that hit, is the one the peer prints for the file.
#include <cstdint>
#include <memory>
#include <vector>

#include "geom/ray_cast.h"
#include "geom/ray_dump.h"
#include "moss/moss_run.h"
#include "moss/moss_state.h"
#include "workloads.h"

namespace niwa {
namespace {

struct RayBench {
  std::unique_ptr<moss::MossRun> run;
  std::vector<geom::CastRay> rays;
};

Workload ThesisRays() {
  Workload wl;
  wl.name = "moss/rays-thesis";
  wl.note =
      "The first day's photon rays on thesis (8,192 photons, seed 1; niwa moss photons --rays) "
      "cast again through the cells' BVH (FirstHitWithoutNormal), the land query alone";
  wl.unit = "ray";
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [units]() -> WorkloadBody {
    auto b = std::make_shared<RayBench>();
    moss::MossState state;
    state.days = 1;
    Result<moss::MossRun> run = moss::MossRun::Start(state, Budget{});
    if (!run.ok()) return [] { return -1.0; };
    b->run = std::make_unique<moss::MossRun>(std::move(*run));
    b->run->NextDayPhotons(&b->rays);
    *units = static_cast<double>(b->rays.size());
    return [b]() {
      const moss::SoilCells& cells = b->run->cells();
      double sum = 0;
      bool same = true;
      for (const geom::CastRay& r : b->rays) {
        const geom::RayHit h =
            geom::FirstHitWithoutNormal(cells.mesh, cells.bvh, r.origin, r.dir, r.max_distance);
        same = same && h.hit == r.hit && (!h.hit || h.triangle == r.triangle);
        if (h.hit) sum += static_cast<double>(h.triangle) + 1.0;
      }
      return same ? sum : -1.0;
    };
  };
  return wl;
}

}  // namespace

std::vector<Workload> MossRaysWorkloads() { return {ThesisRays()}; }

}  // namespace niwa

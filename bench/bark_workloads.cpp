// Bark workloads (core/bark, paper 003; issue 30, spec bark.md §6's table): one E1 run of the
// 2-layer model (128 x 64 lattice, camphor, the preset's cycles and settling) timed once cold with
// ns per spring-step as its unit; a 64 x 32 run warm; and the four maps (base colour, normal,
// 16-bit height, ORM) at 1024 px from a grown lattice: raster and PNG encoding together, the
// raster alone (the spec's "raster 1024x591 (4 maps) <= 50 ms" goal) and the encoding alone; one
// cycle of the 4-layer model (pine, 64 x 32) on one lane and on two. The grow workloads' notes
// carry the estimate's seconds a spring-step (bark_run.h), to hold beside what they measure.
#include <memory>
#include <string>
#include <vector>

#include "bark/bark_run.h"
#include "bark/bark_state.h"
#include "workloads.h"

namespace niwa {
namespace {

bark::BarkState StateOf(const std::string& species, int n_r, int n_h) {
  bark::BarkState state;
  (void)bark::SetBarkSpecies(species, &state);
  (void)state.params.Set(bark::BarkParam::kNR, n_r);
  (void)state.params.Set(bark::BarkParam::kNH, n_h);
  return state;
}

double Checksum(const bark::BarkRun& run) {
  return static_cast<double>(run.steps()) + 1e-3 * run.spring_steps() * 1e-6;
}

std::string EstimateNote() {
  return "; the estimate assumes " + std::to_string(bark::kBarkSecondsPerSpringStep * 1e9) +
         " ns a spring-step";
}

// Start and Advance of `species` on an n_r x n_h lattice; the unit is one spring-step. With
// lanes > 0: the 4-layer model over one cycle (T and settling as the table's) on that many lanes.
Workload Grow(const std::string& species, int n_r, int n_h, bool once, int lanes = 0) {
  Workload wl;
  const std::string size = std::to_string(n_r) + "x" + std::to_string(n_h);
  wl.name = "bark/" + species + "-" + size +
            (lanes > 0 ? "-4layer-" + std::to_string(lanes) + "lane" : std::string());
  wl.note = "BarkRun::Start and Advance: the " +
            std::string(lanes > 0 ? "4-layer model (one cycle, " + std::to_string(lanes) +
                                        " lane(s): CPU time is not wall time with two)"
                                  : "2-layer model") +
            ", " + species + " preset on a " + size + " lattice, seed 1" +
            (once ? ", timed once (cold)" : "") + EstimateNote();
  wl.once = once;
  wl.unit = "spring-step";
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [species, n_r, n_h, units, lanes]() -> WorkloadBody {
    bark::BarkState state = StateOf(species, n_r, n_h);
    if (lanes > 0) (void)bark::SetBarkModel("4layer", &state);
    return [state, units, lanes]() {
      Result<bark::BarkRun> run = bark::BarkRun::Start(state, Budget{});
      if (!run.ok()) return -1.0;
      run->SetLanes(lanes > 0 ? lanes : 1);
      if (!run->Advance({}).ok()) return -1.0;
      *units = run->spring_steps();
      return Checksum(*run);
    };
  };
  return wl;
}

// The four maps at map_size px from a 128 x 64 camphor lattice grown beforehand: `what` is "all"
// (raster and PNG bytes), "raster" (the four images) or "png" (the encoding of maps drawn
// beforehand).
Workload Maps(int size, const std::string& what) {
  Workload wl;
  wl.name = "bark/maps-" + (what == "all" ? std::string() : what + "-") + std::to_string(size);
  wl.note = "The four maps (base colour, normal, 16-bit height, ORM) at " + std::to_string(size) +
            " px from a grown 128x64 camphor lattice, " +
            (what == "all"      ? "PNG bytes included"
             : what == "raster" ? "the raster alone (no PNG)"
                                : "the PNG encoding alone (maps drawn beforehand)");
  wl.prepare = [size, what]() -> WorkloadBody {
    bark::BarkState state = StateOf("camphor", 128, 64);
    (void)state.params.Set(bark::BarkParam::kMapSize, size);
    auto run = std::make_shared<Result<bark::BarkRun>>(bark::BarkRun::Start(state, Budget{}));
    if (!run->ok() || !(*run)->Advance({}).ok()) return []() { return -1.0; };
    if (what == "png") (void)(*run)->maps();  // drawn once here; the body encodes only
    return [run, what]() {
      bark::BarkRun fresh = **run;  // a copy (without maps unless "png" drew them)
      if (what == "raster") return static_cast<double>(fresh.maps().height.pixels[0]);
      double sum = 0;
      for (const char* map : {"base_colour", "normal", "height", "orm"}) {
        Result<std::string> png = fresh.MapPng(map);
        sum += png.ok() ? 1e-3 * static_cast<double>(png->size()) : -1;
      }
      return sum;
    };
  };
  return wl;
}

}  // namespace

std::vector<Workload> BarkWorkloads() {
  std::vector<Workload> all;
  all.push_back(Grow("camphor", 128, 64, true));
  all.push_back(Grow("camphor", 64, 32, false));
  all.push_back(Grow("pine", 64, 32, true, 1));
  all.push_back(Grow("pine", 64, 32, true, 2));
  all.push_back(Maps(1024, "all"));
  all.push_back(Maps(1024, "raster"));
  all.push_back(Maps(1024, "png"));
  return all;
}

}  // namespace niwa

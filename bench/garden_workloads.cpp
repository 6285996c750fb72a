// Garden workloads (core/compose/garden_*, issue 33 item 7): the planting rules alone over a flat
// 1 km square asking for 100,000 trees (the unit one dart: the goal is 100 k candidates in
// <= 100 ms, <= 1 us a dart), and the scale workload: a 100 m x 100 m garden on a 512² terrain
// ground with 100 trees of 10 species grown to 15 years on one clock (shade on), ivy on the four
// default objects and the default moss, timed once; and the 1,000-tree export: a 320 m garden of
// about 1,000 trees grown alone (shade off: 3 variants of each of the 3 default species, instanced)
// to 10 years and written as .glb, timed once, its check the .glb's megabytes (the goal: <= 50 MB),
// and the same garden with shade on, its shaded trees drawn with shared shapes (shapes 1).
#include <memory>
#include <string>
#include <vector>

#include "compose/garden_plant.h"
#include "compose/garden_run.h"
#include "compose/garden_scene.h"
#include "compose/garden_state.h"
#include "workloads.h"

namespace niwa {
namespace {

using compose::GardenParam;

Workload Plant() {
  Workload wl;
  wl.name = "garden/plant-100k";
  wl.note =
      "PlantGarden: the planting rules over a flat 1000 m square, density 0.1 (100,000 "
      "trees asked for), spacing 1.5 m, slope and altitude open, the default objects; the "
      "unit one dart (candidate)";
  wl.unit = "dart";
  auto units = wl.units;
  wl.prepare = [units]() -> WorkloadBody {
    auto state = std::make_shared<compose::GardenState>(compose::DefaultGardenState());
    (void)state->params.Set(GardenParam::kSize, 1000);
    (void)state->params.Set(GardenParam::kDensity, 0.1);
    (void)state->params.Set(GardenParam::kSpacing, 1.5);
    (void)state->params.Set(GardenParam::kGroundRes, 8);
    state->ground = compose::GroundKind::kFlat;
    compose::LayOutDefaults(state.get());
    auto scene = std::make_shared<compose::GardenScene>();
    Result<compose::GardenScene> made = compose::BuildGardenScene(*state, Budget{});
    if (!made.ok()) return []() { return -1.0; };
    *scene = std::move(*made);
    return [state, scene, units]() {
      Result<compose::Planting> p = compose::PlantGarden(*state, *scene);
      if (!p.ok()) return -1.0;
      *units = static_cast<double>(p->report.candidates);
      return static_cast<double>(p->trees.size()) +
             1e-6 * static_cast<double>(p->report.candidates);
    };
  };
  return wl;
}

Workload Scale() {
  Workload wl;
  wl.name = "garden/scale-100-trees-15y";
  wl.note =
      "GardenRun::Start and Advance: 100 m x 100 m, terrain ground at 512², 100 trees of 10 "
      "species by the rules (density 0.01, spacing 5 m), 15 years on one clock, shade on; "
      "timed once (cold); ivy on the 4 default objects (60 steps a year: 900 each), the "
      "default moss (10 days a year: 150 days) on the ground resampled to 128² and the objects";
  wl.once = true;
  wl.prepare = []() -> WorkloadBody {
    return []() {
      compose::GardenState state = compose::DefaultGardenState();
      (void)state.params.Set(GardenParam::kSize, 100);
      (void)state.params.Set(GardenParam::kGroundRes, 512);
      (void)state.params.Set(GardenParam::kYears, 15);
      (void)state.params.Set(GardenParam::kDensity, 0.0099);
      (void)state.params.Set(GardenParam::kSpacing, 5);
      (void)state.params.Set(GardenParam::kSlopeMax, 90);
      compose::LayOutDefaults(&state);
      state.ivy_on = {"objects[0]", "objects[1]", "objects[2]", "objects[3]"};
      state.mix.clear();
      for (const char* s : {"keyaki", "sakura", "maple", "pine", "ginkgo", "weeping", "tsutsuji",
                            "binary", "keyaki-thesis", "sakura-thesis"})
        state.mix.push_back({s, 1});
      Result<compose::GardenRun> run = compose::GardenRun::Start(state, Budget{});
      if (!run.ok() || !run->Advance({}).ok()) return -1.0;
      return static_cast<double>(run->planting().trees.size()) +
             1e-6 * static_cast<double>(run->groups().size());
    };
  };
  return wl;
}

}  // namespace

// The 320 m garden of about 1,000 trees grown to 10 years and written as .glb (check: its MB).
WorkloadBody ExportGarden(bool shade, int shapes) {
  return [shade, shapes]() {
    compose::GardenState state = compose::DefaultGardenState();
    (void)state.params.Set(GardenParam::kSize, 320);
    (void)state.params.Set(GardenParam::kDensity, 0.0098);
    (void)state.params.Set(GardenParam::kSpacing, 3);
    (void)state.params.Set(GardenParam::kSlopeMax, 90);
    (void)state.params.Set(GardenParam::kShade, shade ? 1 : 0);
    (void)state.params.Set(GardenParam::kShapes, shapes);
    compose::LayOutDefaults(&state);
    Result<compose::GardenRun> run = compose::GardenRun::Start(state, Budget{});
    if (!run.ok() || !run->Advance({}).ok()) return -1.0;
    Result<std::string> glb = run->Export("glb");
    if (!glb.ok()) return -1.0;
    return static_cast<double>(glb->size()) / 1e6 +
           1e-6 * static_cast<double>(run->planting().trees.size());
  };
}

Workload Export1000() {
  Workload wl;
  wl.name = "garden/export-1000-trees";
  wl.note =
      "GardenRun::Start, Advance and Export(\"glb\"): 320 m x 320 m terrain garden, density 0.0098 "
      "(about 1,000 trees of the 3 default species, 3 variants each), spacing 3 m, shade off "
      "(so each variant is one instanced mesh), 10 years, the default ivy and moss; timed once "
      "(cold); check: the .glb's MB (goal <= 50 with instancing)";
  wl.once = true;
  wl.prepare = []() -> WorkloadBody { return ExportGarden(false, 8); };
  return wl;
}

// The same 1,000-tree garden with shade on (the garden's default): nearly every tree is grown with
// its neighbours' shade, so each is distinct; `shapes` 1 draws each variant's shaded trees with
// one shared shape, turned and scaled per tree (compose/garden_shapes).
Workload Export1000Shade() {
  Workload wl;
  wl.name = "garden/export-1000-trees-shade";
  wl.note =
      "as garden/export-1000-trees with shade on (961 of 1,005 trees grown with their "
      "neighbours' shade) and shapes 1; timed once (cold); check: the .glb's MB (goal <= 50)";
  wl.once = true;
  wl.prepare = []() -> WorkloadBody { return ExportGarden(true, 1); };
  return wl;
}

std::vector<Workload> GardenWorkloads() {
  return {Plant(), Scale(), Export1000(), Export1000Shade()};
}

}  // namespace niwa

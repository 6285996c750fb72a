// Ivy workloads (core/ivy, paper 004): cubes4's 50 steps warm (BVH built) and cold (scene and BVH
// made in the timed part), with the .glb; per-step growth on `wall` subdivided to 4 k .. 4 M
// triangles (the issue: per-step time at 4 M within 3x that at 4 k); and the BVH against
// --accel linear at 262 k triangles (the issue: >= 100x).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geom/bvh.h"
#include "geom/primitives.h"
#include "ivy/growth.h"
#include "ivy/ivy_mesh.h"
#include "ivy/ivy_params.h"
#include "ivy/scenes.h"
#include "workloads.h"

namespace niwa {
namespace {

// A built scene with its BVH (made once per workload in prepare()).
struct IvyBench {
  ivy::IvyScene scene;
  geom::Bvh bvh;
  IvyParams params = *IvyPreset("paper");
};

std::shared_ptr<IvyBench> MakeBench(const char* name, int subdivide) {
  auto b = std::make_shared<IvyBench>();
  b->scene = *ivy::MakeIvyScene(name);
  if (subdivide > 0) b->scene.mesh = geom::Subdivide(b->scene.mesh, subdivide);
  b->bvh = geom::Bvh::Build(b->scene.mesh);
  return b;
}

// A checksum of a model: internodes and the sum of the bud coordinates.
double Checksum(const ivy::IvyModel& m) {
  double sum = static_cast<double>(m.internodes.size());
  for (const ivy::Bud& bud : m.buds) sum += 1e-6 * (bud.pos.x + bud.pos.y + bud.pos.z);
  return sum;
}

ivy::IvyModel GrowOn(const IvyBench& b, int steps, ivy::Accel accel, int* steps_run) {
  ivy::Support support{&b.scene.mesh, &b.bvh, accel};
  ivy::GrowLog log;
  Result<ivy::IvyModel> m = ivy::Grow(support, {b.scene.seeds[0].pos}, b.params, steps, 1, &log);
  if (steps_run != nullptr) *steps_run = log.steps_run;
  return m.ok() ? std::move(m).value() : ivy::IvyModel{};
}

Workload Cubes4(const std::string& variant) {
  Workload wl;
  wl.name = "ivy/cubes4-50" + (variant.empty() ? "" : "-" + variant);
  wl.unit = "step";
  std::shared_ptr<double> units = wl.units;
  if (variant.empty()) {
    wl.note = "Grow on cubes4, preset paper, seed 1, 50 steps (BVH built beforehand)";
  } else if (variant == "glb") {
    wl.note = "Grow on cubes4 (50 steps) and WriteIvyGlb with the support";
  } else {
    wl.note = "cubes4 made, its BVH built and 50 steps grown, timed once without warm-up";
    wl.once = true;
  }
  wl.prepare = [variant, units]() -> WorkloadBody {
    *units = 50;
    if (variant == "cold") {
      return []() {
        std::shared_ptr<IvyBench> b = MakeBench("cubes4", 0);
        return Checksum(GrowOn(*b, 50, ivy::Accel::kBvh, nullptr));
      };
    }
    std::shared_ptr<IvyBench> b = MakeBench("cubes4", 0);
    const bool glb = variant == "glb";
    return [b, glb]() {
      ivy::IvyModel m = GrowOn(*b, 50, ivy::Accel::kBvh, nullptr);
      double sum = Checksum(m);
      if (glb) {
        Result<std::vector<unsigned char>> bytes =
            ivy::WriteIvyGlb(m, b->params, 1, 50, &b->scene.mesh);
        sum += bytes.ok() ? 1e-3 * static_cast<double>(bytes->size()) : -1;
      }
      return sum;
    };
  };
  return wl;
}

// wall subdivided K times (4 * 4^K triangles): `steps` steps of growth; the unit is one step.
Workload Wall(const char* label, int k, int steps, ivy::Accel accel, bool once) {
  Workload wl;
  const bool linear = accel == ivy::Accel::kLinear;
  wl.name = std::string("ivy/wall") + (linear ? "-linear" : "") + "/" + label;
  wl.note = "Grow " + std::to_string(steps) + " steps on wall --subdivide " + std::to_string(k) +
            " (" + label + " triangles)" + (linear ? " with --accel linear" : " through the BVH") +
            (once ? ", timed once" : "");
  wl.unit = "step";
  wl.once = once;
  std::shared_ptr<double> units = wl.units;
  wl.prepare = [k, steps, accel, units]() -> WorkloadBody {
    std::shared_ptr<IvyBench> b = MakeBench("wall", k);
    *units = steps;
    return [b, steps, accel]() { return Checksum(GrowOn(*b, steps, accel, nullptr)); };
  };
  return wl;
}

}  // namespace

std::vector<Workload> IvyWorkloads() {
  std::vector<Workload> all;
  all.push_back(Cubes4(""));
  all.push_back(Cubes4("glb"));
  all.push_back(Cubes4("cold"));
  all.push_back(Wall("4k", 5, 50, ivy::Accel::kBvh, false));
  all.push_back(Wall("65k", 7, 50, ivy::Accel::kBvh, false));
  all.push_back(Wall("262k", 8, 50, ivy::Accel::kBvh, false));
  all.push_back(Wall("1m", 9, 50, ivy::Accel::kBvh, false));
  all.push_back(Wall("4m", 10, 50, ivy::Accel::kBvh, false));  // slow to prepare, fast to run
  // The BVH against brute force at 262 k: 10 steps each (linear takes seconds per step).
  all.push_back(Wall("262k-10", 8, 10, ivy::Accel::kBvh, false));
  all.push_back(Wall("262k-10", 8, 10, ivy::Accel::kLinear, true));
  return all;
}

}  // namespace niwa

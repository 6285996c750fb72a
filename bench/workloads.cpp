// Benchmark workloads: growth of every preset, sakura at several ages, mesh, .glb, the light
// model and wind sway.
#include "workloads.h"

#include <cstdlib>
#include <glm/vec3.hpp>
#include <memory>
#include <utility>

#include "random/pcg32.h"
#include "sway/skin.h"
#include "sway/sway.h"
#include "tree/growth.h"
#include "tree/light.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree.h"
#include "tree/tree_gltf.h"

namespace niwa {
namespace {

constexpr int kLightSpheres = 2000;

GrowRequest PresetRequest(const Preset& preset, int years) {
  GrowRequest r;
  r.preset = preset.name;
  r.params = preset.params;
  r.years = years;
  r.seed = 1;
  return r;
}

const Preset& Sakura() { return *FindPreset("sakura-thesis"); }

Workload GrowWorkload(const Preset& preset, int years) {
  GrowRequest request = PresetRequest(preset, years);
  return {"grow/" + preset.name + "-" + std::to_string(years) + "y",
          "GrowTree, " + preset.name + " " + std::to_string(years) + " years, seed 1",
          [request]() -> WorkloadBody {
            return [request]() {
              Tree tree = GrowTree(request);
              return static_cast<double>(ComputeStats(tree).internodes);
            };
          }};
}

// 2,000 leaf spheres scattered through a crown-sized box (cm), from the project's PCG32.
std::vector<LeafSphere> RandomSpheres(int count) {
  Pcg32 rng(12345);
  std::vector<LeafSphere> spheres;
  spheres.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    // One draw per statement: argument evaluation order differs between g++ and clang (em++).
    float x = static_cast<float>(rng.Uniform(-150.0, 150.0));
    float y = static_cast<float>(rng.Uniform(100.0, 400.0));
    float z = static_cast<float>(rng.Uniform(-150.0, 150.0));
    float radius = static_cast<float>(rng.Uniform(3.0, 12.0));
    spheres.push_back({glm::vec3(x, y, z), radius});
  }
  return spheres;
}

double LightChecksum(const std::vector<LightSample>& samples) {
  double sum = 0;
  for (const LightSample& s : samples) sum += s.light;
  return sum;
}

Workload LightWorkload(bool reference, int spheres_count = kLightSpheres) {
  std::string n = std::to_string(spheres_count);
  return {reference ? "light/reference-" + n : "light/grid-" + n,
          reference ? "ComputeLightReference (pairwise), " + n + " random spheres"
                    : "ComputeLightGrid (voxel grid), " + n + " random spheres",
          [reference, spheres_count]() -> WorkloadBody {
            auto spheres = std::make_shared<std::vector<LeafSphere>>(RandomSpheres(spheres_count));
            auto sky = std::make_shared<Sky>(MakeSky(60.0f, 0.0f, 0.3f));
            return [spheres, sky, reference]() {
              return LightChecksum(reference ? ComputeLightReference(*spheres, *sky, 0.5f)
                                             : ComputeLightGrid(*spheres, *sky, 0.5f));
            };
          },
          reference&& spheres_count > kLightSpheres};
}

// One second of sway animation (thesis ch. 3) on sakura of the given age in a 10 m/s gust: 30
// dynamics steps (dt 1/30 s), each followed by what a renderer needs for the frame: with `poses`
// the skin poses of every node point (WriteSwayPoses, what the page uploads), else the eq. 3.15
// position of every original node (NodePositions). Each run restarts from one simulator state
// prepared 2 s into the gust, so the checksum is the same every run. Reported per internode-step.
Workload SwayWorkload(int years, bool poses) {
  constexpr int kSteps = 30;
  Workload w;
  w.name =
      std::string(poses ? "sway-poses" : "sway") + "/sakura-thesis-" + std::to_string(years) + "y";
  w.note = "30 sway steps + " + std::string(poses ? "WriteSwayPoses" : "NodePositions (eq. 3.15)") +
           ", sakura-thesis " + std::to_string(years) + " years, 10 m/s";
  w.unit = "internode-step";
  std::shared_ptr<double> units = w.units;
  w.prepare = [years, poses, units]() -> WorkloadBody {
    Tree tree = GrowTree(PresetRequest(Sakura(), years));
    TreeParams params = Sakura().params;
    if (!params.Set(ParamId::kWindSpeed, 10).ok()) std::abort();
    auto base = std::make_shared<SwaySimulator>(tree, SwayParams(params));
    while (base->time() < 3.0) base->Step();  // 2 s into the gust (gust_on 1 s)
    *units = static_cast<double>(kSteps) * static_cast<double>(base->model().internodes);
    auto sim = std::make_shared<SwaySimulator>(*base);
    auto positions = std::make_shared<std::vector<glm::dvec3>>();
    auto pose = std::make_shared<std::vector<float>>(base->model().nodes.size() * kSwayPoseFloats);
    return [base, sim, positions, pose, poses]() {
      *sim = *base;
      for (int k = 0; k < kSteps; ++k) {
        sim->Step();
        if (poses) {
          WriteSwayPoses(*sim, MeshOptions{}.cm_to_units, pose->data());
        } else {
          sim->NodePositions(positions.get());
        }
      }
      double sum = 0;
      if (poses) {
        for (float f : *pose) sum += static_cast<double>(f);
      } else {
        for (const glm::dvec3& p : *positions) sum += p.x + p.y + p.z;
      }
      return sum;
    };
  };
  return w;
}

std::vector<Workload> MakeWorkloads() {
  std::vector<Workload> all;
  for (const Preset& p : Presets()) all.push_back(GrowWorkload(p, p.years));
  for (int years : {10, 20}) {  // sakura 20 years: about 120,000 internodes
    if (years != Sakura().years) all.push_back(GrowWorkload(Sakura(), years));
  }
  // Scaling with the number of leaves (issue: at most 2.5x time per doubling of leaves).
  for (int years : {10, 20, 40}) all.push_back(GrowWorkload(*FindPreset("maple"), years));
  all.push_back(
      {"grow+mesh/sakura-thesis-15y", "GrowTree and BuildTreeMesh of sakura-thesis 15 years", [] {
         return WorkloadBody([]() {
           TreeMesh mesh = BuildTreeMesh(GrowTree(PresetRequest(Sakura(), 15)));
           return static_cast<double>(mesh.bark.indices.size() / 3 +
                                      mesh.leaves.indices.size() / 3 +
                                      mesh.flowers.indices.size() / 3);
         });
       }});
  all.push_back({"mesh/sakura-thesis-15y",
                 "BuildTreeMesh of sakura-thesis 15 years (tree grown untimed)", [] {
                   auto tree = std::make_shared<Tree>(GrowTree(PresetRequest(Sakura(), 15)));
                   return WorkloadBody([tree]() {
                     TreeMesh mesh = BuildTreeMesh(*tree);
                     return static_cast<double>(mesh.bark.vertex_count() +
                                                mesh.leaves.vertex_count() +
                                                mesh.flowers.vertex_count());
                   });
                 }});
  all.push_back({"glb/sakura-thesis-15y",
                 "WriteGlb in memory of the sakura-thesis 15 years mesh (mesh untimed)", [] {
                   auto mesh = std::make_shared<TreeMesh>(
                       BuildTreeMesh(GrowTree(PresetRequest(Sakura(), 15))));
                   return WorkloadBody([mesh]() {
                     std::vector<unsigned char> bytes;
                     (void)WriteTreeGlb(*mesh, &bytes);
                     return static_cast<double>(bytes.size());
                   });
                 }});
  all.push_back(LightWorkload(false));
  all.push_back(LightWorkload(true));
  all.push_back(LightWorkload(false, 20000));
  all.push_back(LightWorkload(true, 20000));  // about half a minute: timed once
  for (bool poses : {false, true}) {
    for (int years : {6, 10, 15}) all.push_back(SwayWorkload(years, poses));
  }
  for (Workload& w : AreaWorkloads()) all.push_back(std::move(w));
  return all;
}

}  // namespace

const std::vector<Workload>& Workloads() {
  static const std::vector<Workload> workloads = MakeWorkloads();
  return workloads;
}

}  // namespace niwa

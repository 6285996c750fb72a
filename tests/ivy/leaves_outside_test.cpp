// Leaves sit outside the support (issue 31 item 7): on the Stanford bunny (tests/data/meshes/
// bunny.obj, closed) at most 1 % of the leaf area is inside it, judged by ray casts (the parity
// of three rays from area-weighted points of every leaf triangle, by majority); the leaves placed
// without the support's check (the spec's §1.5 as before) are measured too and are worse.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>

#include "geom/closest_point.h"
#include "geom/ray_cast.h"
#include "io/mesh_reader.h"
#include "ivy/ivy_run.h"
#include "support/ivy_bunny.h"

namespace niwa::ivy {
namespace {

// Is p inside the closed mesh? Three rays in fixed, non-axis directions; each counts the faces
// it crosses (stepping past every hit); odd = inside; the majority wins.
bool Inside(const geom::TriMesh& mesh, const geom::Bvh& bvh, glm::vec3 p, float step) {
  const glm::vec3 dirs[3] = {glm::normalize(glm::vec3(0.31f, 0.83f, 0.46f)),
                             glm::normalize(glm::vec3(-0.72f, 0.18f, 0.67f)),
                             glm::normalize(glm::vec3(0.27f, -0.61f, -0.74f))};
  int votes = 0;
  for (const glm::vec3& dir : dirs) {
    int crossings = 0;
    glm::vec3 o = p;
    for (int guard = 0; guard < 1000; ++guard) {
      const geom::RayHit hit =
          geom::FirstHit(mesh, bvh, o, dir, std::numeric_limits<float>::infinity());
      if (!hit.hit) break;
      ++crossings;
      o = hit.point + step * dir;
    }
    votes += crossings % 2;
  }
  return votes >= 2;
}

// The share of the leaves' area inside the support.
double AreaInside(const geom::TriMesh& leaves, const geom::TriMesh& mesh, const geom::Bvh& bvh,
                  float step) {
  double total = 0, inside = 0;
  for (std::size_t t = 0; t < leaves.triangle_count(); ++t) {
    const glm::dvec3 a(leaves.positions[leaves.indices[3 * t]]);
    const glm::dvec3 b(leaves.positions[leaves.indices[3 * t + 1]]);
    const glm::dvec3 c(leaves.positions[leaves.indices[3 * t + 2]]);
    const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
    if (!(area > 0)) continue;
    total += area;
    // Four area-weighted points: the centroid and the three points 2/3 toward each corner.
    const glm::dvec3 points[4] = {(a + b + c) / 3.0, (4.0 * a + b + c) / 6.0,
                                  (a + 4.0 * b + c) / 6.0, (a + b + 4.0 * c) / 6.0};
    for (const glm::dvec3& p : points) {
      if (Inside(mesh, bvh, glm::vec3(p), step)) inside += area / 4;
    }
  }
  return total > 0 ? inside / total : 0;
}

struct OutsideIvy {
  double inside = 0, unchecked = 0;
  std::size_t leaves = 0;
  LeafPlacement placement;
};

// Grows `preset` for `steps` on `support` (its front seed, or `seed` when given) and measures the
// leaves inside the mesh, placed as the run places them and unchecked.
OutsideIvy GrowAndMeasure(const std::shared_ptr<const IvySupport>& support, const char* preset,
                          int steps, const std::vector<glm::dvec3>& seeds = {}) {
  OutsideIvy g;
  IvyState state;
  EXPECT_TRUE(SetIvyPreset(preset, &state).ok());
  state.steps = steps;
  state.seed_points = seeds;
  IvyRunOptions options;
  options.build_meshes = true;
  Result<IvyRun> run = IvyRun::Start(state, support, Budget{}, options);
  EXPECT_TRUE(run.ok()) << run.status().Line();
  if (!run.ok() || !run->Advance({}).ok()) return g;
  EXPECT_GT(run->model().buds.size(), 100u) << preset;
  const float step = static_cast<float>(1e-5 * support->extent());
  const geom::TriMesh& mesh = *support->mesh();
  g.leaves = run->model().buds.size() - 1;
  g.inside = AreaInside(run->meshes().leaves, mesh, support->bvh(), step);
  const Support grown_on = support->ForGrow();
  (void)BuildIvyMeshes(run->model(), run->params(), &grown_on, &g.placement);
  g.unchecked =
      AreaInside(BuildIvyMeshes(run->model(), run->params()).leaves, mesh, support->bvh(), step);
  return g;
}

TEST(IvyLeaves, AtMostOnePercentOfTheLeafAreaIsInsideTheBunny) {
  for (bool inward : {false, true}) {
    std::shared_ptr<const IvySupport> bunny = testing::BunnySupport(inward);
    for (const char* preset : {"paper", "improved"}) {
      if (inward && preset != std::string("paper")) continue;  // the seed's side is what differs
      const OutsideIvy g = GrowAndMeasure(bunny, preset, 150);
      std::printf(
          "%s bunny, %s: %zu leaves; inside %.4f of the leaf area (unchecked %.4f); "
          "turned %zu, shrunk %zu, still crossing %zu\n",
          inward ? "inward" : "outward", preset, g.leaves, g.inside, g.unchecked,
          g.placement.turned, g.placement.shrunk, g.placement.crossing);
      EXPECT_LE(g.inside, 0.01) << preset;
      EXPECT_GT(g.unchecked, g.inside) << preset;  // the check is what keeps them out
    }
  }
  // What the page did before on a scan wound inward: the default seed exactly on the surface was
  // lifted along the face's winding, inside, and the ivy grew inside the bunny, every leaf with it.
  std::shared_ptr<const IvySupport> inward = testing::BunnySupport(true);
  const NamedSeed front = inward->scene().seeds.at(0);
  const geom::ClosestHit on = geom::ClosestPoint(
      *inward->mesh(), inward->bvh(), glm::vec3(front.pos), std::numeric_limits<float>::infinity());
  const OutsideIvy before = GrowAndMeasure(inward, "paper", 150, {glm::dvec3(on.point)});
  std::printf("inward bunny, seed on the surface: inside %.4f of the leaf area\n", before.inside);
  EXPECT_GT(before.inside, 0.5);
}

}  // namespace
}  // namespace niwa::ivy

// Leaves (and tubes) keep a size in metres on a dropped mesh (issue 31 items 4 and 7): the same
// mesh (the Stanford bunny) as a 0.3 m rock and a 20 m facade, read as glTF (metres), grows leaves
// of about the same width in metres, measured on the leaf meshes, while its growth keeps the scale
// of its bounds; read as OBJ (no unit) its leaves stay a fixed share of its size, as before. The
// row leaf_spacing puts those leaves a real stem length apart on both (counted on the meshes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdio>
#include <glm/geometric.hpp>
#include <string>
#include <utility>
#include <vector>

#include "geom/mesh_metrics.h"
#include "io/mesh_reader.h"
#include "ivy/ivy_mesh.h"
#include "ivy/ivy_run.h"

namespace niwa::ivy {
namespace {

// The width of every leaf blade, measured: a blade is the leaf outline's unit coordinates times
// its width, and its uvs are those coordinates (ivy_mesh.cpp: u = x + 0.5, v = 1 - y), so along
// an edge of a blade triangle |dp| / |duv| is the width of its leaf. One value per triangle (its
// longest edge in uv; petiole triangles, whose uvs are one or two texels, are skipped).
std::vector<double> BladeWidths(const geom::TriMesh& leaves) {
  std::vector<double> widths;
  for (std::size_t t = 0; t + 2 < leaves.indices.size(); t += 3) {
    double best_uv = 0, width = 0;
    for (int e = 0; e < 3; ++e) {
      const uint32_t a = leaves.indices[t + e], b = leaves.indices[t + (e + 1) % 3];
      const double duv = glm::length(glm::dvec2(leaves.uvs[a] - leaves.uvs[b]));
      if (duv > best_uv) {
        best_uv = duv;
        width = glm::length(glm::dvec3(leaves.positions[a] - leaves.positions[b])) / duv;
      }
    }
    if (best_uv > 0.1) widths.push_back(width);
  }
  std::sort(widths.begin(), widths.end());
  return widths;
}

double Quantile(const std::vector<double>& sorted, double q) {
  return sorted.empty()
             ? 0
             : sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

struct SizedIvy {
  double px_per_unit = 0, look_px_per_unit = 0, L = 0, leaf_size = 0, r_tip = 0;
  std::size_t leaves = 0;
  double p50 = 0, p90 = 0;  // blade widths in scene units
  // Without the support's checks: leaves drawn, buds that carry them (all but the seeds), and
  // the stems' length (scene units).
  std::size_t drawn = 0, leafy_buds = 0;
  double stem_length = 0;
};

// The bunny scaled to `extent` scene units across, read with `metres_per_unit` (1: a glTF, 0: an
// OBJ), with the page's front seed, grown 60 steps with the page's default preset (artist).
SizedIvy GrowBunny(double extent, double metres_per_unit,
                   std::vector<std::pair<std::string, double>> rows = {}) {
  const std::string path = std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/bunny.obj";
  Result<geom::TriMesh> mesh = io::ReadMeshFile(path);
  EXPECT_TRUE(mesh.ok()) << mesh.status().Line();
  const geom::Bounds3 b = geom::MeshBounds(*mesh);
  const glm::vec3 size = b.max - b.min;
  const float k = static_cast<float>(extent / std::max({size.x, size.y, size.z}));
  for (glm::vec3& p : mesh->positions) p = (p - b.min) * k;
  IvySupportOptions options;
  options.front_seed = true;
  Result<std::shared_ptr<const IvySupport>> support = IvySupport::Prepare(
      IvySupportInput::Mesh(*mesh, "bunny", {}, metres_per_unit), options, Budget{});
  EXPECT_TRUE(support.ok()) << support.status().Line();
  IvyState state;
  EXPECT_TRUE(SetIvyPreset("artist", &state).ok());
  for (const auto& [key, value] : rows) {
    EXPECT_TRUE(state.params.SetFromText(key, std::to_string(value)).ok()) << key;
  }
  state.steps = 60;
  IvyRunOptions run_options;
  run_options.build_meshes = true;
  Result<IvyRun> run = IvyRun::Start(state, *support, Budget{}, run_options);
  EXPECT_TRUE(run.ok()) << run.status().Line();
  EXPECT_TRUE(run->Advance({}).ok());
  SizedIvy g;
  g.px_per_unit = (*support)->px_per_unit();
  g.look_px_per_unit = (*support)->look_px_per_unit();
  g.L = run->params().Get(IvyParam::kL);
  g.leaf_size = run->params().Get(IvyParam::kLeafSize);
  g.r_tip = run->params().Get(IvyParam::kRTip);
  const std::vector<double> widths = BladeWidths(run->meshes().leaves);
  g.leaves = widths.size();
  g.p50 = Quantile(widths, 0.5);
  g.p90 = Quantile(widths, 0.9);
  LeafPlacement placement;
  (void)BuildIvyMeshes(run->model(), run->params(), nullptr, &placement);
  g.drawn = placement.drawn;
  for (const Bud& bud : run->model().buds) g.leafy_buds += bud.parent >= 0 ? 1 : 0;
  for (const Internode& in : run->model().internodes) {
    g.stem_length += glm::length(run->model().buds[static_cast<std::size_t>(in.to_bud)].pos -
                                 run->model().buds[static_cast<std::size_t>(in.from_bud)].pos);
  }
  std::printf(
      "[ leaves   ] bunny %.1f m across, %s: %zu blade triangles, widths median %.4f, 90th "
      "percentile %.4f scene units; L %.4f\n",
      extent, metres_per_unit > 0 ? "glTF (metres)" : "OBJ (no unit)", g.leaves, g.p50, g.p90, g.L);
  return g;
}

TEST(IvyLeafSize, AGltfsLeavesAreCentimetresWhateverItsSize) {
  const SizedIvy rock = GrowBunny(0.3, 1), facade = GrowBunny(20, 1);
  for (const SizedIvy* g : {&rock, &facade}) {
    EXPECT_EQ(g->look_px_per_unit, 1000);  // a glTF's metres
    EXPECT_EQ(g->leaf_size, 0.075);        // artist: 75 px = 75 mm
    EXPECT_EQ(g->r_tip, 0.0015);           // 1.5 px: the tubes' tips 1.5 mm
    ASSERT_GT(g->leaves, 100u);
    // SizedIvy leaves 4-12 cm (age and light shrink the young and shaded ones, turns keep them
    // out).
    EXPECT_GE(g->p90, 0.04);
    EXPECT_LE(g->p90, 0.12);
    EXPECT_GE(g->p50, 0.01);
  }
  // The growth keeps the scale of the bounds (1200 px across): L = 50 px of it.
  // (The scaled positions are floats: the extents within a millionth.)
  EXPECT_NEAR(rock.px_per_unit, 1200 / 0.3, 1e-6 * 1200 / 0.3);
  EXPECT_NEAR(facade.px_per_unit, 1200 / 20.0, 1e-6 * 1200 / 20.0);
  EXPECT_NEAR(rock.L, 50 * 0.3 / 1200, 1e-6 * rock.L);
  EXPECT_NEAR(facade.L, 50 * 20.0 / 1200, 1e-6 * facade.L);
  // The same leaves within a factor of 2 though the meshes differ 67 times in size.
  EXPECT_LT(std::max(rock.p90, facade.p90) / std::min(rock.p90, facade.p90), 2.0);
}

TEST(IvyLeafSize, AnObjNamesNoUnitSoItsLeavesFollowItsBounds) {
  const SizedIvy rock = GrowBunny(0.3, 0), facade = GrowBunny(20, 0);
  EXPECT_EQ(rock.look_px_per_unit, rock.px_per_unit);
  EXPECT_NEAR(rock.leaf_size, 75 * 0.3 / 1200, 1e-6 * rock.leaf_size);
  EXPECT_NEAR(facade.leaf_size, 75 * 20.0 / 1200, 1e-6 * facade.leaf_size);
  EXPECT_NEAR(facade.r_tip, 1.5 * 20.0 / 1200, 1e-6 * facade.r_tip);
  // A fixed share of the mesh: the measured widths scale with it (the moss-like carpet on a
  // small rock a glTF no longer gets).
  ASSERT_GT(rock.leaves, 100u);
  EXPECT_NEAR(facade.p90 / rock.p90, 20 / 0.3, 20 / 0.3 * 0.05);
  // "scale" given (the CLI's --units m, the page's Scale row): every length row, leaves too.
  const std::string path = std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/bunny.obj";
  Result<geom::TriMesh> mesh = io::ReadMeshFile(path);
  ASSERT_TRUE(mesh.ok());
  Result<std::shared_ptr<const IvySupport>> support =
      IvySupport::Prepare(IvySupportInput::Mesh(*mesh, "bunny", {}, 1), {}, Budget{});
  ASSERT_TRUE(support.ok());
  IvyParams declared;
  ASSERT_TRUE(declared.Set(IvyParam::kScale, 10).ok());  // cm
  Result<IvyParams> scaled = (*support)->Scaled(declared);
  ASSERT_TRUE(scaled.ok());
  EXPECT_EQ(scaled->Get(IvyParam::kLeafSize), 5.0);
  EXPECT_EQ(scaled->Get(IvyParam::kL), 5.0);
}

// The row leaf_spacing (artist: 50 px, 5 cm on a glTF): where the growth is scaled to the mesh's
// bounds and the leaves are in metres, a 0.3 m rock's 1.25 cm internodes share a leaf (a quarter
// of the buds keep one) and a 20 m facade's 83 cm internodes carry 8 (the cap; 16.7 would be 5 cm
// apart), so both have leaves a few centimetres of stem apart instead of a heap and a scatter.
// leaf_light 0 here: no leaf thinned by light, so the counts are the spacing's alone.
TEST(IvyLeafSize, AGltfsLeavesAreARealStemLengthApart) {
  const SizedIvy rock = GrowBunny(0.3, 1, {{"leaf_light", 0}});
  const SizedIvy facade = GrowBunny(20, 1, {{"leaf_light", 0}});
  const SizedIvy rock_one = GrowBunny(0.3, 1, {{"leaf_light", 0}, {"leaf_spacing", 0}});
  for (const SizedIvy* g : {&rock, &facade, &rock_one}) {
    std::printf("[ spacing  ] %zu leaves on %zu buds, %.3f scene units of stem: %.4f a leaf\n",
                g->drawn, g->leafy_buds, g->stem_length,
                g->stem_length / static_cast<double>(std::max<std::size_t>(g->drawn, 1)));
    ASSERT_GT(g->leafy_buds, 100u);
  }
  // leaf_spacing 0: one leaf a bud (the paper), a leaf every 1.25 cm of stem on the rock.
  EXPECT_EQ(rock_one.drawn, rock_one.leafy_buds);
  // The rock: each bud keeps its leaf with probability n = 0.25 (a hash of its id).
  const double kept = static_cast<double>(rock.drawn) / static_cast<double>(rock.leafy_buds);
  EXPECT_GT(kept, 0.18);
  EXPECT_LT(kept, 0.32);
  EXPECT_GT(rock.stem_length / static_cast<double>(rock.drawn), 0.035);
  EXPECT_LT(rock.stem_length / static_cast<double>(rock.drawn), 0.07);
  // The facade: 8 leaves a bud, about 10 cm of stem apart.
  EXPECT_EQ(facade.drawn, 8 * facade.leafy_buds);
  EXPECT_GT(facade.stem_length / static_cast<double>(facade.drawn), 0.07);
  EXPECT_LT(facade.stem_length / static_cast<double>(facade.drawn), 0.14);
}

// Where the growth and the leaves share a scale (a built-in scene, an OBJ, a tree), L / s_n is
// exactly 1 with artist's 50 / 50 px: one leaf a bud, the same leaves as without the row.
TEST(IvyLeafSize, OneScaleMeansOneLeafABudAsBefore) {
  const SizedIvy obj = GrowBunny(0.3, 0, {{"leaf_light", 0}});
  EXPECT_EQ(obj.drawn, obj.leafy_buds);
}

}  // namespace
}  // namespace niwa::ivy

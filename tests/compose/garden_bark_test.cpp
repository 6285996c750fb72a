// Simulated bark per trunk in the garden (core/compose/garden_bark, issue 33 items 1, 3, 5): each
// distinct tree's bark is the bark study run on that tree's own trunk history (the radii equal a
// lone growth's, recorded year by year with its nursery years), so a tree of another age and
// species gets other maps; the garden .glb's "bark" material of each tree carries that tree's maps
// while every vertex position stays bark 0's; the least cost is refused up front naming "bark"; a
// map size that is not a power of two names bark_map_size.
#include "compose/garden_bark.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "bark/bark_params.h"
#include "compose/garden_run.h"
#include "compose/garden_state.h"
#include "compose/garden_view.h"
#include "render/tree_run.h"
#include "tree/tree_state.h"

namespace niwa::compose {
namespace {

// Two hand-placed trees far apart (each its own growth, no shade), a flat ground, small maps.
GardenState TwoTrees(const GardenPlant& a, const GardenPlant& b, int years, int bark) {
  GardenState s = DefaultGardenState();
  s.default_layout = false;
  s.objects.clear();
  s.ivy_on.clear();
  s.ground = GroundKind::kFlat;
  s.plants = {a, b};
  EXPECT_TRUE(s.params.Set(GardenParam::kSize, 30).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kGroundRes, 16).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kShade, 0).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMaxTriangles, 1500).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kYears, years).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kBark, bark).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());  // the moss is not this test's
  return s;
}

// The trunk of `species` (seed, grown `years` alone) at `height_m`, year by year.
TrunkHistory LoneTrunk(const std::string& species, uint64_t seed, int years, double height_m) {
  TreeState ts;
  EXPECT_TRUE(SetStatePreset(species, &ts).ok());
  EXPECT_TRUE(SetStateSeed(static_cast<double>(seed), &ts).ok());
  EXPECT_TRUE(SetStateYears(years, &ts).ok());
  Result<TreeRun> run = TreeRun::Start(ts, Budget{});
  EXPECT_TRUE(run.ok());
  TrunkHistory h;
  h.height_m = height_m;
  while (run->done() < years && run->GrowYear()) RecordTrunkYear(run->tree(), &h);
  return h;
}

// The PNG bytes of texture `t` of the document.
std::string Png(const gltf::Document& doc, int t) {
  if (t < 0) return "";
  const std::vector<unsigned char>& p = doc.textures[static_cast<std::size_t>(t)].png;
  return std::string(p.begin(), p.end());
}

TEST(GardenBark, EachTreesBarkIsFromItsOwnTrunkHistory) {
  // A pine planted at 3 years and a sakura seedling, 4 garden years: the pine's nursery years
  // count.
  const GardenState s = TwoTrees({"pine", 2, 3, -8, 0, 0}, {"sakura", 1, 0, 8, 0, 0}, 4, 1);
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  ASSERT_TRUE(run->Advance({}).ok());
  ASSERT_EQ(run->groups().size(), 2u);
  const GardenBarks& barks = run->barks();
  ASSERT_EQ(barks.trees.size(), 2u);
  EXPECT_EQ(barks.simulated(), 2) << run->StatsJson();
  for (std::size_t g = 0; g < 2; ++g) {
    const GardenTreeGroup& group = run->groups()[g];
    const GardenBark& b = barks.trees[g];
    ASSERT_TRUE(b.frame) << group.name << ": " << b.procedural_why;
    EXPECT_EQ(b.species, GardenBarkSpecies(group.species));
    // The radii the bark ran on are the tree's own: a lone growth of the same tree, its nursery
    // and garden years, recorded at the bark's height.
    const TrunkHistory lone = LoneTrunk(group.species, group.seed, group.age + 4, b.height_m);
    ASSERT_EQ(lone.years.size(), static_cast<std::size_t>(group.age + 4)) << group.name;
    std::vector<double> radii;
    for (const TrunkYear& y : lone.years)
      if (y.year >= b.plan.first_year && y.year <= b.plan.last_year) radii.push_back(y.radius_cm);
    EXPECT_EQ(b.plan.last_year, group.age + 4) << group.name;
    EXPECT_EQ(b.plan.radii_cm, radii) << group.name;
    // The surface's strain is the tree's own, below both its limits (no ceiling reached:
    // docs/bark-model.md, "On Niwa's trees" item 4).
    const double dr = b.plan.state.params.Get(bark::BarkParam::kDeltaR);
    EXPECT_NEAR(dr, SurfaceStrain(b.plan.hoop_strain, b.plan.turnover_strain), 1e-15);
    EXPECT_LT(dr, b.plan.hoop_strain) << group.name;
    EXPECT_LT(dr, b.plan.turnover_strain) << group.name;
  }
  EXPECT_EQ(barks.trees[0].species, "pine");
  EXPECT_EQ(barks.trees[1].species, "tallow");
  // Two species and ages: other histories, other maps.
  EXPECT_NE(barks.trees[0].plan.radii_cm, barks.trees[1].plan.radii_cm);
  EXPECT_NE(barks.trees[0].frame->hash, barks.trees[1].frame->hash);
  EXPECT_NE(barks.trees[0].frame->base_colour, barks.trees[1].frame->base_colour);
  const nlohmann::json stats = nlohmann::json::parse(run->StatsJson());
  EXPECT_EQ(stats["bark"]["simulated"], 2);
  EXPECT_EQ(stats["bark"]["species"]["pine"], 1);
  EXPECT_EQ(stats["bark"]["species"]["tallow"], 1);
}

TEST(GardenBark, BarkOneChangesOnlyTheBarkAndWearsItsMaps) {
  GardenState s = TwoTrees({"keyaki", 1, 2, -8, 0, 0}, {"keyaki", 1, 2, 8, 0, 0}, 3, 0);
  s.plants.pop_back();
  Result<GardenRun> plain = GardenRun::Start(s, {});
  ASSERT_TRUE(s.params.Set(GardenParam::kBark, 1).ok());
  Result<GardenRun> sim = GardenRun::Start(s, {});
  ASSERT_TRUE(plain.ok() && sim.ok());
  ASSERT_TRUE(plain->Advance({}).ok());
  ASSERT_TRUE(sim->Advance({}).ok());
  EXPECT_FALSE(plain->barks().on);
  EXPECT_TRUE(plain->barks().trees.empty());
  EXPECT_EQ(nlohmann::json::parse(plain->StatsJson()).count("bark"), 0u);
  ASSERT_EQ(sim->barks().simulated(), 1) << sim->StatsJson();
  const BarkFrame& f = *sim->barks().trees[0].frame;
  Result<gltf::Document> p = plain->Document(), q = sim->Document();
  ASSERT_TRUE(p.ok() && q.ok());
  // The same nodes, meshes and vertices; only the bark's UVs and textures differ.
  ASSERT_EQ(p->nodes.size(), q->nodes.size());
  ASSERT_EQ(p->meshes.size(), q->meshes.size());
  int bark_primitives = 0, moved_uvs = 0;
  for (std::size_t m = 0; m < p->meshes.size(); ++m) {
    ASSERT_EQ(p->meshes[m].primitives.size(), q->meshes[m].primitives.size());
    for (std::size_t k = 0; k < p->meshes[m].primitives.size(); ++k) {
      const gltf::Primitive &x = p->meshes[m].primitives[k], &y = q->meshes[m].primitives[k];
      EXPECT_EQ(x.mesh.positions, y.mesh.positions) << p->meshes[m].name;
      EXPECT_EQ(x.mesh.indices, y.mesh.indices);
      const bool bark = p->materials[static_cast<std::size_t>(x.material)].name == "bark";
      bark_primitives += bark ? 1 : 0;
      if (!bark) {
        EXPECT_EQ(x.mesh.uvs, y.mesh.uvs) << p->meshes[m].name;
      }
      if (bark && x.mesh.uvs != y.mesh.uvs) ++moved_uvs;
    }
  }
  EXPECT_EQ(bark_primitives, 1);
  EXPECT_EQ(moved_uvs, 1) << "the ring UVs wrap the simulated tile";
  for (const gltf::Material& m : p->materials) EXPECT_LT(m.occlusion_texture, 0) << m.name;
  // The tree's "bark" material wears its own maps: colour, normal, occlusion.
  int dressed = 0;
  for (const gltf::Material& m : q->materials) {
    if (m.name == "bark" && Png(*q, m.base_color_texture) == f.base_colour &&
        Png(*q, m.normal_texture) == f.normal && Png(*q, m.occlusion_texture) == f.orm)
      ++dressed;
  }
  EXPECT_EQ(dressed, 1);
  // The page's view of it (compose/garden_view): the group's frame, its two maps decoded from the
  // PNGs the .glb carries, the page mesh's bark UVs wrapping its tile; with bark 0, none of them.
  EXPECT_EQ(GardenGroupBark(*sim, 0), &f);
  EXPECT_EQ(GardenGroupBark(*plain, 0), nullptr);
  const Result<image::Rgba8Image> colour = GardenGroupBarkImage(*sim, 0, false);
  const Result<image::Rgba8Image> normal = GardenGroupBarkImage(*sim, 0, true);
  ASSERT_TRUE(colour.ok() && normal.ok());
  // The map's longer side is map_size (a power of two either way, GrowOldBark): a thin trunk's
  // tall tile gets a narrower map, its texels about square on the trunk.
  const int size = sim->barks().map_size;
  EXPECT_LT(colour->width, size) << "this 3-year trunk's tile is taller than it is wide";
  EXPECT_GE(std::max(colour->width, colour->height), size / 2);
  EXPECT_LE(std::max(colour->width, colour->height), 2 * size);
  const double texel_aspect = (f.tile_width_m / colour->width) / (f.tile_height_m / colour->height);
  EXPECT_GT(texel_aspect, 0.5) << colour->width << " x " << colour->height;
  EXPECT_LT(texel_aspect, 2.0) << colour->width << " x " << colour->height;
  EXPECT_TRUE(f.height.empty()) << "the garden reads no height map";
  // The far tree's line colour (C_b in the hybrid view): the map's mean, a bark's dull colour.
  EXPECT_EQ(f.mean_colour,
            image::MeanLinearRgb(f.colour_pixels.empty() ? *colour : f.colour_pixels));
  for (double c : f.mean_colour) {
    EXPECT_GT(c, 0.005);
    EXPECT_LT(c, 0.8);
  }
  EXPECT_EQ(colour->pixels.size(), static_cast<std::size_t>(4 * colour->width * colour->height));
  EXPECT_NE(colour->pixels, normal->pixels);
  EXPECT_EQ(GardenGroupBarkImage(*plain, 0, false).status().field(), "bark");
  const TreeMesh mesh = GardenGroupMesh(*sim, 0);
  const std::vector<float> uvs = GardenGroupBarkUvs(*sim, 0, sim->done(), mesh);
  EXPECT_EQ(uvs.size(), mesh.bark.uvs.size());
  EXPECT_NE(uvs, mesh.bark.uvs);
  EXPECT_TRUE(GardenGroupBarkUvs(*plain, 0, plain->done(), GardenGroupMesh(*plain, 0)).empty());
}

TEST(GardenBark, RefusedUpFrontNamingBarkAndBadMapSizeNamed) {
  GardenState s = TwoTrees({"pine", 1, 0, -8, 0, 0}, {"sakura", 1, 0, 8, 0, 0}, 3, 1);
  Budget tight;
  tight.seconds = 0.05;  // the maps alone (256 px wide, up to 4096 rows) take longer
  const Result<GardenRun> refused = GardenRun::Start(s, tight);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().field(), "bark") << refused.status().Line();
  ASSERT_TRUE(s.params.Set(GardenParam::kBark, 0).ok());
  EXPECT_TRUE(GardenRun::Start(s, tight).ok()) << "bark 0: nothing to refuse";
  ASSERT_TRUE(s.params.Set(GardenParam::kBark, 1).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kBarkMapSize, 300).ok());
  const Result<GardenRun> bad = GardenRun::Start(s, Budget{});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().field(), "bark_map_size") << bad.status().Line();
}

}  // namespace
}  // namespace niwa::compose

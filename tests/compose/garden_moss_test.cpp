// Moss in the garden (core/compose/garden_moss, GardenRun's moss): the land is the ground and the
// objects; the canopy is the trees' leaf spheres where the trees stand; under a crown the moss's
// light falls against the same garden with moss_shade 0, cell for cell; moss_days 0 grows none;
// the moss's state rides in the garden's JSON and link; the tufts are in the .glb; the moss's
// estimate counts its work.
#include "compose/garden_moss.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "compose/garden_run.h"
#include "compose/garden_state.h"
#include "geom/primitives.h"
#include "geom/radius_grid.h"
#include "io/gltf_writer.h"
#include "light/sun.h"
#include "math/det_math.h"
#include "moss/photons.h"

namespace niwa::compose {
namespace {

// A flat 12 m garden, one sakura by hand at the centre (4 years old), a rock east of it, moss for
// 5 years × 12 days at 4,096 photons a day.
GardenState MossGarden(bool shade) {
  GardenState s = DefaultGardenState();
  s.ground = GroundKind::kFlat;
  EXPECT_TRUE(s.params.Set(GardenParam::kSize, 12).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kGroundRes, 24).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kYears, 5).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMossDays, 12).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kMossShade, shade ? 1 : 0).ok());
  EXPECT_TRUE(s.moss.params.Set(moss::MossParam::kPhotons, 4096).ok());
  s.default_layout = false;
  s.objects = {{"rock", 3.5, 0, 0, 1}};
  s.plants = {{"sakura", 1, 4, 0, 0, 0}};
  s.ivy_on.clear();
  return s;
}

GardenRun Grown(const GardenState& s) {
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  EXPECT_TRUE(run.ok()) << run.status().Line();
  EXPECT_TRUE(run->Advance(nullptr).ok());
  return std::move(*run);
}

TEST(GardenMoss, TheLandIsTheGroundAndTheObjects) {
  const GardenState s = MossGarden(true);
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok());
  const moss::MossScene land = GardenMossLand(*scene);
  const std::size_t ground = scene->ground.Mesh().triangle_count();
  ASSERT_EQ(land.mesh.triangle_count(), ground + scene->objects[0].mesh.triangle_count());
  ASSERT_EQ(land.region.size(), land.mesh.triangle_count());
  EXPECT_EQ(land.region_names[land.region.front()], "ground");
  EXPECT_EQ(land.region_names[land.region.back()], "rock");
  EXPECT_EQ(land.geology.front(), moss::Geology::kHumus);
  EXPECT_EQ(land.geology.back(), moss::Geology::kAsphalt);
  EXPECT_EQ(land.region_names.size(), 4u);  // no mesh object: the four regions
  // A dropped mesh object is its own region, "mesh", not the lanterns'.
  GardenState with_mesh = s;
  GardenObject o("mesh", 2, 1, 0, 1);
  o.file = "box.obj";
  o.mesh = geom::MakeBox({0.5f, 0.5f, 0.5f}, {0.0f, 0.5f, 0.0f});
  with_mesh.objects.push_back(o);
  Result<GardenScene> meshed = BuildGardenScene(with_mesh, Budget{});
  ASSERT_TRUE(meshed.ok()) << meshed.status().Line();
  const moss::MossScene land2 = GardenMossLand(*meshed);
  ASSERT_EQ(land2.region_names.size(), 5u);
  EXPECT_EQ(land2.region_names[land2.region.back()], "mesh");
}

// A ground finer than kMossGroundCells a side is resampled for the moss: 128 cells a side whose
// vertices lie on the garden's ground; the light overlay still covers every vertex of the fine
// grid. At 128 or fewer the moss's ground is the garden's own (the default garden's bytes).
TEST(GardenMoss, AFineGroundIsResampledForTheMoss) {
  GardenState s = MossGarden(true);
  s.ground = GroundKind::kTerrain;
  ASSERT_TRUE(s.params.Set(GardenParam::kGroundRes, 300).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 1).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kMossDays, 2).ok());
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok()) << scene.status().Line();
  ASSERT_EQ(scene->ground.n, 300);
  const GardenGround coarse = MossGround(scene->ground);
  ASSERT_EQ(coarse.n, kMossGroundCells);
  EXPECT_DOUBLE_EQ(coarse.size, scene->ground.size);
  ASSERT_GT(scene->ground.relief, 0.1);  // a terrain: the heights matter
  for (int j = 0; j <= coarse.n; j += 7)
    for (int i = 0; i <= coarse.n; i += 5) {
      const double x = -coarse.size / 2 + i * coarse.cell, z = -coarse.size / 2 + j * coarse.cell;
      EXPECT_DOUBLE_EQ(coarse.At(i, j), scene->ground.HeightAt(x, z));
    }
  const moss::MossScene land = GardenMossLand(*scene);
  EXPECT_EQ(land.mesh.triangle_count(),
            2u * kMossGroundCells * kMossGroundCells + scene->objects[0].mesh.triangle_count());
  const GardenRun run = Grown(s);
  ASSERT_NE(run.moss(), nullptr);
  const std::vector<float> light = GardenMossGroundLight(*run.moss(), run.scene().ground);
  ASSERT_EQ(light.size(), 301u * 301u);
  // Every fine vertex reads the light, the corners too: no triangle's centroid is nearest the moss
  // grid's (0, 0) and (n, n) corners (each cell's two triangles bin to its (i + 1, j) and
  // (i, j + 1) corners), so they read their neighbours' cells.
  std::size_t none = 0;
  for (const float v : light) none += v < 0 ? 1 : 0;
  EXPECT_EQ(none, 0u);
  EXPECT_GE(light.front(), 0.0f);
  EXPECT_GE(light.back(), 0.0f);
  EXPECT_GE(light[150 * 301 + 150], 0.0f);
  // At ground_res 24 (≤ 128) the moss's ground is the garden's, vertex for vertex.
  Result<GardenScene> small = BuildGardenScene(MossGarden(true), Budget{});
  ASSERT_TRUE(small.ok());
  EXPECT_EQ(MossGround(small->ground).h, small->ground.h);
  EXPECT_EQ(MossGround(small->ground).n, small->ground.n);
}

TEST(GardenMoss, TheCanopyShadesTheMossUnderTheCrown) {
  const GardenRun shaded = Grown(MossGarden(true));
  const GardenRun open = Grown(MossGarden(false));
  ASSERT_NE(shaded.moss(), nullptr);
  ASSERT_NE(open.moss(), nullptr);
  EXPECT_EQ(shaded.moss()->world().day, 60);
  const moss::CanopyShade* canopy = shaded.moss()->canopy();
  ASSERT_NE(canopy, nullptr);
  EXPECT_GT(canopy->size(), 20u);
  EXPECT_EQ(open.moss()->canopy(), nullptr);
  // The canopy's spheres are where the tree's leaves are: over the trunk, above the ground.
  double lowest = 1e9, far = 0;
  for (const moss::CanopySphere& c : canopy->spheres()) {
    lowest = std::min(lowest, c.centre.y);
    far = std::max(far, std::hypot(c.centre.x, c.centre.z));
  }
  EXPECT_GT(lowest, 0.2);
  EXPECT_LT(far, 4.0);
  // The same cells (one land) in the crown's shade (the path to the sun, 55° in the south,
  // crosses more than one optical depth of leaves): the light with the leaves against without.
  const glm::dvec3 sun = glm::normalize(glm::dvec3(light::SunDirection(55, 90)));
  const moss::SoilCells& cells = shaded.moss()->cells();
  ASSERT_EQ(cells.size(), open.moss()->cells().size());
  double with = 0, without = 0, far_with = 0, far_without = 0;
  int under = 0, away = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (cells.region[i] != 0) continue;
    const double depth = canopy->OpticalDepth(cells.centroid[i], sun, 1e9);
    if (depth > 1.0) {
      with += shaded.moss()->world().S[i];
      without += open.moss()->world().S[i];
      ++under;
    } else if (depth == 0.0 && std::hypot(cells.centroid[i].x, cells.centroid[i].z) > 4.5) {
      far_with += shaded.moss()->world().S[i];
      far_without += open.moss()->world().S[i];
      ++away;
    }
  }
  ASSERT_GT(under, 5);
  ASSERT_GT(away, 50);
  EXPECT_LT(with, 0.6 * without) << "under the crown: " << with / under << " against "
                                 << without / under << " W/m² without leaves";
  // Away from the crown the light is about the same (the gather's noise, and the sky the crown
  // hides low over the horizon).
  EXPECT_NEAR(far_with / far_without, 1.0, 0.1);
  // The stats split the ground by the crowns.
  const nlohmann::json j = nlohmann::json::parse(shaded.StatsJson());
  ASSERT_TRUE(j.contains("moss"));
  EXPECT_GT(j["moss"]["ground_in_crown_shade"]["area_m2"].get<double>(), 1.0);
  EXPECT_LT(j["moss"]["ground_in_crown_shade"]["mean_S"].get<double>(),
            j["moss"]["ground_open"]["mean_S"].get<double>());
  EXPECT_GT(j["moss"]["canopy"]["photons_intercepted"].get<double>(), 0);
}

TEST(GardenMoss, NoMossDaysNoMoss) {
  GardenState s = MossGarden(true);
  ASSERT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());
  const GardenRun run = Grown(s);
  EXPECT_EQ(run.moss(), nullptr);
  EXPECT_FALSE(nlohmann::json::parse(run.StatsJson()).contains("moss"));
}

TEST(GardenMoss, OverTheBudgetTheMossIsRefusedUpFrontNamingMossDays) {
  Budget tight;
  tight.seconds = 0.05;
  const Result<GardenRun> refused = GardenRun::Start(MossGarden(true), tight);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().field(), "moss_days") << refused.status().Line();
  EXPECT_NE(refused.status().Line().find("set moss_days 0"), std::string::npos)
      << refused.status().Line();
  GardenState none = MossGarden(true);
  ASSERT_TRUE(none.params.Set(GardenParam::kMossDays, 0).ok());
  EXPECT_TRUE(GardenRun::Start(none, tight).ok()) << "without moss the trees fit";
}

// One budget: the ivy gets what the trees' growth and the moss's whole run left of it.
TEST(GardenMoss, TheIvyGetsWhatTheTreesAndTheMossLeft) {
  GardenState s = MossGarden(true);
  s.ivy_on = {"objects[0]"};
  ASSERT_TRUE(s.params.Set(GardenParam::kIvySteps, 10).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 2).ok());
  Budget budget;
  budget.seconds = 1000;
  Result<GardenRun> within = GardenRun::Start(s, budget);
  ASSERT_TRUE(within.ok()) << within.status().Line();
  ASSERT_TRUE(within->Advance(nullptr).ok());
  double trees = 0;
  for (const GardenTreeGroup& g : within->groups()) trees += g.run->grown().seconds;
  const double moss = within->moss()->RunEstimate().seconds;
  EXPECT_DOUBLE_EQ(moss, within->moss_estimate().seconds);
  EXPECT_GT(moss, 0.0);
  EXPECT_DOUBLE_EQ(within->ivy_budget().seconds, budget.seconds - moss - trees);
}

// The moss's time estimate against the work its counts stand for (deterministic: no clock is read;
// the seconds a unit takes are measured in scripts/bench and docs/garden-model.md "The moss's
// estimate"). The run's estimate is the garden's figures (GardenMossCosts) on its cells and land;
// it is linear in the days (each day the same work); and the density it assumes under the
// gather's 1 m disc (cells and photons × π r² / the land's area) bounds what a day's photons
// actually meet: the next day's stored photons, each with the cells whose centre is within
// r_gather of it (the soil's spread), and each cell with the photons within r_gather of its centre
// (a moss's gather there).
TEST(GardenMoss, TheMossEstimateCountsItsWork) {
  GardenState s = MossGarden(true);
  ASSERT_TRUE(s.moss.params.Set(moss::MossParam::kRGather, 1).ok());
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  const moss::MossRun& m = *run->moss();
  const moss::MossCosts costs = GardenMossCosts();
  EXPECT_EQ(m.costs().photon, costs.photon);
  const double cells = static_cast<double>(m.cells().size());
  const double area = m.land_area();
  EXPECT_GT(area, 144.0);  // the 12 m square and the rock
  const Estimate e = moss::MossRun::RunEstimate(m.state(), m.cells().size(), area, costs);
  EXPECT_DOUBLE_EQ(run->moss_estimate().seconds, e.seconds);
  EXPECT_LT(e.seconds, moss::MossRun::RunEstimate(m.state(), m.cells().size()).seconds)
      << "the study's provisional figures count more than the garden measured";
  // Linear in the days: the same day's work each day, the cells' build once.
  moss::MossState half = m.state(), none = m.state();
  half.days = m.state().days / 2;
  none.days = 0;
  ASSERT_EQ(2 * half.days, m.state().days);
  const auto at = [&](const moss::MossState& st) {
    return moss::MossRun::RunEstimate(st, m.cells().size(), area, costs).seconds;
  };
  EXPECT_NEAR(at(m.state()) - at(half), at(half) - at(none), 1e-9 * e.seconds);
  EXPECT_NEAR(
      at(none),
      cells * (costs.cell_build + costs.cell_list * std::min(96.0, cells * det::kPi / area)),
      1e-9 * e.seconds);
  // The density under the disc, against a day's photons counted where they are.
  const double r = 1, share = det::kPi * r * r / area;
  const moss::PhotonMap day = m.NextDayPhotons();
  const double photons = m.state().params.Get(moss::MossParam::kPhotons);
  ASSERT_GT(day.photons.size(), 0.2 * photons);
  const geom::RadiusGrid by_cell(m.cells().centroid, r);
  std::vector<glm::dvec3> stored;
  for (const moss::Photon& ph : day.photons) stored.push_back(ph.position);
  const geom::RadiusGrid by_photon(stored, r);
  double pairs = 0, near_cell = 0;
  for (const moss::Photon& ph : day.photons)
    if (!ph.on_moss) by_cell.ForEachWithin(ph.position, [&](uint32_t, double) { ++pairs; });
  for (const glm::dvec3& c : m.cells().centroid)
    by_photon.ForEachWithin(c, [&](uint32_t, double) { ++near_cell; });
  near_cell /= cells;
  // Every emitted photon counted with the disc's cells: at least the stored photons' pairs, not
  // four times them (2.3 here; a path stores 0.44 photons on the measured gardens).
  EXPECT_LE(pairs, photons * cells * share);
  EXPECT_GE(4 * pairs, photons * cells * share);
  // A moss's gather: the emitted photons in a disc, at least the stored ones near a cell's centre
  // (2.3 times them here).
  EXPECT_LE(near_cell, photons * share);
  EXPECT_GE(4 * near_cell, photons * share);
}

TEST(GardenMoss, TheMossStateRidesInTheJsonAndTheLink) {
  GardenState s = MossGarden(true);
  // The garden's defaults write nothing of the moss.
  EXPECT_EQ(GardenStateJson(DefaultGardenState()).find("\"moss\""), std::string::npos);
  EXPECT_EQ(EncodeGardenHash(DefaultGardenState()).find("moss."), std::string::npos);
  ASSERT_TRUE(s.moss.params.Set(moss::MossParam::kT, 290).ok());
  const std::string hash = EncodeGardenHash(s, "");
  EXPECT_NE(hash.find("moss.T=290"), std::string::npos) << hash;
  GardenState back = DefaultGardenState();
  std::vector<std::string> notices;
  ApplyGardenHash(hash, "", &back, &notices);
  EXPECT_TRUE(notices.empty()) << notices.front();
  EXPECT_EQ(moss::MossStateJson(back.moss), moss::MossStateJson(s.moss));
  GardenState from_json = DefaultGardenState();
  ASSERT_TRUE(ApplyGardenStateJson(GardenStateJson(s), &from_json).ok());
  EXPECT_EQ(moss::MossStateJson(from_json.moss), moss::MossStateJson(s.moss));
  // A bad moss row names itself under "moss".
  GardenState bad = DefaultGardenState();
  const Status st = ApplyGardenStateJson(R"({"moss": {"params": {"photons": -1}}})", &bad);
  ASSERT_FALSE(st.ok());
  EXPECT_EQ(st.field().rfind("moss", 0), 0u) << st.Line();
}

TEST(GardenMoss, TheTuftsAreInTheGlb) {
  const GardenRun run = Grown(MossGarden(true));
  ASSERT_GT(run.moss()->world().mosses.size(), 0u);
  Result<gltf::Document> doc = run.Document();
  ASSERT_TRUE(doc.ok());
  bool found = false;
  for (const gltf::Node& n : doc->nodes)
    if (n.name == "moss_tufts") {
      found = true;
      const geom::TriMesh& m = doc->meshes[static_cast<std::size_t>(n.mesh)].primitives[0].mesh;
      EXPECT_GE(m.triangle_count(), run.moss()->world().mosses.size());
    }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace niwa::compose

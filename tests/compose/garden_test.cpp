// The garden (core/compose/garden_*): its state JSON and hash round trips and their errors naming
// the field; the ground's heights against a ray cast down onto its own drawn triangles (the twin);
// objects and trees standing on the surface (within 2 cm); the planting rules' spacing, altitude
// band, slope limit, mask and objects each kept, every dart counted once; a hand-placed tree in a
// wall refused naming plants[i].pos; the run's groups (copies share one growth when no neighbour
// is within reach) and its clock; two trees 3 m apart leaning their crowns apart with shade on; ivy
// from the wall's foot climbing the wall, and an ivy seed naming nothing refused naming "ivy"; the
// ivy grown within what the trees left of the budget.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "compose/garden_plant.h"
#include "compose/garden_run.h"
#include "compose/garden_scene.h"
#include "compose/garden_state.h"
#include "geom/bvh.h"
#include "geom/mesh_metrics.h"
#include "geom/primitives.h"
#include "geom/ray_cast.h"
#include "image/png.h"
#include "ivy/ivy_budget.h"

namespace niwa::compose {
namespace {

GardenState SmallGarden() {
  GardenState s = DefaultGardenState();
  EXPECT_TRUE(s.params.Set(GardenParam::kSize, 30).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kGroundRes, 48).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kYears, 2).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kDensity, 0.05).ok());
  EXPECT_TRUE(s.params.Set(GardenParam::kSpacing, 2).ok());
  return s;
}

// The ground's height at (x, z) by a ray cast straight down onto its drawn triangles.
double CastDown(const geom::TriMesh& mesh, const geom::Bvh& bvh, double x, double z) {
  const geom::RayHit hit =
      geom::FirstHit(mesh, bvh, glm::vec3(x, 1000.0, z), glm::vec3(0, -1, 0), 5000.0f);
  EXPECT_TRUE(hit.hit);
  return hit.point.y;
}

TEST(Garden, StateJsonRoundTripsAndBadFieldsAreNamed) {
  GardenState s = SmallGarden();
  const std::string text = GardenStateJson(s);
  GardenState back;
  ASSERT_TRUE(ApplyGardenStateJson(text, &back).ok());
  EXPECT_EQ(GardenStateJson(back), text);
  const std::pair<const char*, const char*> bad[] = {
      {R"({"plants": [{"species": "oak", "pos": [0, 0]}]})", "plants[0].species"},
      {R"({"plants": [{"species": "pine", "pos": [0]}]})", "plants[0].pos"},
      {R"({"plants": [{"species": "pine", "pos": [0, 99]}]})", "plants[0].pos"},
      {R"({"plants": [{"species": "pine", "pos": [0, 0], "age": 2.5}]})", "plants[0].age"},
      {R"({"objects": [{"kind": "castle", "pos": [0, 0]}]})", "objects[0].kind"},
      {R"({"objects": [{"kind": "rock", "pos": [0, 0], "scale": 0}]})", "objects[0].scale"},
      {R"({"mix": {"pine": -1}})", "mix.pine"},
      {R"({"params": {"spacing": 0}})", "spacing"},
      {R"({"params": {"alt_min": 9, "alt_max": 3}})", "alt_min"},
      {R"({"ground": {"kind": "lava"}})", "ground.kind"},
      {R"({"ground": {"terrain": {"preset": "nope"}}})", "ground.terrain"},
      {R"({"trees": []})", "trees"},
  };
  for (const auto& [json, field] : bad) {
    GardenState t = SmallGarden();
    const Status st = ApplyGardenStateJson(json, &t);
    ASSERT_FALSE(st.ok()) << json;
    EXPECT_EQ(st.field(), field) << st.Line();
    EXPECT_EQ(GardenStateJson(t), GardenStateJson(SmallGarden())) << "the state is unchanged";
  }
}

TEST(Garden, HashRoundTripsAndDropsBadItemsWithANotice) {
  GardenState s = SmallGarden();
  s.plants.push_back({"pine", 7, 3, 4.5, -2.25, 90});
  s.ground = GroundKind::kFlat;
  const std::string hash = EncodeGardenHash(s, "garden.");
  GardenState back = DefaultGardenState();
  std::vector<std::string> notices;
  ApplyGardenHash(hash, "garden.", &back, &notices);
  EXPECT_TRUE(notices.empty()) << notices.front();
  EXPECT_EQ(GardenStateJson(back), GardenStateJson(s));
  GardenState t = DefaultGardenState();
  ApplyGardenHash("plants=pine:1:0:0:0:0,oak:1:0:0:0:0&size=99999", "", &t, &notices);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_NE(notices[0].find("plants"), std::string::npos) << notices[0];
  EXPECT_EQ(t.plants.size(), DefaultGardenState().plants.size())
      << "a list with a bad item is dropped whole";
  EXPECT_EQ(t.params.Get(GardenParam::kSize), 1000) << "clamped into its range";
}

TEST(Garden, GroundHeightsAreItsDrawnTrianglesAndThingsStandOnThem) {
  const GardenState s = SmallGarden();
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok()) << scene.status().Line();
  const GardenGround& g = scene->ground;
  EXPECT_NEAR(g.relief, 6.0, 1e-9);
  const geom::TriMesh mesh = g.Mesh();
  const geom::Bvh bvh = geom::Bvh::Build(mesh);
  for (int k = 0; k < 200; ++k) {
    const double x = -14.9 + 29.8 * ((k * 37) % 200) / 200.0,
                 z = -14.9 + 29.8 * ((k * 91) % 200) / 200.0;
    EXPECT_NEAR(g.HeightAt(x, z), CastDown(mesh, bvh, x, z), 1e-3) << x << ", " << z;
  }
  for (const PlacedObject& o : scene->objects)
    EXPECT_NEAR(o.base_y, CastDown(mesh, bvh, o.x, o.z), 0.02) << o.kind;
  Result<Planting> planting = PlantGarden(s, *scene);
  ASSERT_TRUE(planting.ok());
  for (const PlacedTree& t : planting->trees)
    EXPECT_NEAR(t.y, CastDown(mesh, bvh, t.x, t.z), 0.02)
        << t.species << " at " << t.x << ", " << t.z;
}

// A mesh ground: its plan's square over the garden, the surface seen from above scaled to the
// relief: a square pyramid (apex at the centre) gives its height falling linearly to the rim, the
// highest hit wins over a lower sheet under it, and a hole in the mesh takes the lowest height hit.
TEST(Garden, AMeshGroundIsItsSurfaceFromAbove) {
  GardenState s = DefaultGardenState();
  s.ground = GroundKind::kMesh;
  s.heightmap_name = "pyramid.obj";
  ASSERT_TRUE(s.params.Set(GardenParam::kSize, 20).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kGroundRes, 20).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kRelief, 5).ok());
  s.default_layout = false;
  s.objects.clear();
  s.plants.clear();
  geom::TriMesh& m = s.ground_mesh;
  // A pyramid 4 units wide, 1 high, over x, z in [-2, 2], with its north-east quarter's face left
  // out (a hole), and a lower sheet at y = -3 under all of it.
  m.positions = {{-2, 0, -2},  {2, 0, -2},  {2, 0, 2},  {-2, 0, 2}, {0, 1, 0},
                 {-2, -3, -2}, {2, -3, -2}, {2, -3, 2}, {-2, -3, 2}};
  m.indices = {0, 4, 1, 2, 4, 3, 3, 4, 0, 5, 6, 7, 5, 7, 8};  // no 1-4-2 face (east)
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok()) << scene.status().Line();
  const GardenGround& g = scene->ground;
  EXPECT_EQ(g.source, "mesh pyramid.obj (5 triangles)");
  EXPECT_NEAR(g.relief, 5.0, 1e-9);
  // The apex at the centre; halfway to the west rim (x = -5 m: mesh x = -1) half its height above
  // the rim's; the east face is a hole: its ray meets the sheet 3 below the rim, the lowest hit
  // (0).
  EXPECT_NEAR(g.HeightAt(0, 0), 5.0, 1e-6);
  const double rim = g.HeightAt(-10, 0);
  EXPECT_NEAR(g.HeightAt(-5, 0), rim + (5.0 - rim) / 2, 1e-6);
  EXPECT_NEAR(g.HeightAt(5, 0), 0.0, 1e-6);
  EXPECT_NEAR(rim, 5.0 * 3 / 4, 1e-6);  // the sheet at -3, the apex at 1: the rim 3 of 4 up
  // No triangles: refused naming ground.file.
  s.ground_mesh = geom::TriMesh{};
  Result<GardenScene> none = BuildGardenScene(s, Budget{});
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.status().field(), "ground.file");
}

// A round mesh (here a diamond, a bowl dipping 1 to its centre) leaves the square's corners
// without a hit: they run on level from the rim, not down to the lowest height (a cliff).
TEST(Garden, AMeshGroundRunsOnLevelPastItsRim) {
  GardenState s = DefaultGardenState();
  s.ground = GroundKind::kMesh;
  s.heightmap_name = "bowl.obj";
  ASSERT_TRUE(s.params.Set(GardenParam::kSize, 20).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kGroundRes, 20).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kRelief, 4).ok());
  s.default_layout = false;
  s.objects.clear();
  s.plants.clear();
  s.ground_mesh.positions = {{-2, 0, 0}, {0, 0, -2}, {2, 0, 0}, {0, 0, 2}, {0, -1, 0}};
  s.ground_mesh.indices = {0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0};
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok()) << scene.status().Line();
  const GardenGround& g = scene->ground;
  EXPECT_NEAR(g.HeightAt(0, 0), 0.0, 1e-6);    // the bowl's bottom, the lowest
  EXPECT_NEAR(g.HeightAt(-10, 0), 4.0, 1e-6);  // the rim, the relief
  // Every corner of the square lies outside the diamond: at the rim's height, not the bottom's.
  for (const double x : {-10.0, 10.0})
    for (const double z : {-10.0, 10.0}) EXPECT_GT(g.HeightAt(x, z), 3.5) << x << ", " << z;
}

// A mesh as an object stands on the ground at its place by its bounds' base centre, wherever the
// mesh was modelled (here a box from y 5 to 6 around x 10.5, z -20.5), and its footprint refuses
// trees (Covers).
TEST(Garden, AMeshObjectStandsOnTheGroundWhereItIsPlaced) {
  GardenState s = DefaultGardenState();  // the default terrain ground
  s.default_layout = false;
  s.plants.clear();
  GardenObject o("mesh", 2, 1, 30, 2);
  o.file = "box.obj";
  o.mesh = geom::MakeBox({1.0f, 1.0f, 1.0f}, {10.5f, 5.5f, -20.5f});
  o.mesh.normals.clear();  // given none: made from its triangles
  s.objects = {o};
  ASSERT_TRUE(CheckGardenState(s).ok()) << CheckGardenState(s).Line();
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok()) << scene.status().Line();
  const PlacedObject& p = scene->objects[0];
  const geom::Bounds3 box = geom::MeshBounds(p.mesh);
  EXPECT_NEAR(box.min.y, scene->ground.HeightAt(2, 1), 1e-4);
  EXPECT_NEAR(box.max.y - box.min.y, 2.0, 1e-4);  // scale 2
  EXPECT_NEAR((box.min.x + box.max.x) / 2, 2.0, 1e-4);
  EXPECT_NEAR((box.min.z + box.max.z) / 2, 1.0, 1e-4);
  EXPECT_EQ(p.mesh.normals.size(), p.mesh.positions.size());
  EXPECT_TRUE(p.Covers(2, 1, 0));
  EXPECT_FALSE(p.Covers(5, 1, 0));
  // A mesh object's file rides in the state JSON; a built-in object has none.
  EXPECT_EQ(nlohmann::json::parse(GardenStateJson(s))["objects"][0]["file"], "box.obj");
  s.objects[0].kind = "rock";
  EXPECT_EQ(CheckGardenState(s).field(), "objects[0].file");
}

TEST(Garden, PlantingRulesKeepSpacingAltitudeSlopeAndObjects) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kAltMin, 1).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kAltMax, 5).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kSlopeMax, 24).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kSpacing, 2.5).ok());
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok());
  Result<Planting> p = PlantGarden(s, *scene);
  ASSERT_TRUE(p.ok()) << p.status().Line();
  const PlantingReport& r = p->report;
  EXPECT_EQ(r.target, 45);
  EXPECT_GT(r.by_rule, 5);
  EXPECT_EQ(r.candidates, r.by_rule + r.refused_mask + r.refused_altitude + r.refused_slope +
                              r.refused_object + r.refused_spacing);
  EXPECT_GT(r.refused_altitude, 0);
  EXPECT_GT(r.refused_slope, 0);
  EXPECT_GT(r.refused_spacing, 0);
  for (std::size_t a = 0; a < p->trees.size(); ++a) {
    const PlacedTree& t = p->trees[a];
    if (t.hand >= 0) continue;
    EXPECT_GE(t.y, 1.0);
    EXPECT_LE(t.y, 5.0);
    EXPECT_LE(scene->ground.SlopeAt(t.x, t.z), 24.0);
    for (const PlacedObject& o : scene->objects) EXPECT_FALSE(o.Covers(t.x, t.z, kTrunkClearance));
    for (std::size_t b = 0; b < p->trees.size(); ++b) {
      if (b == a) continue;
      EXPECT_GE(std::hypot(t.x - p->trees[b].x, t.z - p->trees[b].z), 2.5);
    }
  }
  // The same state plants the same trees; another seed others.
  Result<Planting> again = PlantGarden(s, *scene);
  EXPECT_EQ(PlantingJson(*again), PlantingJson(*p));
  ASSERT_TRUE(s.params.Set(GardenParam::kPlantSeed, 2).ok());
  EXPECT_NE(PlantingJson(*PlantGarden(s, *scene)), PlantingJson(*p));
}

TEST(Garden, AMaskKeepsTreesOffItsBlackHalf) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kSlopeMax, 90).ok());
  image::Rgba8Image mask;
  mask.width = 8, mask.height = 8;
  mask.pixels.assign(8 * 8 * 4, 255);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 4; ++x)  // the west half black
      for (int c = 0; c < 3; ++c) mask.pixels[4 * (y * 8 + x) + c] = 0;
  Result<std::vector<unsigned char>> png = image::EncodeRgba8Png(mask);
  ASSERT_TRUE(png.ok());
  s.mask_png = *png;
  s.mask_name = "half.png";
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  Result<Planting> p = PlantGarden(s, *scene);
  ASSERT_TRUE(p.ok()) << p.status().Line();
  EXPECT_GT(p->report.refused_mask, 0);
  EXPECT_GT(p->report.by_rule, 5);
  for (const PlacedTree& t : p->trees) {
    if (t.hand < 0) {
      EXPECT_GE(t.x, 0.0) << "a rule tree on the mask's black half";
    }
  }
  s.mask_png = {1, 2, 3};
  const Result<Planting> bad = PlantGarden(s, *scene);
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().field(), "mask");
}

// The heightmap's and the mask's bytes, checked as every front end reads them (the CLI's files, the
// page's opened ones): 16-bit samples kept, an 8-bit grey scaled, a colour heightmap, a non-PNG,
// a 1-pixel heightmap and a side over the cap each one line naming the field and the file; the
// files read through a front end's reader; a link of a masked garden says the mask is not carried.
TEST(Garden, HeightmapAndMaskFilesAreCheckedAndReadByName) {
  image::Gray16Image ramp = image::MakeGray16(3, 2);
  ramp.pixels = {0, 1, 65535, 2, 3, 40000};
  const std::vector<unsigned char> png16 = *image::EncodeGray16Png(ramp);
  Result<image::Gray16Image> h = DecodeGardenHeightmap("ramp.png", png16);
  ASSERT_TRUE(h.ok()) << h.status().Line();
  EXPECT_EQ(h->pixels, ramp.pixels) << "16-bit samples as stored";
  image::Rgba8Image rgb;
  rgb.width = 2, rgb.height = 2;
  rgb.pixels.assign(16, 200);
  const std::vector<unsigned char> colour = *image::EncodeRgba8Png(rgb);
  const Result<image::Gray16Image> c = DecodeGardenHeightmap("rgb.png", colour);
  ASSERT_FALSE(c.ok());
  EXPECT_EQ(c.status().Line(),
            "ground.file: 'rgb.png' is a colour (RGBA) PNG; must be a grey PNG (16-bit or 8-bit)");
  EXPECT_TRUE(DecodeGardenMask("rgb.png", colour).ok()) << "a mask may be in colour";
  const std::vector<unsigned char> text = {'n', 'o', 't', ' ', 'a', ' ', 'P', 'N', 'G'};
  EXPECT_EQ(DecodeGardenHeightmap("x.png", text).status().Line(),
            "ground.file: 'x.png': not a PNG file (no PNG signature); must be a grey PNG (16-bit "
            "or 8-bit)");
  EXPECT_EQ(DecodeGardenMask("x.png", text).status().field(), "mask");
  const std::vector<unsigned char> dot = *image::EncodeGray16Png(image::MakeGray16(1, 1));
  EXPECT_EQ(DecodeGardenHeightmap("dot.png", dot).status().Line(),
            "ground.file: 'dot.png' is 1 x 1 pixels; each side must be in 2..4096");
  EXPECT_TRUE(DecodeGardenMask("dot.png", dot).ok());
  const std::vector<unsigned char> wide =
      *image::EncodeGray16Png(image::MakeGray16(kMaxGardenImageSide + 1, 2));
  EXPECT_EQ(DecodeGardenMask("wide.png", wide).status().Line(),
            "mask: 'wide.png' is 4097 x 2 pixels; each side must be in 1..4096");
  // A file over kMaxGardenImageBytes is refused by its size before its chunks are read (a valid
  // PNG's bytes with zeros after them).
  std::vector<unsigned char> big = dot;
  big.resize(kMaxGardenImageBytes + 1, 0);
  EXPECT_EQ(DecodeGardenHeightmap("big.png", big).status().Line(),
            "ground.file: 'big.png' is 67,108,865 bytes; at most 67,108,864 (64 MB)");
  EXPECT_EQ(DecodeGardenMask("big.png", big).status().field(), "mask");
  big.resize(kMaxGardenImageBytes);
  EXPECT_TRUE(DecodeGardenMask("big.png", big).ok())
      << "at the limit the size passes (the bytes after IEND are not read)";
  // Read by name through the front end's reader, the field named.
  GardenState s = SmallGarden();
  ASSERT_TRUE(ApplyGardenStateJson(
                  R"({"ground": {"kind": "heightmap", "file": "ramp.png"}, "mask": "m.png"})", &s)
                  .ok());
  std::vector<std::string> asked;
  const Status read = LoadGardenImages(
      [&](const std::string& field, const std::string& file) -> Result<std::vector<unsigned char>> {
        asked.push_back(field + "=" + file);
        return png16;
      },
      &s);
  ASSERT_TRUE(read.ok()) << read.Line();
  EXPECT_EQ(asked, (std::vector<std::string>{"ground.file=ramp.png", "mask=m.png"}));
  EXPECT_EQ(s.heightmap_png, png16);
  EXPECT_EQ(s.mask_png, png16);
  const Status missing = LoadGardenImages(
      [](const std::string&, const std::string&) -> Result<std::vector<unsigned char>> {
        return Status::Error("", "gone");
      },
      &s);
  EXPECT_EQ(missing.Line(), "ground.file: gone");
  // A link cannot carry the files: ground=heightmap reads back flat and mask=1 as no mask, each
  // with a notice.
  const std::string hash = EncodeGardenHash(s);
  EXPECT_NE(hash.find("mask=1"), std::string::npos) << hash;
  GardenState back = DefaultGardenState();
  std::vector<std::string> notices;
  ApplyGardenHash(hash, "", &back, &notices);
  ASSERT_EQ(notices.size(), 2u);
  EXPECT_EQ(notices[0], "ground: a heightmap is not carried by a link; the ground is flat");
  EXPECT_EQ(notices[1], "mask: a density mask is not carried by a link (its file); no mask");
  EXPECT_TRUE(back.mask_name.empty());
  EXPECT_EQ(back.ground, GroundKind::kFlat);
}

TEST(Garden, AHandPlacedTreeInsideAnObjectIsRefusedNamingIt) {
  GardenState s = SmallGarden();
  s.plants = {{"keyaki", 1, 0, 0.5, -12, 0}};  // in the default wall at z = −12
  Result<GardenScene> scene = BuildGardenScene(s, Budget{});
  ASSERT_TRUE(scene.ok());
  const Result<Planting> p = PlantGarden(s, *scene);
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.status().field(), "plants[0].pos") << p.status().Line();
  EXPECT_NE(p.status().message().find("objects[0] (wall)"), std::string::npos);
}

TEST(Garden, CopiesShareOneGrowthAndTheClockGrowsEveryTree) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kShade, 0).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kVariants, 1).ok());
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  EXPECT_EQ(run->done(), 0);
  ASSERT_TRUE(run->Advance({}).ok());
  EXPECT_EQ(run->done(), 2);
  // One growth per (species, seed, age): the hand keyaki (age 5) and one per species of the mix.
  EXPECT_EQ(run->groups().size(), 4u);
  for (const GardenTreeGroup& g : run->groups()) EXPECT_EQ(g.run->done(), g.age + 2) << g.name;
  const nlohmann::json stats = nlohmann::json::parse(run->StatsJson());
  EXPECT_EQ(stats["trees"]["count"].get<std::size_t>(), run->planting().trees.size());
  EXPECT_EQ(stats["trees"]["distinct"], 4);
  // With shade on, trees within reach are grown on their own.
  ASSERT_TRUE(s.params.Set(GardenParam::kShade, 1).ok());
  Result<GardenRun> shaded = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(shaded.ok());
  EXPECT_GT(shaded->groups().size(), 4u);
}

TEST(Garden, TwoTreesThreeMetresApartLeanTheirCrownsApart) {
  // Issue 33 item 3's measure, through the garden: two sakura 3 m apart grown 10 years with shade
  // on and off (off: both are the one lone growth). With shade, each crown's leaf centroid moves
  // away from the other's (compose/tree_neighbours measures seeds 1-8: 52 cm apart more on
  // average).
  GardenState s = SmallGarden();
  s.default_layout = false;
  s.objects.clear();
  s.ivy_on.clear();
  s.plants = {{"sakura", 1, 0, -1.5, 0, 0}, {"sakura", 1, 0, 1.5, 0, 0}};
  s.ground = GroundKind::kFlat;
  ASSERT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 10).ok());
  double apart[2] = {0, 0}, west[2] = {0, 0}, east[2] = {0, 0};
  for (int shade : {0, 1}) {
    ASSERT_TRUE(s.params.Set(GardenParam::kShade, shade).ok());
    Result<GardenRun> run = GardenRun::Start(s, Budget{});
    ASSERT_TRUE(run.ok()) << run.status().Line();
    ASSERT_TRUE(run->Advance({}).ok());
    EXPECT_EQ(run->groups().size(), shade ? 2u : 1u);
    const glm::dvec3 a = run->CrownCentroid(0), b = run->CrownCentroid(1);
    apart[shade] = std::hypot(a.x - b.x, a.z - b.z);
    west[shade] = a.x + 1.5;  // each crown's centroid from its trunk, along x (east +)
    east[shade] = b.x - 1.5;
  }
  EXPECT_GT(apart[1], apart[0] + 0.10)
      << "alone " << apart[0] << " m, together " << apart[1] << " m";
  // Together they lean apart; one seed's pair need not move both ways (seed 1: the east crown
  // 0.5 m further east, the west one 8 cm east too): tree_neighbours_test averages seeds 1-8.
  EXPECT_GT(east[1] - west[1], east[0] - west[0] + 0.10)
      << "west " << west[0] << " -> " << west[1] << ", east " << east[0] << " -> " << east[1];
}

TEST(Garden, IvyClimbsTheWallItStartsAt) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 3).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kIvySteps, 40).ok());
  s.ivy_on = {"objects[0]"};
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  ASSERT_TRUE(run->Advance({}).ok());
  ASSERT_NE(run->ivy(), nullptr);
  EXPECT_EQ(run->ivy()->log().steps_run, 120);
  const ivy::IvyModel& m = run->ivy()->model();
  ASSERT_GT(m.internodes.size(), 50u);
  // The wall: 6 m along x, 0.45 m thick, 1.8 m high, at (0, base, −0.3·size).
  const PlacedObject& wall = run->scene().objects[0];
  int on_wall = 0, up_high = 0;
  for (const ivy::Bud& b : m.buds) {
    on_wall += wall.Covers(b.pos.x, b.pos.z, 0.3) ? 1 : 0;
    up_high += b.pos.y > wall.base_y + 0.9 ? 1 : 0;
  }
  EXPECT_GT(on_wall, static_cast<int>(m.buds.size()) / 2) << "most of the ivy is on the wall";
  EXPECT_GT(up_high, 10) << "some climbed above half the wall's height";
  const nlohmann::json stats = nlohmann::json::parse(run->StatsJson());
  EXPECT_EQ(stats["ivy"]["internodes"].get<std::size_t>(), m.internodes.size());

  s.ivy_on = {"objects[9]"};
  const Result<GardenRun> bad = GardenRun::Start(s, Budget{});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().field(), "ivy") << bad.status().Line();
}

// The garden is one job: the ivy gets what the trees' growth left of the budget, so trees and ivy
// together stay within it (before, the ivy had the whole budget again after the trees).
TEST(Garden, TheIvyGetsWhatTheTreesLeftOfTheBudget) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 3).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kIvySteps, 40).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());  // the moss would take its share
  s.ivy_on = {"objects[0]"};
  s.ground = GroundKind::kFlat;  // a grown terrain would take the budget's first share itself
  Budget tight;
  tight.seconds = 0.05;
  Result<GardenRun> run = GardenRun::Start(s, tight);
  ASSERT_TRUE(run.ok()) << run.status().Line();
  ASSERT_TRUE(run->Advance({}).ok());
  double trees = 0;
  for (const GardenTreeGroup& g : run->groups()) trees += g.run->grown().seconds;
  EXPECT_GT(trees, 0.0);
  EXPECT_LE(trees, tight.seconds);
  // The ivy grows year by year: its budget is what the trees had used by the last year it grew
  // in (at most their final growth).
  EXPECT_GE(run->ivy_budget().seconds, tight.seconds - trees);
  EXPECT_LT(run->ivy_budget().seconds, tight.seconds);
  const std::string& line = run->truncated_by();
  ASSERT_EQ(line.rfind("ivy: max_seconds: stopped ", 0), 0u) << line;
  if (run->ivy() != nullptr) {
    EXPECT_LT(run->ivy()->log().steps_run, 120) << "the ivy stopped at what the trees left";
  } else {
    EXPECT_NE(line.find("before step 1"), std::string::npos) << line;
  }
}

// The memory a front end holds per ivy bud (the page's mesh of it) counts in the ivy's limits.
TEST(Garden, TheIvyCountsTheMemoryItsFrontEndHoldsPerBud) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 3).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kIvySteps, 40).ok());
  s.ivy_on = {"objects[0]"};
  s.ground = GroundKind::kFlat;
  Budget budget;
  budget.memory_bytes = uint64_t{512} << 20;
  Result<GardenRun> held = GardenRun::Start(s, budget);
  ASSERT_TRUE(held.ok()) << held.status().Line();
  held->set_ivy_extra_bytes_per_bud(4e6);  // about 100 buds fit in what is left
  ASSERT_TRUE(held->Advance({}).ok());
  ASSERT_NE(held->ivy(), nullptr);
  EXPECT_LT(held->ivy()->log().steps_run, 120);
  EXPECT_EQ(held->truncated_by().rfind("ivy: max_memory: stopped ", 0), 0u) << held->truncated_by();
  Result<GardenRun> alone = GardenRun::Start(s, budget);
  ASSERT_TRUE(alone.ok());
  ASSERT_TRUE(alone->Advance({}).ok());
  EXPECT_EQ(alone->ivy()->log().steps_run, 120) << alone->truncated_by();
}

// The ivy grows on the garden's clock (issue 33 item 2): ivy_steps steps a year, on the trunks as
// they stand that year. A hand-placed keyaki with ivy at its foot, beside the wall's: the ivy of
// year 2 of a 4-year garden is the 2-year garden's ivy, bud for bud (the same positions: it grew
// on the 2-year trunk, not on the 4-year one), and the ivy grows every year.
TEST(Garden, TheIvyGrowsYearByYearOnTheTrunksOfEachYear) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kIvySteps, 20).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());
  s.ground = GroundKind::kFlat;
  s.ivy_on = {"plants[0]", "objects[0]"};  // the default's hand-placed keaki and its wall
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 4).ok());
  Result<GardenRun> four = GardenRun::Start(s, Budget{}, true);
  ASSERT_TRUE(four.ok()) << four.status().Line();
  ASSERT_TRUE(four->Advance({}).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 2).ok());
  Result<GardenRun> two = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(two.ok()) << two.status().Line();
  ASSERT_TRUE(two->Advance({}).ok());
  ASSERT_NE(four->ivy(), nullptr);
  ASSERT_NE(two->ivy(), nullptr);
  EXPECT_TRUE(four->truncated_by().empty()) << four->truncated_by();
  EXPECT_EQ(four->ivy()->log().steps_run, 80);
  EXPECT_EQ(two->ivy()->log().steps_run, 40);
  // Every year's internodes, each year more; the last is the grown ivy's.
  const std::vector<long>& by_year = four->ivy_internodes_by_year();
  ASSERT_EQ(by_year.size(), 4u);
  for (std::size_t y = 1; y < by_year.size(); ++y) EXPECT_LT(by_year[y - 1], by_year[y]) << y;
  EXPECT_EQ(by_year.back(), static_cast<long>(four->ivy()->model().internodes.size()));
  // The records carry it: year 0 none, year 2 the 2-year garden's.
  ASSERT_EQ(four->years().size(), 5u);
  EXPECT_EQ(four->years()[0].ivy_internodes, 0);
  EXPECT_EQ(four->years()[2].ivy_steps, 40);
  EXPECT_EQ(four->years()[2].ivy_internodes,
            static_cast<long>(two->ivy()->model().internodes.size()));
  EXPECT_LT(four->years()[2].ivy_internodes, four->years()[4].ivy_internodes);
  // Year 2 of the 4-year ivy is the 2-year ivy: the buds born by step 40, where they grew.
  const ivy::IvyModel& a = four->ivy()->model();
  const ivy::IvyModel& b = two->ivy()->model();
  ASSERT_LE(b.buds.size(), a.buds.size());
  std::size_t born = 0, on_trunk = 0;
  for (const ivy::Bud& bud : a.buds) born += bud.born_step <= 40 ? 1 : 0;
  EXPECT_EQ(born, b.buds.size());
  for (std::size_t k = 0; k < b.buds.size(); ++k) {
    ASSERT_EQ(a.buds[k].pos, b.buds[k].pos) << "bud " << k;
    on_trunk += b.buds[k].plant == 0 ? 1 : 0;
  }
  EXPECT_GT(on_trunk, 10u) << "the keyaki's ivy grew on its trunk";
  const nlohmann::json stats = nlohmann::json::parse(four->StatsJson());
  EXPECT_EQ(stats["ivy"]["internodes_by_year"].size(), 4u);
}

// The budget's estimate of the ivy (time and memory) against the work a small garden's ivy did,
// counted (deterministic: no clock is read; the time each unit takes is measured in scripts/bench
// and docs/garden-model.md "The ivy's estimate"). Time: the garden's own figures (GardenIvyCosts,
// not the ivy study's) are in the ivy's limits; the estimate prices every candidate tested and
// every year's support, and the rest of it (the bud-steps) stays under the candidates' and
// supports' share, so an estimate that dropped a count or grew a term by a multiple fails. Memory:
// the ivy's own structures as held at the end (its buds, internodes and axes, the last support's
// mesh and BVH), against the estimate above the process's base.
TEST(Garden, TheIvysEstimateCountsItsWork) {
  GardenState s = SmallGarden();
  ASSERT_TRUE(s.params.Set(GardenParam::kDensity, 0).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kYears, 4).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kIvySteps, 40).ok());
  ASSERT_TRUE(s.params.Set(GardenParam::kMossDays, 0).ok());
  s.ivy_on = {"plants[0]", "objects[0]"};
  Result<GardenRun> run = GardenRun::Start(s, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  ASSERT_TRUE(run->Advance({}).ok());
  ASSERT_NE(run->ivy(), nullptr);
  const ivy::IvyRun& ivy = *run->ivy();
  const ivy::IvyGrowLimits& limits = ivy.limits();
  const ivy::GrowLog& log = ivy.log();
  EXPECT_EQ(log.steps_run, 160);
  // The garden's measured figures, not the study's (which the study alone keeps).
  const ivy::IvyCosts costs = GardenIvyCosts();
  const double kPerCandidate = costs.candidate;
  const double kPerNewTriangle = kGardenIvyMeshSecondsPerTriangle + costs.triangle_build;
  EXPECT_DOUBLE_EQ(limits.seconds_per_candidate, kPerCandidate);
  EXPECT_DOUBLE_EQ(limits.seconds_per_bud_step, costs.bud_step);
  const ivy::IvyGrowLimits study =
      ivy::IvyLimits(ivy.params(), Budget{}, ivy::EstimateIvySupport({}), true);
  EXPECT_DOUBLE_EQ(study.seconds_per_bud_step, ivy::IvyCosts{}.bud_step);
  EXPECT_LT(limits.seconds_per_bud_step, study.seconds_per_bud_step);
  EXPECT_LT(limits.seconds_per_candidate, study.seconds_per_candidate);
  // Every year's support counted: the ground and the objects (the kept part) meshed and built once,
  // each year's trunks (no more than the last year's: they only widen) meshed and built, and every
  // triangle joined and copied each year.
  double kept = static_cast<double>(run->scene().ground.Mesh().triangle_count());
  for (const PlacedObject& o : run->scene().objects)
    kept += static_cast<double>(o.mesh.triangle_count());
  const double last = ivy.support().triangles();
  ASSERT_GT(last, kept) << "the keyaki's trunk is in the support";
  EXPECT_GE(limits.seconds_before,
            (kPerNewTriangle + kGardenIvyJoinSecondsPerTriangle) * last * (1 - 1e-9));
  EXPECT_LE(limits.seconds_before, (kPerNewTriangle * (kept + 4 * (last - kept)) +
                                    4 * kGardenIvyJoinSecondsPerTriangle * last) *
                                       (1 + 1e-9));
  const Estimate e = ivy::EstimateIvyGrown(ivy.model(), log, limits);
  const double counted =
      kPerCandidate * static_cast<double>(log.candidates) + limits.seconds_before;
  EXPECT_GT(log.candidates, 100000) << "the garden's ivy tested its candidates";
  EXPECT_GE(e.seconds, counted) << "estimated " << e.seconds << " s for " << log.candidates
                                << " candidates and " << limits.seconds_before << " s of supports";
  EXPECT_LE(e.seconds, 1.5 * counted) << "estimated " << e.seconds << " s, " << log.bud_steps
                                      << " bud-steps beside " << log.candidates << " candidates";
  const ivy::IvyModel& m = ivy.model();
  const geom::TriMesh& mesh = *ivy.support().mesh();
  const double held =
      static_cast<double>(m.buds.capacity() * sizeof(ivy::Bud) +
                          m.internodes.capacity() * sizeof(ivy::Internode) +
                          m.axes.capacity() * sizeof(ivy::Axis)) +
      static_cast<double>(mesh.positions.capacity() * sizeof(glm::vec3) +
                          mesh.indices.capacity() * sizeof(uint32_t)) +
      static_cast<double>(ivy.support().bvh().nodes().capacity() * sizeof(geom::BvhNode) +
                          ivy.support().bvh().wide_nodes().capacity() * sizeof(geom::BvhWideNode) +
                          ivy.support().bvh().wide_boxes().capacity() * sizeof(geom::BvhWideBoxes) +
                          ivy.support().bvh().order().capacity() * sizeof(uint32_t) +
                          ivy.support().bvh().corners().capacity() * sizeof(glm::vec3));
  const double above_base = e.memory_bytes - ivy::kIvyBaseBytes;
  EXPECT_GE(above_base, held) << "estimated " << above_base << " B, held " << held << " B";
  EXPECT_LE(above_base, 2 * held) << "estimated " << above_base << " B, held " << held << " B";
}

}  // namespace
}  // namespace niwa::compose

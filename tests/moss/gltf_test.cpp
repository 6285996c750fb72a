// The moss study's glTF output (core/moss/moss_gltf.h, MossRun's Document, Parts, MapValues and
// export estimates): fig 3.7's tuft within 24 triangles with outward normals, turned onto a
// moss's normal; the land's map per cell; merged and instanced tufts with per-moss extras; the
// .glb estimate refused over the budget; moss.json's cells.
#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "moss/moss_gltf.h"
#include "moss/moss_run.h"
#include "support/glb_parse.h"

namespace niwa::moss {
namespace {

MossRun GrownRun(const std::string& scene, int days, int photons) {
  MossState state;
  EXPECT_TRUE(SetMossScene(scene, &state).ok());
  state.days = days;
  EXPECT_TRUE(state.params.Set(MossParam::kPhotons, photons).ok());
  Result<MossRun> run = MossRun::Start(state, Budget{});
  EXPECT_TRUE(run.ok());
  EXPECT_TRUE(run->Advance(nullptr).ok());
  return std::move(*run);
}

// Fig 3.7's tuft: at most 24 triangles, unit height from y 0, stem and crown facing away from the
// axis, every leaf half facing up, unit normals.
TEST(MossTuft, AtMost24TrianglesWithOutwardFaces) {
  const geom::TriMesh tuft = TuftMesh();
  EXPECT_EQ(tuft.triangle_count(), static_cast<std::size_t>(kTuftTriangles));
  EXPECT_LE(kTuftTriangles, 24);
  EXPECT_EQ(tuft.vertex_count(), static_cast<std::size_t>(kTuftVertices));
  float lo = 1, hi = 0;
  for (const glm::vec3& p : tuft.positions) {
    lo = std::min(lo, p.y), hi = std::max(hi, p.y);
    EXPECT_LE(std::hypot(p.x, p.z), 0.5f);
  }
  EXPECT_EQ(lo, 0.0f);
  EXPECT_EQ(hi, 1.0f);
  for (std::size_t t = 0; t < tuft.triangle_count(); ++t) {
    const glm::vec3 a = tuft.positions[tuft.indices[3 * t]],
                    b = tuft.positions[tuft.indices[3 * t + 1]],
                    c = tuft.positions[tuft.indices[3 * t + 2]];
    const glm::vec3 n = glm::cross(b - a, c - a);
    const glm::vec3 mid = (a + b + c) / 3.0f;
    if (t < 9) {  // stem and crown: away from the axis
      EXPECT_GT(n.x * mid.x + n.z * mid.z, 0.0f) << "triangle " << t;
    } else {  // leaves: up
      EXPECT_GT(n.y, 0.0f) << "triangle " << t;
    }
  }
  for (const glm::vec3& n : tuft.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
}

// A merged tuft is turned onto its normal: the crown's tip (vertex 6) at pos + size·normal.
TEST(MossTuft, MergedTuftsStandOnTheirNormals) {
  std::vector<TuftPlace> tufts(4);
  const glm::dvec3 normals[4] = {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
  for (int k = 0; k < 4; ++k) {
    tufts[k].pos = glm::dvec3(k, 2, 3);
    tufts[k].normal = normals[k];
    tufts[k].size = 0.02;
    tufts[k].angle = 0.7 * k;
    tufts[k].species = static_cast<Species>(k % 3);
  }
  const geom::TriMesh mesh = MergedTufts(tufts);
  ASSERT_EQ(mesh.vertex_count(), 4u * kTuftVertices);
  ASSERT_EQ(mesh.triangle_count(), 4u * kTuftTriangles);
  const geom::VertexAttribute* colour = mesh.FindAttribute("COLOR_0");
  ASSERT_NE(colour, nullptr);
  for (int k = 0; k < 4; ++k) {
    const glm::vec3 tip = mesh.positions[k * kTuftVertices + 6];
    const glm::dvec3 want = tufts[k].pos + 0.02 * normals[k];
    EXPECT_NEAR(tip.x, want.x, 1e-6);
    EXPECT_NEAR(tip.y, want.y, 1e-6);
    EXPECT_NEAR(tip.z, want.z, 1e-6);
    EXPECT_EQ(colour->values[3 * k * kTuftVertices], SpeciesColour(tufts[k].species)[0]);
    // The base stays on the moss's place, within the stem's radius.
    EXPECT_LE(glm::length(glm::dvec3(mesh.positions[k * kTuftVertices]) - tufts[k].pos),
              0.02 * 0.05 + 1e-6);
  }
}

TEST(MossMapName, EveryNameRoundTripsAndAnUnknownOneNamesMap) {
  for (int k = 0; k < kMossMapCount; ++k) {
    MossMap map;
    ASSERT_TRUE(MossMapFromName(MossMapName(static_cast<MossMap>(k)), &map).ok());
    EXPECT_EQ(static_cast<int>(map), k);
  }
  MossMap map;
  const Status bad = MossMapFromName("irradiance", &map);
  EXPECT_EQ(bad.field(), "map");
  EXPECT_NE(bad.message().find("coverage, S, T_s"), std::string::npos);
  EXPECT_EQ(RampColour(-1)[0], RampColour(0)[0]);
  EXPECT_EQ(RampColour(std::nan(""))[1], RampColour(0)[1]);
  EXPECT_EQ(RampColour(7)[2], RampColour(1)[2]);
}

// The maps per cell: coverage from the mosses on faces (the stats' coverage, area-weighted), the
// soil values as the world holds them, theta's ramp over theta_SAT, fitness within [0, 1].
TEST(MossRunGltf, MapValuesPerCell) {
  const MossRun run = GrownRun("thesis", 12, 2048);
  const MossWorld& w = run.world();
  const SoilCells& cells = run.cells();
  std::vector<double> ramp;
  const std::vector<double> coverage = run.MapValues(MossMap::kCoverage, &ramp);
  ASSERT_EQ(coverage.size(), cells.size());
  double covered = 0, area = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    ASSERT_GE(coverage[i], 0.0);
    ASSERT_LE(coverage[i], 1.0);
    EXPECT_EQ(ramp[i], coverage[i]);
    if (cells.normal[i].y > 0.5) covered += coverage[i] * cells.area[i], area += cells.area[i];
  }
  const nlohmann::json stats = nlohmann::json::parse(run.StatsJson());
  EXPECT_NEAR(covered / area, stats["mosses"]["coverage"]["up"].get<double>(), 1e-12);
  EXPECT_GT(covered, 0.0);
  EXPECT_EQ(run.MapValues(MossMap::kT_s, &ramp), w.T_s);
  EXPECT_EQ(run.MapValues(MossMap::kS, &ramp), w.S);
  const std::vector<double> theta = run.MapValues(MossMap::kTheta, &ramp);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    ASSERT_EQ(theta[i], w.theta[i]);
    ASSERT_NEAR(ramp[i], w.theta[i] / GeologyLawOf(MossParams(), cells.geology[i]).theta_SAT,
                1e-12);
  }
  const std::vector<double> fitness = run.MapValues(MossMap::kFitness, &ramp);
  double best = 0;
  for (double g : fitness) {
    ASSERT_GE(g, 0.0);
    ASSERT_LE(g, 1.0);
    best = std::max(best, g);
  }
  EXPECT_GT(best, 0.0);
}

// The .glb: land (its map as COLOR_0 and the raw attribute) and the tufts merged, species and
// birth day per moss in the tufts node's extras; Parts() names land and tufts.
TEST(MossRunGltf, MergedDocumentHoldsTheLandAndEveryTuft) {
  const MossRun run = GrownRun("thesis", 12, 2048);
  const std::size_t mosses = run.world().mosses.size();
  ASSERT_GT(mosses, 0u);
  Result<gltf::Document> doc = run.Document();
  ASSERT_TRUE(doc.ok());
  Result<std::vector<unsigned char>> bytes = gltf::WriteGlb(*doc);
  ASSERT_TRUE(bytes.ok()) << bytes.status().message();
  const testing::Glb glb = testing::ParseGlb(*bytes);
  const auto& nodes = glb.gltf["nodes"];
  ASSERT_EQ(nodes.size(), 2u);
  EXPECT_EQ(nodes[0]["name"], "land");
  EXPECT_EQ(nodes[0]["extras"]["map"], "coverage");
  EXPECT_EQ(nodes[1]["name"], "tufts");
  EXPECT_EQ(nodes[1]["extras"]["species"].size(), mosses);
  EXPECT_EQ(nodes[1]["extras"]["birth_day"].size(), mosses);
  for (std::size_t k = 0; k < mosses; ++k) {
    EXPECT_EQ(nodes[1]["extras"]["species"][k], static_cast<int>(run.world().mosses[k].species));
    EXPECT_EQ(nodes[1]["extras"]["birth_day"][k], run.world().mosses[k].birth_day);
  }
  const auto& land = glb.gltf["meshes"][0]["primitives"][0]["attributes"];
  EXPECT_TRUE(land.contains("COLOR_0"));
  EXPECT_TRUE(land.contains("_COVERAGE"));
  EXPECT_EQ(glb.gltf["accessors"][land["POSITION"].get<int>()]["count"], 3 * run.cells().size());
  const auto& tufts = glb.gltf["meshes"][1]["primitives"][0]["attributes"];
  EXPECT_EQ(glb.gltf["accessors"][tufts["POSITION"].get<int>()]["count"], mosses * kTuftVertices);
  const std::vector<run::Part> parts = run.Parts();
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0].name, "land");
  EXPECT_EQ(parts[1].name, "tufts");
  EXPECT_EQ(parts[1].mesh.triangle_count(), mosses * kTuftTriangles);
  // The tufts' turns come from their own stream: the same run gives the same bytes.
  EXPECT_EQ(*gltf::WriteGlb(*run.Document()), *bytes);
}

// --instancing: one tuft mesh per species present, drawn once per moss of it.
TEST(MossRunGltf, InstancedDocumentDrawsEachSpeciesTuftPerMoss) {
  const MossRun run = GrownRun("thesis", 12, 2048);
  Result<gltf::Document> doc = run.MapDocument(MossMap::kFitness, true);
  ASSERT_TRUE(doc.ok());
  std::array<std::size_t, kSpeciesCount> by_species{};
  for (const MossPlant& m : run.world().mosses) ++by_species[static_cast<int>(m.species)];
  std::size_t instances = 0, nodes = 0;
  for (int child : doc->nodes[1].children) {
    const gltf::Node& node = doc->nodes[child];
    ++nodes;
    instances += node.instance_count();
    EXPECT_EQ(doc->meshes[node.mesh].primitives[0].mesh.triangle_count(),
              static_cast<std::size_t>(kTuftTriangles));
    const nlohmann::json extras = nlohmann::json::parse(node.extras_json);
    Species s;
    ASSERT_TRUE(SpeciesFromName(extras["species"].get<std::string>().c_str(), &s));
    EXPECT_EQ(node.instance_count(), by_species[static_cast<int>(s)]);
    EXPECT_EQ(extras["birth_day"].size(), node.instance_count());
  }
  EXPECT_EQ(instances, run.world().mosses.size());
  EXPECT_EQ(nodes, static_cast<std::size_t>((by_species[0] > 0) + (by_species[1] > 0) +
                                            (by_species[2] > 0)));
  EXPECT_EQ(nlohmann::json::parse(doc->nodes[0].extras_json)["map"], "fitness");
  EXPECT_TRUE(gltf::WriteGlb(*doc).ok());
}

// The .glb's estimate grows with cells and mosses, the planned one (at the cap, with the days)
// is above it, and a small budget refuses it naming the limit.
TEST(MossRunGltf, GlbEstimateIsRefusedOverTheBudget) {
  const MossRun run = GrownRun("plane", 3, 256);
  Result<Estimate> now = run.ExportEstimate("glb");
  Result<Estimate> planned = run.PlannedExportEstimate("glb");
  ASSERT_TRUE(now.ok());
  ASSERT_TRUE(planned.ok());
  EXPECT_GT(planned->memory_bytes, now->memory_bytes);
  EXPECT_GT(planned->seconds, now->seconds);
  // The written file fits within the estimate's share for it.
  const std::vector<unsigned char> glb = *gltf::WriteGlb(*run.Document());
  EXPECT_GT(MossGlbEstimate(run.cells().size(), run.world().mosses.size()).memory_bytes,
            static_cast<double>(glb.size()));
  Budget small;
  small.memory_bytes = 1 << 20;
  const Status refused = CheckEstimate(*planned, small, "lower days");
  EXPECT_EQ(refused.field(), "max_memory");
  EXPECT_NE(refused.message().find(".glb"), std::string::npos) << refused.message();
  EXPECT_EQ(run.ExportEstimate("obj").status().field(), "format");
}

// moss.json: every moss as before, then every cell with its geology and last day's soil.
TEST(MossRunGltf, MossesJsonListsEveryCell) {
  const MossRun run = GrownRun("plane", 4, 256);
  const nlohmann::json j = nlohmann::json::parse(run.MossesJson());
  ASSERT_EQ(j["cells"].size(), run.cells().size());
  EXPECT_EQ(j["mosses"].size(), run.world().mosses.size());
  const nlohmann::json& c = j["cells"][7];
  EXPECT_EQ(c["geology"], "humus");
  EXPECT_EQ(c["T_s"].get<double>(), run.world().T_s[7]);
  EXPECT_EQ(c["theta"].get<double>(), run.world().theta[7]);
  EXPECT_EQ(c["m_over_M"].get<double>(), run.world().m_over_M[7]);
  EXPECT_EQ(c["centre"][1].get<double>(), run.cells().centroid[7].y);
  EXPECT_EQ(c["normal"].size(), 3u);
}

}  // namespace
}  // namespace niwa::moss

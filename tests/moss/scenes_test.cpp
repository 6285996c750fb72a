// The moss study's built-in scenes (core/moss/scenes.h): sizes, geologies, regions, outward
// winding, the rocks' triangle knob and the refusals.
#include "moss/scenes.h"

#include <gtest/gtest.h>

#include <array>
#include <glm/geometric.hpp>
#include <vector>

namespace niwa::moss {
namespace {

struct Box {
  glm::dvec3 lo, hi;
  bool Contains(const glm::dvec3& p) const {
    return p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z;
  }
};

glm::dvec3 Corner(const geom::TriMesh& m, std::size_t t, int k) {
  return glm::dvec3(m.positions[m.indices[3 * t + k]]);
}
glm::dvec3 Centroid(const geom::TriMesh& m, std::size_t t) {
  return (Corner(m, t, 0) + Corner(m, t, 1) + Corner(m, t, 2)) / 3.0;
}
glm::dvec3 WindingNormal(const geom::TriMesh& m, std::size_t t) {
  return glm::normalize(
      glm::cross(Corner(m, t, 1) - Corner(m, t, 0), Corner(m, t, 2) - Corner(m, t, 0)));
}
double Area(const geom::TriMesh& m, std::size_t t) {
  return 0.5 * glm::length(glm::cross(Corner(m, t, 1) - Corner(m, t, 0),
                                      Corner(m, t, 2) - Corner(m, t, 0)));
}

// Every face of a union of boxes faces out: a step along its winding normal leaves every box, a
// step against it enters one.
void ExpectOutward(const MossScene& scene, const std::vector<Box>& boxes) {
  for (std::size_t t = 0; t < scene.mesh.triangle_count(); ++t) {
    const glm::dvec3 c = Centroid(scene.mesh, t), n = WindingNormal(scene.mesh, t);
    bool out_inside = false, in_inside = false;
    for (const Box& b : boxes) {
      out_inside |= b.Contains(c + 1e-3 * n);
      in_inside |= b.Contains(c - 1e-3 * n);
    }
    ASSERT_FALSE(out_inside) << scene.name << " triangle " << t;
    ASSERT_TRUE(in_inside) << scene.name << " triangle " << t;
  }
}

TEST(MossScenes, EveryBuiltInSceneIsWellFormed) {
  ASSERT_EQ(SceneNames(), (std::vector<std::string>{"plane", "thesis", "walls", "rocks"}));
  for (const std::string& name : SceneNames()) {
    Result<MossScene> scene = BuildScene(name);
    ASSERT_TRUE(scene.ok()) << name;
    const geom::TriMesh& m = scene->mesh;
    EXPECT_EQ(scene->name, name);
    EXPECT_EQ(scene->geology.size(), m.triangle_count());
    EXPECT_EQ(scene->region.size(), m.triangle_count());
    EXPECT_EQ(m.normals.size(), m.positions.size());
    for (uint8_t r : scene->region) ASSERT_LT(r, scene->region_names.size());
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      ASSERT_GT(Area(m, t), 1e-6) << name;
      // The 5 cm grid (2 triangles a square): no edge above soil_edge (the rocks' may be longer).
      for (int k = 0; k < 3 && name != "rocks"; ++k)
        ASSERT_LE(glm::length(Corner(m, t, k) - Corner(m, t, (k + 1) % 3)), 0.0708) << name;
    }
  }
}

TEST(MossScenes, PlaneIsTwoMetresOfHumus) {
  const MossScene scene = *BuildScene("plane");
  EXPECT_EQ(scene.mesh.triangle_count(), 3200u);
  double area = 0;
  for (std::size_t t = 0; t < scene.mesh.triangle_count(); ++t) {
    area += Area(scene.mesh, t);
    EXPECT_EQ(scene.geology[t], Geology::kHumus);
    EXPECT_GT(WindingNormal(scene.mesh, t).y, 0.999);
  }
  EXPECT_NEAR(area, 4.0, 1e-5);
}

TEST(MossScenes, ThesisHasTheThreeGeologiesTheRegionsAndNoHiddenFaces) {
  const MossScene scene = *BuildScene("thesis");
  const geom::TriMesh& m = scene.mesh;
  ExpectOutward(scene, {{{-1, -0.3, -1}, {1, 0, 1}},
                        {{-1, 0, -1}, {1, 1.5, -0.9}},
                        {{-1, 1.0, -0.9}, {1, 1.05, -0.2}},
                        {{0.3, 0, 0.1}, {0.7, 0.4, 0.5}},
                        {{-0.7, 0, 0.2}, {-0.3, 0.25, 0.6}}});
  std::array<double, kGeologyCount> floor_area{};
  std::vector<double> region_area(scene.region_names.size(), 0.0);
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const glm::dvec3 c = Centroid(m, t);
    region_area[scene.region[t]] += Area(m, t);
    if (std::abs(c.y) < 1e-6 && WindingNormal(m, t).y > 0.5)
      floor_area[static_cast<int>(scene.geology[t])] += Area(m, t);
  }
  // The slab top: 4 m² less the wall (0.2) and the two stones (0.16 each); the geology by the
  // square's centre x (the bounds ±1/3 fall inside a 5 cm column).
  EXPECT_NEAR(floor_area[0] + floor_area[1] + floor_area[2], 3.48, 1e-5);
  for (double a : floor_area) EXPECT_GT(a, 1.0);
  const auto area_of = [&](const std::string& name) {
    for (std::size_t r = 0; r < scene.region_names.size(); ++r)
      if (scene.region_names[r] == name) return region_area[r];
    ADD_FAILURE() << name;
    return 0.0;
  };
  EXPECT_NEAR(area_of("roof_under"), 2.0 * 0.7, 1e-5);
  EXPECT_NEAR(area_of("wall_sheltered"), 2.0 * 1.0, 1e-5);
  // Sheltered floor: z in [-0.9, -0.2] across 2 m, less nothing (the stones are in front).
  EXPECT_NEAR(area_of("floor_sheltered"), 2.0 * 0.7, 1e-5);
  // Tops: roof top 1.4, wall top 0.2, stone tops 0.16 + 0.16.
  EXPECT_NEAR(area_of("tops"), 1.4 + 0.2 + 0.32, 1e-5);
}

TEST(MossScenes, WallsFaceEachOther) {
  const MossScene scene = *BuildScene("walls");
  ExpectOutward(scene, {{{-1, -1, -1}, {1, 0, 1}},  // below the ground
                        {{-0.8, 0, -0.6}, {0.8, 1.0, -0.5}},
                        {{-0.8, 0, 0.5}, {0.8, 1.0, 0.6}}});
  double sunlit = 0, shaded = 0;
  for (std::size_t t = 0; t < scene.mesh.triangle_count(); ++t) {
    const glm::dvec3 n = WindingNormal(scene.mesh, t);
    if (scene.region_names[scene.region[t]] == "sunlit_face") {
      EXPECT_GT(n.z, 0.999);
      sunlit += Area(scene.mesh, t);
    }
    if (scene.region_names[scene.region[t]] == "shaded_face") {
      EXPECT_LT(n.z, -0.999);
      shaded += Area(scene.mesh, t);
    }
  }
  EXPECT_NEAR(sunlit, 1.6, 1e-5);
  EXPECT_NEAR(shaded, 1.6, 1e-5);
}

TEST(MossScenes, RocksFaceOutAndFollowTheTriangleKnob) {
  std::size_t ground = 0;
  for (int level = 0; level <= 3; ++level) {
    const int rock_triangles = 5 * 20 * (1 << (2 * level));
    const MossScene scene = *BuildScene("rocks", rock_triangles);
    std::size_t rock = 0;
    for (std::size_t t = 0; t < scene.mesh.triangle_count(); ++t) {
      if (scene.geology[t] == Geology::kSandy) {
        ++rock;
        // Outward: the winding normal points away from the rock's centre (the relief is 12 %).
        const glm::dvec3 c = Centroid(scene.mesh, t);
        const glm::dvec3 n = WindingNormal(scene.mesh, t);
        double best = 1e9;
        glm::dvec3 centre(0.0);
        for (const glm::dvec3 rc : {glm::dvec3(-0.5, 0.125, -0.4), glm::dvec3(0.45, 0.15, -0.3),
                                    glm::dvec3(0.0, 0.11, 0.45), glm::dvec3(-0.55, 0.075, 0.5),
                                    glm::dvec3(0.6, 0.09, 0.55)})
          if (glm::length(c - rc) < best) {
            best = glm::length(c - rc);
            centre = rc;
          }
        if (level >= 2) {
          ASSERT_GT(glm::dot(n, glm::normalize(c - centre)), 0.0) << t;
        }
      }
    }
    EXPECT_EQ(rock, static_cast<std::size_t>(rock_triangles));
    if (level == 0) ground = scene.mesh.triangle_count() - rock;
    EXPECT_EQ(scene.mesh.triangle_count() - rock, ground);
  }
  EXPECT_LT(ground, 3200u);
  EXPECT_GT(ground, 2600u);
  // A knob between levels rounds up to the next level.
  EXPECT_EQ(BuildScene("rocks", 101)->geology.size() - ground, 400u);
}

TEST(MossScenes, RefusalsNameTheField) {
  EXPECT_EQ(BuildScene("garden").status().field(), "scene");
  EXPECT_EQ(BuildScene("rocks", 99).status().field(), "rock_triangles");
  EXPECT_EQ(BuildScene("rocks", kRockTrianglesMax + 1).status().field(), "rock_triangles");
}

}  // namespace
}  // namespace niwa::moss

// core/tree/bark_support: a grown tree's bark as one TriMesh with the trunk-foot seed on it, and
// its errors naming tree or tree_years.
#include "tree/bark_support.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/mesh_metrics.h"

namespace niwa {
namespace {

TEST(BarkSupport, IsTheBarkWithASeedAtTheTrunkFoot) {
  Result<BarkSupport> bark = GrowBarkSupport("sakura", 6);
  ASSERT_TRUE(bark.ok()) << bark.status().Line();
  EXPECT_GT(bark->mesh.triangle_count(), 1000u);
  EXPECT_EQ(bark->mesh.normals.size(), bark->mesh.positions.size());
  EXPECT_TRUE(geom::ValidateMesh(bark->mesh, "bark").ok());
  // On the +z side of the trunk, near the ground.
  EXPECT_GT(bark->trunk_seed.z, 0.0);
  EXPECT_LT(bark->trunk_seed.y, 0.3);
  EXPECT_LT(std::fabs(bark->trunk_seed.x), 0.2);
  // The same request, the same bits.
  Result<BarkSupport> again = GrowBarkSupport("sakura", 6);
  ASSERT_TRUE(again.ok());
  EXPECT_EQ(again->mesh.positions, bark->mesh.positions);
  EXPECT_EQ(again->trunk_seed, bark->trunk_seed);
}

TEST(BarkSupport, BadInputNamesTreeOrTreeYears) {
  Result<BarkSupport> oak = GrowBarkSupport("oak", 6);
  ASSERT_FALSE(oak.ok());
  EXPECT_EQ(oak.status().field(), "tree");
  EXPECT_NE(oak.status().message().find("sakura"), std::string::npos) << oak.status().Line();
  for (double years : {0.0, 2.5, 101.0, std::nan("")}) {
    Result<BarkSupport> r = GrowBarkSupport("sakura", years);
    ASSERT_FALSE(r.ok()) << years;
    EXPECT_EQ(r.status().field(), "tree_years") << r.status().Line();
  }
}

}  // namespace
}  // namespace niwa

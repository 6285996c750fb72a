// Ivy birth geometry: one tube per internode, one leaf per bud but the seed on the side opposite
// its sucker, one sucker per bud ending at its anchor, birth_step on every vertex; the .glb bytes
// are the same for the same run.
#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>

#include "geom/bvh.h"
#include "ivy/growth.h"
#include "ivy/ivy_mesh.h"
#include "ivy/scenes.h"

namespace niwa::ivy {
namespace {

TEST(IvyMesh, TubesLeavesAndSuckersMatchTheModel) {
  IvyScene scene = *MakeIvyScene("cubes4");
  geom::Bvh bvh = geom::Bvh::Build(scene.mesh);
  IvyParams p;
  Result<IvyModel> m =
      Grow(Support{&scene.mesh, &bvh, Accel::kBvh}, {scene.seeds[1].pos}, p, 40, 2, nullptr);
  ASSERT_TRUE(m.ok());
  IvyMeshes meshes = BuildIvyMeshes(*m, p);
  // 6-sided open tubes: 12 triangles per internode.
  EXPECT_EQ(meshes.stems.triangle_count(), 12 * m->internodes.size());
  // Per non-seed bud: petiole tube (12) + 10-point fan (10).
  EXPECT_EQ(meshes.leaves.triangle_count(), 22 * (m->buds.size() - 1));
  // Per bud: sucker tube (12) + 8-point disc (8).
  EXPECT_EQ(meshes.suckers.triangle_count(), 20 * m->buds.size());
  for (const geom::TriMesh* mesh : {&meshes.stems, &meshes.leaves, &meshes.suckers}) {
    const geom::VertexAttribute* birth = mesh->FindAttribute("birth_step");
    ASSERT_NE(birth, nullptr);
    ASSERT_EQ(birth->values.size(), mesh->vertex_count());
    EXPECT_GE(*std::min_element(birth->values.begin(), birth->values.end()), 0.0f);
    EXPECT_LE(*std::max_element(birth->values.begin(), birth->values.end()), 40.0f);
  }
  // Leaves lie on the outward side: every leaf vertex is farther from the support plane side than
  // the sucker's anchor, i.e. (v - anchor) · outward > 0 for the blade of each bud.
  std::size_t v = 0;
  for (const Bud& b : m->buds) {
    if (b.parent < 0) continue;
    const std::size_t per_leaf = 12 + 11;  // petiole 12 vertices, fan centre + 10
    for (std::size_t k = 12; k < per_leaf; ++k) {
      const glm::dvec3 q(meshes.leaves.positions[v + k]);
      EXPECT_GT(glm::dot(q - b.anchor, b.outward), 0.0) << "bud " << b.id;
    }
    v += per_leaf;
  }
  Result<std::vector<unsigned char>> a = WriteIvyGlb(*m, p, 2, 40, &scene.mesh);
  Result<std::vector<unsigned char>> b = WriteIvyGlb(*m, p, 2, 40, &scene.mesh);
  ASSERT_TRUE(a.ok()) << a.status().Line();
  EXPECT_EQ(*a, *b);
  EXPECT_GT(a->size(), 1000u);
}

}  // namespace
}  // namespace niwa::ivy

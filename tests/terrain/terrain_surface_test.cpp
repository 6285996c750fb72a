// The page's flat buffers (core/terrain/terrain_surface): the surface is the .glb's mesh vertex for
// vertex (positions, normals, tint, triangles; terrain_output's TerrainDocument is the oracle), the
// contour lines are every ring edge at its elevation and level, the summits are the terrain's, and
// a regrow reuses the indices on the same grid and rebuilds them on another.
#include "terrain/terrain_surface.h"

#include <gtest/gtest.h>

#include "terrain/generate.h"
#include "terrain/heightfield.h"
#include "terrain/terrain_output.h"
#include "terrain/terrain_state.h"

namespace niwa::terrain {
namespace {

Terrain GrowState(const char* builtin, const char* method, int seed) {
  TerrainState s;
  EXPECT_TRUE(SetTerrainBuiltin(builtin, &s).ok());
  EXPECT_TRUE(SetTerrainPreset(method, &s).ok());
  EXPECT_TRUE(SetTerrainSeed(seed, &s).ok());
  Result<Terrain> t = Grow(*StateSeed(s), s.params, s.seed);
  EXPECT_TRUE(t.ok());
  return t.ok() ? *t : Terrain();
}

// Exact equality of two floats (the buffers must be the .glb's numbers, not near them; a flat
// cell's normal may be +0 in one and −0 in the other).
bool Same(float a, float b) { return a == b; }

TEST(TerrainSurface, SurfaceIsTheGlbMeshVertexForVertex) {
  for (const char* builtin : {"lobes7", "dumbbell", "valleys"}) {
    const Terrain t = GrowState(builtin, "improved", 2);
    const Heightfield hf = BuildHeightfield(t, 40);
    SurfaceBuffers flat;
    BuildSurfaceBuffers(t, hf, &flat);
    const gltf::Document doc = TerrainDocument(t, hf, /*tint=*/true);
    const geom::TriMesh& m = doc.meshes[0].primitives[0].mesh;
    ASSERT_EQ(flat.positions.size(), 3 * m.positions.size()) << builtin;
    ASSERT_EQ(flat.normals.size(), 3 * m.normals.size()) << builtin;
    const geom::VertexAttribute* tint = m.FindAttribute("COLOR_0");
    ASSERT_NE(tint, nullptr);
    ASSERT_EQ(flat.colours.size(), tint->values.size());
    int differ = 0;
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
      for (int c = 0; c < 3; ++c) {
        const std::size_t k = 3 * v + static_cast<std::size_t>(c);
        if (!Same(flat.positions[k], m.positions[v][c])) ++differ;
        if (!Same(flat.normals[k], m.normals[v][c])) ++differ;
        if (!Same(flat.colours[k], tint->values[k])) ++differ;
      }
    }
    EXPECT_EQ(differ, 0) << builtin;
    EXPECT_EQ(flat.indices, m.indices) << builtin;
    // Contour lines: every ring edge, both ends at the ring's elevation, with its level.
    std::size_t edges = 0;
    for (const ContourNode& c : t.contours) edges += c.ring.size();
    ASSERT_EQ(flat.line_positions.size(), 6 * edges);
    ASSERT_EQ(flat.line_height.size(), 2 * edges);
    ASSERT_EQ(flat.line_level.size(), 2 * edges);
    std::size_t e = 0;
    for (const ContourNode& c : t.contours) {
      for (std::size_t p = 0; p < c.ring.size(); ++p, ++e) {
        const Vec2& u = c.ring[p];
        const Vec2& w = c.ring[(p + 1) % c.ring.size()];
        EXPECT_TRUE(Same(flat.line_positions[6 * e], static_cast<float>(u.x)));
        EXPECT_TRUE(Same(flat.line_positions[6 * e + 2], static_cast<float>(-u.y)));
        EXPECT_TRUE(Same(flat.line_positions[6 * e + 3], static_cast<float>(w.x)));
        EXPECT_TRUE(Same(flat.line_positions[6 * e + 5], static_cast<float>(-w.y)));
        EXPECT_TRUE(Same(flat.line_height[2 * e], static_cast<float>(c.elevation)));
        EXPECT_EQ(flat.line_level[2 * e + 1], static_cast<float>(c.level));
      }
    }
    ASSERT_EQ(flat.summit_radius.size(), t.summits.size());
    for (std::size_t s = 0; s < t.summits.size(); ++s)
      EXPECT_TRUE(
          Same(flat.summit_positions[3 * s + 1], static_cast<float>(t.summits[s].elevation)));
  }
}

TEST(TerrainSurface, RegrowReusesIndicesOnTheSameGridOnly) {
  const Terrain a = GrowState("lobes7", "improved", 1), b = GrowState("lobes7", "improved", 5);
  SurfaceBuffers flat;
  BuildSurfaceBuffers(a, BuildHeightfield(a, 32), &flat);
  const std::vector<uint32_t> first = flat.indices;
  const Heightfield hb = BuildHeightfield(b, 32);
  BuildSurfaceBuffers(b, hb, &flat);
  // Another mountain on a grid of the same size: the same triangles, the new heights.
  EXPECT_EQ(flat.indices, first);
  EXPECT_TRUE(
      Same(flat.positions[3 * (hb.h.size() / 2) + 1], static_cast<float>(hb.h[hb.h.size() / 2])));
  const Heightfield big = BuildHeightfield(b, 48);
  BuildSurfaceBuffers(b, big, &flat);
  EXPECT_EQ(flat.indices.size(),
            static_cast<std::size_t>(big.width - 1) * static_cast<std::size_t>(big.height - 1) * 6);
  EXPECT_EQ(flat.positions.size(), 3 * big.h.size());
  const gltf::Document doc = TerrainDocument(b, big, true);
  EXPECT_EQ(flat.indices, doc.meshes[0].primitives[0].mesh.indices);
}

}  // namespace
}  // namespace niwa::terrain

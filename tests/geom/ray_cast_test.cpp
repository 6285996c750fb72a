// FirstHit and SegmentHits: hand-computed hits, watertightness through shared edges and vertices
// of closed meshes, and the BVH against the linear twins on thousands of seeded queries.
#include "geom/ray_cast.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "geom/linear_queries.h"
#include "geom/primitives.h"
#include "geom/query_detail.h"
#include "geom_oracle.h"
#include "support/test_meshes.h"

namespace niwa::geom {
namespace {

TEST(FirstHit, HandComputedBoxHit) {
  TriMesh box = MakeBox({2.0f, 2.0f, 2.0f});  // faces at ±1
  Bvh bvh = Bvh::Build(box);
  // From (0.25, 0.5, 5) straight down -z (dir not unit: it is normalized): hits z = +1 at 4.
  RayHit h = FirstHit(box, bvh, {0.25f, 0.5f, 5.0f}, {0.0f, 0.0f, -3.0f}, 100.0f);
  ASSERT_TRUE(h.hit);
  EXPECT_FLOAT_EQ(h.distance, 4.0f);
  EXPECT_FLOAT_EQ(h.point.z, 1.0f);
  EXPECT_FLOAT_EQ(h.normal.z, 1.0f);  // the +z face, outward
  EXPECT_EQ(h.triangle / 2, 4u);      // face 4 of MakeBox is +z
  EXPECT_NEAR(h.barycentric.x + h.barycentric.y + h.barycentric.z, 1.0f, 1e-6f);
  // Max distance is inclusive; shorter misses; zero or NaN direction misses.
  EXPECT_TRUE(FirstHit(box, bvh, {0.25f, 0.5f, 5.0f}, {0, 0, -1}, 4.0f).hit);
  EXPECT_FALSE(FirstHit(box, bvh, {0.25f, 0.5f, 5.0f}, {0, 0, -1}, 3.99f).hit);
  EXPECT_FALSE(FirstHit(box, bvh, {0.25f, 0.5f, 5.0f}, {0, 0, 0}, 10.0f).hit);
  EXPECT_FALSE(FirstHit(box, bvh, {0.25f, 0.5f, 5.0f}, {std::nanf(""), 0, 0}, 10.0f).hit);
  EXPECT_FALSE(FirstHit(box, bvh, {0.25f, 0.5f, 5.0f}, {0, 0, -1}, -1.0f).hit);
  // From inside: the back faces count (no culling).
  RayHit inside = FirstHit(box, bvh, {0, 0, 0}, {1, 0, 0}, 10.0f);
  ASSERT_TRUE(inside.hit);
  EXPECT_FLOAT_EQ(inside.distance, 1.0f);
  // Pointing away: nothing.
  EXPECT_FALSE(FirstHit(box, bvh, {0, 0, 5}, {0, 0, 1}, 100.0f).hit);
}

TEST(SegmentHits, HandComputedCases) {
  TriMesh box = MakeBox({2.0f, 2.0f, 2.0f});
  Bvh bvh = Bvh::Build(box);
  EXPECT_TRUE(SegmentHits(box, bvh, {0, 0, 0}, {0, 0, 3}));                  // inside → out
  EXPECT_FALSE(SegmentHits(box, bvh, {0, 0, 0}, {0, 0, 0.9f}));              // stays inside
  EXPECT_FALSE(SegmentHits(box, bvh, {0, 0, 1.5f}, {0, 0, 3}));              // stays outside
  EXPECT_TRUE(SegmentHits(box, bvh, {-3, 0.2f, 0.1f}, {3, 0.2f, 0.1f}));     // through both sides
  EXPECT_TRUE(SegmentHits(box, bvh, {0, 0, 3}, {0, 0, 1}));                  // ends on the face
  EXPECT_FALSE(SegmentHits(box, bvh, {0, 0, 3}, {0, 0, 3}));                 // a point
  EXPECT_FALSE(SegmentHits(box, bvh, {1.5f, 1.5f, 1.5f}, {3, 1.5f, 1.5f}));  // passes by
}

// Watertight: on a closed mesh every segment from inside to outside crosses the surface, even
// when it passes exactly through a shared edge (box quads' diagonals, face borders) or a vertex.
void ExpectWatertight(const TriMesh& mesh, const glm::vec3& inside, float out_scale) {
  Bvh bvh = Bvh::Build(mesh);
  int missed = 0, tried = 0;
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    glm::vec3 a = mesh.positions[mesh.indices[3 * t]], b = mesh.positions[mesh.indices[3 * t + 1]];
    for (const glm::vec3& target : {a, (a + b) * 0.5f, a * 0.75f + b * 0.25f}) {
      glm::vec3 far = inside + (target - inside) * out_scale;
      ++tried;
      bool bvh_hit = SegmentHits(mesh, bvh, inside, far);
      bool linear_hit = SegmentHitsLinear(mesh, inside, far);
      RayHit ray = FirstHit(mesh, bvh, inside, target - inside, 1e6f);
      if (!bvh_hit || !linear_hit || !ray.hit) ++missed;
    }
  }
  EXPECT_EQ(missed, 0) << "of " << tried << " segments through edges and vertices";
}

TEST(SegmentHits, WatertightThroughSharedEdgesAndVertices) {
  ExpectWatertight(MakeBox({2, 2, 2}), glm::vec3(0.1f, 0.05f, -0.02f), 3.0f);
  ExpectWatertight(Subdivide(MakeBox({2, 1, 3}), 2), glm::vec3(0), 2.0f);
  ExpectWatertight(MakeIcosphere(1.0f, 2), glm::vec3(0), 2.0f);
  ExpectWatertight(MakeCylinder(0.5f, 2.0f, 16, true), glm::vec3(0.0f, 1.0f, 0.0f), 3.0f);
}

TEST(RayCast, BvhEqualsLinearOnThousandsOfQueries) {
  uint64_t seed = 200;
  for (const test::OracleCase& c : test::OracleMeshes()) {
    Bvh bvh = Bvh::Build(c.mesh);
    test::OracleCounts counts = test::CompareWithLinear(c.mesh, bvh, 3000, seed++);
    SCOPED_TRACE(c.name);
    EXPECT_EQ(counts.ray_mismatch, 0) << counts.first_mismatch;
    EXPECT_EQ(counts.segment_mismatch, 0) << counts.first_mismatch;
    EXPECT_GT(counts.ray_hits, 300);  // both hits and misses were compared
    EXPECT_LT(counts.ray_hits, 3000);
    EXPECT_GT(counts.segment_hits, 300);
    EXPECT_LT(counts.segment_hits, 3000);
  }
}

// FirstHitWithoutNormal is FirstHit's hit bit for bit, only the normal left zero.
TEST(RayCast, WithoutNormalIsTheSameHit) {
  const TriMesh m = Subdivide(MakeBox({2, 1, 3}), 3);
  const Bvh bvh = Bvh::Build(m);
  int hits = 0;
  for (int i = 0; i < 400; ++i) {
    const float a = 0.05f * static_cast<float>(i), b = 0.031f * static_cast<float>(i);
    const glm::vec3 o(3.0f * std::cos(a), 0.4f * std::sin(b), 3.0f * std::sin(a));
    const glm::vec3 d = glm::vec3(0.1f * std::sin(b), -0.05f, 0.2f * std::cos(b)) - o;
    const RayHit h = FirstHit(m, bvh, o, d, 1e6f);
    const RayHit w = FirstHitWithoutNormal(m, bvh, o, d, 1e6f);
    ASSERT_EQ(h.hit, w.hit);
    if (!h.hit) continue;
    ++hits;
    EXPECT_EQ(h.triangle, w.triangle);
    EXPECT_EQ(std::memcmp(&h.distance, &w.distance, sizeof(float)), 0);
    EXPECT_EQ(std::memcmp(&h.point, &w.point, sizeof(glm::vec3)), 0);
    EXPECT_EQ(std::memcmp(&h.barycentric, &w.barycentric, sizeof(glm::vec3)), 0);
    EXPECT_EQ(w.normal, glm::vec3(0.0f));
  }
  EXPECT_GT(hits, 300);
}

// The oblique rays' near/far slab test (WideRayKeys) keeps and keys a wide node's children as the
// general lane-by-lane RayBox does, bit for bit: down the tree of every oracle mesh along the
// kept children, rays from inside and outside, finite and infinite max distances, with the general
// path taken by rays with a zero component.
TEST(RayCast, ObliqueSlabKeysAreTheGeneralKeys) {
  Pcg32 rng(77, 5);
  int64_t kept = 0, nodes = 0;
  for (const test::OracleCase& c : test::OracleMeshes()) {
    const Bvh bvh = Bvh::Build(c.mesh);
    const std::vector<BvhWideNode>& wide = bvh.wide_nodes();
    if (wide.empty()) continue;
    const Bounds3 box = bvh.nodes()[0].bounds;
    for (int i = 0; i < 3000; ++i) {
      const glm::vec3 o =
          test::RandomPoint(rng, Bounds3{box.min - glm::vec3(1), box.max + glm::vec3(1)});
      glm::vec3 d = test::RandomDirection(rng);
      if (i % 10 == 0) d[i % 3] = 0.0f;
      const detail::PreparedRay ray = detail::PrepareRay(o, d, /*normalize=*/true);
      if (!ray.valid) continue;
      const double t_max = i % 2 ? std::numeric_limits<double>::infinity() : 4.0 * rng.Uniform();
      uint32_t at = 0;
      for (int level = 0; level < 64; ++level) {
        const BvhWideNode& n = wide[at];
        double fast[4] = {-1, -1, -1, -1}, general[4] = {-1, -1, -1, -1};
        const int a = detail::WideRayKeys(n, ray, t_max, fast);
        const int b = detail::WideRayKeysGeneral(n, ray, t_max, general);
        ++nodes;
        ASSERT_EQ(a, b) << c.name;
        ASSERT_EQ(std::memcmp(fast, general, sizeof fast), 0) << c.name;
        int next = -1;
        for (int k = 0; k < 4; ++k)
          if (n.count[k] != BvhWideNode::kEmpty && (a & (1 << k))) {
            ++kept;
            if (n.count[k] == 0 && (next < 0 || rng.Uniform() < 0.5)) next = k;
          }
        if (next < 0) break;
        at = n.child[next];
      }
    }
  }
  EXPECT_GT(nodes, 20000);
  EXPECT_GT(kept, 10000);
}

// The float lanes' conservative slab test (WideRayKeysConservative) keeps every child the exact
// test keeps, with a key at most the exact one, and FirstHit (which walks with it) finds the
// linear twin's hit: down the tree of every oracle mesh, rays from inside and outside the box,
// finite and infinite limits. Also: it does keep more now and then (the margins are there), and a
// box it drops is one the exact test drops.
TEST(RayCast, ConservativeFloatKeysKeepEveryExactChild) {
  Pcg32 rng(78, 5);
  int64_t kept = 0, nodes = 0, lower = 0;
  for (const test::OracleCase& c : test::OracleMeshes()) {
    const Bvh bvh = Bvh::Build(c.mesh);
    const std::vector<BvhWideNode>& wide = bvh.wide_nodes();
    if (wide.empty()) continue;
    const Bounds3 box = bvh.nodes()[0].bounds;
    for (int i = 0; i < 3000; ++i) {
      const glm::vec3 o =
          test::RandomPoint(rng, Bounds3{box.min - glm::vec3(1), box.max + glm::vec3(1)});
      const glm::vec3 d = test::RandomDirection(rng);
      const detail::PreparedRay ray = detail::PrepareRay(o, d, /*normalize=*/true);
      const detail::FloatSlabRay float_ray = detail::PrepareFloatSlabRay(ray, o, box);
      if (!float_ray.usable) continue;
      const double t_max = i % 2 ? std::numeric_limits<double>::infinity() : 4.0 * rng.Uniform();
      uint32_t at = 0;
      for (int level = 0; level < 64; ++level) {
        const BvhWideNode& n = wide[at];
        double exact[4], loose[4];
        const int a = detail::WideRayKeys(n, ray, t_max, exact);
        const int b = detail::WideRayKeysConservative(n, float_ray, t_max, loose);
        ++nodes;
        int next = -1;
        for (int k = 0; k < 4; ++k) {
          if (n.count[k] == BvhWideNode::kEmpty || !(a & (1 << k))) continue;
          ++kept;
          ASSERT_TRUE(b & (1 << k)) << c.name;
          ASSERT_LE(loose[k], exact[k]) << c.name;
          if (loose[k] < exact[k]) ++lower;
          if (n.count[k] == 0 && (next < 0 || rng.Uniform() < 0.5)) next = k;
        }
        if (next < 0) break;
        at = n.child[next];
      }
      const RayHit h = FirstHitWithoutNormal(c.mesh, bvh, o, d, static_cast<float>(t_max));
      const RayHit l = FirstHitLinear(c.mesh, o, d, static_cast<float>(t_max));
      ASSERT_EQ(h.hit, l.hit) << c.name;
      if (h.hit) {
        EXPECT_EQ(h.triangle, l.triangle) << c.name;
        EXPECT_EQ(std::memcmp(&h.distance, &l.distance, sizeof(float)), 0) << c.name;
      }
    }
  }
  EXPECT_GT(nodes, 20000);
  EXPECT_GT(kept, 10000);
  EXPECT_GT(lower, kept / 2);  // the keys are lowered, not copied
}

// The decoded boxes (Bvh::DecodeWideBoxes) are ChildBounds' floats, and the keys from them are
// WideRayKeysConservative's bits (kept bits and keys), so FirstHit walks the same nodes with or
// without them: the same visit counts, hit, triangle and distance bits, on every oracle mesh.
TEST(RayCast, DecodedWideBoxesGiveTheBytesKeys) {
  Pcg32 rng(79, 5);
  int64_t nodes = 0, hits = 0;
  for (const test::OracleCase& c : test::OracleMeshes()) {
    const Bvh plain = Bvh::Build(c.mesh);
    Bvh decoded = Bvh::Build(c.mesh);
    decoded.DecodeWideBoxes();
    const std::vector<BvhWideNode>& wide = decoded.wide_nodes();
    ASSERT_EQ(decoded.wide_boxes().size(), wide.size()) << c.name;
    EXPECT_TRUE(plain.wide_boxes().empty());
    for (std::size_t w = 0; w < wide.size(); ++w)
      for (int k = 0; k < 4; ++k) {
        const Bounds3 b = wide[w].ChildBounds(k);
        for (int a = 0; a < 3; ++a) {
          ASSERT_EQ(std::memcmp(&decoded.wide_boxes()[w].lo[a][k], &b.min[a], 4), 0) << c.name;
          ASSERT_EQ(std::memcmp(&decoded.wide_boxes()[w].hi[a][k], &b.max[a], 4), 0) << c.name;
        }
      }
    if (wide.empty()) continue;
    const Bounds3 box = decoded.nodes()[0].bounds;
    for (int i = 0; i < 2000; ++i) {
      const glm::vec3 o =
          test::RandomPoint(rng, Bounds3{box.min - glm::vec3(1), box.max + glm::vec3(1)});
      const glm::vec3 d = test::RandomDirection(rng);
      const detail::PreparedRay ray = detail::PrepareRay(o, d, /*normalize=*/true);
      const detail::FloatSlabRay float_ray = detail::PrepareFloatSlabRay(ray, o, box);
      const double t_max = i % 2 ? std::numeric_limits<double>::infinity() : 4.0 * rng.Uniform();
      if (float_ray.usable) {
        const std::size_t w = rng.NextU32() % wide.size();
        double from_bytes[4], from_boxes[4];
        const int a = detail::WideRayKeysConservative(wide[w], float_ray, t_max, from_bytes);
        const int b = detail::WideRayKeysConservativeDecoded(decoded.wide_boxes()[w], float_ray,
                                                             t_max, from_boxes);
        ASSERT_EQ(a, b) << c.name;
        for (int k = 0; k < 4; ++k) {
          if (a & (1 << k)) {
            ASSERT_EQ(std::memcmp(&from_bytes[k], &from_boxes[k], 8), 0) << c.name;
          }
        }
        ++nodes;
      }
      QueryStats sp, sd;
      const RayHit hp = FirstHitWithoutNormal(c.mesh, plain, o, d, static_cast<float>(t_max), &sp);
      const RayHit hd =
          FirstHitWithoutNormal(c.mesh, decoded, o, d, static_cast<float>(t_max), &sd);
      const RayHit l = FirstHitLinear(c.mesh, o, d, static_cast<float>(t_max));
      ASSERT_EQ(sp.nodes_visited, sd.nodes_visited) << c.name;
      ASSERT_EQ(sp.triangles_tested, sd.triangles_tested) << c.name;
      ASSERT_EQ(hd.hit, hp.hit) << c.name;
      ASSERT_EQ(hd.hit, l.hit) << c.name;
      if (hd.hit) {
        ++hits;
        EXPECT_EQ(hd.triangle, l.triangle) << c.name;
        EXPECT_EQ(std::memcmp(&hd.distance, &l.distance, sizeof(float)), 0) << c.name;
        EXPECT_EQ(std::memcmp(&hd.distance, &hp.distance, sizeof(float)), 0) << c.name;
      }
    }
  }
  EXPECT_GT(nodes, 10000);
  EXPECT_GT(hits, 1000);
}

// A ray too large for float lanes (or with a zero direction component) keeps the exact test.
TEST(RayCast, FloatSlabRayOnlyForObliqueTameRays) {
  const Bounds3 box{glm::vec3(-1), glm::vec3(1)};
  auto usable = [&](glm::vec3 o, glm::vec3 d, Bounds3 b) {
    return detail::PrepareFloatSlabRay(detail::PrepareRay(o, d, true), o, b).usable;
  };
  EXPECT_TRUE(usable({0, 0, 0}, {1, 2, 3}, box));
  EXPECT_FALSE(usable({0, 0, 0}, {1, 0, 3}, box));
  EXPECT_FALSE(usable({0, 0, 0}, {1, 1e-13f, 3}, box));  // |inverse| > 2^40
  EXPECT_FALSE(usable({2e12f, 0, 0}, {1, 2, 3}, box));
  EXPECT_FALSE(usable({0, 0, 0}, {1, 2, 3}, Bounds3{glm::vec3(-1), glm::vec3(1e13f)}));
}

TEST(RayCast, StatsCountQueries) {
  TriMesh m = MakeIcosphere(1.0f, 4);
  Bvh bvh = Bvh::Build(m);
  QueryStats s;
  (void)FirstHit(m, bvh, {0, 0, 5}, {0, 0, -1}, 10.0f, &s);
  (void)SegmentHits(m, bvh, {0, 0, 5}, {0, 0, 0}, &s);
  EXPECT_EQ(s.queries, 2u);
  EXPECT_GT(s.nodes_visited, 2u);
  EXPECT_GT(s.triangles_tested, 0u);
  EXPECT_LT(s.triangles_tested, 100u);  // of 5120
}

}  // namespace
}  // namespace niwa::geom

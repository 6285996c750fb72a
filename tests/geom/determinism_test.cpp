// Same bits natively and in WASM: one digest over primitives, BVH trees, query answers and samples,
// checked against the value both builds gave when this test was written (native g++ 12 and em++
// 3.1.6 under node, 2026-12-01). A change to any of them that moves a bit changes the digest:
// then check that native and WASM still agree with each other and record the new value.
#include <gtest/gtest.h>

#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <type_traits>
#include <vector>

#include "geom/bvh.h"
#include "geom/closest_point.h"
#include "geom/primitives.h"
#include "geom/ray_cast.h"
#include "geom/surface_sampling.h"
#include "geom_oracle.h"
#include "support/test_meshes.h"

namespace niwa::geom {
namespace {

struct Digest {
  uint64_t h = 1469598103934665603ULL;  // FNV-1a 64
  void Bytes(const void* data, std::size_t n) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ULL;
  }
  template <typename T>
  void Vector(const std::vector<T>& v) {
    static_assert(std::has_unique_object_representations_v<T> || std::is_floating_point_v<T> ||
                  std::is_same_v<T, glm::vec3> || std::is_same_v<T, glm::vec2>);
    Bytes(v.data(), v.size() * sizeof(T));
  }
  void Value(float f) { Bytes(&f, sizeof f); }
  void Value(uint32_t u) { Bytes(&u, sizeof u); }
};

uint64_t GeometryDigest() {
  Digest d;
  for (const test::OracleCase& c : test::OracleMeshes()) {
    d.Vector(c.mesh.positions);
    d.Vector(c.mesh.normals);
    d.Vector(c.mesh.uvs);
    d.Vector(c.mesh.indices);
    Bvh bvh = Bvh::Build(c.mesh);
    d.Value(static_cast<uint32_t>(bvh.node_count()));
    d.Value(static_cast<uint32_t>(bvh.depth()));
    for (const BvhNode& n : bvh.nodes()) {
      d.Bytes(&n.bounds.min, sizeof n.bounds.min);
      d.Bytes(&n.bounds.max, sizeof n.bounds.max);
      d.Value(n.first);
      d.Value(n.count);
    }
    d.Vector(bvh.order());
    Pcg32 rng(31);
    Bounds3 box = MeshBounds(c.mesh);
    for (int i = 0; i < 500; ++i) {
      glm::vec3 p = test::RandomPoint(rng, box);
      glm::vec3 dir = test::RandomDirection(rng);
      ClosestHit h = ClosestPoint(c.mesh, bvh, p, 0.5f * glm::length(box.diagonal()));
      d.Value(h.found ? h.triangle : 0xffffffffu);
      d.Value(h.distance);
      d.Bytes(&h.point, sizeof h.point);
      RayHit r = FirstHit(c.mesh, bvh, p, dir, 1e6f);
      d.Value(r.hit ? r.triangle : 0xffffffffu);
      d.Value(r.distance);
      d.Value(SegmentHits(c.mesh, bvh, p, p + dir * 0.3f) ? 1u : 0u);
    }
    for (const SurfaceSample& s : SampleSurface(c.mesh, 200, 8)) {
      d.Bytes(&s.point, sizeof s.point);
      d.Value(s.triangle);
      d.Bytes(&s.normal, sizeof s.normal);
    }
  }
  // A mesh past the threaded build's threshold (natively its root's halves are built on two
  // threads; WASM builds on one): the same nodes either way.
  TriMesh big = Subdivide(MakePlane(2.0f, 1.0f, 64, 32), 2);  // 65,536 triangles
  Bvh big_bvh = Bvh::Build(big);
  for (const BvhNode& n : big_bvh.nodes()) {
    d.Bytes(&n.bounds.min, sizeof n.bounds.min);
    d.Bytes(&n.bounds.max, sizeof n.bounds.max);
    d.Value(n.first);
    d.Value(n.count);
  }
  d.Vector(big_bvh.order());
  return d.h;
}

// The threaded build (native) gives the nodes and order of the one-thread build, byte for byte.
TEST(Determinism, ThreadedBuildEqualsOneThread) {
  TriMesh big = Subdivide(MakePlane(2.0f, 1.0f, 64, 32), 2);
  ASSERT_GE(big.triangle_count(), 65536u);
  BvhOptions one;
  one.threads = false;
  Bvh a = Bvh::Build(big), b = Bvh::Build(big, one);
  ASSERT_EQ(a.node_count(), b.node_count());
  EXPECT_EQ(a.depth(), b.depth());
  EXPECT_EQ(0, std::memcmp(a.nodes().data(), b.nodes().data(), a.nodes().size() * sizeof(BvhNode)));
  EXPECT_EQ(a.order(), b.order());
  EXPECT_EQ(a.wide_nodes().size(), b.wide_nodes().size());
  EXPECT_EQ(0, std::memcmp(a.wide_nodes().data(), b.wide_nodes().data(),
                           a.wide_nodes().size() * sizeof(BvhWideNode)));
}

TEST(Determinism, SameDigestNativelyAndInWasm) {
  uint64_t digest = GeometryDigest();
  std::printf("geometry digest %016" PRIx64 "\n", digest);
  EXPECT_EQ(digest, GeometryDigest());  // and within one run
  EXPECT_EQ(digest, 0x4ea63785c1fb9a13ULL)
      << "recorded digest of both builds; see the file's first lines";
}

}  // namespace
}  // namespace niwa::geom

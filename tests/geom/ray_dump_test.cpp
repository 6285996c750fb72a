// The ray file (geom/ray_dump.h): bytes written and read back to the same mesh, rays and hits;
// the layout the node peer reads (header words, a ray's 36 bytes); files that are not one refused
// naming the field.
#include "geom/ray_dump.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>

#include "geom/primitives.h"
#include "geom/ray_cast.h"

namespace niwa::geom {
namespace {

std::vector<CastRay> BoxRays(const TriMesh& box, const Bvh& bvh) {
  std::vector<CastRay> rays;
  const float inf = std::numeric_limits<float>::infinity();
  for (int i = 0; i < 40; ++i) {
    CastRay r;
    const float f = static_cast<float>(i);
    r.origin = glm::vec3(-0.9f + 0.045f * f, 0.3f, 5.0f);
    r.dir = glm::vec3(0.01f * f, -0.02f, -1.0f);
    r.max_distance = i % 5 == 0 ? 3.0f : inf;  // some stop short of the box
    const RayHit h = FirstHit(box, bvh, r.origin, r.dir, r.max_distance);
    r.hit = h.hit;
    r.triangle = h.triangle;
    r.distance = h.distance;
    rays.push_back(r);
  }
  return rays;
}

TEST(RayDump, RoundTripsTheMeshRaysAndHits) {
  const TriMesh box = MakeBox({2.0f, 2.0f, 2.0f});
  const Bvh bvh = Bvh::Build(box);
  const std::vector<CastRay> rays = BoxRays(box, bvh);
  int hits = 0;
  for (const CastRay& r : rays) hits += r.hit ? 1 : 0;
  ASSERT_GT(hits, 10);
  ASSERT_LT(hits, 40);  // misses too
  const std::string bytes = WriteRayDump(box, rays);
  EXPECT_EQ(bytes.size(), kRayDumpHeaderBytes + 12 * box.positions.size() + 4 * box.indices.size() +
                              kRayDumpRayBytes * rays.size());
  const Result<RayDump> back = ReadRayDump(bytes);
  ASSERT_TRUE(back.ok()) << back.status().Line();
  EXPECT_EQ(back->mesh.positions, box.positions);
  EXPECT_EQ(back->mesh.indices, box.indices);
  ASSERT_EQ(back->rays.size(), rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const CastRay &a = rays[i], &b = back->rays[i];
    EXPECT_EQ(a.origin, b.origin);
    EXPECT_EQ(a.dir, b.dir);
    EXPECT_EQ(std::memcmp(&a.max_distance, &b.max_distance, 4), 0);  // inf too
    EXPECT_EQ(a.hit, b.hit);
    if (a.hit) {
      EXPECT_EQ(a.triangle, b.triangle);
      EXPECT_EQ(a.distance, b.distance);
    }
  }
  // The same bytes again from what was read.
  EXPECT_EQ(WriteRayDump(back->mesh, back->rays), bytes);
}

TEST(RayDump, LayoutIsLittleEndianWords) {
  const TriMesh box = MakeBox({2.0f, 2.0f, 2.0f});
  CastRay miss;
  miss.origin = glm::vec3(1.5f, 0, 0);
  miss.dir = glm::vec3(1, 0, 0);
  miss.max_distance = std::numeric_limits<float>::infinity();
  const std::string bytes = WriteRayDump(box, {miss});
  EXPECT_EQ(bytes.substr(0, 8), "NIWARAY1");
  auto word = [&](std::size_t at) {
    uint32_t v = 0;
    for (int k = 0; k < 4; ++k)
      v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[at + k])) << (8 * k);
    return v;
  };
  EXPECT_EQ(word(8), box.positions.size());
  EXPECT_EQ(word(12), box.triangle_count());
  EXPECT_EQ(word(16), 1u);
  EXPECT_EQ(word(20), 0u);
  const std::size_t ray = bytes.size() - kRayDumpRayBytes;
  EXPECT_EQ(word(ray), 0x3fc00000u);       // 1.5f
  EXPECT_EQ(word(ray + 24), 0x7f800000u);  // +inf
  EXPECT_EQ(word(ray + 28), 0xffffffffu);  // no hit: -1
  EXPECT_EQ(word(ray + 32), 0u);
}

TEST(RayDump, RefusesWhatIsNotARayFile) {
  const TriMesh box = MakeBox({2.0f, 2.0f, 2.0f});
  const Bvh bvh = Bvh::Build(box);
  const std::string bytes = WriteRayDump(box, BoxRays(box, bvh));
  EXPECT_EQ(ReadRayDump("NIWARAY", "--rays").status().field(), "--rays");
  EXPECT_FALSE(ReadRayDump("NIWARAY2" + bytes.substr(8)).ok());
  const Status cut = ReadRayDump(bytes.substr(0, bytes.size() - 1)).status();
  EXPECT_EQ(cut.field(), "rays");
  EXPECT_NE(cut.message().find("its header declares"), std::string::npos) << cut.message();
  // An index past the vertices.
  std::string bad_index = bytes;
  bad_index[kRayDumpHeaderBytes + 12 * box.positions.size()] = static_cast<char>(0xff);
  EXPECT_NE(ReadRayDump(bad_index).status().message().find("must be below"), std::string::npos);
  // A hit on a triangle past the mesh's.
  std::string bad_hit = bytes;
  const std::size_t first_ray = bytes.size() - 40 * kRayDumpRayBytes;
  for (int k = 0; k < 4; ++k) bad_hit[first_ray + 28 + k] = k == 0 ? 100 : 0;
  EXPECT_NE(ReadRayDump(bad_hit).status().message().find("hit on triangle 100"), std::string::npos);
}

}  // namespace
}  // namespace niwa::geom

// The photon pass's rays (TracePhotons' `rays`, MossRun::NextDayPhotons; the file of
// `niwa moss photons --rays`): recording them leaves the photon map as it was, each recorded ray
// cast again finds the recorded hit, the rays account for every stored land photon and escape,
// and the file read back is the same rays.
#include <gtest/gtest.h>

#include <cstring>

#include "geom/ray_cast.h"
#include "geom/ray_dump.h"
#include "moss/moss_run.h"
#include "moss/photons.h"

namespace niwa::moss {
namespace {

bool SameMap(const PhotonMap& a, const PhotonMap& b) {
  if (a.photons.size() != b.photons.size() || a.stored_by_depth != b.stored_by_depth ||
      a.escaped != b.escaped || a.absorbed != b.absorbed)
    return false;
  for (std::size_t i = 0; i < a.photons.size(); ++i) {
    const Photon &p = a.photons[i], &q = b.photons[i];
    if (p.position != q.position || p.target != q.target || p.depth != q.depth ||
        p.on_moss != q.on_moss)
      return false;
  }
  return true;
}

TEST(MossPhotonRays, RecordingLeavesTheMapAndEveryRayRecastsToItsHit) {
  const MossParams params = *MossPreset("nomura2010");
  const SoilCells cells = *MakeSoilCells(*BuildScene("thesis"), SoilCellOptions{});
  const PhotonLight light = *PhotonLightOf(params, cells);
  MossOccluders none;
  none.Build({}, 0.005);
  PhotonMap plain, recorded;
  Pcg32 a(3, 1), b(3, 1);
  TracePhotons(cells, none, light, 2048, &a, &plain);
  std::vector<geom::CastRay> rays;
  TracePhotons(cells, none, light, 2048, &b, &recorded, &rays);
  EXPECT_TRUE(SameMap(plain, recorded));
  // No mosses: a ray's land hit is a stored photon, a ray without one an escape.
  int64_t hits = 0, misses = 0, stored = 0;
  for (int64_t n : recorded.stored_by_depth) stored += n;
  for (const geom::CastRay& r : rays) (r.hit ? hits : misses) += 1;
  EXPECT_EQ(hits, stored);
  EXPECT_EQ(misses, recorded.escaped);
  EXPECT_GT(rays.size(), 2048u);  // bounces
  for (std::size_t i = 0, k = 0; i < rays.size(); ++i) {
    const geom::CastRay& r = rays[i];
    const geom::RayHit h =
        geom::FirstHitWithoutNormal(cells.mesh, cells.bvh, r.origin, r.dir, r.max_distance);
    ASSERT_EQ(h.hit, r.hit) << "ray " << i;
    if (!r.hit) continue;
    EXPECT_EQ(h.triangle, r.triangle) << "ray " << i;
    EXPECT_EQ(h.distance, r.distance) << "ray " << i;
    // The map's photons in the rays' order.
    EXPECT_EQ(recorded.photons[k++].target, r.triangle) << "ray " << i;
  }
}

TEST(MossPhotonRays, NextDayRaysWithMossesRoundTripThroughTheFile) {
  MossState state;
  state.scene = "walls";
  state.days = 3;
  ASSERT_TRUE(state.params.Set(MossParam::kPhotons, 1024).ok());
  Result<MossRun> run = MossRun::Start(state, Budget{});
  ASSERT_TRUE(run.ok()) << run.status().Line();
  ASSERT_TRUE(run->Advance(nullptr).ok());
  ASSERT_GT(run->world().mosses.size(), 0u);
  std::vector<geom::CastRay> rays;
  const PhotonMap with = run->NextDayPhotons(&rays);
  EXPECT_TRUE(SameMap(with, run->NextDayPhotons()));
  // A ray stopped by a moss still records the land hit behind it (or none): at least one ray
  // a photon, and every stored land photon came from a ray that hit its cell.
  EXPECT_GE(rays.size(), 1024u);
  int64_t land = 0, ray_hits = 0;
  for (const Photon& p : with.photons) land += p.on_moss ? 0 : 1;
  for (const geom::CastRay& r : rays) ray_hits += r.hit ? 1 : 0;
  EXPECT_GE(ray_hits, land);
  const std::string bytes = geom::WriteRayDump(run->cells().mesh, rays);
  const Result<geom::RayDump> back = geom::ReadRayDump(bytes);
  ASSERT_TRUE(back.ok()) << back.status().Line();
  EXPECT_EQ(back->mesh.positions, run->cells().mesh.positions);
  EXPECT_EQ(back->mesh.indices, run->cells().mesh.indices);
  ASSERT_EQ(back->rays.size(), rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    EXPECT_EQ(back->rays[i].origin, rays[i].origin);
    EXPECT_EQ(back->rays[i].dir, rays[i].dir);
    EXPECT_EQ(back->rays[i].hit, rays[i].hit);
    EXPECT_EQ(back->rays[i].triangle, rays[i].triangle);
    EXPECT_EQ(back->rays[i].distance, rays[i].distance);
  }
  // The file's estimate names what it writes.
  const Result<Estimate> e = run->ExportEstimate("rays");
  ASSERT_TRUE(e.ok());
  EXPECT_GT(e->memory_bytes, static_cast<double>(bytes.size()));
  EXPECT_NE(e->what.find("rays"), std::string::npos);
}

}  // namespace
}  // namespace niwa::moss

// A file of cast rays and the hits one tracer found, with the mesh they were cast at: the photon
// tracer's rays written out (niwa moss photons --rays) so another ray tracer can be timed and
// checked on the same rays and triangles (bench/moss_rays_peer.mjs, three-mesh-bvh). Plain
// little-endian binary, every field 4 bytes so a reader can view it as typed arrays:
//   "NIWARAY1", u32 vertices V, u32 triangles T, u32 rays R, u32 0,
//   V x (f32 x, y, z), T x (u32 a, b, c),
//   R x (f32 origin x, y, z, f32 dir x, y, z, f32 max_distance, i32 triangle (-1: no hit),
//        f32 distance (0 without a hit)).
// Does not: cast rays (ray_cast.h) or keep normals, UVs or attributes.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "base/status.h"
#include "geom/tri_mesh.h"

namespace niwa::geom {

// One ray as given to FirstHit (dir as passed: FirstHit normalises it) and what it hit.
struct CastRay {
  glm::vec3 origin{0}, dir{0};
  float max_distance = 0;  // may be +inf
  bool hit = false;
  uint32_t triangle = 0;  // with hit
  float distance = 0;     // with hit: along unit(dir)
};

struct RayDump {
  TriMesh mesh;  // positions and indices
  std::vector<CastRay> rays;
};

constexpr std::size_t kRayDumpHeaderBytes = 24;
constexpr std::size_t kRayDumpRayBytes = 36;

// The file's bytes.
std::string WriteRayDump(const TriMesh& mesh, const std::vector<CastRay>& rays);
// The file read back; errors name `field`: a wrong magic, a size that is not the header's, an
// index outside the vertices or a hit triangle outside the triangles.
Result<RayDump> ReadRayDump(std::string_view bytes, const std::string& field = "rays");

}  // namespace niwa::geom

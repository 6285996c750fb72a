// The ray file of ray_dump.h: written and read byte by byte (little-endian on every build).
#include "geom/ray_dump.h"

#include <cstring>

namespace niwa::geom {
namespace {

constexpr char kRayDumpMagic[8] = {'N', 'I', 'W', 'A', 'R', 'A', 'Y', '1'};

void DumpPutU32(uint32_t v, std::string* out) {
  for (int k = 0; k < 4; ++k) out->push_back(static_cast<char>((v >> (8 * k)) & 0xffu));
}
void DumpPutF32(float f, std::string* out) {
  uint32_t v = 0;
  std::memcpy(&v, &f, 4);
  DumpPutU32(v, out);
}
uint32_t DumpGetU32(std::string_view bytes, std::size_t* at) {
  uint32_t v = 0;
  for (int k = 0; k < 4; ++k)
    v |= static_cast<uint32_t>(static_cast<unsigned char>(bytes[*at + k])) << (8 * k);
  *at += 4;
  return v;
}
float DumpGetF32(std::string_view bytes, std::size_t* at) {
  const uint32_t v = DumpGetU32(bytes, at);
  float f = 0;
  std::memcpy(&f, &v, 4);
  return f;
}

}  // namespace

std::string WriteRayDump(const TriMesh& mesh, const std::vector<CastRay>& rays) {
  std::string out;
  out.reserve(kRayDumpHeaderBytes + 12 * mesh.positions.size() + 4 * mesh.indices.size() +
              kRayDumpRayBytes * rays.size());
  out.append(kRayDumpMagic, sizeof kRayDumpMagic);
  DumpPutU32(static_cast<uint32_t>(mesh.positions.size()), &out);
  DumpPutU32(static_cast<uint32_t>(mesh.triangle_count()), &out);
  DumpPutU32(static_cast<uint32_t>(rays.size()), &out);
  DumpPutU32(0, &out);
  for (const glm::vec3& p : mesh.positions)
    for (int k = 0; k < 3; ++k) DumpPutF32(p[k], &out);
  for (std::size_t i = 0; i < 3 * mesh.triangle_count(); ++i) DumpPutU32(mesh.indices[i], &out);
  for (const CastRay& r : rays) {
    for (int k = 0; k < 3; ++k) DumpPutF32(r.origin[k], &out);
    for (int k = 0; k < 3; ++k) DumpPutF32(r.dir[k], &out);
    DumpPutF32(r.max_distance, &out);
    DumpPutU32(r.hit ? r.triangle : 0xffffffffu, &out);
    DumpPutF32(r.hit ? r.distance : 0.0f, &out);
  }
  return out;
}

Result<RayDump> ReadRayDump(std::string_view bytes, const std::string& field) {
  if (bytes.size() < kRayDumpHeaderBytes || std::memcmp(bytes.data(), kRayDumpMagic, 8) != 0)
    return Status::Error(field, "is not a Niwa ray file (it must start with NIWARAY1)");
  std::size_t at = 8;
  const uint64_t vertices = DumpGetU32(bytes, &at), triangles = DumpGetU32(bytes, &at),
                 rays = DumpGetU32(bytes, &at);
  if (DumpGetU32(bytes, &at) != 0)
    return Status::Error(field, "has a nonzero reserved header word");
  const uint64_t size =
      kRayDumpHeaderBytes + 12 * vertices + 12 * triangles + kRayDumpRayBytes * rays;
  if (bytes.size() != size)
    return Status::Error(field, "is " + std::to_string(bytes.size()) +
                                    " bytes; its header declares " + std::to_string(size));
  RayDump dump;
  dump.mesh.positions.resize(vertices);
  for (glm::vec3& p : dump.mesh.positions)
    for (int k = 0; k < 3; ++k) p[k] = DumpGetF32(bytes, &at);
  dump.mesh.indices.resize(3 * triangles);
  for (uint32_t& i : dump.mesh.indices) {
    i = DumpGetU32(bytes, &at);
    if (i >= vertices)
      return Status::Error(field, "has an index " + std::to_string(i) + "; must be below " +
                                      std::to_string(vertices) + " (the vertices)");
  }
  dump.rays.resize(rays);
  for (CastRay& r : dump.rays) {
    for (int k = 0; k < 3; ++k) r.origin[k] = DumpGetF32(bytes, &at);
    for (int k = 0; k < 3; ++k) r.dir[k] = DumpGetF32(bytes, &at);
    r.max_distance = DumpGetF32(bytes, &at);
    const uint32_t t = DumpGetU32(bytes, &at);
    const float distance = DumpGetF32(bytes, &at);
    r.hit = t != 0xffffffffu;
    if (r.hit && t >= triangles)
      return Status::Error(field, "has a hit on triangle " + std::to_string(t) +
                                      "; must be below " + std::to_string(triangles));
    r.triangle = r.hit ? t : 0;
    r.distance = r.hit ? distance : 0.0f;
  }
  return dump;
}

}  // namespace niwa::geom

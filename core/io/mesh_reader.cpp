// Mesh input shared by the readers: capped file reading, the degenerate-triangle test, and the
// reader picked by file extension.
#include "io/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "base/echo.h"
#include "io/gltf_reader.h"
#include "io/obj_reader.h"

namespace niwa::io {

std::string BaseName(const std::string& path) {
  std::size_t slash = path.find_last_of("/\\");
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

Result<std::string> ReadFileCapped(const std::string& path, std::size_t max_bytes) {
  const std::string field = BaseName(path);
  // Only a regular file is opened: a FIFO would block the open, a device never ends.
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (!error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
    return Status::Error(field, "cannot read '" + Echo(path) + "': not a regular file");
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::Error(field, "cannot open '" + path + "' (missing or unreadable)");
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  if (size < 0) return Status::Error(field, "cannot read '" + path + "' (is it a folder?)");
  if (static_cast<std::size_t>(size) > max_bytes) {
    return Status::Error(field, "the file has " + std::to_string(size) + " bytes; the limit is " +
                                    std::to_string(max_bytes));
  }
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.seekg(0, std::ios::beg);
  in.read(bytes.data(), size);
  if (in.gcount() != size) {
    return Status::Error(field, "cannot read '" + path + "' (is it a folder?)");
  }
  return bytes;
}

bool DegenerateTriangle(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a);
  const glm::dvec3 n(e1.y * e2.z - e1.z * e2.y, e1.z * e2.x - e1.x * e2.z,
                     e1.x * e2.y - e1.y * e2.x);
  return n.x == 0.0 && n.y == 0.0 && n.z == 0.0;
}

Result<geom::TriMesh> ReadMeshBytes(const std::string& bytes, const std::string& name,
                                    MeshReadStats* stats) {
  const bool obj = name.size() >= 4 && (name.compare(name.size() - 4, 4, ".obj") == 0 ||
                                        name.compare(name.size() - 4, 4, ".OBJ") == 0);
  return obj ? ReadObjMesh(bytes, name, stats) : ReadGltfMesh(bytes, name, "", stats);
}

Result<geom::TriMesh> ReadMeshFile(const std::string& path, MeshReadStats* stats) {
  std::string name = BaseName(path);
  std::size_t dot = name.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : name.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".glb" || ext == ".gltf") return ReadGltfFile(path, stats);
  if (ext == ".obj") return ReadObjFile(path, stats);
  return Status::Error(name,
                       "unknown mesh file extension '" + ext + "'; must be .glb, .gltf or .obj");
}

}  // namespace niwa::io

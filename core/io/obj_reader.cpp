// Wavefront OBJ reader, written small on purpose: Debian's tinyobjloader (2.0.0rc10, the library
// that fits both builds) turns unparsable numbers such as "nan" or "1.0abc" into 0 and reports
// out-of-range indices as warnings without always naming the line, so bad input would load as a
// wrong mesh. tests/io/obj_reader_test.cpp checks this reader against tinyobjloader on valid files.
#include "io/obj_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

namespace niwa::io {
namespace {

// Statements of the OBJ format (Wavefront "Object Files (.obj)", Appendix B1) that carry no
// triangles: accepted and ignored.
bool IgnoredStatement(std::string_view k) {
  static const char* const kNames[] = {
      "vp",    "o",        "g",        "s",    "usemtl",     "mtllib",    "cstype",
      "deg",   "bmat",     "step",     "curv", "curv2",      "surf",      "parm",
      "trim",  "hole",     "scrv",     "sp",   "end",        "con",       "mg",
      "bevel", "c_interp", "d_interp", "lod",  "shadow_obj", "trace_obj", "ctech",
      "stech", "maplib",   "usemap",   "call", "csh"};
  for (const char* n : kNames)
    if (k == n) return true;
  return false;
}

std::vector<std::string_view> Tokens(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// A whole token as a double (strtod: "nan" and "inf" parse and are rejected by the caller).
bool ParseDouble(std::string_view token, double* out) {
  std::string s(token);
  char* end = nullptr;
  errno = 0;
  *out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && !s.empty();
}

// 64 bits on every build (long is 32 bits in WASM): the same index gives the same line natively
// and in WASM.
bool ParseLong(std::string_view token, long long* out) {
  std::string s(token);
  if (s.empty()) return false;
  char* end = nullptr;
  errno = 0;
  *out = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno == 0;
}

class ObjParser {
 public:
  ObjParser(std::string name, MeshReadStats* stats) : name_(std::move(name)), stats_(stats) {}

  Status Line(std::size_t number, std::string_view line, geom::TriMesh* mesh);
  std::size_t points_lines = 0, faces = 0;

 private:
  Status Error(std::size_t number, const std::string& message) const {
    return Status::Error(name_, "line " + std::to_string(number) + ": " + message);
  }
  // Resolves a 1-based or negative OBJ index against count items read so far.
  Status Index(std::size_t number, std::string_view token, const char* what, std::size_t count,
               uint32_t* out) const;

  std::string name_;
  MeshReadStats* stats_;
  std::size_t texcoords_ = 0, normals_ = 0;
};

Status ObjParser::Index(std::size_t number, std::string_view token, const char* what,
                        std::size_t count, uint32_t* out) const {
  long long i = 0;
  const std::string range = count == 0 ? std::string("none are defined yet")
                                       : "must be in [1, " + std::to_string(count) + "] or [-" +
                                             std::to_string(count) + ", -1]";
  if (!ParseLong(token, &i)) {
    return Error(number, std::string(what) + " index '" + std::string(token) +
                             "' is not a whole number; " + range);
  }
  const long long n = static_cast<long long>(count);
  if (i == 0 || i > n || i < -n) {
    return Error(number,
                 std::string(what) + " index " + std::to_string(i) + " is out of range; " + range);
  }
  *out = static_cast<uint32_t>(i > 0 ? i - 1 : n + i);
  return Status::Ok();
}

Status ObjParser::Line(std::size_t number, std::string_view line, geom::TriMesh* mesh) {
  std::size_t hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> t = Tokens(line);
  if (t.empty()) return Status::Ok();
  const std::string_view key = t[0];
  if (key == "v") {
    if (t.size() < 4) return Error(number, "a vertex needs three numbers: v x y z");
    double xyz[3];
    for (int k = 0; k < 3; ++k) {
      if (!ParseDouble(t[static_cast<std::size_t>(k) + 1], &xyz[k])) {
        return Error(number, "vertex coordinate '" +
                                 std::string(t[static_cast<std::size_t>(k) + 1]) +
                                 "' is not a number");
      }
      if (!std::isfinite(xyz[k])) return Error(number, "vertex position is NaN or infinite");
    }
    glm::vec3 p(static_cast<float>(xyz[0]), static_cast<float>(xyz[1]), static_cast<float>(xyz[2]));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      return Error(number, "vertex position is too large for a float");
    }
    if (mesh->positions.size() >= kMaxMeshVertices) {
      return Error(number, "more than " + std::to_string(kMaxMeshVertices) +
                               " vertices; the limit is " + std::to_string(kMaxMeshVertices) +
                               " (12 M)");
    }
    mesh->positions.push_back(p);
    return Status::Ok();
  }
  if (key == "vt") {
    ++texcoords_;
    return Status::Ok();
  }
  if (key == "vn") {
    ++normals_;
    return Status::Ok();
  }
  if (key == "p" || key == "l") {
    ++points_lines;
    if (stats_ != nullptr) ++stats_->skipped_points_lines;
    return Status::Ok();
  }
  if (key == "f") {
    if (t.size() < 4) {
      return Error(number, "a face needs at least 3 vertices, got " + std::to_string(t.size() - 1));
    }
    std::vector<uint32_t> corners;
    corners.reserve(t.size() - 1);
    for (std::size_t k = 1; k < t.size(); ++k) {
      // v, v/vt, v//vn or v/vt/vn
      std::string_view c = t[k];
      std::size_t s1 = c.find('/');
      uint32_t v = 0, unused = 0;
      NIWA_RETURN_IF_ERROR(Index(number, c.substr(0, s1), "vertex", mesh->positions.size(), &v));
      if (s1 != std::string_view::npos) {
        std::string_view rest = c.substr(s1 + 1);
        std::size_t s2 = rest.find('/');
        std::string_view vt = rest.substr(0, s2);
        if (!vt.empty()) NIWA_RETURN_IF_ERROR(Index(number, vt, "texture", texcoords_, &unused));
        if (s2 != std::string_view::npos) {
          std::string_view vn = rest.substr(s2 + 1);
          NIWA_RETURN_IF_ERROR(Index(number, vn, "normal", normals_, &unused));
        } else if (vt.empty()) {
          return Error(number,
                       "face corner '" + std::string(c) + "' must be v, v/vt, v//vn or v/vt/vn");
        }
      }
      corners.push_back(v);
    }
    ++faces;
    if (stats_ != nullptr) ++stats_->primitives;
    // Fan triangulation: (c0, ci, ci+1).
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      if (mesh->triangle_count() + 1 > kMaxMeshTriangles) {
        return Error(number, "more than " + std::to_string(kMaxMeshTriangles) +
                                 " triangles; the limit is " + std::to_string(kMaxMeshTriangles) +
                                 " (4 M)");
      }
      uint32_t a = corners[0], b = corners[k], c = corners[k + 1];
      if (a == b || b == c || a == c ||
          DegenerateTriangle(mesh->positions[a], mesh->positions[b], mesh->positions[c])) {
        if (stats_ != nullptr) ++stats_->degenerate;
        continue;
      }
      mesh->indices.insert(mesh->indices.end(), {a, b, c});
    }
    return Status::Ok();
  }
  if (IgnoredStatement(key)) return Status::Ok();
  std::string shown(key.substr(0, 24));
  for (char& ch : shown)
    if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126) ch = '?';
  return Error(number, "unknown statement '" + shown + "' (not an OBJ file?)");
}

}  // namespace

Result<geom::TriMesh> ReadObjMesh(const std::string& text, const std::string& name,
                                  MeshReadStats* stats) {
  if (stats != nullptr) *stats = MeshReadStats{};
  if (text.find_first_not_of(" \t\r\n") == std::string::npos) {
    return Status::Error(name, "the file is empty");
  }
  if (text.find('\0') != std::string::npos) {
    return Status::Error(name, "not OBJ text: the file holds binary data");
  }
  geom::TriMesh mesh;
  ObjParser parser(name, stats);
  std::size_t number = 1, start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    NIWA_RETURN_IF_ERROR(
        parser.Line(number, std::string_view(text).substr(start, end - start), &mesh));
    start = end + 1;
    ++number;
  }
  if (parser.faces == 0) {
    if (parser.points_lines > 0) {
      return Status::Error(name, "only points or lines (" + std::to_string(parser.points_lines) +
                                     " statements), no faces");
    }
    return Status::Error(name, "no faces (f lines)");
  }
  if (mesh.indices.empty()) return Status::Error(name, "every triangle is degenerate (zero area)");
  if (stats != nullptr) stats->meshes = 1;
  return mesh;
}

Result<geom::TriMesh> ReadObjFile(const std::string& path, MeshReadStats* stats) {
  Result<std::string> text = ReadFileCapped(path);
  if (!text.ok()) return text.status();
  return ReadObjMesh(*text, BaseName(path), stats);
}

}  // namespace niwa::io

// The moss study's soil cells on a land mesh (soil_cells.h).
#include "moss/soil_cells.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

#include "geom/ray_cast.h"
#include "image/png.h"
#include "math/det_math.h"
#include "moss/sampling.h"

namespace niwa::moss {
namespace {

// One triangle being split: its corners (double), its parent's face and, on a textured face, the
// corners' UVs (split with the positions; zero otherwise).
struct CellSplitTri {
  glm::dvec3 a, b, c;
  uint32_t face;
  glm::dvec2 ua{0.0}, ub{0.0}, uc{0.0};
};

double LongestEdgeSquared(const CellSplitTri& t, int* which) {
  const double ab = glm::dot(t.b - t.a, t.b - t.a), bc = glm::dot(t.c - t.b, t.c - t.b),
               ca = glm::dot(t.a - t.c, t.a - t.c);
  *which = ab >= bc && ab >= ca ? 0 : (bc >= ca ? 1 : 2);
  return std::max(ab, std::max(bc, ca));
}

// Longest-edge bisection of one triangle until no edge exceeds `edge`: emits the leaves in
// depth-first order (the first half before the second), or only counts them when `out` is null.
std::size_t SplitCellTriangle(const CellSplitTri& t, double edge, std::vector<CellSplitTri>* out,
                              std::size_t limit) {
  std::vector<CellSplitTri> stack = {t};
  std::size_t count = 0;
  const double edge2 = edge * edge;
  while (!stack.empty()) {
    const CellSplitTri cur = stack.back();
    stack.pop_back();
    int which = 0;
    if (LongestEdgeSquared(cur, &which) <= edge2) {
      if (out) out->push_back(cur);
      if (++count > limit) return count;
      continue;
    }
    // Split the longest edge at its midpoint; the two halves keep the winding.
    CellSplitTri first = cur, second = cur;
    if (which == 0) {
      const glm::dvec3 m = 0.5 * (cur.a + cur.b);
      first.b = m, second.a = m;
      const glm::dvec2 mu = 0.5 * (cur.ua + cur.ub);
      first.ub = mu, second.ua = mu;
    } else if (which == 1) {
      const glm::dvec3 m = 0.5 * (cur.b + cur.c);
      first.c = m, second.b = m;
      const glm::dvec2 mu = 0.5 * (cur.ub + cur.uc);
      first.uc = mu, second.ub = mu;
    } else {
      const glm::dvec3 m = 0.5 * (cur.c + cur.a);
      first.a = m, second.c = m;
      const glm::dvec2 mu = 0.5 * (cur.uc + cur.ua);
      first.ua = mu, second.uc = mu;
    }
    stack.push_back(second);
    stack.push_back(first);
  }
  return count;
}

double LinearToSrgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * std::exp(std::log(c) / 2.4) - 0.055;
}

// The same curve through det_math (a texel's colour is the same bits in both builds).
double DetLinearToSrgb(double c) {
  c = std::clamp(c, 0.0, 1.0);
  return c <= 0.0031308 ? 12.92 * c : 1.055 * det::Exp(det::Log(c) / 2.4) - 0.055;
}
double DetSrgbToLinear(double c) {
  return c <= 0.04045 ? c / 12.92 : det::Exp(2.4 * det::Log((c + 0.055) / 1.055));
}

// A texel coordinate (u scaled by the side) under a glTF wrap mode, nearest texel.
int WrapTexel(double u, int side, int mode) {
  if (!std::isfinite(u)) u = 0.0;
  double t = u;
  if (mode == io::kWrapClampToEdge) {
    t = std::clamp(u, 0.0, 1.0);
  } else if (mode == io::kWrapMirroredRepeat) {
    const double period = u - 2.0 * std::floor(u / 2.0);  // [0, 2)
    t = period <= 1.0 ? period : 2.0 - period;
  } else {
    t = u - std::floor(u);  // [0, 1)
  }
  const int x = static_cast<int>(std::floor(t * side));
  return std::clamp(x, 0, side - 1);
}

}  // namespace

Geology GeologyOfColour(const glm::dvec3& srgb) {
  static const glm::dvec3 kRef[kGeologyCount] = {{0x4A / 255.0, 0x33 / 255.0, 0x22 / 255.0},
                                                 {0xC2 / 255.0, 0x9A / 255.0, 0x5B / 255.0},
                                                 {0x80 / 255.0, 0x80 / 255.0, 0x80 / 255.0}};
  int best = 0;
  double best_d = std::numeric_limits<double>::infinity();
  for (int g = 0; g < kGeologyCount; ++g) {
    const glm::dvec3 d = srgb - kRef[g];
    const double d2 = glm::dot(d, d);
    if (d2 < best_d) best_d = d2, best = g;
  }
  return static_cast<Geology>(best);
}

bool GeologyOfMaterialName(const std::string& name, Geology* geology) {
  std::string lower = name;
  for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (lower.find("humus") != std::string::npos) return *geology = Geology::kHumus, true;
  if (lower.find("sand") != std::string::npos) return *geology = Geology::kSandy, true;
  if (lower.find("asphalt") != std::string::npos) return *geology = Geology::kAsphalt, true;
  return false;
}

Geology GeologyOfTexel(const unsigned char* rgb, const glm::dvec3& tint) {
  if (tint == glm::dvec3(1.0)) return GeologyOfColour(glm::dvec3(rgb[0], rgb[1], rgb[2]) / 255.0);
  const glm::dvec3 linear(DetSrgbToLinear(rgb[0] / 255.0) * tint.x,
                          DetSrgbToLinear(rgb[1] / 255.0) * tint.y,
                          DetSrgbToLinear(rgb[2] / 255.0) * tint.z);
  return GeologyOfColour(
      {DetLinearToSrgb(linear.x), DetLinearToSrgb(linear.y), DetLinearToSrgb(linear.z)});
}

const unsigned char* SampleTexture(const SceneTexture& texture, glm::dvec2 uv) {
  const int x = WrapTexel(uv.x, texture.texels.width, texture.wrap_s);
  const int y = WrapTexel(uv.y, texture.texels.height, texture.wrap_t);
  return texture.texels.At(x, y);
}

Result<MossScene> SceneFromMesh(const geom::TriMesh& mesh,
                                const std::vector<io::MeshMaterial>& materials,
                                const std::string& name, const std::vector<io::MeshImage>& images) {
  MossScene scene;
  scene.name = name;
  scene.mesh.positions = mesh.positions;
  scene.mesh.indices = mesh.indices;
  scene.region_names = {"all"};
  scene.description = "a loaded mesh";
  const geom::VertexAttribute* colour = mesh.FindAttribute(io::kColorAttribute);
  const geom::VertexAttribute* material = mesh.FindAttribute(io::kMaterialAttribute);
  // The base colour textures the faces use, decoded once each (image index -> scene texture),
  // sampled where the reader put each vertex's baseColorTexture UV (its texCoord set with its
  // KHR_texture_transform applied).
  const geom::VertexAttribute* base_uv = mesh.FindAttribute(io::kBaseColorUvAttribute);
  const bool has_uvs = base_uv != nullptr && base_uv->components == 2 &&
                       base_uv->values.size() == 2 * mesh.positions.size();
  std::vector<int32_t> texture_of_material(materials.size(), -1);
  for (std::size_t mi = 0; mi < materials.size() && has_uvs; ++mi) {
    const int image_index = materials[mi].base_color_image;
    Geology named;
    if (image_index < 0 || static_cast<std::size_t>(image_index) >= images.size() ||
        images[static_cast<std::size_t>(image_index)].bytes.empty() ||
        GeologyOfMaterialName(materials[mi].name, &named)) {
      continue;
    }
    const io::MeshImage& im = images[static_cast<std::size_t>(image_index)];
    Result<image::Rgba8Image> decoded =
        image::DecodeRgba8PngOrJpeg(reinterpret_cast<const unsigned char*>(im.bytes.data()),
                                    im.bytes.size(), io::kMaxTexturePixels);
    if (!decoded.ok()) {
      return Status::Error(
          name, "material " + std::to_string(mi) +
                    (materials[mi].name.empty() ? "" : " '" + materials[mi].name + "'") +
                    " baseColorTexture image '" + im.name + "': " + decoded.status().message());
    }
    texture_of_material[mi] = static_cast<int32_t>(scene.textures.size());
    scene.textures.push_back(
        {std::move(decoded).value(), materials[mi].wrap_s, materials[mi].wrap_t});
  }
  const bool textured = !scene.textures.empty();
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const uint32_t v0 = mesh.indices[3 * t];
    const io::MeshMaterial* m = nullptr;
    int32_t texture = -1;
    if (material != nullptr) {
      const int index = static_cast<int>(material->values[v0]);
      if (index >= 0 && static_cast<std::size_t>(index) < materials.size()) {
        m = &materials[index];
        texture = texture_of_material[static_cast<std::size_t>(index)];
      }
    }
    Geology geology = Geology::kHumus;
    glm::dvec3 linear(1.0);
    if (m != nullptr && GeologyOfMaterialName(m->name, &geology)) {
      // the name overrides
    } else if (colour != nullptr || m != nullptr) {
      if (colour != nullptr) {
        glm::dvec3 sum(0.0);
        for (int k = 0; k < 3; ++k) {
          const std::size_t v = mesh.indices[3 * t + k];
          sum += glm::dvec3(colour->values[4 * v], colour->values[4 * v + 1],
                            colour->values[4 * v + 2]);
        }
        linear = sum / 3.0;
      }
      if (m != nullptr) linear *= glm::dvec3(m->base_color);
      geology =
          GeologyOfColour({LinearToSrgb(linear.x), LinearToSrgb(linear.y), LinearToSrgb(linear.z)});
    }
    scene.geology.push_back(geology);
    scene.region.push_back(0);
    if (textured) {
      scene.texture.push_back(texture);
      scene.tint.push_back(linear);
      for (int k = 0; k < 3; ++k) {
        const std::size_t v = mesh.indices[3 * t + k];
        scene.corner_uv.emplace_back(base_uv->values[2 * v], base_uv->values[2 * v + 1]);
      }
    }
  }
  return scene;
}

Result<SoilCells> MakeSoilCells(const MossScene& scene, const SoilCellOptions& options) {
  const geom::TriMesh& land = scene.mesh;
  if (land.triangle_count() == 0) return Status::Error("scene", "has no triangles");
  SoilCells cells;
  cells.region_names = scene.region_names;
  // A loaded mesh's textured faces: each cell samples the texture at its centroid's UV.
  const bool textured = !scene.textures.empty() && scene.texture.size() == land.triangle_count() &&
                        scene.corner_uv.size() == 3 * land.triangle_count() &&
                        scene.tint.size() == land.triangle_count();
  auto tri_of = [&](std::size_t t) {
    CellSplitTri tri{glm::dvec3(land.positions[land.indices[3 * t]]),
                     glm::dvec3(land.positions[land.indices[3 * t + 1]]),
                     glm::dvec3(land.positions[land.indices[3 * t + 2]]), static_cast<uint32_t>(t)};
    if (textured && scene.texture[t] >= 0) {
      tri.ua = glm::dvec2(scene.corner_uv[3 * t]);
      tri.ub = glm::dvec2(scene.corner_uv[3 * t + 1]);
      tri.uc = glm::dvec2(scene.corner_uv[3 * t + 2]);
    }
    return tri;
  };
  // The edge: soil_edge, doubled while the cells would exceed the cap: max_cells, or the land's
  // own triangles when it has more (each triangle is one cell at least; the run's estimate
  // decides whether that many are grown).
  const std::size_t cap = std::max(options.max_cells, land.triangle_count());
  double edge = options.soil_edge;
  for (int doubling = 0;; ++doubling) {
    std::size_t count = 0;
    for (std::size_t t = 0; t < land.triangle_count() && count <= cap; ++t)
      count += SplitCellTriangle(tri_of(t), edge, nullptr, cap - count);
    if (count <= cap) break;
    if (doubling == 16)
      return Status::Error("scene", "needs more than " + std::to_string(cap) +
                                        " soil cells even at soil_edge " + std::to_string(edge) +
                                        " (each triangle is one cell at least)");
    edge *= 2;
  }
  cells.soil_edge = edge;
  if (edge != options.soil_edge)
    cells.notices.push_back("soil_edge doubled to " + std::to_string(edge) + " m: more than " +
                            std::to_string(cap) + " soil cells" +
                            (cap > options.max_cells ? " (the land's own triangles)" : ""));
  std::vector<CellSplitTri> split;
  for (std::size_t t = 0; t < land.triangle_count(); ++t)
    SplitCellTriangle(tri_of(t), edge, &split, std::numeric_limits<std::size_t>::max());

  // The cell mesh (corners not shared: a cell is a triangle), its tree and the per-cell values.
  const std::size_t n = split.size();
  cells.mesh.positions.reserve(3 * n);
  cells.mesh.indices.reserve(3 * n);
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const CellSplitTri& s : split) {
    for (const glm::dvec3& p : {s.a, s.b, s.c}) {
      cells.mesh.indices.push_back(static_cast<uint32_t>(cells.mesh.positions.size()));
      cells.mesh.positions.push_back(glm::vec3(p));
      lo = glm::min(lo, glm::dvec3(glm::vec3(p)));
      hi = glm::max(hi, glm::dvec3(glm::vec3(p)));
    }
    const glm::dvec3 cr = glm::cross(s.b - s.a, s.c - s.a);
    const double len = glm::length(cr);
    cells.centroid.push_back((s.a + s.b + s.c) / 3.0);
    cells.normal.push_back(len > 0 ? cr / len : glm::dvec3(0, 1, 0));
    cells.area.push_back(0.5 * len);
    if (textured && scene.texture[s.face] >= 0) {
      const SceneTexture& texture = scene.textures[static_cast<std::size_t>(scene.texture[s.face])];
      cells.geology.push_back(
          GeologyOfTexel(SampleTexture(texture, (s.ua + s.ub + s.uc) / 3.0), scene.tint[s.face]));
    } else {
      cells.geology.push_back(scene.geology[s.face]);
    }
    cells.region.push_back(scene.region[s.face]);
  }
  cells.centre = 0.5 * (lo + hi);
  cells.radius = 0.5 * glm::length(hi - lo);
  cells.bvh = geom::Bvh::Build(cells.mesh);
  cells.bvh.DecodeWideBoxes();  // the photons' ray casts key children from them (96 B a node)

  // Soil depth (spec §1.2): a ray from 1e-4 m inside the face along −y (upward faces) or +y
  // (downward faces) to the first hit; none: open ground, h_max; near-vertical: h_wall.
  cells.h.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec3 c = cells.centroid[i], nrm = cells.normal[i];
    if (std::abs(nrm.y) <= kVerticalNy) {
      cells.h[i] = options.h_wall;
      continue;
    }
    const glm::dvec3 origin = c - 1e-4 * nrm;
    const glm::vec3 dir(0.0f, nrm.y > 0 ? -1.0f : 1.0f, 0.0f);
    const geom::RayHit hit = geom::FirstHit(cells.mesh, cells.bvh, glm::vec3(origin), dir,
                                            std::numeric_limits<float>::infinity());
    const double h =
        hit.hit ? 1000.0 * std::abs(static_cast<double>(hit.point.y) - c.y) : options.h_max;
    cells.h[i] = std::clamp(h, options.h_wall, options.h_max);
  }

  // Sky view (spec §1.3): the share of 64 cosine-weighted Hammersley rays about n from 1e-4 m off
  // the face that leave the enclosing sphere without hitting the land.
  cells.V_sky.assign(n, 1.0);
  if (options.sky_view) {
    const float reach = static_cast<float>(4.0 * cells.radius + 1.0);
    for (std::size_t i = 0; i < n; ++i) {
      const glm::vec3 origin(cells.centroid[i] + 1e-4 * cells.normal[i]);
      int open = 0;
      for (int r = 0; r < kSkyViewRays; ++r) {
        double u = 0, v = 0;
        Hammersley(r, kSkyViewRays, &u, &v);
        const glm::vec3 dir(CosineDirection(cells.normal[i], u, v));
        if (!geom::FirstHit(cells.mesh, cells.bvh, origin, dir, reach).hit) ++open;
      }
      cells.V_sky[i] = static_cast<double>(open) / kSkyViewRays;
    }
  }
  return cells;
}

}  // namespace niwa::moss

// Triangle-budgeted tree meshes and LOD .glb documents: tubes, crossed branch cards, twig cones and
// leaf-cluster cards chosen by a monotone bisection, with a CPU-rasterized card atlas.
//
// Why a rasterizer of our own: the atlas geometry (core/render/atlas_mesh) is already projected to
// atlas clip space, so painting it is a z-buffered triangle fill with a texture lookup (about 60
// lines); a software-rendering library would bring a GL state machine, and the result must be the
// same bits natively and in WASM (plain float arithmetic, no FMA contraction, fixed order).
#include "render/tree_lod.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <limits>
#include <utility>

#include "image/png.h"
#include "params/param_text.h"
#include "render/atlas_mesh.h"
#include "render/hybrid.h"
#include "sway/wind_attributes.h"
#include "tree/tree_gltf.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

constexpr int kCardPlanes = 2;     // crossed branch cards (thesis: >= 2 planes)
constexpr int kClusterPlanes = 3;  // leaf-cluster cards: normal z, x and y
constexpr int kTwigSides = 3;      // twig cones: 3 sides, 3 triangles (fewer than a card's 4)
constexpr int kClusterLadder[] = {32, 24, 16, 12, 8, 6, 4, 3, 2, 1};
constexpr int kBisections = 40;

long Triangles(const MeshBuffers& b) { return static_cast<long>(b.indices.size() / 3); }

bool LodUsable(const Branch& b) { return b.alive && b.nodes.size() >= 2; }

RenderOptions SceneOptions(int cells, int atlas_size) {
  RenderOptions o;
  o.leaf_mode = LeafMode::kClusterCards;  // branch cards carry wood only
  o.card_planes = kCardPlanes;
  o.cluster_cells = cells;
  o.cluster_planes = kClusterPlanes;
  o.atlas_size = atlas_size;
  return o;
}

// Bark triangles per branch id (by the branch of each triangle's first vertex).
std::vector<long> TubeTriangles(const Tree& tree, const TreeMesh& mesh) {
  std::vector<long> out(tree.branches.size(), 0);
  for (std::size_t t = 0; t + 2 < mesh.bark.indices.size(); t += 3) {
    const uint32_t b = mesh.bark_branch_id[mesh.bark.indices[t]];
    if (b < out.size()) ++out[b];
  }
  return out;
}

// Wood triangles at tube radius r: tubes at and above r, crossed cards down to r / ratio, twig
// cones down to r / ratio / twig_ratio.
long WoodTriangles(const std::vector<float>& radius, const std::vector<long>& tubes, float r,
                   float ratio, float twig_ratio) {
  long sum = 0;
  const float card = r / ratio;
  const float twig = card / twig_ratio;
  for (std::size_t i = 0; i < radius.size(); ++i) {
    if (radius[i] < 0) continue;  // not drawn (dead or a single node)
    if (radius[i] >= r) {
      sum += tubes[i];
    } else if (radius[i] >= card) {
      sum += 2 * kCardPlanes;
    } else if (radius[i] >= twig) {
      sum += kTwigSides;
    }
  }
  return sum;
}

// One twig cone: a triangle of `radius_m` around `base` (normals radial) and the apex at `tip`
// (normal along the axis); 3 outward-facing triangles.
void PushTwig(const glm::vec3& base, const glm::vec3& tip, float radius_m, MeshBuffers* out) {
  const glm::vec3 along = tip - base;
  const float length = glm::length(along);
  const glm::vec3 axis = length > 0 ? along / length : glm::vec3(0.0f, 1.0f, 0.0f);
  // A side vector: the axis crossed with the world axis it is least parallel to.
  const glm::vec3 helper =
      std::fabs(axis.y) < 0.9f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 u = glm::normalize(glm::cross(helper, axis));
  const glm::vec3 w = glm::cross(axis, u);
  const uint32_t first = static_cast<uint32_t>(out->vertex_count());
  constexpr float kCos[kTwigSides] = {1.0f, -0.5f, -0.5f};
  constexpr float kSin[kTwigSides] = {0.0f, 0.8660254f, -0.8660254f};
  for (int k = 0; k < kTwigSides; ++k) {
    const glm::vec3 radial = kCos[k] * u + kSin[k] * w;
    const glm::vec3 p = base + radius_m * radial;
    out->positions.insert(out->positions.end(), {p.x, p.y, p.z});
    out->normals.insert(out->normals.end(), {radial.x, radial.y, radial.z});
  }
  out->positions.insert(out->positions.end(), {tip.x, tip.y, tip.z});
  out->normals.insert(out->normals.end(), {axis.x, axis.y, axis.z});
  const uint32_t apex = first + kTwigSides;
  for (uint32_t k = 0; k < kTwigSides; ++k) {
    out->indices.insert(out->indices.end(), {first + k, first + (k + 1) % kTwigSides, apex});
  }
}

// The node of `branch` (id `id`) nearest each vertex's place along its axis (`along`, 0..1, one a
// vertex from `first` on), appended to the vertices' ids.
void AppendAxisNodes(const std::vector<float>& along, std::size_t first, std::size_t id,
                     const Branch& branch, std::vector<uint32_t>* branch_id,
                     std::vector<uint32_t>* node_index) {
  const float last = static_cast<float>(branch.nodes.size() - 1);
  for (std::size_t v = first; v < along.size(); ++v) {
    branch_id->push_back(static_cast<uint32_t>(id));
    node_index->push_back(static_cast<uint32_t>(std::lround(along[v] * last)));
  }
}

// Branch kinds of one level, thinnest last in the demotion order.
enum class Kind : int { kNone = 0, kTwig = 1, kCard = 2, kTube = 3 };

// Keeps at most `cap` branches of `kind` (cap < 0: no cap): the thinnest excess ones (by radius,
// then id, so the order is fixed) become `to`.
void CapKind(const std::vector<float>& radius, Kind kind, Kind to, long cap,
             std::vector<Kind>* kinds) {
  if (cap < 0) return;
  std::vector<std::size_t> of_kind;
  for (std::size_t i = 0; i < kinds->size(); ++i) {
    if ((*kinds)[i] == kind) of_kind.push_back(i);
  }
  if (static_cast<long>(of_kind.size()) <= cap) return;
  std::sort(of_kind.begin(), of_kind.end(), [&](std::size_t a, std::size_t b) {
    return radius[a] != radius[b] ? radius[a] < radius[b] : a < b;
  });
  const std::size_t excess = of_kind.size() - static_cast<std::size_t>(cap);
  for (std::size_t k = 0; k < excess; ++k) (*kinds)[of_kind[k]] = to;
}

// Copies the bark of the branches with keep[branch] into out (vertices remapped).
void CopyBark(const TreeMesh& mesh, const std::vector<bool>& keep, TreeMesh* out) {
  const std::size_t n = mesh.bark.vertex_count();
  std::vector<uint32_t> remap(n, UINT32_MAX);
  for (std::size_t v = 0; v < n; ++v) {
    const uint32_t b = mesh.bark_branch_id[v];
    if (b >= keep.size() || !keep[b]) continue;
    remap[v] = static_cast<uint32_t>(out->bark.vertex_count());
    for (int k = 0; k < 3; ++k) {
      out->bark.positions.push_back(mesh.bark.positions[3 * v + static_cast<std::size_t>(k)]);
      out->bark.normals.push_back(mesh.bark.normals[3 * v + static_cast<std::size_t>(k)]);
    }
    out->bark.uvs.push_back(mesh.bark.uvs[2 * v]);
    out->bark.uvs.push_back(mesh.bark.uvs[2 * v + 1]);
    out->bark_branch_id.push_back(b);
    out->bark_node_index.push_back(mesh.bark_node_index[v]);
  }
  for (std::size_t t = 0; t + 2 < mesh.bark.indices.size(); t += 3) {
    const uint32_t a = remap[mesh.bark.indices[t]], b = remap[mesh.bark.indices[t + 1]],
                   c = remap[mesh.bark.indices[t + 2]];
    if (a == UINT32_MAX || b == UINT32_MAX || c == UINT32_MAX) continue;
    out->bark.indices.insert(out->bark.indices.end(), {a, b, c});
  }
}

void PushQuad(const glm::vec3 (&corners)[4], const glm::vec3& normal, const AtlasTile& tile,
              int atlas_size, MeshBuffers* out) {
  const uint32_t base = static_cast<uint32_t>(out->vertex_count());
  const float inv = 1.0f / static_cast<float>(atlas_size);
  const float x0 = static_cast<float>(tile.x) * inv, x1 = static_cast<float>(tile.x + tile.w) * inv;
  const float y0 = static_cast<float>(tile.y) * inv, y1 = static_cast<float>(tile.y + tile.h) * inv;
  const float uv[8] = {x0, y0, x1, y0, x1, y1, x0, y1};
  for (int k = 0; k < 4; ++k) {
    out->positions.insert(out->positions.end(), {corners[k].x, corners[k].y, corners[k].z});
    out->normals.insert(out->normals.end(), {normal.x, normal.y, normal.z});
    out->uvs.insert(out->uvs.end(), {uv[2 * k], uv[2 * k + 1]});
  }
  out->indices.insert(out->indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// ---- the atlas rasterizer ----

struct Texel {
  float r, g, b, a;
};

Texel Sample(const Rgba8Image& image, float u, float v, bool wrap) {
  if (image.empty()) return {1, 1, 1, 1};
  auto index = [&](float t, int size) {
    float f = std::floor(t * static_cast<float>(size));
    long i = static_cast<long>(f);
    if (wrap) {
      i %= size;
      if (i < 0) i += size;
    } else {
      i = std::clamp(i, 0L, static_cast<long>(size - 1));
    }
    return static_cast<int>(i);
  };
  const unsigned char* p = image.At(index(u, image.width), index(v, image.height));
  return {p[0] / 255.0f, p[1] / 255.0f, p[2] / 255.0f, p[3] / 255.0f};
}

// Z-buffered fill of one projected part (atlas clip coordinates) with its texture, lit by a
// distant sun like the page (LineShading's L_i): albedo × (0.65 + 0.35 |n · L|).
void Rasterize(const MeshBuffers& part, const Rgba8Image& texture, bool wrap, float alpha_cut,
               int size, std::vector<float>* depth, Rgba8Image* atlas) {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
  const float half = 0.5f * static_cast<float>(size);
  for (std::size_t t = 0; t + 2 < part.indices.size(); t += 3) {
    glm::vec3 p[3];
    glm::vec2 uv[3];
    glm::vec3 n(0.0f);
    for (int k = 0; k < 3; ++k) {
      const std::size_t v = part.indices[t + static_cast<std::size_t>(k)];
      p[k] = {(part.positions[3 * v] + 1.0f) * half, (part.positions[3 * v + 1] + 1.0f) * half,
              part.positions[3 * v + 2]};
      uv[k] = {part.uvs[2 * v], part.uvs[2 * v + 1]};
      n += glm::vec3(part.normals[3 * v], part.normals[3 * v + 1], part.normals[3 * v + 2]);
    }
    const float area =
        (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    if (!(std::fabs(area) > 1e-12f)) continue;
    const float len = glm::length(n);
    const float shade = 0.65f + 0.35f * (len > 0 ? std::fabs(glm::dot(n / len, sun)) : 1.0f);
    const int x_lo = std::max(0, static_cast<int>(std::floor(std::min({p[0].x, p[1].x, p[2].x}))));
    const int x_hi =
        std::min(size - 1, static_cast<int>(std::ceil(std::max({p[0].x, p[1].x, p[2].x}))));
    const int y_lo = std::max(0, static_cast<int>(std::floor(std::min({p[0].y, p[1].y, p[2].y}))));
    const int y_hi =
        std::min(size - 1, static_cast<int>(std::ceil(std::max({p[0].y, p[1].y, p[2].y}))));
    for (int y = y_lo; y <= y_hi; ++y) {
      for (int x = x_lo; x <= x_hi; ++x) {
        const float px = static_cast<float>(x) + 0.5f, py = static_cast<float>(y) + 0.5f;
        // Barycentric weights by edge functions, for either winding.
        const float w0 = ((p[1].x - px) * (p[2].y - py) - (p[2].x - px) * (p[1].y - py)) / area;
        const float w1 = ((p[2].x - px) * (p[0].y - py) - (p[0].x - px) * (p[2].y - py)) / area;
        const float w2 = 1.0f - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const float z = w0 * p[0].z + w1 * p[1].z + w2 * p[2].z;
        const std::size_t at = static_cast<std::size_t>(y) * static_cast<std::size_t>(size) +
                               static_cast<std::size_t>(x);
        if (z >= (*depth)[at]) continue;
        const glm::vec2 s = w0 * uv[0] + w1 * uv[1] + w2 * uv[2];
        const Texel c = Sample(texture, s.x, s.y, wrap);
        if (c.a < alpha_cut) continue;
        (*depth)[at] = z;
        unsigned char* out = atlas->At(x, y);
        out[0] = static_cast<unsigned char>(std::lround(std::min(1.0f, c.r * shade) * 255.0f));
        out[1] = static_cast<unsigned char>(std::lround(std::min(1.0f, c.g * shade) * 255.0f));
        out[2] = static_cast<unsigned char>(std::lround(std::min(1.0f, c.b * shade) * 255.0f));
        out[3] = 255;
      }
    }
  }
}

// Leaves a few texels across lose coverage when a card is minified (alpha-tested mipmaps average
// them away): a transparent texel with at least `min_neighbours` opaque ones of its 8 becomes
// opaque with their mean colour (one pass: leaves grow by about a texel at their outline).
void GrowCoverage(Rgba8Image* image, int min_neighbours) {
  Rgba8Image next = *image;
  for (int y = 1; y + 1 < image->height; ++y) {
    for (int x = 1; x + 1 < image->width; ++x) {
      if (image->At(x, y)[3] != 0) continue;
      int count = 0, r = 0, g = 0, b = 0;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const unsigned char* q = image->At(x + dx, y + dy);
          if (q[3] == 0) continue;
          ++count;
          r += q[0];
          g += q[1];
          b += q[2];
        }
      }
      if (count < min_neighbours) continue;
      unsigned char* o = next.At(x, y);
      o[0] = static_cast<unsigned char>(r / count);
      o[1] = static_cast<unsigned char>(g / count);
      o[2] = static_cast<unsigned char>(b / count);
      o[3] = 255;
    }
  }
  *image = std::move(next);
}

// Transparent texels take the colour of an opaque neighbour (alpha stays 0), so that filtering
// and mipmaps at the cut-out edges do not darken the cards.
void BleedColour(Rgba8Image* image, int passes) {
  for (int pass = 0; pass < passes; ++pass) {
    Rgba8Image next = *image;
    for (int y = 0; y < image->height; ++y) {
      for (int x = 0; x < image->width; ++x) {
        if (image->At(x, y)[3] != 0 || next.At(x, y)[3] != 0) continue;
        const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
        for (int k = 0; k < 4; ++k) {
          const int nx = x + dx[k], ny = y + dy[k];
          if (nx < 0 || ny < 0 || nx >= image->width || ny >= image->height) continue;
          const unsigned char* q = image->At(nx, ny);
          if (q[3] == 0 && q[0] == 0 && q[1] == 0 && q[2] == 0) continue;
          unsigned char* o = next.At(x, y);
          o[0] = q[0];
          o[1] = q[1];
          o[2] = q[2];
          break;
        }
      }
    }
    *image = std::move(next);
  }
}

Rgba8Image PaintAtlas(const TreeMesh& mesh, const HybridScene& scene) {
  const int size = scene.atlas_size;
  Rgba8Image atlas;
  atlas.width = atlas.height = size;
  atlas.pixels.assign(4 * static_cast<std::size_t>(size) * static_cast<std::size_t>(size), 0);
  std::vector<float> depth(static_cast<std::size_t>(size) * static_cast<std::size_t>(size),
                           std::numeric_limits<float>::infinity());
  const AtlasMesh projected = BuildAtlasMesh(mesh, scene);
  Rasterize(projected.bark, MakeBarkTexture(), true, 0.0f, size, &depth, &atlas);
  Rasterize(projected.leaves, MakeLeafTexture(mesh.look), false, 0.5f, size, &depth, &atlas);
  Rasterize(projected.flowers, MakeFlowerTexture(mesh.look), false, 0.5f, size, &depth, &atlas);
  GrowCoverage(&atlas, 2);
  BleedColour(&atlas, 2);
  return atlas;
}

long ClusterTriangles(const HybridScene& scene) {
  long sum = 0;
  for (const LeafCluster& c : scene.clusters) sum += 2 * static_cast<long>(c.planes.size());
  return sum;
}

}  // namespace

long FullTriangles(const TreeMesh& mesh) {
  return Triangles(mesh.bark) + Triangles(mesh.leaves) + Triangles(mesh.flowers);
}

namespace {

// BuildLodMesh, and with `above` (the level above in BuildLodLevels) no kind of primitive grows
// beyond it: tubes at least as thick, no more cluster triangles, branch cards and twigs.
// The wind data of a level's parts (bark tubes, full leaves and flowers) from their branch and
// node.
void PartsWind(const Tree& tree, const std::vector<int>& levels, LodMesh* out) {
  const TreeMesh& m = out->parts;
  out->parts_wind[0] = WindAttributes(tree, levels, m.bark_branch_id, m.bark_node_index);
  out->parts_wind[1] = WindAttributes(tree, levels, m.leaf_branch_id, m.leaf_node_index);
  out->parts_wind[2] = WindAttributes(tree, levels, m.flower_branch_id, m.flower_node_index);
}

Result<LodMesh> BuildLevel(const Tree& tree, long max_triangles, const LodOptions& options,
                           const std::string& field, const LodMesh* above) {
  if (max_triangles < kMinLodTriangles) {
    return Status::Error(field, FormatNumber(static_cast<double>(max_triangles)) +
                                    " is too few; must be at least " +
                                    std::to_string(kMinLodTriangles));
  }
  NIWA_RETURN_IF_ERROR(CheckValue("atlas_size", options.atlas_size, 256, 4096, true));
  TreeMesh full = BuildTreeMesh(tree);
  LodMesh out;
  out.choice.triangles = FullTriangles(full);
  if (out.choice.triangles <= max_triangles && (above == nullptr || above->choice.full)) {
    out.parts = std::move(full);
    for (const Branch& b : tree.branches) out.choice.tubes += LodUsable(b) ? 1 : 0;
    PartsWind(tree, BranchLevels(tree), &out);
    return out;
  }
  LodChoice& choice = out.choice;
  choice.full = false;
  const bool above_clusters = above != nullptr && above->choice.leaf_clusters;

  // Foliage: full leaves when they take at most half the budget, else the finest cluster grid
  // (below a clustered level: also with no more cluster triangles than it has).
  const long leaf_triangles = Triangles(full.leaves) + Triangles(full.flowers);
  const long half = max_triangles / 2;
  HybridScene scene;
  long foliage = leaf_triangles;
  if (leaf_triangles > half || above_clusters) {
    choice.leaf_clusters = true;
    for (int cells : kClusterLadder) {
      scene = BuildHybridScene(tree, SceneOptions(cells, options.atlas_size));
      choice.cluster_cells = cells;
      foliage = ClusterTriangles(scene);
      if (foliage <= half && (!above_clusters || foliage <= above->cluster_triangles)) break;
    }
    if (foliage > max_triangles) {
      return Status::Error(field, std::to_string(max_triangles) +
                                      " is too few for this tree's leaf-cluster cards; must be at "
                                      "least " +
                                      std::to_string(foliage));
    }
  } else {
    scene = BuildHybridScene(tree, SceneOptions(1, options.atlas_size));
  }

  // Wood: the smallest tube radius whose triangles fit what the foliage leaves (below a level:
  // at least its tube radius, so the tubes are a subset of its tubes).
  const long wood_budget = max_triangles - foliage;
  const std::vector<long> tubes = TubeTriangles(tree, full);
  std::vector<float> radius(tree.branches.size(), -1.0f);
  float thickest = 0;
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    if (!LodUsable(tree.branches[i])) continue;
    radius[i] = BranchRadius(tree.branches[i]);
    thickest = std::max(thickest, radius[i]);
  }
  const float ratio = std::max(1.0f, options.card_ratio);
  const float twig_ratio = std::max(1.0f, options.twig_ratio);
  float lo = 0.0f;
  if (above != nullptr && !above->choice.full) lo = above->choice.tube_radius_cm;
  // hi: every branch thinner than a twig (0 triangles).
  float hi = std::max(lo, thickest * ratio * twig_ratio * 1.01f + 1.0f);
  if (WoodTriangles(radius, tubes, lo, ratio, twig_ratio) <= wood_budget) {
    hi = lo;
  } else {
    for (int k = 0; k < kBisections; ++k) {
      const float mid = 0.5f * (lo + hi);
      if (WoodTriangles(radius, tubes, mid, ratio, twig_ratio) <= wood_budget) {
        hi = mid;
      } else {
        lo = mid;
      }
    }
  }
  choice.tube_radius_cm = hi;
  choice.card_radius_cm = hi / ratio;
  choice.twig_radius_cm = choice.card_radius_cm / twig_ratio;

  std::vector<Kind> kinds(tree.branches.size(), Kind::kNone);
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    if (radius[i] < 0) continue;
    if (radius[i] >= choice.tube_radius_cm) {
      kinds[i] = Kind::kTube;
    } else if (radius[i] >= choice.card_radius_cm && scene.group_of_branch[i] >= 0) {
      kinds[i] = Kind::kCard;
    } else if (radius[i] >= choice.twig_radius_cm) {
      kinds[i] = Kind::kTwig;
    }
  }
  if (above != nullptr && !above->choice.full) {
    // Fewer triangles each: the budget still holds.
    CapKind(radius, Kind::kCard, Kind::kTwig, above->choice.cards, &kinds);
    CapKind(radius, Kind::kTwig, Kind::kNone, above->choice.twigs, &kinds);
  }

  std::vector<bool> keep(tree.branches.size(), false);
  const float scale = scene.options.cm_to_units;
  const std::vector<int> levels = BranchLevels(tree);
  out.card_wind = EmptyWind();
  out.twig_wind = EmptyWind();
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    const Branch& branch = tree.branches[i];
    switch (kinds[i]) {
      case Kind::kTube:
        keep[i] = true;
        ++choice.tubes;
        break;
      case Kind::kCard: {
        ++choice.cards;
        const std::size_t g = static_cast<std::size_t>(scene.group_of_branch[i]);
        const std::size_t first = out.cards.vertex_count();
        for (int k = 0; k < kCardPlanes; ++k) {
          glm::vec3 corners[4];
          CardCorners(scene, static_cast<int>(i), k, corners);
          PushQuad(corners, scene.frames[i].planes[static_cast<std::size_t>(k)].normal,
                   scene.group_tiles[g][static_cast<std::size_t>(k)], scene.atlas_size, &out.cards);
        }
        AppendAxisWind(out.cards.positions, first, branch.nodes.front() * scale,
                       branch.nodes.back() * scale, static_cast<float>(levels[i]),
                       WindPhase(static_cast<uint32_t>(i)), &out.card_wind);
        AppendAxisNodes(out.card_wind[1].values, first, i, branch, &out.card_branch_id,
                        &out.card_node_index);
        break;
      }
      case Kind::kTwig: {
        ++choice.twigs;
        const std::size_t first = out.twigs.vertex_count();
        PushTwig(branch.nodes.front() * scale, branch.nodes.back() * scale, radius[i] * scale,
                 &out.twigs);
        AppendAxisWind(out.twigs.positions, first, branch.nodes.front() * scale,
                       branch.nodes.back() * scale, static_cast<float>(levels[i]),
                       WindPhase(static_cast<uint32_t>(i)), &out.twig_wind);
        AppendAxisNodes(out.twig_wind[1].values, first, i, branch, &out.twig_branch_id,
                        &out.twig_node_index);
        break;
      }
      case Kind::kNone:
        if (radius[i] >= 0) ++choice.dropped;
        break;
    }
  }
  CopyBark(full, keep, &out.parts);
  if (choice.leaf_clusters) {
    const long branch_card_triangles = Triangles(out.cards);
    int deepest = 0;
    for (int l : levels) deepest = std::max(deepest, l);
    for (std::size_t c = 0; c < scene.clusters.size(); ++c) {
      const LeafCluster& cluster = scene.clusters[c];
      for (std::size_t k = 0; k < cluster.planes.size(); ++k) {
        const CardPlane& p = cluster.planes[k];
        auto at = [&](float u, float v) { return cluster.origin + u * p.right + v * p.up; };
        const glm::vec3 corners[4] = {at(p.u0, p.v0), at(p.u1, p.v0), at(p.u1, p.v1),
                                      at(p.u0, p.v1)};
        PushQuad(corners, p.normal, scene.cluster_tiles[c][k], scene.atlas_size, &out.cards);
      }
      // Foliage: the deepest level, free along its whole card, a phase past the branches' ids.
      const std::size_t added = out.cards.vertex_count() - out.card_wind[0].values.size();
      const float phase = WindPhase(static_cast<uint32_t>(tree.branches.size() + c));
      out.card_wind[0].values.insert(out.card_wind[0].values.end(), added,
                                     static_cast<float>(deepest));
      out.card_wind[1].values.insert(out.card_wind[1].values.end(), added, 1.0f);
      out.card_wind[2].values.insert(out.card_wind[2].values.end(), added, phase);
      // The sway binds the card to its leafiest branch's tip.
      uint32_t leafiest = 0;
      std::size_t most = 0;
      bool any = false;
      for (int b : cluster.branches) {
        const Branch& branch = tree.branches[static_cast<std::size_t>(b)];
        const std::size_t count = branch.leaves.size() + branch.flowers.size();
        if (!any || count > most || (count == most && static_cast<uint32_t>(b) < leafiest)) {
          leafiest = static_cast<uint32_t>(b);
          most = count;
          any = true;
        }
      }
      const uint32_t tip =
          any ? static_cast<uint32_t>(tree.branches[leafiest].nodes.empty()
                                          ? 0
                                          : tree.branches[leafiest].nodes.size() - 1)
              : 0;
      out.card_branch_id.insert(out.card_branch_id.end(), added,
                                any ? leafiest : static_cast<uint32_t>(tree.branches.size()));
      out.card_node_index.insert(out.card_node_index.end(), added, tip);
    }
    choice.clusters = static_cast<int>(scene.clusters.size());
    out.cluster_triangles = Triangles(out.cards) - branch_card_triangles;
  } else {
    out.parts.leaves = std::move(full.leaves);
    out.parts.leaf_branch_id = std::move(full.leaf_branch_id);
    out.parts.leaf_node_index = std::move(full.leaf_node_index);
    out.parts.flowers = std::move(full.flowers);
    out.parts.flower_branch_id = std::move(full.flower_branch_id);
    out.parts.flower_node_index = std::move(full.flower_node_index);
  }
  if (!out.cards.indices.empty()) out.atlas = PaintAtlas(full, scene);
  PartsWind(tree, levels, &out);
  choice.triangles = FullTriangles(out.parts) + Triangles(out.cards) + Triangles(out.twigs);
  return out;
}

// A level's cards or twigs (flat buffers) as a glTF primitive's mesh: positions, normals, the
// uvs when asked (the cards'; the twigs have none) and the indices.
void AppendPrimitiveMesh(const MeshBuffers& from, bool with_uvs, gltf::Primitive* to) {
  const std::size_t n = from.vertex_count();
  for (std::size_t v = 0; v < n; ++v) {
    to->mesh.positions.push_back(
        {from.positions[3 * v], from.positions[3 * v + 1], from.positions[3 * v + 2]});
    to->mesh.normals.push_back(
        {from.normals[3 * v], from.normals[3 * v + 1], from.normals[3 * v + 2]});
    if (with_uvs) to->mesh.uvs.push_back({from.uvs[2 * v], from.uvs[2 * v + 1]});
  }
  to->mesh.indices = from.indices;
}

}  // namespace

Result<LodMesh> BuildLodMesh(const Tree& tree, long max_triangles, const LodOptions& options,
                             const std::string& field) {
  return BuildLevel(tree, max_triangles, options, field, nullptr);
}

Result<std::vector<LodMesh>> BuildLodLevels(const Tree& tree, long max_triangles,
                                            const LodOptions& options, const std::string& field) {
  std::vector<LodMesh> levels;
  long budget = max_triangles;
  if (budget < 0) budget = FullTriangles(BuildTreeMesh(tree));
  Result<LodMesh> lod0 = BuildLodMesh(tree, budget, options, field);
  if (!lod0.ok()) return lod0.status();
  levels.push_back(std::move(lod0).value());
  const long base = levels[0].choice.triangles;
  int level_index = 0;
  for (long share : {25L, 5L}) {  // percent of LOD0
    const long within = base * share / 100;
    // Seen from farther away: half the atlas side a level (at least 256 texels).
    LodOptions level_options = options;
    level_options.atlas_size = std::max(256, options.atlas_size >> ++level_index);
    Result<LodMesh> level = BuildLevel(tree, within, level_options, "lod", &levels.back());
    if (!level.ok()) {
      return Status::Error(
          "lod", "LOD0 has " + std::to_string(base) + " triangles, so " + std::to_string(share) +
                     " % of it (" + std::to_string(within) +
                     ") is too few for a level of this tree; " + level.status().message());
    }
    levels.push_back(std::move(level).value());
  }
  return levels;
}

Result<gltf::Document> LodGltfDocument(const std::vector<LodMesh>& levels, const std::string& name,
                                       LodLayout layout) {
  if (levels.empty()) return Status::Error("lod", "no levels");
  gltf::Document doc;
  doc.scene_name = name;
  auto material_index = [&](const gltf::Document& from, int m) {
    const gltf::Material& wanted = from.materials[static_cast<std::size_t>(m)];
    for (std::size_t i = 0; i < doc.materials.size(); ++i) {
      if (doc.materials[i].name == wanted.name) return static_cast<int>(i);
    }
    gltf::Material copy = wanted;
    if (copy.base_color_texture >= 0) {
      doc.textures.push_back(from.textures[static_cast<std::size_t>(copy.base_color_texture)]);
      copy.base_color_texture = static_cast<int>(doc.textures.size()) - 1;
    }
    for (int* t :
         {&copy.normal_texture, &copy.metallic_roughness_texture, &copy.occlusion_texture}) {
      if (*t < 0) continue;
      doc.textures.push_back(from.textures[static_cast<std::size_t>(*t)]);
      *t = static_cast<int>(doc.textures.size()) - 1;
    }
    doc.materials.push_back(std::move(copy));
    return static_cast<int>(doc.materials.size()) - 1;
  };
  int twigs_material = -1;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const LodMesh& level = levels[l];
    const std::string node_name = levels.size() == 1 ? name : name + "_LOD" + std::to_string(l);
    Result<gltf::Document> parts = TreeGltfDocument(level.parts);
    if (!parts.ok()) return parts.status();
    gltf::Mesh mesh;
    mesh.name = node_name;
    if (!parts->meshes.empty()) {
      // TreeGltfDocument's primitives: the non-empty parts in order (bark, leaves, flowers).
      const MeshBuffers* buffers[3] = {&level.parts.bark, &level.parts.leaves,
                                       &level.parts.flowers};
      std::size_t part = 0;
      for (gltf::Primitive& p : parts->meshes[0].primitives) {
        while (part < 3 && buffers[part]->indices.empty()) ++part;
        if (part < 3) p.mesh.attributes = level.parts_wind[part++];
        p.material = material_index(*parts, p.material);
        mesh.primitives.push_back(std::move(p));
      }
    }
    if (!level.cards.indices.empty()) {
      gltf::Texture texture;
      texture.name = "cards_" + std::to_string(l);
      texture.wrap_s = texture.wrap_t = gltf::Wrap::kClampToEdge;
      texture.min_filter = gltf::kFilterLinear;  // no mipmaps: they thin alpha-tested leaves out
      Result<std::vector<unsigned char>> png = image::EncodeRgba8Png(level.atlas);
      if (!png.ok()) return png.status().Within("card atlas");
      texture.png = std::move(png).value();
      doc.textures.push_back(std::move(texture));
      gltf::Material material;
      material.name = "cards_" + std::to_string(l);
      material.base_color_texture = static_cast<int>(doc.textures.size()) - 1;
      material.alpha_mode = gltf::AlphaMode::kMask;
      material.double_sided = true;
      material.metallic_factor = 0.0;
      material.roughness_factor = 0.8;
      doc.materials.push_back(std::move(material));
      gltf::Primitive cards;
      AppendPrimitiveMesh(level.cards, /*with_uvs=*/true, &cards);
      cards.mesh.attributes = level.card_wind;
      cards.material = static_cast<int>(doc.materials.size()) - 1;
      mesh.primitives.push_back(std::move(cards));
    }
    if (!level.twigs.indices.empty()) {
      if (twigs_material < 0) {
        gltf::Material twigs;
        twigs.name = "twigs";
        // LineShading::branch_color (0.36, 0.25, 0.17) as linear values (glTF factors are
        // linear): about its sRGB^2.2.
        twigs.base_color_factor = {0.106, 0.047, 0.020, 1.0};
        twigs.metallic_factor = 0.0;
        twigs.roughness_factor = 0.9;
        doc.materials.push_back(std::move(twigs));
        twigs_material = static_cast<int>(doc.materials.size()) - 1;
      }
      gltf::Primitive twigs;
      AppendPrimitiveMesh(level.twigs, /*with_uvs=*/false, &twigs);
      twigs.mesh.attributes = level.twig_wind;
      twigs.material = twigs_material;
      mesh.primitives.push_back(std::move(twigs));
    }
    gltf::Node node;
    node.name = node_name;
    if (!mesh.primitives.empty()) {
      doc.meshes.push_back(std::move(mesh));
      node.mesh = static_cast<int>(doc.meshes.size()) - 1;
    }
    doc.nodes.push_back(std::move(node));
    if (layout == LodLayout::kSiblings || l == 0)
      doc.scene_nodes.push_back(static_cast<int>(doc.nodes.size()) - 1);
  }
  if (layout == LodLayout::kMsftLod && levels.size() > 1) {
    // Level k (k >= 1) from the screen coverage equal to its share of LOD0's triangles.
    const double base = static_cast<double>(std::max(1L, levels[0].choice.triangles));
    std::string coverage;
    double last = 1;
    for (std::size_t l = 1; l < levels.size(); ++l) {
      doc.nodes[0].lod_ids.push_back(static_cast<int>(l));
      last = static_cast<double>(levels[l].choice.triangles) / base;
      coverage += FormatNumber(std::round(last * 1e4) / 1e4) + ", ";
    }
    coverage += FormatNumber(std::round(last * 1e3) / 1e4);  // nothing drawn below
    doc.nodes[0].extras_json = "{\"MSFT_screencoverage\": [" + coverage + "]}";
  }
  return doc;
}

Status WriteLodGlb(const std::vector<LodMesh>& levels, std::vector<unsigned char>* bytes,
                   const std::string& name, LodLayout layout) {
  if (bytes == nullptr) return Status::Error("glb", "no output buffer");
  bytes->clear();
  Result<gltf::Document> doc = LodGltfDocument(levels, name, layout);
  if (!doc.ok()) return doc.status();
  Result<std::vector<unsigned char>> glb = gltf::WriteGlb(*doc);
  if (!glb.ok()) return glb.status();
  *bytes = std::move(glb).value();
  return Status::Ok();
}

}  // namespace niwa

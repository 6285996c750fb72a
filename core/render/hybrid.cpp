// Hybrid rendering (thesis chapter 4 and 5.2): card/line selection, card planes, grouping, atlas,
// leaf clusters, eq. 4.2 colours, draw lists and counts. Plain C++17, det:: math only.
#include "render/hybrid.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <glm/geometric.hpp>
#include <map>
#include <optional>
#include <sstream>
#include <tuple>

#include "base/echo.h"
#include "math/det_math.h"
#include "math/rotation.h"
#include "params/param_text.h"
#include "tree/tree_look.h"
#include "tree/tree_params.h"

namespace niwa {
namespace {

constexpr float kEpsilon = 1e-6f;
constexpr float kFlowerPad_cm =
    kFlowerOuterRadius_cm + kFlowerLift_cm;  // a flower's reach (mesh.h)

glm::vec3 SafeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  float length = glm::length(v);
  if (!(length > kEpsilon) || !std::isfinite(length)) return fallback;
  return v / length;
}

float TanHalf(float angle) {
  double s = 0, c = 1;
  det::SinCos(0.5 * static_cast<double>(angle), &s, &c);
  return static_cast<float>(s / c);
}

bool Usable(const Branch& branch) { return branch.alive && branch.nodes.size() >= 2; }

// Grows the rectangle of `plane` by point p (relative to the frame origin) padded by pad.
void Cover(CardPlane* plane, const glm::vec3& p, float pad, bool* first) {
  float u = glm::dot(p, plane->right), v = glm::dot(p, plane->up);
  if (*first) {
    plane->u0 = u - pad;
    plane->u1 = u + pad;
    plane->v0 = v - pad;
    plane->v1 = v + pad;
    *first = false;
    return;
  }
  plane->u0 = std::min(plane->u0, u - pad);
  plane->u1 = std::max(plane->u1, u + pad);
  plane->v0 = std::min(plane->v0, v - pad);
  plane->v1 = std::max(plane->v1, v + pad);
}

// Points (metres, relative to origin) with padding that a card of the branch must cover.
struct PaddedPoint {
  glm::vec3 p;
  float pad;
};

void BranchPoints(const Branch& branch, float leaf_size_cm, bool with_leaves, float scale,
                  const glm::vec3& origin, std::vector<PaddedPoint>* out) {
  const float radius = BranchRadius(branch) * scale;
  for (const glm::vec3& node : branch.nodes) out->push_back({node * scale - origin, radius});
  if (!with_leaves) return;
  for (const Leaf& leaf : branch.leaves) {
    if (leaf.node < 0 || leaf.node >= static_cast<int>(branch.nodes.size())) continue;
    glm::vec3 base = branch.nodes[static_cast<std::size_t>(leaf.node)] * scale - origin;
    glm::vec3 along = SafeNormalize(leaf.direction, glm::vec3(0, 1, 0));
    float half_width = 0.25f * leaf_size_cm * scale;  // mesh.cpp AddLeaf: blade half width
    out->push_back({base, half_width});
    out->push_back({base + along * (leaf_size_cm * scale), half_width});
  }
  for (int node : branch.flowers) {
    if (node < 0 || node >= static_cast<int>(branch.nodes.size())) continue;
    out->push_back(
        {branch.nodes[static_cast<std::size_t>(node)] * scale - origin, kFlowerPad_cm * scale});
  }
}

CardFrame MakeCardFrame(const Branch& branch, float leaf_size_cm, bool with_leaves,
                        const RenderOptions& options, std::vector<PaddedPoint>* scratch) {
  CardFrame frame;
  const float scale = options.cm_to_units;
  frame.origin = branch.nodes.front() * scale;
  glm::vec3 tip = branch.nodes.back() * scale;
  frame.length = glm::length(tip - frame.origin);
  frame.b = SafeNormalize(tip - frame.origin, SafeNormalize(branch.bud_direction, {0, 1, 0}));
  // Plane 0 is the plane closest to the branch: through b_i and the node farthest from the
  // base→tip line (thesis 4.2.2); a straight branch takes its phyllotaxis azimuth.
  glm::vec3 deviation(0.0f);
  float largest = 0;
  for (const glm::vec3& node : branch.nodes) {
    glm::vec3 p = node * scale - frame.origin;
    glm::vec3 off = p - frame.b * glm::dot(p, frame.b);
    float size = glm::length(off);
    if (size > largest) {
      largest = size;
      deviation = off;
    }
  }
  glm::vec3 right0 = largest > 1e-3f * frame.length && largest > kEpsilon
                         ? deviation / largest
                         : Orthonormalize(branch.azimuth, frame.b);
  std::vector<PaddedPoint>& points = *scratch;  // reused across branches: no allocation per branch
  points.clear();
  BranchPoints(branch, leaf_size_cm, with_leaves, scale, frame.origin, &points);
  const int planes = options.card_planes;
  frame.planes.reserve(static_cast<std::size_t>(planes));
  for (int k = 0; k < planes; ++k) {
    CardPlane plane;
    float angle = kPi * static_cast<float>(k) / static_cast<float>(planes);
    plane.up = frame.b;
    plane.right = SafeNormalize(RotateAbout(right0, frame.b, angle), AnyPerpendicular(frame.b));
    plane.normal = glm::cross(plane.right, plane.up);
    bool first = true;
    for (const PaddedPoint& q : points) Cover(&plane, q.p, q.pad, &first);
    frame.planes.push_back(plane);
  }
  return frame;
}

// Bin index of x on a logarithmic scale whose bins are (1 + tolerance) wide.
int LogBin(float x, float tolerance) {
  double value = std::max(1e-3, static_cast<double>(x));
  return static_cast<int>(std::floor(det::Log(value) / det::Log(1.0 + tolerance)));
}

// Tiles of an atlas: sizes from the texel density, shelf packing (tallest first).
struct TileRequest {
  float width_m, height_m;
};

bool PackTiles(const std::vector<TileRequest>& requests, float texels_per_unit,
               const RenderOptions& o, std::vector<AtlasTile>* tiles) {
  const int size = o.atlas_size, pad = o.atlas_padding;
  tiles->assign(requests.size(), AtlasTile{});
  for (std::size_t i = 0; i < requests.size(); ++i) {
    float w = std::max(requests[i].width_m, 1e-6f), h = std::max(requests[i].height_m, 1e-6f);
    float longest = std::max(w, h);
    float long_px =
        std::min(static_cast<float>(o.max_tile_px),
                 std::max(static_cast<float>(o.min_tile_px), longest * texels_per_unit));
    float per_unit = long_px / longest;  // keeps the representative's aspect
    (*tiles)[i].w = std::max(1, static_cast<int>(std::lround(w * per_unit)));
    (*tiles)[i].h = std::max(1, static_cast<int>(std::lround(h * per_unit)));
  }
  std::vector<std::size_t> order(requests.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return (*tiles)[a].h > (*tiles)[b].h; });
  int x = pad, y = pad, shelf = 0;
  bool fits = true;
  for (std::size_t i : order) {
    AtlasTile& t = (*tiles)[i];
    if (x + t.w + pad > size) {
      x = pad;
      y += shelf + pad;
      shelf = 0;
    }
    if (x + t.w + pad > size || y + t.h + pad > size) fits = false;
    t.x = x;
    t.y = y;
    x += t.w + pad;
    shelf = std::max(shelf, t.h);
  }
  return fits;
}

void LayoutAtlas(HybridScene* scene) {
  const RenderOptions& o = scene->options;
  std::vector<TileRequest> requests;
  for (int rep : scene->group_representative) {
    for (const CardPlane& p : scene->frames[static_cast<std::size_t>(rep)].planes) {
      requests.push_back({p.u1 - p.u0, p.v1 - p.v0});
    }
  }
  for (const LeafCluster& c : scene->clusters) {
    for (const CardPlane& p : c.planes) requests.push_back({p.u1 - p.u0, p.v1 - p.v0});
  }
  scene->atlas_size = o.atlas_size;
  std::vector<AtlasTile> tiles;
  float shortest = 1e30f;
  for (const TileRequest& r : requests) {
    shortest = std::min(shortest, std::max(1e-6f, std::max(r.width_m, r.height_m)));
  }
  // Largest texel density that still fits (bisection; every tile at max_tile_px is the top).
  float lo = 0, hi = requests.empty() ? 1.0f : static_cast<float>(o.max_tile_px) / shortest;
  scene->atlas_fits = PackTiles(requests, lo, o, &tiles);
  if (scene->atlas_fits) {
    if (PackTiles(requests, hi, o, &tiles)) {
      lo = hi;
    } else {
      for (int i = 0; i < 40; ++i) {
        float mid = 0.5f * (lo + hi);
        if (PackTiles(requests, mid, o, &tiles)) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
    }
    PackTiles(requests, lo, o, &tiles);
  }
  scene->texels_per_unit = lo;
  std::size_t next = 0;
  scene->group_tiles.assign(scene->group_representative.size(), {});
  for (std::vector<AtlasTile>& g : scene->group_tiles) {
    for (int k = 0; k < o.card_planes; ++k) g.push_back(tiles[next++]);
  }
  scene->cluster_tiles.assign(scene->clusters.size(), {});
  for (std::size_t c = 0; c < scene->clusters.size(); ++c) {
    for (std::size_t k = 0; k < scene->clusters[c].planes.size(); ++k) {
      scene->cluster_tiles[c].push_back(tiles[next++]);
    }
  }
}

void BuildClusters(const Tree& tree, float leaf_size_cm, HybridScene* scene) {
  const RenderOptions& o = scene->options;
  const float scale = o.cm_to_units;
  // Leaf (and flower) points of every carrying branch, and their common box.
  std::vector<std::vector<PaddedPoint>> points(tree.branches.size());
  Bounds3 box;
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    const Branch& branch = tree.branches[i];
    if (!Usable(branch) || !scene->carries_leaves[i]) continue;
    std::vector<PaddedPoint> all;
    BranchPoints(branch, leaf_size_cm, true, scale, glm::vec3(0.0f), &all);
    // Drop the wood's own nodes (the first nodes.size() entries): only leaves and flowers.
    points[i].assign(all.begin() + static_cast<std::ptrdiff_t>(branch.nodes.size()), all.end());
    for (const PaddedPoint& q : points[i]) box.Add(q.p);
  }
  if (box.empty) return;
  glm::vec3 extent = box.max - box.min;
  float cell = std::max(1e-3f, std::max(extent.x, std::max(extent.y, extent.z)) /
                                   static_cast<float>(o.cluster_cells));
  std::map<std::tuple<int, int, int>, int> cluster_of_cell;
  std::vector<std::vector<PaddedPoint>> cluster_points;
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    if (points[i].empty()) continue;
    glm::vec3 centroid(0.0f);
    for (const PaddedPoint& q : points[i]) centroid += q.p;
    centroid /= static_cast<float>(points[i].size());
    glm::vec3 g = (centroid - box.min) / cell;
    auto index = [&](float v) {
      return std::min(o.cluster_cells - 1, std::max(0, static_cast<int>(std::floor(v))));
    };
    std::tuple<int, int, int> key(index(g.x), index(g.y), index(g.z));
    auto found = cluster_of_cell.find(key);
    int c = 0;
    if (found == cluster_of_cell.end()) {
      c = static_cast<int>(scene->clusters.size());
      cluster_of_cell[key] = c;
      scene->clusters.emplace_back();
      cluster_points.emplace_back();
    } else {
      c = found->second;
    }
    LeafCluster& cluster = scene->clusters[static_cast<std::size_t>(c)];
    cluster.branches.push_back(static_cast<int>(i));
    cluster.leaves += static_cast<int>(tree.branches[i].leaves.size());
    cluster.flowers += static_cast<int>(tree.branches[i].flowers.size());
    scene->cluster_of_branch[i] = c;
    cluster_points[static_cast<std::size_t>(c)].insert(
        cluster_points[static_cast<std::size_t>(c)].end(), points[i].begin(), points[i].end());
  }
  // Axis-aligned planes through the centre of the cluster's box: normal z, x, then y.
  const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const CardPlane bases[3] = {
      {x, y, z, 0, 0, 0, 0}, {-z, y, x, 0, 0, 0, 0}, {x, -z, y, 0, 0, 0, 0}};
  for (std::size_t c = 0; c < scene->clusters.size(); ++c) {
    LeafCluster& cluster = scene->clusters[c];
    Bounds3 b;
    for (const PaddedPoint& q : cluster_points[c]) b.Add(q.p);
    cluster.origin = 0.5f * (b.min + b.max);
    for (int k = 0; k < o.cluster_planes; ++k) {
      CardPlane plane = bases[k];
      bool first = true;
      for (const PaddedPoint& q : cluster_points[c])
        Cover(&plane, q.p - cluster.origin, q.pad, &first);
      cluster.planes.push_back(plane);
    }
  }
}

}  // namespace

void Bounds3::Add(const glm::vec3& p) {
  if (empty) {
    min = max = p;
    empty = false;
    return;
  }
  min = glm::min(min, p);
  max = glm::max(max, p);
}

Bounds3 MeshBounds(const TreeMesh& mesh) {
  Bounds3 bounds;
  for (const MeshBuffers* m : {&mesh.bark, &mesh.leaves, &mesh.flowers}) {
    for (std::size_t i = 0; i + 2 < m->positions.size(); i += 3) {
      bounds.Add({m->positions[i], m->positions[i + 1], m->positions[i + 2]});
    }
  }
  return bounds;
}

OrbitView FrameOrbitView(const Bounds3& bounds, float fov_y, float margin) {
  OrbitView view;
  glm::vec3 size = bounds.max - bounds.min;
  float radius = std::max(0.25f, 0.5f * glm::length(size));
  view.target = 0.5f * (bounds.min + bounds.max);
  view.distance = radius / det::Sinf(0.5f * fov_y) * margin;
  return view;
}

Status ParseOrbitView(const std::string& text, OrbitView* view) {
  std::vector<float> values;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ',')) {
    std::optional<double> number = ParseNumber(item);
    if (!number || !(std::fabs(*number) <= 1e30)) {  // in float range before the cast
      return Status::Error(
          "cam", "'" + Echo(item) + "' is not a number; must be yaw,pitch,distance,tx,ty,tz");
    }
    values.push_back(static_cast<float>(*number));
  }
  if (values.size() != 6) {
    return Status::Error("cam", "must be six numbers yaw,pitch,distance,tx,ty,tz");
  }
  if (values[1] < kMinPitch || values[1] > kMaxPitch) {
    return Status::Error("cam", "pitch must be in [-0.1, 1.5] (radians)");
  }
  if (values[2] < kMinDistance || values[2] > kMaxDistance) {
    return Status::Error("cam", "distance must be in [0.2, 400] (metres)");
  }
  if (!(std::fabs(values[0]) <= kMaxYaw)) {
    return Status::Error("cam", "yaw must be in [-1000, 1000] (radians)");
  }
  for (int i = 3; i < 6; ++i) {
    if (!(std::fabs(values[static_cast<std::size_t>(i)]) <= kMaxTarget)) {
      return Status::Error("cam", "target tx,ty,tz must each be in [-10000, 10000] (metres)");
    }
  }
  view->yaw = values[0];
  view->pitch = values[1];
  view->distance = values[2];
  view->target = glm::vec3(values[3], values[4], values[5]);
  return Status::Ok();
}

std::string FormatOrbitView(const OrbitView& v) {
  // Shortest text per value that reads back as the same float.
  auto text = [](float value) {
    char buffer[32];
    for (int precision = 1; precision <= 9; ++precision) {
      std::snprintf(buffer, sizeof buffer, "%.*g", precision, static_cast<double>(value));
      if (std::strtof(buffer, nullptr) == value) break;
    }
    return std::string(buffer);
  };
  return text(v.yaw) + "," + text(v.pitch) + "," + text(v.distance) + "," + text(v.target.x) + "," +
         text(v.target.y) + "," + text(v.target.z);
}

glm::vec3 RenderCamera::ViewDirection() const {
  return SafeNormalize(target - eye, glm::vec3(0, 0, -1));
}

float RenderCamera::Depth(const glm::vec3& point) const {
  return glm::dot(point - eye, ViewDirection());
}

float RenderCamera::Distance(const glm::vec3& point) const { return glm::length(point - eye); }

float RenderCamera::PixelsPerUnit(float depth) const {
  return static_cast<float>(height) / (2.0f * depth * TanHalf(fov_y));
}

// The visible half-extent along the shorter screen side at this depth: the sphere of radius R
// that just fits the view there (thesis 4.2.1 frames the tree's sphere so).
float RenderCamera::EquivalentRadius(float depth) const {
  return depth * TanHalf(fov_y) * static_cast<float>(std::min(width, height)) /
         static_cast<float>(height);
}

RenderCamera CameraFromOrbit(const OrbitView& view, int width, int height, float fov_y) {
  RenderCamera camera;
  float cp = det::Cosf(view.pitch);
  camera.target = view.target;
  camera.eye =
      view.target + view.distance * glm::vec3(cp * det::Sinf(view.yaw), det::Sinf(view.pitch),
                                              cp * det::Cosf(view.yaw));
  camera.fov_y = fov_y;
  camera.width = width;
  camera.height = height;
  return camera;
}

RenderOptions RenderOptionsFromParams(const ParamSet& params) {
  RenderOptions options;
  options.threshold_px = static_cast<float>(params.Get(ParamId::kLineThreshold));
  options.card_planes = static_cast<int>(params.Get(ParamId::kCardPlanes));
  options.leaf_mode = params.Get(ParamId::kLeafClusterCards) != 0.0 ? LeafMode::kClusterCards
                                                                    : LeafMode::kBranchCards;
  return options;
}

Status CheckRenderOptions(const RenderOptions& o) {
  // Each range once, through params' CheckValue (the same one-line text as every parameter).
  NIWA_RETURN_IF_ERROR(CheckValue("threshold", o.threshold_px, 0.1, 1000, false));
  NIWA_RETURN_IF_ERROR(CheckValue("hysteresis", o.hysteresis, 0, 0.9, false));
  NIWA_RETURN_IF_ERROR(CheckValue("card_planes", o.card_planes, 2, 8, true));
  NIWA_RETURN_IF_ERROR(CheckValue("cluster_cells", o.cluster_cells, 1, 64, true));
  NIWA_RETURN_IF_ERROR(CheckValue("cluster_planes", o.cluster_planes, 1, 3, true));
  NIWA_RETURN_IF_ERROR(CheckValue("line_segments", o.line_segments, 1, 64, true));
  NIWA_RETURN_IF_ERROR(CheckValue("length_tolerance", o.length_tolerance, 0.01, 4, false));
  NIWA_RETURN_IF_ERROR(CheckValue("thickness_tolerance", o.thickness_tolerance, 0.01, 4, false));
  NIWA_RETURN_IF_ERROR(CheckValue("bend_tolerance", o.bend_tolerance_deg, 1, 180, false));
  NIWA_RETURN_IF_ERROR(CheckValue("atlas_size", o.atlas_size, 256, 16384, true));
  if ((o.atlas_size & (o.atlas_size - 1)) != 0) {
    return Status::Error("atlas_size", FormatNumber(o.atlas_size) + " must be a power of two");
  }
  NIWA_RETURN_IF_ERROR(CheckValue("atlas_padding", o.atlas_padding, 0, 16, true));
  NIWA_RETURN_IF_ERROR(CheckValue("min_tile_px", o.min_tile_px, 1, 256, true));
  NIWA_RETURN_IF_ERROR(CheckValue("max_tile_px", o.max_tile_px, 8, 4096, true));
  if (o.max_tile_px < o.min_tile_px) {
    return Status::Error("max_tile_px",
                         FormatNumber(o.max_tile_px) + " must be at least min_tile_px");
  }
  NIWA_RETURN_IF_ERROR(CheckValue("cm_to_units", o.cm_to_units, 1e-6, 1e6, false));
  return Status::Ok();
}

float ScreenWidthPx(float d_i, float sphere_radius, int width, int height) {
  // thesis eq. 4.1
  return d_i * static_cast<float>(std::min(height, width)) / (2.0f * sphere_radius);
}

glm::vec3 LineColor(const glm::vec3& branch_color, const glm::vec3& light_color,
                    const glm::vec3& b_i, const glm::vec3& light_dir, float k_d, float k_a) {
  // thesis eq. 4.2: |b_i| |L_i| sin θ is the length of b_i × L_i.
  float sin_term = glm::length(glm::cross(b_i, light_dir));
  glm::vec3 c = branch_color * (k_d * light_color * sin_term + glm::vec3(k_a));
  return glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f));
}

int ChooseCardPlane(const std::vector<CardPlane>& planes, const glm::vec3& view_direction) {
  int best = 0;
  float best_cos = -1;
  glm::vec3 v = SafeNormalize(view_direction, glm::vec3(0, 0, -1));
  for (std::size_t k = 0; k < planes.size(); ++k) {
    float c = std::fabs(glm::dot(planes[k].normal, v));
    if (c > best_cos) {
      best_cos = c;
      best = static_cast<int>(k);
    }
  }
  return best;
}

BranchShape MeasureBranch(const Branch& branch) {
  BranchShape s;
  s.thickness_cm = 2.0f * BranchRadius(branch);
  s.leaves = static_cast<int>(branch.leaves.size());
  s.flowers = static_cast<int>(branch.flowers.size());
  if (branch.nodes.size() < 2) return s;
  s.internodes = static_cast<int>(branch.nodes.size()) - 1;
  glm::vec3 first(0.0f), last(0.0f);
  for (std::size_t i = 0; i + 1 < branch.nodes.size(); ++i) {
    glm::vec3 d = branch.nodes[i + 1] - branch.nodes[i];
    float len = glm::length(d);
    s.length_cm += len;
    if (len > kEpsilon) {
      if (first == glm::vec3(0.0f)) first = d / len;
      last = d / len;
    }
  }
  if (first != glm::vec3(0.0f)) s.bend_deg = AngleBetween(first, last) * (180.0f / kPi);
  return s;
}

HybridScene BuildHybridScene(const Tree& tree, const RenderOptions& options) {
  HybridScene scene;
  scene.options = options;
  const std::size_t n = tree.branches.size();
  // The leaf cards' extent, as the mesh draws them (mesh.cpp: leaf_size times leaf_card).
  const float leaf_size = LeafCardLength(tree.params);
  const bool leaves_on_cards = options.leaf_mode == LeafMode::kBranchCards;
  scene.frames.resize(n);
  scene.shapes.resize(n);
  scene.thickness_units.assign(n, 0.0f);
  scene.carries_leaves.assign(n, false);
  scene.group_of_branch.assign(n, -1);
  scene.group_scale.assign(n, 1.0f);
  scene.cluster_of_branch.assign(n, -1);
  // Groups (thesis 4.2.2): same bins of length, thickness, internodes and bend (and, when the
  // leaves are drawn on the branch's card, of leaf count and whether it flowers).
  std::map<std::array<int, 6>, int> group_of_key;
  std::vector<PaddedPoint> scratch;
  for (std::size_t i = 0; i < n; ++i) {
    const Branch& branch = tree.branches[i];
    scene.shapes[i] = MeasureBranch(branch);
    if (!Usable(branch)) continue;
    const BranchShape& s = scene.shapes[i];
    scene.thickness_units[i] = s.thickness_cm * options.cm_to_units;
    scene.carries_leaves[i] = s.leaves > 0 || s.flowers > 0;
    scene.frames[i] = MakeCardFrame(branch, leaf_size, leaves_on_cards, options, &scratch);
    std::array<int, 6> key = {LogBin(s.length_cm, options.length_tolerance),
                              LogBin(s.thickness_cm, options.thickness_tolerance),
                              s.internodes,
                              static_cast<int>(std::floor(s.bend_deg / options.bend_tolerance_deg)),
                              0,
                              0};
    if (leaves_on_cards) {
      key[4] = s.leaves == 0 ? -1000 : LogBin(static_cast<float>(s.leaves), 0.5f);
      key[5] = s.flowers > 0 ? 1 : 0;
    }
    auto found = group_of_key.find(key);
    int g = 0;
    if (found == group_of_key.end()) {
      g = static_cast<int>(scene.group_representative.size());
      group_of_key[key] = g;
      scene.group_representative.push_back(static_cast<int>(i));
      scene.group_size.push_back(0);
    } else {
      g = found->second;
    }
    scene.group_of_branch[i] = g;
    scene.group_size[static_cast<std::size_t>(g)] += 1;
    float rep_length = scene
                           .frames[static_cast<std::size_t>(
                               scene.group_representative[static_cast<std::size_t>(g)])]
                           .length;
    scene.group_scale[i] = rep_length > kEpsilon ? scene.frames[i].length / rep_length : 1.0f;
  }
  if (options.leaf_mode == LeafMode::kClusterCards) BuildClusters(tree, leaf_size, &scene);
  LayoutAtlas(&scene);
  return scene;
}

std::vector<AtlasJob> AtlasJobs(const HybridScene& scene) {
  std::vector<AtlasJob> jobs;
  const bool leaves_on_cards = scene.options.leaf_mode == LeafMode::kBranchCards;
  for (std::size_t g = 0; g < scene.group_representative.size(); ++g) {
    const int rep = scene.group_representative[g];
    const CardFrame& frame = scene.frames[static_cast<std::size_t>(rep)];
    for (std::size_t k = 0; k < frame.planes.size(); ++k) {
      AtlasJob job;
      job.tile = scene.group_tiles[g][k];
      job.origin = frame.origin;
      job.plane = frame.planes[k];
      job.branches = {rep};
      job.with_leaves = leaves_on_cards;
      jobs.push_back(job);
    }
  }
  for (std::size_t c = 0; c < scene.clusters.size(); ++c) {
    const LeafCluster& cluster = scene.clusters[c];
    for (std::size_t k = 0; k < cluster.planes.size(); ++k) {
      AtlasJob job;
      job.tile = scene.cluster_tiles[c][k];
      job.origin = cluster.origin;
      job.plane = cluster.planes[k];
      job.branches = cluster.branches;
      job.with_wood = false;
      job.with_leaves = true;
      jobs.push_back(job);
    }
  }
  return jobs;
}

void CardCorners(const HybridScene& scene, int id, int plane, glm::vec3 out[4]) {
  const std::size_t i = static_cast<std::size_t>(id);
  const CardFrame& frame = scene.frames[i];
  const int g = scene.group_of_branch[i];
  const CardPlane& rect =
      scene
          .frames[static_cast<std::size_t>(scene.group_representative[static_cast<std::size_t>(g)])]
          .planes[static_cast<std::size_t>(plane)];
  const CardPlane& own = frame.planes[static_cast<std::size_t>(plane)];
  const float s = scene.group_scale[i];
  auto at = [&](float u, float v) { return frame.origin + s * (u * own.right + v * own.up); };
  out[0] = at(rect.u0, rect.v0);
  out[1] = at(rect.u1, rect.v0);
  out[2] = at(rect.u1, rect.v1);
  out[3] = at(rect.u0, rect.v1);
}

void GroupToBranchMatrix(const HybridScene& scene, int id, float out[16]) {
  const std::size_t i = static_cast<std::size_t>(id);
  const CardFrame& f = scene.frames[i];
  const float s = scene.group_scale[i];
  const CardPlane& p0 = f.planes.front();
  const glm::vec3 columns[4] = {p0.right * s, p0.up * s, p0.normal * s, f.origin};
  for (int c = 0; c < 4; ++c) {
    out[c * 4 + 0] = columns[c].x;
    out[c * 4 + 1] = columns[c].y;
    out[c * 4 + 2] = columns[c].z;
    out[c * 4 + 3] = c == 3 ? 1.0f : 0.0f;
  }
}

HybridSelection SelectHybrid(const Tree& tree, const HybridScene& scene, const RenderCamera& camera,
                             const HybridSelection* previous) {
  const RenderOptions& o = scene.options;
  const std::size_t n = tree.branches.size();
  HybridSelection selection;
  selection.draw.assign(n, BranchDraw::kHidden);
  selection.screen_width_px.assign(n, 0.0f);
  // Branch ids are stable while a tree grows (Tree::branches: index == id, dead ones stay), so a
  // previous selection of fewer branches (the same tree a year earlier) still applies to its ids.
  const std::size_t known = previous && previous->draw.size() <= n ? previous->draw.size() : 0;
  const float target_depth = camera.Depth(camera.target);
  for (std::size_t i = 0; i < n; ++i) {
    if (!Usable(tree.branches[i]) || i >= scene.frames.size() || scene.frames[i].planes.empty())
      continue;
    const CardFrame& f = scene.frames[i];
    float depth =
        o.per_branch_depth ? camera.Depth(f.origin + f.b * (0.5f * f.length)) : target_depth;
    depth = std::max(depth, 1e-4f);
    float d_px = ScreenWidthPx(scene.thickness_units[i], camera.EquivalentRadius(depth),
                               camera.width, camera.height);  // eq. 4.1
    selection.screen_width_px[i] = d_px;
    bool card = false;
    if (o.leaf_mode == LeafMode::kBranchCards && scene.carries_leaves[i]) {
      card = true;  // thesis 4.2.1: branches with leaves always use textures
    } else if (i < known && previous->draw[i] == BranchDraw::kCard) {
      card = d_px >= o.threshold_px * (1.0f - o.hysteresis);
    } else if (i < known && previous->draw[i] == BranchDraw::kLine) {
      card = d_px > o.threshold_px * (1.0f + o.hysteresis);
    } else {
      card = d_px > o.threshold_px;
    }
    selection.draw[i] = card ? BranchDraw::kCard : BranchDraw::kLine;
  }
  return selection;
}

namespace {

void PushCard(const glm::vec3 (&corners)[4], const AtlasTile& tile, int atlas_size, int branch,
              HybridDrawList* list) {
  uint32_t base = static_cast<uint32_t>(list->card_positions.size() / 3);
  for (const glm::vec3& c : corners)
    list->card_positions.insert(list->card_positions.end(), {c.x, c.y, c.z});
  // GL texture space: the tile is the atlas framebuffer's viewport (x, y, w, h), so the card's
  // (u0, v0) corner (branch base) is at (x, y) and (u1, v1) at (x + w, y + h).
  float inv = 1.0f / static_cast<float>(atlas_size);
  float x0 = static_cast<float>(tile.x) * inv, x1 = static_cast<float>(tile.x + tile.w) * inv;
  float y0 = static_cast<float>(tile.y) * inv, y1 = static_cast<float>(tile.y + tile.h) * inv;
  list->card_uvs.insert(list->card_uvs.end(), {x0, y0, x1, y0, x1, y1, x0, y1});
  list->card_indices.insert(list->card_indices.end(),
                            {base, base + 1, base + 2, base, base + 2, base + 3});
  list->card_branch.push_back(branch);
}

int LineSegments(const HybridScene& scene, std::size_t i) {
  return std::min(scene.options.line_segments, std::max(1, scene.shapes[i].internodes));
}

}  // namespace

HybridDrawList BuildDrawList(const Tree& tree, const HybridScene& scene,
                             const HybridSelection& selection, const RenderCamera& camera,
                             const LineShading& shading) {
  HybridDrawList list;
  const float scale = scene.options.cm_to_units;
  for (std::size_t i = 0; i < selection.draw.size() && i < tree.branches.size(); ++i) {
    const Branch& branch = tree.branches[i];
    const CardFrame& f = scene.frames[i];
    if (selection.draw[i] == BranchDraw::kCard) {
      glm::vec3 centre = f.origin + f.b * (0.5f * f.length);
      int plane = ChooseCardPlane(f.planes, centre - camera.eye);
      glm::vec3 corners[4];
      CardCorners(scene, static_cast<int>(i), plane, corners);
      const AtlasTile& tile = scene.group_tiles[static_cast<std::size_t>(scene.group_of_branch[i])]
                                               [static_cast<std::size_t>(plane)];
      PushCard(corners, tile, scene.atlas_size, static_cast<int>(i), &list);
    } else if (selection.draw[i] == BranchDraw::kLine) {
      const int segments = LineSegments(scene, i);
      const int internodes = static_cast<int>(branch.nodes.size()) - 1;
      glm::vec3 color = LineColor(shading.branch_color, shading.light_color, f.b, shading.light_dir,
                                  shading.k_d, shading.k_a);  // eq. 4.2
      // D_i itself: a line thinner than a pixel is drawn 1 px wide with coverage D_i (the page's
      // line shader), so that a crown of sub-pixel twigs does not turn into solid wood.
      float width = selection.screen_width_px[i];
      for (int k = 0; k < segments; ++k) {
        int a = k * internodes / segments, b = (k + 1) * internodes / segments;
        glm::vec3 p = branch.nodes[static_cast<std::size_t>(a)] * scale;
        glm::vec3 q = branch.nodes[static_cast<std::size_t>(b)] * scale;
        list.line_positions.insert(list.line_positions.end(), {p.x, p.y, p.z, q.x, q.y, q.z});
        list.line_colors.insert(list.line_colors.end(), {color.r, color.g, color.b});
        list.line_widths.push_back(width);
        list.line_branch.push_back(static_cast<int>(i));
        list.line_nodes.insert(list.line_nodes.end(), {a, b});
      }
    }
  }
  for (std::size_t c = 0; c < scene.clusters.size(); ++c) {
    const LeafCluster& cluster = scene.clusters[c];
    int plane = ChooseCardPlane(cluster.planes, cluster.origin - camera.eye);
    const CardPlane& p = cluster.planes[static_cast<std::size_t>(plane)];
    auto at = [&](float u, float v) { return cluster.origin + u * p.right + v * p.up; };
    const glm::vec3 corners[4] = {at(p.u0, p.v0), at(p.u1, p.v0), at(p.u1, p.v1), at(p.u0, p.v1)};
    PushCard(corners, scene.cluster_tiles[c][static_cast<std::size_t>(plane)], scene.atlas_size, -1,
             &list);
  }
  return list;
}

RenderStats CountHybrid(const HybridScene& scene, const HybridSelection& selection) {
  RenderStats stats;
  std::vector<bool> group_used(scene.group_representative.size(), false);
  const bool leaves_on_cards = scene.options.leaf_mode == LeafMode::kBranchCards;
  for (std::size_t i = 0; i < selection.draw.size(); ++i) {
    if (selection.draw[i] == BranchDraw::kLine) {
      stats.line_branches += 1;
      stats.lines += LineSegments(scene, i);
    } else if (selection.draw[i] == BranchDraw::kCard) {
      stats.card_branches += 1;
      if (leaves_on_cards && scene.carries_leaves[i]) {
        stats.leaf_polygons += 2;  // table 4.1 counts cards of leaf-bearing branches as leaves
      } else {
        stats.branch_polygons += 2;
      }
      group_used[static_cast<std::size_t>(scene.group_of_branch[i])] = true;
    }
  }
  stats.leaf_clusters = static_cast<int>(scene.clusters.size());
  for (std::size_t i = 0; i < selection.draw.size(); ++i) {
    if (selection.draw[i] != BranchDraw::kHidden && scene.carries_leaves[i])
      stats.leaf_branches += 1;
  }
  stats.leaf_polygons += 2 * stats.leaf_clusters;
  stats.total_polygons = stats.branch_polygons + stats.leaf_polygons;
  stats.primitives = stats.total_polygons + stats.lines;
  stats.texture_groups = static_cast<int>(std::count(group_used.begin(), group_used.end(), true));
  int cluster_tiles = 0;
  for (const LeafCluster& c : scene.clusters) cluster_tiles += static_cast<int>(c.planes.size());
  stats.textures = stats.texture_groups * scene.options.card_planes + cluster_tiles;
  stats.atlas_tiles =
      static_cast<int>(scene.group_representative.size()) * scene.options.card_planes +
      cluster_tiles;
  return stats;
}

void CountFull(const TreeMesh& mesh, RenderStats* stats) {
  stats->full_bark = static_cast<int>(mesh.bark.indices.size() / 3);
  stats->full_leaves = static_cast<int>(mesh.leaves.indices.size() / 3);
  stats->full_flowers = static_cast<int>(mesh.flowers.indices.size() / 3);
  stats->full_polygons = stats->full_bark + stats->full_leaves + stats->full_flowers;
}

}  // namespace niwa

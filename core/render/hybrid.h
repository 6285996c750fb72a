// Hybrid tree rendering of thesis chapter 4 without a GPU: per-branch card-or-line choice (eq. 4.1)
// with hysteresis, card planes, texture groups and their atlas, leaf-cluster cards (5.2), line
// colours (eq. 4.2), draw lists for WebGL and the table 4.1 counts. See docs/rendering-model.md.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "base/status.h"
#include "tree/mesh.h"
#include "tree/tree.h"
#include "tree/tree_params.h"

namespace niwa {

// ---- camera: the page's orbit camera (web/gl/orbit_camera.js), in metres ----

constexpr float kDefaultYaw = 0.6f;         // OrbitCamera.DEFAULT_YAW, radians about +y
constexpr float kDefaultPitch = 0.25f;      // OrbitCamera.DEFAULT_PITCH, radians above the horizon
constexpr float kDefaultFovY = 0.7853982f;  // 45° vertical field of view, radians
constexpr float kPageFrameMargin = 1.12f;   // margin of camera.frame() for a new tree / Reset view

// Axis-aligned box in metres.
struct Bounds3 {
  glm::vec3 min{0.0f}, max{0.0f};
  bool empty = true;
  void Add(const glm::vec3& p);
};

// Bounds of every vertex of the mesh (bark, leaves, flowers): the page's stats.bounds.
Bounds3 MeshBounds(const TreeMesh& mesh);

// The share link's cam= field: "yaw,pitch,distance,tx,ty,tz" (radians, metres).
struct OrbitView {
  float yaw = kDefaultYaw;
  float pitch = kDefaultPitch;
  float distance = 10.0f;
  glm::vec3 target{0.0f, 2.0f, 0.0f};
};

// camera.js frame(bounds, margin): target = box centre, distance = r / sin(fov/2) * margin with
// r = max(0.25, half the box diagonal); yaw and pitch are the defaults.
OrbitView FrameOrbitView(const Bounds3& bounds, float fov_y = kDefaultFovY,
                         float margin = kPageFrameMargin);

// Parses "yaw,pitch,distance,tx,ty,tz"; on failure the error names the state field "cam" and says
// which value is out of its range (pitch in [-0.1, 1.5], distance in [0.2, 400], all finite); the
// view is then unchanged.
Status ParseOrbitView(const std::string& text, OrbitView* view);
std::string FormatOrbitView(const OrbitView& view);

// A perspective camera and viewport (camera.js: lookAt(eye, target, up) and perspective(fov_y)).
struct RenderCamera {
  glm::vec3 eye{0.0f, 2.0f, 10.0f};
  glm::vec3 target{0.0f, 2.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y = kDefaultFovY;  // vertical, radians
  int width = 512, height = 512;

  glm::vec3 ViewDirection() const;               // unit, eye → target
  float Depth(const glm::vec3& point) const;     // distance along the view direction
  float Distance(const glm::vec3& point) const;  // Euclidean distance from the eye
  float PixelsPerUnit(float depth) const;        // H / (2 depth tan(fov_y / 2))
  float EquivalentRadius(float depth) const;     // R of eq. 4.1 at that depth (rendering-model.md)
};

// eye = target + distance (cos pitch sin yaw, sin pitch, cos pitch cos yaw), as camera.js.
RenderCamera CameraFromOrbit(const OrbitView& view, int width, int height,
                             float fov_y = kDefaultFovY);

// ---- options ----

enum class LeafMode : uint8_t {
  kBranchCards,   // thesis 4.2.1: a branch carrying leaves (or flowers) is always a card, leaves on
                  // it
  kClusterCards,  // thesis 5.2: leaves of nearby branches merged into leaf-cluster cards
};

// Ranges are checked by CheckRenderOptions (docs/rendering-model.md explains each choice).
struct RenderOptions {
  float threshold_px = 4.0f;  // eq. 4.1 threshold: card when D_i > it, in [0.1, 1000]
  float hysteresis = 0.25f;  // h: card→line below t(1−h), line→card above t(1+h), in [0, 0.9]
  int card_planes = 2;       // planes per branch rotated about b_i, in [2, 8] (thesis: >= 2)
  LeafMode leaf_mode = LeafMode::kClusterCards;
  int cluster_cells = 6;   // leaf-cluster grid cells along the leaves' longest side, [1, 64]
  int cluster_planes = 3;  // cluster card planes: normal z, x, then y (horizontal), [1, 3]
  int line_segments = 1;   // most segments per line branch (1: base→tip, thesis), [1, 64]
  float length_tolerance = 0.25f;     // relative bin width of branch length, [0.01, 4]
  float thickness_tolerance = 0.25f;  // relative bin width of branch thickness, [0.01, 4]
  float bend_tolerance_deg = 15.0f;   // bin width of the bend angle, degrees, [1, 180]
  int atlas_size = 2048;              // square atlas side, a power of two in [256, 16384]
  int atlas_padding = 2;              // texels around every tile, [0, 16]
  int min_tile_px = 8;                // smallest tile side, [1, 256]
  int max_tile_px = 512;              // largest tile side, [8, 4096]
  bool per_branch_depth = true;  // R from each branch's depth; false: one R at the target's depth
  float cm_to_units = 0.01f;     // tree data are in cm; the camera works in metres (mesh.h)
};

// "" or a one-line error naming the field and its allowed range.
Status CheckRenderOptions(const RenderOptions& options);

// Hybrid options from the "render" rows of the parameter table (line_threshold, card_planes,
// leaf_cluster_cards); the other options keep their defaults.
RenderOptions RenderOptionsFromParams(const ParamSet& params);

// ---- eq. 4.1 and eq. 4.2 ----

// thesis eq. 4.1: D_i = d_i min(H, W) / (2R), d_i and R in the same unit, D_i in pixels.
float ScreenWidthPx(float d_i, float sphere_radius, int width, int height);

// thesis eq. 4.2: C_i = C_b (k_d C_L |b_i| |L_i| sin θ + k_a), θ the angle between b_i and L_i
// (|b||L| sin θ = |b × L|); each channel clamped to [0, 1].
glm::vec3 LineColor(const glm::vec3& branch_color, const glm::vec3& light_color,
                    const glm::vec3& b_i, const glm::vec3& light_dir, float k_d, float k_a);

// ---- cards ----

// One card plane: orthonormal basis with up = b_i, and its rectangle [u0, u1] × [v0, v1] (metres,
// from the frame origin along right and up) covering the branch's nodes, radius (and leaves).
struct CardPlane {
  glm::vec3 right{1.0f, 0.0f, 0.0f}, up{0.0f, 1.0f, 0.0f}, normal{0.0f, 0.0f, 1.0f};
  float u0 = 0, u1 = 0, v0 = 0, v1 = 0;
};

// Card frame of one branch (metres): origin = base node, b_i = unit base→tip, plane 0 the plane
// closest to the branch (through b_i and its largest bend), planes k rotated by kπ/P about b_i.
struct CardFrame {
  glm::vec3 origin{0.0f};
  glm::vec3 b{0.0f, 1.0f, 0.0f};
  float length = 0;  // |tip − base|, metres
  std::vector<CardPlane> planes;
};

// The plane whose normal is closest to the view direction (|cos|, cards are double-sided).
int ChooseCardPlane(const std::vector<CardPlane>& planes, const glm::vec3& view_direction);

// Grouping features of a branch (thesis 4.2.2: length, thickness, node count, bend).
struct BranchShape {
  float length_cm = 0;     // arc length over the internodes
  float thickness_cm = 0;  // d_i: base diameter (pipe model)
  int internodes = 0;
  float bend_deg = 0;  // angle between the first and the last internode
  int leaves = 0, flowers = 0;
};
BranchShape MeasureBranch(const Branch& branch);

// A set of leaves (and flowers) of nearby branches drawn as one card (thesis 5.2).
struct LeafCluster {
  glm::vec3 origin{0.0f};  // centre of the leaves' box, metres
  std::vector<int> branches;
  int leaves = 0, flowers = 0;
  std::vector<CardPlane> planes;
};

// A tile of the square atlas in texels, as a GL viewport of the atlas framebuffer: (x, y) is its
// lower-left corner in GL texture space (t = y / atlas_size). Render the plane's rectangle
// orthographically into it looking along −normal with up = plane.up (screen right = plane.right).
struct AtlasTile {
  int x = 0, y = 0, w = 0, h = 0;
};

// Everything that does not depend on the view: build once per tree, reuse for every frame.
struct HybridScene {
  RenderOptions options;
  std::vector<CardFrame> frames;          // per branch id (empty planes when dead)
  std::vector<BranchShape> shapes;        // per branch id
  std::vector<float> thickness_units;     // d_i per branch id, metres
  std::vector<bool> carries_leaves;       // leaves or flowers on the branch
  std::vector<int> group_of_branch;       // per branch id, -1 when dead
  std::vector<int> group_representative;  // per group: branch id (its first member)
  std::vector<int> group_size;            // per group: member count
  std::vector<float> group_scale;         // per branch id: length / representative length
  std::vector<LeafCluster> clusters;      // kClusterCards only
  std::vector<int> cluster_of_branch;     // per branch id, -1 when none
  int atlas_size = 0;
  float texels_per_unit = 0;  // atlas texels per metre (before tile clamping)
  bool atlas_fits = true;
  std::vector<std::vector<AtlasTile>> group_tiles;    // [group][plane]
  std::vector<std::vector<AtlasTile>> cluster_tiles;  // [cluster][plane]
};

HybridScene BuildHybridScene(const Tree& tree, const RenderOptions& options);

// World corners (metres) of branch `id`'s card on `plane`: the representative's rectangle,
// scaled by group_scale and placed in the branch's own frame (the group-to-branch transform).
// Order: (u0,v0), (u1,v0), (u1,v1), (u0,v1).
void CardCorners(const HybridScene& scene, int id, int plane, glm::vec3 out[4]);

// Column-major 4×4 (WebGL) transform from the representative's card frame (x = right of plane 0,
// y = b, z = normal of plane 0; metres of the representative) to world for branch `id`.
void GroupToBranchMatrix(const HybridScene& scene, int id, float out[16]);

// One orthographic render that fills one atlas tile (thesis 4.2.2 texture generation): draw the
// bark of `branches` (and, when with_leaves, their leaves and flowers) as in BuildTreeMesh, seen
// from origin + plane.normal looking along −plane.normal, up = plane.up, the view volume's x and y
// spanning [u0, u1] and [v0, v1] of the plane, into the viewport `tile`; transparent elsewhere.
struct AtlasJob {
  AtlasTile tile;
  glm::vec3 origin{0.0f};
  CardPlane plane;
  std::vector<int> branches;  // the group's representative, or every branch of a leaf cluster
  bool with_wood = true;      // false for leaf-cluster tiles (leaves and flowers only)
  bool with_leaves = false;   // leaves and flowers of those branches
};
std::vector<AtlasJob> AtlasJobs(const HybridScene& scene);

// ---- per view ----

enum class BranchDraw : uint8_t { kHidden, kLine, kCard };

struct HybridSelection {
  std::vector<BranchDraw> draw;        // per branch id
  std::vector<float> screen_width_px;  // D_i per branch id (eq. 4.1)
};

// Eq. 4.1 per branch; with `previous` (the last frame of the same tree, possibly a year younger:
// fewer branches) the threshold has hysteresis for the branches it knows. A previous selection with
// more branches than the tree is ignored; pass nullptr after switching to another tree.
HybridSelection SelectHybrid(const Tree& tree, const HybridScene& scene, const RenderCamera& camera,
                             const HybridSelection* previous);

// Colour and light of eq. 4.2 used by the draw list.
struct LineShading {
  glm::vec3 branch_color{0.36f, 0.25f, 0.17f};  // C_b: bark brown
  glm::vec3 light_color{1.0f, 1.0f, 1.0f};      // C_L
  glm::vec3 light_dir{0.3f, 0.8f, 0.5f};        // L_i (same for every branch: a distant sun)
  float k_d = 0.8f, k_a = 0.35f;
};

// What to draw this frame: GL-ready arrays (metres, atlas texel coordinates / atlas_size).
struct HybridDrawList {
  std::vector<float> card_positions;   // 4 corners × xyz per card
  std::vector<float> card_uvs;         // 4 × uv per card: GL texture coordinates of its tile
  std::vector<uint32_t> card_indices;  // 2 triangles per card
  std::vector<int> card_branch;        // branch id per card, -1 for leaf-cluster cards
  std::vector<float> line_positions;   // 2 endpoints × xyz per segment
  std::vector<float> line_colors;      // rgb per segment (eq. 4.2)
  std::vector<float> line_widths;      // D_i in pixels per segment (eq. 4.1; may be below 1)
  std::vector<int> line_branch;        // branch id per segment
  std::vector<int> line_nodes;         // 2 per segment: the branch's node index at each endpoint
};

HybridDrawList BuildDrawList(const Tree& tree, const HybridScene& scene,
                             const HybridSelection& selection, const RenderCamera& camera,
                             const LineShading& shading = {});

// Table 4.1 counts. Polygons are triangles (a card is one quad = 2 triangles).
struct RenderStats {
  int lines = 0;            // line segments
  int line_branches = 0;    // branches drawn as lines
  int card_branches = 0;    // branches drawn as cards
  int branch_polygons = 0;  // triangles of cards of branches without leaves (per-branch mode) or
                            // of every branch card (cluster mode)
  int leaf_polygons = 0;    // triangles of leaf-bearing branch cards or of leaf-cluster cards
  int total_polygons = 0;   // branch_polygons + leaf_polygons
  int primitives = 0;       // total_polygons + lines
  int textures = 0;         // (group, plane) and (cluster, plane) tiles used by this view's cards
  int texture_groups = 0;   // groups used by this view's branch cards
  int atlas_tiles = 0;      // every tile of the atlas (all groups and clusters, all planes)
  int leaf_clusters = 0;
  int leaf_branches = 0;  // living branches carrying leaves or flowers
  int full_bark = 0, full_leaves = 0, full_flowers = 0;
  int full_polygons = 0;  // triangles of BuildTreeMesh: bark + leaves + flowers
};

RenderStats CountHybrid(const HybridScene& scene, const HybridSelection& selection);
void CountFull(const TreeMesh& mesh, RenderStats* stats);

}  // namespace niwa

// Game-ready tree exports within a triangle budget (issue 17 item 4): thick wood stays bark tubes,
// thinner branches become crossed branch cards (thesis 4.2.1) or 3-sided twig cones (no glTF
// LINES: engines draw lines as one-pixel threads or not at all), leaves and flowers become
// leaf-cluster cards (thesis 5.2) textured from an atlas rasterized here, and LOD levels as
// sibling nodes <name>_LOD0.._LOD2 in one .glb. Does not: choose by view (the export keeps every
// card plane, crossed), simulate sway, write files, or touch the page's GPU atlas.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "image/image.h"
#include "io/gltf_writer.h"
#include "tree/mesh.h"
#include "tree/tree.h"

namespace niwa {

// ---- data ----

// The deterministic choice made for one budget (see ChooseLod).
struct LodChoice {
  bool full = true;            // the whole BuildTreeMesh fits: nothing else is used
  bool leaf_clusters = false;  // leaves and flowers drawn as leaf-cluster cards
  int cluster_cells = 0;       // RenderOptions::cluster_cells of those clusters (0: full leaves)
  float tube_radius_cm = 0;    // branches at least this thick stay tubes
  float card_radius_cm = 0;    // branches at least this thick (and thinner than tubes) are cards
  float twig_radius_cm = 0;    // branches at least this thick (and thinner than cards) are twig
                               // cones (3 triangles); thinner ones are not drawn
  long triangles = 0;          // triangles of the result (every primitive is TRIANGLES)
  int tubes = 0, cards = 0, twigs = 0, clusters = 0;  // branches of each kind, leaf clusters
  int dropped = 0;                                    // branches too thin for the budget
};

// One level of detail, ready for glTF: the parts of BuildTreeMesh it keeps (tube bark, and leaves
// and flowers when not clustered), the cards (branch and leaf-cluster quads, uvs into `atlas`,
// GL texture space = glTF uv since atlas row y is stored as image row y) and the twigs: one
// 3-sided cone a branch, from a triangle of the branch's radius around its base node to its tip
// node (4 vertices, 3 triangles, normals radial at the base and along the axis at the tip; seen
// from every side, so camera-independent, and lit like any mesh).
struct LodMesh {
  LodChoice choice;
  TreeMesh parts;              // bark of the tubes only; leaves/flowers full or empty
  MeshBuffers cards;           // 2 triangles per card plane: branch cards first, then cluster cards
  MeshBuffers twigs;           // 3 triangles per twig cone, metres (uvs empty)
  image::Rgba8Image atlas;     // empty when there are no cards
  long cluster_triangles = 0;  // the cards' triangles that are leaf-cluster cards
  // Wind data of every vertex for an engine's wind shader (sway/wind_attributes.h, written as
  // _WIND_LEVEL, _WIND_ALONG, _WIND_PHASE): the parts' (bark, leaves, flowers) from their branch
  // and node; a branch card's and a twig's from its branch, along its base -> tip axis; a
  // leaf-cluster card's the tree's deepest level, along 1 (foliage moves freely) and a phase of its
  // own.
  std::array<std::vector<geom::VertexAttribute>, 3> parts_wind;
  std::vector<geom::VertexAttribute> card_wind, twig_wind;
  // The branch and node every card and twig vertex hangs on (as TreeMesh's ids, for the sway
  // skin, render/tree_lod_sway): a branch card's and a twig's branch, at the node nearest its
  // place along the base -> tip axis; a leaf-cluster card's, the branch of the cluster with the
  // most leaves and flowers (the lowest id of a tie), at its tip node.
  std::vector<uint32_t> card_branch_id, card_node_index, twig_branch_id, twig_node_index;
};

struct LodOptions {
  int atlas_size = 2048;    // texels of the card atlas side (256..4096)
  float card_ratio = 4.0f;  // card radius = tube radius / card_ratio (one bisection variable)
  float twig_ratio = 4.0f;  // twig radius = card radius / twig_ratio
};

// ---- functions ----

// Fewest triangles any tree can be drawn with (one leaf-cluster grid cell of 3 planes: 6).
constexpr long kMinLodTriangles = 6;

// The level of `tree` within `max_triangles` (>= 1): the full mesh when it fits; else foliage as
// leaf-cluster cards with the finest grid whose cards take at most half the budget (cells 32, 24,
// 16, 12, 8, 6, 4, 3, 2, 1; the coarsest when none does), then the wood's tube radius r found by
// bisection (40 halvings of [0, thickest radius]) as the smallest r whose triangles fit the rest:
// radius >= r tubes, r / card_ratio <= radius < r crossed cards (4 triangles), down to
// r / card_ratio / twig_ratio twig cones (3 triangles), thinner ones not drawn. A branch's
// triangles (tube >= 6 > card 4 > twig 3 > 0) never grow with r, so the count is monotone in r.
// Errors name
// `field` (the state field "max_triangles"; front ends rename it) when even the coarsest level
// does not fit.
Result<LodMesh> BuildLodMesh(const Tree& tree, long max_triangles, const LodOptions& options = {},
                             const std::string& field = "max_triangles");

// Triangles of the full BuildTreeMesh of the tree (bark, leaves, flowers).
long FullTriangles(const TreeMesh& mesh);

// LOD0 within max_triangles (or the full mesh when max_triangles < 0), LOD1 within 25 % and LOD2
// within 5 % of LOD0's triangles; LOD1 and LOD2 use half and a quarter of the atlas side. Every
// kind of primitive shrinks from a level to the next (vertices and triangles of bark, leaves,
// flowers, cards and twigs), with two exceptions where one kind replaces another: below a full
// LOD0 (every branch a tube, the full leaves) cards and twigs appear, and the cards grow at the
// level where the leaves first become leaf-cluster cards (the leaves drop to none). A lower level
// keeps the tubes
// at least as thick as the level above (so its bark is a subset), takes a cluster grid with no
// more cluster triangles, and keeps at most as many branch cards and twigs as the level above
// (the thinnest excess cards become twigs, the thinnest excess twigs are not drawn). LOD0's error
// names `field`; a lower level that cannot fit names "lod".
Result<std::vector<LodMesh>> BuildLodLevels(const Tree& tree, long max_triangles,
                                            const LodOptions& options = {},
                                            const std::string& field = "max_triangles");

// How the levels sit in the .glb: kSiblings, every level a top-level node of the scene (the
// names importers group); kMsftLod, only LOD0 in the scene with the MSFT_lod extension listing
// the others (docs/lod-export.md), and extras.MSFT_screencoverage: level k from the coverage
// equal to its triangle share of LOD0 (25 %, 5 %: the same triangles per covered pixel), nothing
// below a tenth of the last.
enum class LodLayout : int { kSiblings = 0, kMsftLod = 1 };

// A .glb document: one node per level, named `name` when there is one level, else `name`_LOD0,
// `name`_LOD1, ... (the suffix Unity's and Godot's importers group as LODs). Parts: bark, leaves,
// flowers (tree/tree_gltf materials), "cards" (atlas, alpha mask, double-sided), "twigs"
// (triangles, bark colour). Every primitive is TRIANGLES.
Result<gltf::Document> LodGltfDocument(const std::vector<LodMesh>& levels,
                                       const std::string& name = "tree",
                                       LodLayout layout = LodLayout::kSiblings);

Status WriteLodGlb(const std::vector<LodMesh>& levels, std::vector<unsigned char>* bytes,
                   const std::string& name = "tree", LodLayout layout = LodLayout::kSiblings);

}  // namespace niwa

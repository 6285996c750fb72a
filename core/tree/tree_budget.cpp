// The tree study's budgets: growth limits and export estimates (constants: docs/budgets.md).
#include "tree/tree_budget.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "tree/mesh.h"

namespace niwa {
namespace {

// Measured on this machine's native release build and in WASM under node (docs/budgets.md,
// "Calibration"); each is the larger of the two builds' figures times a margin.
// Fixed sizes (not sizeof: the WASM build's pointers are half as wide, and both builds must stop
// at the same point): a node (vec3) 12 bytes, a leaf 16, a bud 40, a Branch with its lists' headers
// 640 (its native 216 bytes up to twice while the branch list doubles, and its lists' headers).
constexpr double kMemorySlack = 1.25;              // allocator rounding, work lists, light grid
constexpr double kBaseBytes = 64.0 * 1024 * 1024;  // the process, tables, code
constexpr double kNodeBytes = 12, kLeafBytes = 16, kBudBytes = 40, kBranchBytes = 640;
constexpr double kNsPerInternodeYear = 160;  // light, hormone, thickening per alive internode
constexpr double kNsPerElement = 120;        // per node, bud and leaf made
constexpr double kNsPerBranch = 400;         // per shoot made

// Export sizes: bytes of the output per counted element, the peak memory per output byte (the
// document tree or mesh, the buffers and the file's bytes at once) and the time per output byte.
struct ExportCost {
  double per_branch, per_internode, per_bud, per_leaf, per_flower, fixed;
  double per_bark_vertex, per_bark_index;
  double memory_per_byte, ns_per_byte;
  const char* what;
};
// .json (indented by one space a level): a branch's fields, each node as a 3-array, each bud
// {node, kind, state, flower}, each leaf {node, direction}.
constexpr ExportCost kJson = {250, 90, 150, 170, 8, 8192, 0, 0, 5.5, 50, "writing the .json"};
// .glb: bark vertices of 32 bytes (position, normal, uv) plus the branch ids and the tangent
// (16, for the bark's normal map), 4 per index; 8 vertices and 12 indices per leaf, 22 and 60
// per flower. Peak 6x the file (measured natively with the tangents, 2026-12-05: sakura 25 years
// 4.6x its 79 MB .glb, sakura 40 years 4.5x its 296 MB; 8 before refused the page's 25-year
// sakura once the tangents made the file 22 % bigger).
constexpr ExportCost kGlb = {0, 0, 0, 304, 944, 65536, 56, 4, 6, 30, "writing the .glb"};
constexpr ExportCost kSvg = {120, 40, 0, 60, 60, 8192, 0, 0, 3, 70, "writing the .svg"};
// The page's mesh: the .glb's buffers plus the skin (8 bytes a vertex) held in the heap while the
// worker copies them out.
constexpr ExportCost kMeshBuild = {0, 0, 0, 400, 1200, 0, 48, 4, 3, 30, "building the mesh"};

}  // namespace

GrowLimits TreeGrowLimits(const TreeParams& p, const Budget& budget,
                          const std::string& years_name) {
  // Per internode made: its node, its leaves (one per lateral bud position, at least one; the
  // lists keep their room after the leaves fall) and its lateral buds; per branch: the Branch, its
  // base node and its terminal and terminally-lateral buds (a tip has no lateral buds: counting
  // them on every internode over-counts by B_l buds a branch).
  const double leaves = std::max(1, p.GetInt(ParamId::kBL));
  const double laterals = p.GetInt(ParamId::kBL);
  const double tip_buds = (p.GetInt(ParamId::kBT) > 0 ? 1 : 0) + p.GetInt(ParamId::kBTl);
  GrowLimits limits;
  limits.max_bytes = static_cast<double>(budget.memory_bytes);
  limits.max_seconds = budget.seconds;
  limits.base_bytes = kBaseBytes;
  limits.bytes_per_branch = kMemorySlack * (kBranchBytes + kNodeBytes + tip_buds * kBudBytes);
  limits.bytes_per_internode =
      kMemorySlack * (kNodeBytes + leaves * kLeafBytes + laterals * kBudBytes);
  limits.seconds_per_internode_year = kNsPerInternodeYear * 1e-9;
  limits.seconds_per_branch = (kNsPerBranch + kNsPerElement * tip_buds) * 1e-9;
  limits.seconds_per_internode = kNsPerElement * 1e-9 * (1.0 + leaves + laterals);
  limits.memory_limit = budget.memory_limit;
  limits.seconds_limit = budget.seconds_limit;
  limits.years_name = years_name;
  return limits;
}

double MeshBytesPerInternode(const TreeParams& p) {
  // A typical tube of 6 sides (thin twigs have 3, the trunk 12: the exact check after the growth
  // covers the rest) and every internode bearing this year's leaves, twice: a growth the budget
  // stops keeps last year's leaves beside this year's (issue 17 item 5, Grower::BreakBuds);
  // flowers are left to that check.
  const double sides = 6;
  const double leaves = 2.0 * std::max(1, p.GetInt(ParamId::kBL));
  return kMeshBuild.memory_per_byte * (kMeshBuild.per_bark_vertex * (sides + 1) +
                                  kMeshBuild.per_bark_index * 6 * sides + kMeshBuild.per_leaf * leaves);
}

TreeCounts CountTree(const Tree& tree) {
  TreeCounts c;
  const MeshOptions mesh;
  const int lo = std::max(3, mesh.min_sides), hi = std::max(lo, mesh.max_sides);
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    if (b.nodes.size() >= 2) {
      // BuildTreeMesh's pass 1: sides grow with sqrt(radius) from 0.1 cm (lo) to 4 cm (hi).
      float t = (BranchRadius(b) - 0.1f) / (4.0f - 0.1f);
      t = std::sqrt(std::min(1.0f, std::max(0.0f, t)));
      const double sides = lo + static_cast<double>(std::lround(t * static_cast<float>(hi - lo)));
      const double rings = static_cast<double>(b.nodes.size());
      c.bark_vertices += rings * (sides + 1) + 1 + sides;
      c.bark_indices += 6 * (rings - 1) * sides + 3 * sides;
    }
    c.branches += 1;
    c.internodes += static_cast<double>(b.nodes.size()) - 1;
    c.buds += static_cast<double>(b.buds.size());
    c.leaves += static_cast<double>(b.leaves.size());
    c.flowers += static_cast<double>(b.flowers.size());
  }
  return c;
}

Estimate EstimateTreeExport(const TreeCounts& c, TreeExport kind) {
  const ExportCost& k = kind == TreeExport::kJson  ? kJson
                        : kind == TreeExport::kGlb ? kGlb
                        : kind == TreeExport::kSvg ? kSvg
                                                   : kMeshBuild;
  const double bytes = k.fixed + k.per_branch * c.branches + k.per_internode * c.internodes +
                       k.per_bud * c.buds + k.per_leaf * c.leaves + k.per_flower * c.flowers +
                       k.per_bark_vertex * c.bark_vertices + k.per_bark_index * c.bark_indices;
  Estimate e;
  e.memory_bytes = bytes * k.memory_per_byte;
  e.seconds = bytes * k.ns_per_byte * 1e-9;
  e.what = std::string(k.what) + " (" + FormatCount(c.internodes) + " internodes, " +
           FormatCount(c.leaves) + " leaves, " + FormatCount(c.flowers) + " flowers)";
  return e;
}

}  // namespace niwa

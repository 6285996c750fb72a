// Trees grown together on one clock, each shaded by the others' leaf spheres of the year.
#include "compose/tree_neighbours.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "math/det_math.h"
#include "tree/tree_params.h"

namespace niwa::compose {
namespace {

constexpr double kShadeCmPerMetre = 100.0;  // the tree's frame is in cm, the garden's in metres

// The box of one tree's leaf spheres of the year, in the garden's frame (cm), and its lowest
// sphere centre.
struct NeighbourCrown {
  bool empty = true;
  glm::vec3 lo{0.0f}, hi{0.0f};
  float lowest_centre = 0.0f;
};

// A tree's placement: its trunk foot in the garden (cm) and its turn about y.
struct NeighbourPlace {
  glm::vec3 origin;
  float cos_rot = 1.0f, sin_rot = 0.0f;
  bool turned = false;
  explicit NeighbourPlace(const TreeAt& tree)
      : origin(static_cast<float>(tree.x * kShadeCmPerMetre),
               static_cast<float>(tree.y * kShadeCmPerMetre),
               static_cast<float>(tree.z * kShadeCmPerMetre)),
        turned(tree.rot != 0) {
    if (turned) {
      const float angle = static_cast<float>(tree.rot * (det::kPi / 180.0));
      cos_rot = det::Cosf(angle);
      sin_rot = det::Sinf(angle);
    }
  }
  // The tree's frame to the garden's: turned about y (counter-clockwise seen from above), moved.
  glm::vec3 ToGarden(const glm::vec3& p) const {
    if (!turned) return origin + p;
    return origin + glm::vec3(cos_rot * p.x + sin_rot * p.z, p.y, cos_rot * p.z - sin_rot * p.x);
  }
  // The garden's frame to the tree's (the inverse).
  glm::vec3 FromGarden(const glm::vec3& g) const {
    const glm::vec3 p = g - origin;
    if (!turned) return p;
    return glm::vec3(cos_rot * p.x - sin_rot * p.z, p.y, cos_rot * p.z + sin_rot * p.x);
  }
};

NeighbourCrown CrownOf(const TreeAt& tree) {
  NeighbourCrown crown;
  const NeighbourPlace place(tree);
  for (const LeafSphere& s : tree.run->leaf_spheres()) {
    const glm::vec3 c = place.ToGarden(s.center);
    if (crown.empty) {
      crown.lo = crown.hi = c;
      crown.lowest_centre = c.y;
      crown.empty = false;
    }
    crown.lo = glm::min(crown.lo, c - glm::vec3(s.radius));
    crown.hi = glm::max(crown.hi, c + glm::vec3(s.radius));
    crown.lowest_centre = std::min(crown.lowest_centre, c.y);
  }
  return crown;
}

// Horizontal (x, z) gap between a point and a box, cm: 0 inside.
float HorizontalGap(const glm::vec3& p, const NeighbourCrown& box) {
  const float dx = std::max({box.lo.x - p.x, 0.0f, p.x - box.hi.x});
  const float dz = std::max({box.lo.z - p.z, 0.0f, p.z - box.hi.z});
  return std::sqrt(dx * dx + dz * dz);
}

std::vector<LeafSphere> ShadeFor(const std::vector<TreeAt>& trees,
                                 const std::vector<NeighbourCrown>& crowns, std::size_t i,
                                 const NeighbourShade& shade) {
  std::vector<LeafSphere> foreign;
  if (!shade.shade_each_other || crowns[i].empty) return foreign;
  const NeighbourCrown& own = crowns[i];
  const float reach = static_cast<float>(shade.reach_m * kShadeCmPerMetre);
  const NeighbourPlace own_place(trees[i]);
  for (std::size_t j = 0; j < trees.size(); ++j) {
    const NeighbourCrown& other = crowns[j];
    if (j == i || other.empty) continue;
    // The whole crown first (so that a garden of many trees looks at the spheres of its near
    // neighbours only), then each sphere.
    const float gap_x = std::max({own.lo.x - other.hi.x, 0.0f, other.lo.x - own.hi.x});
    const float gap_z = std::max({own.lo.z - other.hi.z, 0.0f, other.lo.z - own.hi.z});
    if (gap_x * gap_x + gap_z * gap_z > reach * reach || other.hi.y < own.lowest_centre) continue;
    const NeighbourPlace place(trees[j]);
    for (const LeafSphere& s : trees[j].run->leaf_spheres()) {
      const glm::vec3 c = place.ToGarden(s.center);
      if (c.y + s.radius < own.lowest_centre) continue;  // below every receiver: cannot shade
      if (HorizontalGap(c, own) - s.radius > reach) continue;
      foreign.push_back({own_place.FromGarden(c), s.radius});
    }
  }
  return foreign;
}

std::vector<NeighbourCrown> Crowns(const std::vector<TreeAt>& trees) {
  std::vector<NeighbourCrown> crowns;
  crowns.reserve(trees.size());
  for (const TreeAt& t : trees) crowns.push_back(CrownOf(t));
  return crowns;
}

}  // namespace

Status CheckTreesTogether(const std::vector<TreeAt>& trees, const NeighbourShade& shade) {
  if (!(shade.reach_m >= 0 && shade.reach_m <= kMaxShadeReach)) {
    return Status::Error("reach_m", "must be 0.." + std::to_string(int(kMaxShadeReach)) + " m");
  }
  for (std::size_t i = 0; i < trees.size(); ++i) {
    const TreeAt& t = trees[i];
    if (t.run == nullptr) {
      return Status::Error("trees", "tree " + std::to_string(i) + " has no run");
    }
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z) ||
        !std::isfinite(t.rot)) {
      return Status::Error("trees",
                           "tree " + std::to_string(i) + "'s position and turn must be finite");
    }
  }
  return Status::Ok();
}

std::vector<LeafSphere> ForeignShade(const std::vector<TreeAt>& trees, std::size_t i,
                                     const NeighbourShade& shade) {
  if (!shade.shade_each_other || i >= trees.size()) return {};
  return ShadeFor(trees, Crowns(trees), i, shade);
}

int GrowTogetherYear(const std::vector<TreeAt>& trees, const NeighbourShade& shade) {
  // Every tree's spheres of this year exist before any tree is lit: no tree sees another's
  // spheres of a different year, whatever the order.
  std::vector<char> growing(trees.size(), 0);
  int grown = 0;
  for (std::size_t i = 0; i < trees.size(); ++i) {
    growing[i] = trees[i].run->StartYear() ? 1 : 0;
    grown += growing[i];
  }
  const std::vector<NeighbourCrown> crowns =
      shade.shade_each_other ? Crowns(trees) : std::vector<NeighbourCrown>();
  // Each tree's shade first, then every tree finishes: FinishYear changes nothing of the spheres
  // that another tree's shade reads, but taking them all first keeps that plain.
  std::vector<std::vector<LeafSphere>> foreign(trees.size());
  if (shade.shade_each_other) {
    for (std::size_t i = 0; i < trees.size(); ++i) {
      if (growing[i]) foreign[i] = ShadeFor(trees, crowns, i, shade);
    }
  }
  for (std::size_t i = 0; i < trees.size(); ++i) {
    if (growing[i]) trees[i].run->FinishYear(foreign[i]);
  }
  return grown;
}

Status GrowTreesTogether(const std::vector<TreeAt>& trees, const NeighbourShade& shade,
                         const run::Observer& observer) {
  NIWA_RETURN_IF_ERROR(CheckTreesTogether(trees, shade));
  int to_go = 0;
  for (const TreeAt& t : trees) {
    if (!t.run->finished()) to_go = std::max(to_go, t.run->target() - t.run->done());
  }
  int years = 0;
  for (;;) {
    bool any = false;
    for (const TreeAt& t : trees) any = any || !t.run->finished();
    if (!any) break;
    if (observer && !observer({"trees", static_cast<double>(years), static_cast<double>(to_go)})) {
      return run::CancelledStatus();
    }
    GrowTogetherYear(trees, shade);
    ++years;
  }
  if (observer) observer({"trees", static_cast<double>(years), static_cast<double>(to_go)});
  return Status::Ok();
}

glm::vec3 LeafCentroid(const Tree& tree) {
  const float half_leaf = 0.5f * static_cast<float>(tree.params.Get(ParamId::kLeafSize));
  glm::dvec3 sum(0.0);
  double leaves = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const Leaf& leaf : b.leaves) {
      const glm::vec3 centre =
          b.nodes[static_cast<std::size_t>(leaf.node)] + half_leaf * leaf.direction;
      sum += glm::dvec3(centre);
      leaves += 1;
    }
  }
  if (leaves == 0) return glm::vec3(0.0f);
  return glm::vec3(sum / leaves);
}

}  // namespace niwa::compose

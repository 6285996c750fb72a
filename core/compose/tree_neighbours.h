// Trees grown together on one clock, their leaves shading each other (issue 33 item 3): each year
// every tree's light model (thesis 2.3.2, leaves as shading spheres) is shaded also by the leaf
// spheres its neighbours grow that year, so neighbours grow away from each other. Part of the
// composition tier (the garden calls it; the tree study does not know it). Does not: start, own,
// mesh or export the runs (the caller's TreeRuns do; a tree's nursery years grown alone before are
// the caller's too), shade the ground or another study, let a tree's wood or last year's leaves
// cast shade (only the leaf spheres of the year, as the thesis's own light), run threads, or name
// a flag (the garden's table holds the switch and the reach).
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <vector>

#include "base/status.h"
#include "render/tree_run.h"
#include "run/study_run.h"
#include "tree/light.h"

namespace niwa::compose {

// Horizontal reach of a tree's shade, metres (NeighbourShade::reach_m's default): 10 m is the
// spacing of the 100-tree, 100 m garden (issue 33 item 7); a 4 m crown 10 m away stands under 22
// degrees and spans about 23 degrees of azimuth, so it meets at most one or two of the growth sky's
// 16 directions (5 of them lie below 22 degrees).
constexpr double kDefaultShadeReach = 10.0;
constexpr double kMaxShadeReach = 1000.0;  // m

// One tree of the group: its run (started by the caller with its state and budget; grown here),
// where its trunk foot stands in the garden, metres, y up (y: the ground's height there), and its
// turn about y, degrees, counter-clockwise seen from above (the garden's `rot`: +x turns towards
// -z at 90; the turn the caller gives the tree's node, so its leaves shade where they are drawn).
struct TreeAt {
  TreeRun* run = nullptr;
  double x = 0, y = 0, z = 0;
  double rot = 0;
};

struct NeighbourShade {
  // Off: every tree grows exactly as its lone TreeRun (no sphere is handed over).
  bool shade_each_other = true;
  // A neighbour's leaf sphere shades a tree only when its horizontal gap to the tree's crown (the
  // box of the tree's leaf spheres of the year) is at most this, and its top is above the tree's
  // lowest leaf-sphere centre (every sky direction points upwards). Metres, 0..kMaxShadeReach.
  double reach_m = kDefaultShadeReach;
};

// Checks the group: every run set, every position and turn finite, reach_m in its range (errors
// name "trees" with the index, or "reach_m").
Status CheckTreesTogether(const std::vector<TreeAt>& trees, const NeighbourShade& shade);

// The foreign shade tree `i` gets from the others' current leaf spheres (TreeRun::leaf_spheres,
// each run's last started year), turned and moved into tree i's frame (cm, its foot at the origin,
// its own turn undone) and culled
// by `shade` as said above; in the order of the trees, then of each one's spheres. Empty with
// shade_each_other off.
std::vector<LeafSphere> ForeignShade(const std::vector<TreeAt>& trees, std::size_t i,
                                     const NeighbourShade& shade);

// One year of the clock: every tree not yet finished starts its year (bud break, the shoots laid
// out straight), then each finishes it shaded by ForeignShade; a finished tree keeps shading with
// the spheres of its last year. The order of the trees changes no tree's result. Returns how many
// trees grew.
int GrowTogetherYear(const std::vector<TreeAt>& trees, const NeighbourShade& shade);

// GrowTogetherYear until every tree reached its state's years (or a limit stopped it); the
// observer sees {"trees", years done on this clock, years to go at the start} before each year and
// after the last. A cancel leaves every tree at the last whole year of the clock and returns
// run::CancelledStatus(). Refused as CheckTreesTogether refuses, before any growth.
Status GrowTreesTogether(const std::vector<TreeAt>& trees, const NeighbourShade& shade,
                         const run::Observer& observer);

// The leaves' centre (the lean measure of docs/garden-model.md "Trees shade each other"): the mean
// of the centres of the alive branches' leaves (node + half a leaf along the leaf; every leaf of a
// tree has one size, so this is the leaf-area centroid), in the tree's frame, cm. (0, 0, 0) when
// the tree has no leaves.
glm::vec3 LeafCentroid(const Tree& tree);

}  // namespace niwa::compose

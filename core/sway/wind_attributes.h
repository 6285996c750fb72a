// Per-vertex wind data for an engine's own wind shader (docs/sway-model.md "Wind attributes"):
// _WIND_LEVEL, _WIND_ALONG and _WIND_PHASE, shared by the sway .glb and the budget/LOD .glb.
// Does not: simulate the sway or write glTF (the writers attach these as "_NAME" attributes).
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "geom/tri_mesh.h"
#include "tree/tree.h"

namespace niwa {

// Hierarchy level of every branch: 0 for a shoot without a parent, its parent's + 1 otherwise.
std::vector<int> BranchLevels(const Tree& tree);

// A branch's wind phase in [0, 1): its id through a multiplicative hash (Knuth's 2654435761), the
// top 24 bits, so neighbours sway out of step (same bits natively and in WASM).
float WindPhase(uint32_t branch);

// The three attributes ("wind_level", "wind_along", "wind_phase"; one float a vertex) of vertices
// hanging on (branch_id[v], node_index[v]): the branch's level, node / last node of the branch in
// [0, 1], and the branch's phase. A vertex of no branch (id past the tree) gets 0, 0 and its id's
// phase.
std::vector<geom::VertexAttribute> WindAttributes(const Tree& tree, const std::vector<int>& levels,
                                                  const std::vector<uint32_t>& branch_id,
                                                  const std::vector<uint32_t>& node_index);

// Appends the wind data of vertices [first, positions.size() / 3) of a flat position buffer
// standing for one branch from `base` to `tip` (the same units as the positions): its level and
// phase, and each vertex's place along base -> tip clamped to [0, 1] (0 for a branch of no length).
// `wind` holds the three attributes (WindAttributes' names, in its order).
void AppendAxisWind(const std::vector<float>& positions, std::size_t first, const glm::vec3& base,
                    const glm::vec3& tip, float level, float phase,
                    std::vector<geom::VertexAttribute>* wind);

// Three empty attributes with WindAttributes' names.
std::vector<geom::VertexAttribute> EmptyWind();

}  // namespace niwa

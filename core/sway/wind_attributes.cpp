// Per-vertex wind data (sway/wind_attributes.h): levels, phases and the three attributes.
#include "sway/wind_attributes.h"

#include <algorithm>
#include <glm/geometric.hpp>

namespace niwa {

// Hierarchy level of every branch: 0 for a shoot without a parent, its parent's + 1 otherwise.
std::vector<int> BranchLevels(const Tree& tree) {
  std::vector<int> level(tree.branches.size(), -1);
  for (std::size_t i = 0; i < tree.branches.size(); ++i) {
    // Walk up to a branch whose level is known (or the root), then fill the path down.
    std::vector<std::size_t> path;
    std::size_t b = i;
    while (level[b] < 0) {
      path.push_back(b);
      const int parent = tree.branches[b].parent;
      if (parent < 0 || static_cast<std::size_t>(parent) >= tree.branches.size()) break;
      b = static_cast<std::size_t>(parent);
    }
    int at = level[b] >= 0 ? level[b] + 1 : 0;
    for (std::size_t k = path.size(); k-- > 0;) level[path[k]] = at++;
  }
  return level;
}

// A branch's wind phase in [0, 1): its id through a multiplicative hash (Knuth's 2654435761),
// the top 24 bits, so neighbours sway out of step (same bits natively and in WASM).
float WindPhase(uint32_t branch) {
  const uint32_t h = branch * 2654435761u;
  return static_cast<float>(h >> 8) / 16777216.0f;
}

std::vector<geom::VertexAttribute> EmptyWind() {
  std::vector<geom::VertexAttribute> out(3);
  out[0].name = "wind_level";
  out[1].name = "wind_along";
  out[2].name = "wind_phase";
  return out;
}

// The wind data of one part's vertices (docs/sway-model.md "Wind attributes"): wind_level, the
// branch's hierarchy level; wind_along, the vertex's node along its branch over the branch's
// last node (0 at the base, 1 at the tip); wind_phase, the branch's phase.
std::vector<geom::VertexAttribute> WindAttributes(const Tree& tree, const std::vector<int>& levels,
                                                  const std::vector<uint32_t>& branch_id,
                                                  const std::vector<uint32_t>& node_index) {
  std::vector<geom::VertexAttribute> out = EmptyWind();
  for (std::size_t v = 0; v < branch_id.size(); ++v) {
    const uint32_t b = branch_id[v];
    float level = 0, along = 0;
    if (b < tree.branches.size()) {
      level = static_cast<float>(levels[b]);
      const std::size_t nodes = tree.branches[b].nodes.size();
      if (nodes >= 2) {
        const std::size_t last = nodes - 1;
        along = std::min(1.0f, static_cast<float>(node_index[v]) / static_cast<float>(last));
      }
    }
    out[0].values.push_back(level);
    out[1].values.push_back(along);
    out[2].values.push_back(WindPhase(b));
  }
  return out;
}

void AppendAxisWind(const std::vector<float>& positions, std::size_t first, const glm::vec3& base,
                    const glm::vec3& tip, float level, float phase,
                    std::vector<geom::VertexAttribute>* wind) {
  const glm::vec3 axis = tip - base;
  const float length2 = glm::dot(axis, axis);
  for (std::size_t v = first; 3 * v + 2 < positions.size(); ++v) {
    const glm::vec3 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]);
    const float along =
        length2 > 0 ? std::clamp(glm::dot(p - base, axis) / length2, 0.0f, 1.0f) : 0.0f;
    (*wind)[0].values.push_back(level);
    (*wind)[1].values.push_back(along);
    (*wind)[2].values.push_back(phase);
  }
}

}  // namespace niwa

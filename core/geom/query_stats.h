// QueryStats: counts of what a geometry query touched (BVH nodes, triangles), added up over many
// queries; ivy reports nodes per query as bvh_visits_per_query. Does not: time anything.
#pragma once

#include <cstdint>

namespace niwa::geom {

struct QueryStats {
  uint64_t queries = 0;           // calls that took this QueryStats
  uint64_t nodes_visited = 0;     // BVH nodes whose box was tested (0 for the linear twins)
  uint64_t triangles_tested = 0;  // per-triangle routine calls

  double NodesPerQuery() const {
    return queries == 0 ? 0.0 : static_cast<double>(nodes_visited) / static_cast<double>(queries);
  }
  double TrianglesPerQuery() const {
    return queries == 0 ? 0.0
                        : static_cast<double>(triangles_tested) / static_cast<double>(queries);
  }
};

}  // namespace niwa::geom

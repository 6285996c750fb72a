// A grown tree's bark as a plain geom::TriMesh (metres, y up) with a seed point at the trunk foot:
// what a climbing-plant study (ivy, paper 004) climbs when it grows on a Niwa tree. The CLI
// (`niwa ivy grow --tree-preset`) and the ivy page's bindings both call this, so the two grow the
// same support. Does not: know any climbing plant (core/tree includes no other study), add leaves
// or flowers to the support (ivy climbs bark only), or build a BVH.
#pragma once

#include <glm/vec3.hpp>
#include <string>

#include "base/status.h"
#include "geom/tri_mesh.h"
#include "tree/mesh.h"

namespace niwa {

struct BarkSupport {
  geom::TriMesh mesh;     // the bark tubes (positions and normals in metres)
  glm::dvec3 trunk_seed;  // the bark point nearest to (0, 0.05, 0.001): the +z side of the foot
  std::string description;
};

// The bark buffers of BuildTreeMesh as one TriMesh.
geom::TriMesh BarkTriMesh(const MeshBuffers& bark);

// Grows tree preset `preset` (seed and parameters of the preset) for `years` years and returns its
// bark. Errors name "tree" (an unknown preset, with the list) or "tree_years" (not a whole number
// in [1, kMaxYears], or a tree with no bark); callers rename them to their flags.
Result<BarkSupport> GrowBarkSupport(const std::string& preset, double years);

}  // namespace niwa

// "Birth" geometry of a grown ivy (spec §1.5; the paper only says "I: Draw a tube"): stems as
// 6-sided tubes with pipe-model radii, one 3-lobed leaf per bud on the side opposite its sucker,
// one sucker per bud (a thin tube to the anchor ending in a disc), each vertex carrying its
// birth_step; and the .glb over io/gltf_writer. Does not: grow, read files, or write them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/status.h"
#include "geom/tri_mesh.h"
#include "io/gltf_writer.h"
#include "ivy/growth.h"
#include "ivy/ivy.h"
#include "ivy/ivy_params.h"

namespace niwa::ivy {

struct IvyMeshes {
  geom::TriMesh stems, leaves, suckers;  // each with the attribute "birth_step" (1 float)
};

// With `support` (the one the ivy grew on; issue 31 item 7), every leaf sits outside it: its
// petiole leaves along the anchor face's normal (turned to the bud's side), and a leaf whose
// petiole, spokes or rim would cross a face is turned about that normal (±45°, ±90°, ±135°,
// 180°), then halved (twice), until none does; the last try is kept (LeafPlacement counts).
// Without it, the leaf stands along unit(pos - anchor), unchecked (the spec's §1.5 as before).
struct LeafPlacement {
  std::size_t turned = 0;    // leaves not in their first direction
  std::size_t shrunk = 0;    // leaves halved
  std::size_t crossing = 0;  // leaves whose last try still crosses a face
  std::size_t thinned = 0;   // leaves left out by light (the row leaf_light)
  std::size_t drawn = 0;     // leaves drawn
};
// The row leaf_light (issue 31 item 5, docs/ivy-model.md "The artist preset"): a leaf's light in
// [0.21, 1] from its face's normal n (toward the bud) and the sky: (0.6 + 0.4 (1 + n·ĝ)/2),
// times 0.35 when a ray from the bud toward ĝ meets the support (under an overhang). With
// leaf_light = w > 0 a leaf is drawn with probability 1 - 0.75 w (1 - light) (a hash of its bud,
// no RNG stream), its width times 1 + 0.6 w (1 - light) (shade leaves larger, as real ivy's and
// Luft's ground leaves), and its blade hangs from the petiole's end, leaning out from the face by
// w times half the angle between n and ĝ (flat on a top, 45° out on a wall, straight down under an
// overhang), its normal the side that looks up.
double LeafLight(const glm::dvec3& face_normal, const glm::dvec3& up, bool shaded);
IvyMeshes BuildIvyMeshes(const IvyModel& model, const IvyParams& params,
                         const Support* support = nullptr, LeafPlacement* placement = nullptr);

// The glTF document of the .glb, for a writer or a composer to merge: nodes ivy_stems, ivy_leaves,
// ivy_suckers (+ support when given), asset extras = {params, seed, steps}. `_BIRTH_STEP` per
// vertex. Error: the leaf texture's PNG.
Result<gltf::Document> BuildIvyDocument(const IvyModel& model, const IvyParams& params,
                                        uint64_t seed, int steps,
                                        const geom::TriMesh* support = nullptr,
                                        const Support* leaves_outside = nullptr);

// The .glb: gltf::WriteGlb of BuildIvyDocument.
Result<std::vector<unsigned char>> WriteIvyGlb(const IvyModel& model, const IvyParams& params,
                                               uint64_t seed, int steps,
                                               const geom::TriMesh* support = nullptr,
                                               const Support* leaves_outside = nullptr);

}  // namespace niwa::ivy

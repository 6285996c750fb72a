// Built-in ivy supports in scene units ("px", §4 item 16): cubes4 (the paper's four 400 px cubes as
// an L-tetracube), wall, overhang, stairs, pillar, sphere, and free (no mesh), each with named
// seed points. Does not: read files (io/mesh_reader) or grow.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/status.h"
#include "geom/tri_mesh.h"
#include "io/mesh_reader.h"

namespace niwa::ivy {

struct NamedSeed {
  std::string name;
  glm::dvec3 pos;
};

struct IvyScene {
  std::string name;
  std::string description;
  bool free = false;  // no support: the RNG-free nutrient replay
  geom::TriMesh mesh;
  std::vector<NamedSeed> seeds;  // the first is the default
  // Paper pixels per scene unit (IvyPxPerUnit): 1 on the built-in scenes (px), 1000 on a tree (in
  // metres); 0 = unknown (a read mesh: from its bounds, or the state's "scale").
  double px_per_unit = 0;
  // A read mesh whose file names its unit (glTF: metres, 1000 px per unit; issue 31 item 7): the
  // pixels per unit of the look's lengths (tubes, leaves) when "scale" is 0 (IvyLookPxPerUnit);
  // 0 = no unit named (OBJ).
  double unit_px_per_unit = 0;
};

const std::vector<std::string>& IvySceneNames();

// The triangles of a read mesh that ivy may attach to: all but those whose material (the reader's
// "material" vertex attribute) is named "noivy..." or has extras.niwa_ivy false. `obstacles` gets
// the count left out.
geom::TriMesh IvyAttachTriangles(const geom::TriMesh& mesh,
                                 const std::vector<io::MeshMaterial>& materials,
                                 std::size_t* obstacles);
// Error: {"scene", "'x' is unknown; must be one of cubes4, ..."}.
Result<IvyScene> MakeIvyScene(std::string_view name);

}  // namespace niwa::ivy

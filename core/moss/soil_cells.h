// The moss study's soil cells on a land mesh (Nomura 2010 §3.2, §3.5.3; spec §1.2): every triangle
// split by longest-edge bisection until no edge is longer than soil_edge, one soil cell per
// resulting triangle with its centroid, unit normal, area, geology, region, soil depth h (the
// thickness of the solid along y, by a ray through core/geom's BVH) and, when asked, its sky view
// V_sky (64 cosine-weighted Hammersley rays); the geology of a loaded mesh from its colours: its
// base colour texture sampled at each cell's centroid UV, else COLOR_0, else the material's colour.
// Does not: filter textures (nearest texel), read KHR_texture_transform or a texCoord set other
// than 0, keep a cell's water or light (the run does), or load files.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "base/status.h"
#include "geom/bvh.h"
#include "geom/tri_mesh.h"
#include "io/mesh_reader.h"
#include "moss/moss.h"
#include "moss/scenes.h"

namespace niwa::moss {

// max_cells: a land of more triangles keeps its own (each is one cell at least: its cap is its
// triangle count), and the run's estimate of memory and time, not a count, says whether it is
// grown (moss_run.h RunEstimate).
struct SoilCellOptions {
  double soil_edge = 0.075;        // m (row soil_edge)
  double h_max = 1000;             // mm: open ground and the cap (row h_max)
  double h_wall = 1;               // mm: near-vertical faces (row h_wall)
  std::size_t max_cells = 200000;  // above it soil_edge is doubled, with a notice (spec §1.2)
  bool sky_view = false;           // compute V_sky (read by the sky-view longwave only)
};

// The land after splitting: triangle i of `mesh` is soil cell i.
struct SoilCells {
  geom::TriMesh mesh;                        // positions and indices only
  geom::Bvh bvh;                             // over mesh
  std::vector<glm::dvec3> centroid, normal;  // normal: unit, from the winding
  std::vector<double> area;                  // m²
  std::vector<Geology> geology;
  std::vector<uint8_t> region;
  std::vector<std::string> region_names;
  std::vector<double> h;      // soil depth [mm], in [h_wall, h_max]
  std::vector<double> V_sky;  // sky view in [0, 1]; all 1 unless options.sky_view
  glm::dvec3 centre{0};       // the enclosing sphere: bounding-box centre
  double radius = 0;          //   and half-diagonal R (spec §1.3)
  double soil_edge = 0;       // the edge used (doubled from the option when over max_cells)
  std::vector<std::string> notices;
  std::size_t size() const { return area.size(); }
};

// Near-vertical faces (|n_y| ≤ 0.1, "壁の側面") get h_wall; others h along ∓y (spec §1.2).
constexpr double kVerticalNy = 0.1;
constexpr int kSkyViewRays = 64;

// The soil cells of a scene (built-in, or from SceneFromMesh). Error "scene" for a mesh without
// triangles, or when even soil_edge doubled 16 times leaves more than max(max_cells, triangles)
// cells.
Result<SoilCells> MakeSoilCells(const MossScene& scene, const SoilCellOptions& options);

// The nearest of the three reference colours of fig 3.1 (spec §1.2: humus #4A3322, sandy
// #C29A5B, asphalt #808080) to an sRGB colour (components in [0, 1]); ties go to the lower
// geology.
Geology GeologyOfColour(const glm::dvec3& srgb);
// A material name containing "humus", "sand" or "asphalt" (any case) names the geology; false
// otherwise.
bool GeologyOfMaterialName(const std::string& name, Geology* geology);

// A loaded mesh as a scene: each triangle's geology from its material's name, else the glTF base
// colour turned to sRGB: the material's baseColorFactor times the mean of its corners' COLOR_0
// (io/mesh_reader.h kColorAttribute, linear) times, for a material with a base colour texture (a
// PNG or JPEG of `images`), the texel at each soil cell's centroid UV (MakeSoilCells samples it;
// the UVs are io's kBaseColorUvAttribute: the texture's texCoord set with its
// KHR_texture_transform applied); no material and no colour: humus; one region "all". Errors name
// `name`: a texture that does not decode (io read its header only). A mesh without that attribute
// (no textured material) keeps the untextured colour.
Result<MossScene> SceneFromMesh(const geom::TriMesh& mesh,
                                const std::vector<io::MeshMaterial>& materials,
                                const std::string& name,
                                const std::vector<io::MeshImage>& images = {});

// The geology of a texel (sRGB bytes) times a linear tint (1: the texel's own colour).
Geology GeologyOfTexel(const unsigned char* rgb, const glm::dvec3& tint);

// The texel of `texture` nearest to uv under its wrap modes.
const unsigned char* SampleTexture(const SceneTexture& texture, glm::dvec2 uv);

}  // namespace niwa::moss

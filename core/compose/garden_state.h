// The garden's state (issue 33 item 1): the garden table's values, the ground (flat, a terrain
// grown from a seed contour, or a 16-bit heightmap), the objects placed on it (walls, rocks,
// stone lanterns), the plants placed by hand, the planting rules' species mix and density mask,
// read from a state JSON or a share-link hash and written back; the heightmap's and the mask's
// bytes checked and decoded as the garden reads them (every front end the same lines). Does not:
// read files (a front end reads the heightmap and the mask and hands their bytes in), place or
// grow anything
// (garden_plant.h, garden_run.h), or name a flag (errors name state fields: "plants[2].pos").
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "base/status.h"
#include "compose/garden_params.h"
#include "compose/garden_wind_rows.h"
#include "geom/tri_mesh.h"
#include "image/image.h"
#include "moss/moss_state.h"
#include "terrain/terrain_state.h"

namespace niwa::compose {

// ---- data ----

enum class GroundKind { kFlat, kTerrain, kHeightmap, kMesh };

// A built-in object placed on the ground: its base's centre at (x, ground height, z), turned by
// rot degrees about y (counter-clockwise seen from above), scaled by scale.
struct GardenObject {
  GardenObject() = default;
  GardenObject(std::string kind_in, double x_in, double z_in, double rot_in, double scale_in)
      : kind(std::move(kind_in)), x(x_in), z(z_in), rot(rot_in), scale(scale_in) {}
  std::string kind;  // "wall", "rock" or "lantern" (GardenObjectKinds), or "mesh"
  double x = 0, z = 0, rot = 0, scale = 1;
  // kind "mesh": a .glb, .gltf or .obj (its `file`, read by the front end into `mesh`: world space,
  // y up, metres), stood on the ground at (x, z) by its bounds' base centre.
  std::string file;
  geom::TriMesh mesh;
};

// A tree placed by hand: a tree preset (niwa presets tree), its seed, its age when the garden
// starts (it grows age + years), its trunk foot at (x, ground height, z), turned rot degrees.
struct GardenPlant {
  std::string species;
  uint64_t seed = 1;
  int age = 0;
  double x = 0, z = 0, rot = 0;
};

// A species of the planting rules with its relative weight (> 0).
struct SpeciesWeight {
  std::string species;
  double weight = 1;
};

// The moss's preset and rows in a garden before the state's own (GardenState::moss): the sky's
// light (in a crown's shade most light is the sky's), photons and a gather radius for a scene of
// tens of metres, soil cells no finer than the ground's own triangles, and the light smoothed
// over 10 days (a gather of about 20 photons a day is noisy), the sun in the south at 55°.
// docs/garden-model.md, "Moss".
moss::MossState GardenMossDefaults();

struct GardenState {
  GardenParams params;
  GroundKind ground = GroundKind::kTerrain;
  terrain::TerrainState terrain;  // the ground when kTerrain (its heights scaled to `relief`)
  // kHeightmap: a 16-bit (or 8-bit) grey PNG, row 0 the north (−z) edge, read by the front end.
  // kMesh: any .glb, .gltf or .obj, read by the front end into `ground_mesh` (its world space, y
  // up); heightmap_name is then the mesh file's name (the JSON's ground.file, either kind).
  std::string heightmap_name;
  std::vector<unsigned char> heightmap_png;
  geom::TriMesh ground_mesh;
  // The planting rules' density mask: a grey or colour PNG over the garden (row 0 north), its
  // luminance the chance a candidate is kept; none when empty.
  std::string mask_name;
  std::vector<unsigned char> mask_png;
  std::vector<GardenObject> objects;
  std::vector<GardenPlant> plants;
  std::vector<SpeciesWeight> mix;
  // Ivy: the things it starts at the foot of ("objects[i]" or "plants[i]", the hand-placed
  // trees), grown with the ivy preset `ivy_preset` (niwa presets ivy).
  std::vector<std::string> ivy_on;
  std::string ivy_preset = "artist";
  // The moss's preset and rows (climate, sun, light, life cycle: niwa params moss); its scene,
  // days and seed are the garden's (its land, years × moss_days, plant_seed), not read here.
  moss::MossState moss = GardenMossDefaults();
  // The wind of the page's Blow and of `niwa garden grow --wind-time` (not the growth's: an edit of
  // it regrows nothing): the tree table's "wind" rows but gust_on (IsGardenWindKey), the garden's
  // defaults over the table's (GardenWindBase); the other rows are not read.
  TreeParams wind = GardenWindBase();
  // True until objects or plants are given (a state JSON's lists, a link's): the objects and the
  // hand-placed tree are then the default layout, laid out anew for the garden's size
  // (LayOutDefaults), so a smaller garden keeps them inside.
  bool default_layout = true;
};

// ---- limits ----

constexpr std::size_t kMaxGardenObjects = 256;
constexpr std::size_t kMaxGardenPlants = 1000;  // hand-placed
constexpr std::size_t kMaxGardenMix = 16;
constexpr int kMaxPlantAge = 60;
constexpr double kMaxGardenSeed = 4294967295.0;
// A heightmap's or a mask's file: at most this many bytes, and this many pixels a side (the
// ground's grid is at most 1025 samples a side; a 4096² 16-bit heightmap is 32 MB decoded).
constexpr std::size_t kMaxGardenImageBytes = std::size_t{64} << 20;
constexpr int kMaxGardenImageSide = 4096;

// A thing ivy starts at: objects[index] or plants[index].
struct GardenIvyTarget {
  bool object = false;
  std::size_t index = 0;
};

constexpr std::size_t kMaxGardenIvy = 64;

// ---- functions ----

// "objects[2]" or "plants[0]" of `state`; error "ivy" when it names nothing there.
Result<GardenIvyTarget> ParseIvyTarget(std::string_view text, const GardenState& state);

// "wall", "rock", "lantern".
const std::vector<std::string>& GardenObjectKinds();

// With state->default_layout, the default objects and hand-placed tree at their shares of the
// garden's size (at 40 m: a wall 12 m north, two rocks, a lantern, a keyaki); else nothing.
void LayOutDefaults(GardenState* state);

// The small default garden every front end starts from (a result with no input): a 40 m terrain
// ground 6 m high, a wall, two rocks and a stone lantern, a keyaki placed by hand, and rules
// planting keyaki, sakura and maple.
GardenState DefaultGardenState();

// Checks what the table's ranges cannot: species names (tree presets), object kinds, every
// position inside the garden, alt_min <= alt_max, a non-empty mix when density > 0, the wind's
// rows together (gust_off after the derived gust_on: GardenWindRows). Errors name the field
// ("plants[1].species", "objects[0].pos", "mix", "alt_min", "wind.gust_off").
Status CheckGardenState(const GardenState& state);

// A front end's reader of a mesh file by the name a garden state gives it (the CLI: beside the
// garden file; the page: a file dropped in): the mesh in world space, or its own error line.
using GardenMeshReader = std::function<Result<geom::TriMesh>(const std::string& file)>;

// Fills the meshes a state names by file (a mesh ground's ground_mesh, each mesh object's mesh)
// through `read`; one without a file name is left as it is. A read's error is returned under the
// field that named the file ("ground.file", "objects[2].file").
Status LoadGardenMeshes(const GardenMeshReader& read, GardenState* state);

// A heightmap's PNG bytes (`name` its file) as the ground reads them: a grey PNG (16-bit, or 8-bit
// and lower scaled to 0..65535) of 2 to kMaxGardenImageSide pixels a side, at most
// kMaxGardenImageBytes. Errors name "ground.file" and the file ("ground.file: 'h.png' is an RGB
// PNG ...").
Result<image::Gray16Image> DecodeGardenHeightmap(const std::string& name,
                                                 const std::vector<unsigned char>& png);
// A density mask's PNG bytes as the planting rules read them: any PNG (grey or colour, its
// luminance the chance a dart is kept) of 1 to kMaxGardenImageSide pixels a side, at most
// kMaxGardenImageBytes. Errors name "mask" and the file.
Result<image::Rgba8Image> DecodeGardenMask(const std::string& name,
                                           const std::vector<unsigned char>& png);

// A front end's reader of an image file by the field that names it ("ground.file": the heightmap,
// "mask") and the name the state gives it: its bytes, or its own error line.
using GardenFileReader = std::function<Result<std::vector<unsigned char>>(const std::string& field,
                                                                          const std::string& file)>;

// Fills the heightmap's bytes (a heightmap ground with a file name) and the mask's (a mask name)
// through `read` (decoded, and so checked, when the garden is built: DecodeGardenHeightmap, Mask).
// A read's error is returned under "ground.file" or "mask".
Status LoadGardenImages(const GardenFileReader& read, GardenState* state);

// Applies {params: {...}, ground: {kind: "flat" | "terrain" | "heightmap" | "mesh", terrain:
// {...the terrain's state JSON...}, file: "h.png" or "hill.glb"}, objects: [{kind, pos: [x, z],
// rot, scale}], plants:
// [{species, seed, age, pos: [x, z], rot}], mix: {species: weight}, mask: "m.png", ivy: {preset,
// on: ["objects[0]", "plants[1]"]}, moss: {...the moss's state JSON...}, wind: {wind_speed: 12,
// ...: rows IsGardenWindKey accepts}} onto state.
// Given lists replace the state's; a heightmap's, a ground mesh's and a mask's file names are kept
// for the front end to read (their bytes and mesh are cleared). Strict: the first bad field is the
// error, the state unchanged.
Status ApplyGardenStateJson(const std::string& text, GardenState* state);
// Applies {wind_speed: 12, wind_dir: 90, ...} (rows IsGardenWindKey accepts) onto state->wind,
// then checks them together (CheckGardenState's wind part). Strict: errors name "wind.<key>" (or
// "wind"), the state unchanged.
Status ApplyGardenWindJson(const std::string& text, GardenState* state);
// The state's wind rows that differ from GardenWindBase, as {key: value} in table order ("{}" when
// none).
std::string GardenWindJson(const GardenState& state);
// What ApplyGardenStateJson reads back to the same state (files by name).
std::string GardenStateJson(const GardenState& state);

// The share-link hash: the table's rows that differ from the defaults, ground=flat|terrain|
// heightmap, the terrain's keys under "terrain.", objects=kind:x:z:rot:scale,..., plants=
// species:seed:age:x:z:rot,..., mix=species:weight,..., ivy=objects[0],..., ivy_preset=artist, the
// moss's keys under "moss." when its state is not GardenMossDefaults', the wind's rows that differ
// from GardenWindBase under "wind." (wind.wind_speed=12), mask=1 when the state has a
// mask (a heightmap, a ground mesh, a mesh object or a mask is not carried: a link of such a
// garden says so in `notices` when read). Keys carry `prefix`.
std::string EncodeGardenHash(const GardenState& state, std::string_view prefix = "");
// Forgiving, as every study's hash: bad values clamped or dropped with a printable notice each.
void ApplyGardenHash(std::string_view hash, std::string_view prefix, GardenState* state,
                     std::vector<std::string>* notices);

}  // namespace niwa::compose

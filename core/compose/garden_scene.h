// The garden's stage: the ground (a square grid of heights over [−L/2, L/2]², from a flat plane, a
// grown terrain fitted to the square and scaled to the relief, or a heightmap PNG) and the built-in
// objects standing on it (walls, rocks, stone lanterns: meshes in metres, y up, placed and their
// plan footprints kept for the planting rules). Every height query reads the ground's own
// triangles, so what stands at HeightAt stands on the drawn surface. Does not: plant or grow trees
// (garden_plant.h, garden_run.h), read files (the state carries the PNG bytes), or name a flag.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "base/budget.h"
#include "base/status.h"
#include "compose/garden_state.h"
#include "geom/tri_mesh.h"

namespace niwa::compose {

// ---- data ----

// Heights of (n + 1)² vertices, vertex (i, j) at x = −L/2 + i·cell, z = −L/2 + j·cell (row j = 0
// the north edge), each cell split along its (i, j)–(i + 1, j + 1) diagonal.
struct GardenGround {
  int n = 0;
  double size = 0, cell = 0;
  std::vector<double> h;  // (n + 1)² heights, metres above the lowest point (min 0)
  double relief = 0;      // highest height
  std::string source;     // "flat", "terrain fig16 (seed 1)", "heightmap h.png (257 × 257)"
  double At(int i, int j) const { return h[static_cast<std::size_t>(j) * (n + 1) + i]; }
  // The height of the ground's triangle under (x, z), clamped into the square.
  double HeightAt(double x, double z) const;
  // That triangle's slope in degrees (0 flat).
  double SlopeAt(double x, double z) const;
  // The ground's triangles (normals by central differences, uvs over the square).
  geom::TriMesh Mesh() const;

 private:
  // The triangle under (x, z): its height there and its rise per cell along x and along z.
  struct Plane {
    double h = 0, dx = 0, dz = 0;
  };
  Plane PlaneAt(double x, double z) const;
};

// One placed object: its mesh in the garden's frame and its plan footprint (a rectangle of half
// sides hx, hz around (x, z) turned by rot degrees).
struct PlacedObject {
  std::string kind;
  double x = 0, z = 0, base_y = 0, rot = 0;
  double hx = 0, hz = 0;
  geom::TriMesh mesh;
  // True when (px, pz) is within `margin` metres of the footprint.
  bool Covers(double px, double pz, double margin) const;
};

struct GardenScene {
  GardenGround ground;
  std::vector<PlacedObject> objects;
  std::string truncated_by;  // a terrain ground's grow stop line ("" if none)
};

// ---- functions ----

// The rotation of (x, z) by rot degrees about y (counter-clockwise seen from above: +x towards −z):
// how a placed thing's own frame turns into the garden's (its `rot`), the inverse with −rot.
glm::dvec2 TurnPlan(double x, double z, double rot_deg);

// The ground of the state (its params' size, relief, ground_res; its ground kind) within budget.
// Errors name "ground.terrain" (the terrain's own field after it), "ground.file" (a heightmap that
// is not a grey PNG, or smaller than 2 × 2), or the budget's limit.
Result<GardenGround> BuildGardenGround(const GardenState& state, const Budget& budget,
                                       std::string* truncated_by = nullptr);

// A built-in object's mesh at the origin (base centre at y = 0, metres; GardenObjectKinds), its
// shape varied by `variant` (a rock's outline).
geom::TriMesh GardenObjectMesh(const std::string& kind, uint64_t variant);

// The ground and the state's objects placed on it (each base at the ground height under its
// centre, so the base's centre is on the surface).
Result<GardenScene> BuildGardenScene(const GardenState& state, const Budget& budget);

}  // namespace niwa::compose

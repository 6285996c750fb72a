// Light model (thesis 2.3.2): leaves as shading spheres; light L and its direction v_L per shoot.
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <memory>
#include <vector>

namespace niwa {

struct LeafSphere {
  glm::vec3 center;
  float radius;
};

// Sky: overcast directions over the upper hemisphere plus the sun, weights summing to 1.
struct Sky {
  std::vector<glm::vec3> directions;  // unit, pointing towards the light
  std::vector<float> weights;
};

struct LightSample {
  float light;          // L in [0, 1]
  glm::vec3 direction;  // v_L: unit resultant direction of the received light
};

// 16 sky directions (Fibonacci spiral from the zenith) plus the sun. Sky radiance rises linearly
// in sin(elevation) from 1 at the horizon to zenith_ratio (1: uniform, 3: CIE overcast sky).
Sky MakeSky(float sun_elevation_deg, float sun_azimuth_deg, float sun_weight,
            float zenith_ratio = 1.0f);

// Exact pairwise reference, O(n² · directions): light at each sphere's centre from every other
// sphere.
std::vector<LightSample> ComputeLightReference(const std::vector<LeafSphere>& spheres,
                                               const Sky& sky, float opacity);
// The same with `foreign` spheres (other trees' leaves, core/compose/tree_neighbours): they shade
// every sphere of `spheres` and receive no light themselves.
std::vector<LightSample> ComputeLightReference(const std::vector<LeafSphere>& spheres,
                                               const std::vector<LeafSphere>& foreign,
                                               const Sky& sky, float opacity);

// Near-linear production model: sphere density rasterized into a voxel grid, rays marched through
// it.
std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres, const Sky& sky,
                                          float opacity);

// A working array whose every cell is written before it is read: growing it neither keeps nor
// zeroes the old cells (std::vector::resize zero-filled each new cell, 4 % of the instructions of a
// sakura-thesis 15-year grow; issue 17 item 7).
template <typename T>
class ScratchArray {
 public:
  // Room for n cells (contents unspecified until written); the pointer stays valid until a larger
  // n.
  T* Resize(std::size_t n) {
    if (n > capacity_) {
      capacity_ = n + n / 4;
      cells_.reset(new T[capacity_]);
    }
    return cells_.get();
  }

 private:
  std::unique_ptr<T[]> cells_;
  std::size_t capacity_ = 0;
};

// Working memory of ComputeLightGrid, kept by a caller that calls it again and again (the growth
// loop, once a year) so that the grids are not given back and touched afresh on every call.
struct LightGridBuffers {
  struct Lookup {
    std::ptrdiff_t base[3];  // lower corner of the centre's trilinear cell, in each axis's layout
    float own_depth;         // optical depth of the shoot's own sphere from its centre (one radius)
  };
  std::vector<float> density, dx2, dy2;
  ScratchArray<float> density_x_major, density_y_major, depth[3], transmittance;
  ScratchArray<Lookup> lookups;
  // Per corner c = (c & 1: +x, c & 2: +y, c & 4: +z), one row of all spheres (row c, sphere i at
  // c · spheres + i): the trilinear weight, and half of the corner cell's extinction (the same in
  // every layout).
  ScratchArray<float> corner_weight, corner_half_sigma;
  std::vector<int> spans;  // rasterization: first and last covered x of each row of a sphere's box
  std::vector<float> received, strongest;  // per sphere, while resolving L and v_L
  std::vector<int> strongest_direction;
  ScratchArray<float> foreign_exponents;  // the foreign grid's exponents, per direction a row
};
std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres, const Sky& sky,
                                          float opacity, LightGridBuffers& buffers);
// With `foreign` spheres (other trees' leaves in this tree's frame, core/compose/tree_neighbours)
// that shade `spheres` and receive no light. The spheres' own shade is the grid above, cell for
// cell (so with no foreign spheres the same bits); the foreign spheres go into a second grid over
// the box of both, alone, and its optical depth at each sphere's centre is added to the own one
// before the exponential (Beer-Lambert: the depths along a ray add).
std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres,
                                          const std::vector<LeafSphere>& foreign, const Sky& sky,
                                          float opacity, LightGridBuffers& buffers);

}  // namespace niwa

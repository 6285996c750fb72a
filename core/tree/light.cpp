// Leaf-sphere light model: pairwise reference and voxel-grid production versions (thesis 2.3.2).
#include "tree/light.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "light/sun.h"
#include "math/rotation.h"
#include "math/simd4.h"

namespace niwa {
namespace {

constexpr int kSkyDirections = 16;

// -ln(1 - opacity): the optical depth of one sphere diameter (computed once per call).
float DiameterDepth(float opacity) { return -det::Logf(1.0f - opacity); }

// Extinction per cm inside a sphere: a ray through the whole diameter keeps (1 - opacity).
float Extinction(float diameter_depth, float radius) { return diameter_depth / (2.0f * radius); }

// Length of the ray origin + t·dir, t > 0, inside the sphere.
float ChordLength(const glm::vec3& origin, const glm::vec3& dir, const LeafSphere& sphere) {
  glm::vec3 to_center = sphere.center - origin;
  float along = glm::dot(to_center, dir);
  float miss2 = glm::dot(to_center, to_center) - along * along;
  float r2 = sphere.radius * sphere.radius;
  if (miss2 >= r2) return 0.0f;
  float half = std::sqrt(r2 - miss2);
  float t1 = along + half;
  if (t1 <= 0.0f) return 0.0f;
  float t0 = std::max(0.0f, along - half);
  return t1 - t0;
}

// L is the weighted transmitted light; v_L the direction where the received light is strongest
// (thesis 2.4.3 step 3: "光の強い方向を示す単位ベクトル").
// transmittance[k * stride] is the transmittance towards sky direction k.
LightSample Resolve(const Sky& sky, const float* transmittance, std::size_t stride) {
  float light = 0.0f, strongest = -1.0f;
  glm::vec3 direction(0, 1, 0);
  for (std::size_t k = 0; k < sky.directions.size(); ++k) {
    float received = sky.weights[k] * transmittance[k * stride];
    light += received;
    // Strongest received light: the sun when it is not shaded, else the brightest open patch of
    // sky.
    if (received > strongest) {
      strongest = received;
      direction = sky.directions[k];
    }
  }
  return {std::min(1.0f, light), direction};
}

// Resolve for `count` spheres at once from rows of transmittance (row k: every sphere towards
// direction k), direction by direction: for each sphere the same operations in the same order as
// Resolve, so the same results, with the inner loops over contiguous memory.
void ResolveRows(const Sky& sky, const float* transmittance, std::size_t count,
                 LightGridBuffers& buffers, LightSample* result) {
  std::vector<float>& light = buffers.received;
  std::vector<float>& strongest = buffers.strongest;
  std::vector<int>& strongest_direction = buffers.strongest_direction;
  light.assign(count, 0.0f);
  strongest.assign(count, -1.0f);
  strongest_direction.assign(count, -1);
  for (std::size_t k = 0; k < sky.directions.size(); ++k) {
    const float weight = sky.weights[k];
    // After the first direction every `strongest` is at least 0, so a later direction of weight 0
    // (a sun left out, whose row is not exponentiated) would add 0 and could not be the strongest.
    if (weight == 0.0f && k > 0) continue;
    const float* row = transmittance + k * count;
    const int direction = static_cast<int>(k);
    for (std::size_t i = 0; i < count; ++i) {
      const float received = weight * row[i];
      light[i] += received;
      const bool stronger = received > strongest[i];  // selects, so that the loop vectorizes
      strongest[i] = stronger ? received : strongest[i];
      strongest_direction[i] = stronger ? direction : strongest_direction[i];
    }
  }
  for (std::size_t i = 0; i < count; ++i) {
    const int k = strongest_direction[i];
    result[i] = {std::min(1.0f, light[i]),
                 k < 0 ? glm::vec3(0, 1, 0) : sky.directions[static_cast<std::size_t>(k)]};
  }
}

// to[x * to_stride + y] = from[y * from_stride + x] for x < width, y < height: blocks of 4 × 4
// moved through four 4-lane registers (loads, shuffles and stores only: the same values), the
// edges one by one. Reading down the columns one value at a time was 3 % of a sakura-thesis grow.
void TransposePlane(const float* from, std::ptrdiff_t from_stride, float* to,
                    std::ptrdiff_t to_stride, int width, int height) {
  using simd::Float4;
  int y = 0;
  for (; y + 4 <= height; y += 4) {
    const float* in = from + y * from_stride;
    int x = 0;
    for (; x + 4 <= width; x += 4) {
      Float4 r0, r1, r2, r3;  // rows y..y+3, columns x..x+3
      std::memcpy(&r0, in + x, sizeof r0);
      std::memcpy(&r1, in + from_stride + x, sizeof r1);
      std::memcpy(&r2, in + 2 * from_stride + x, sizeof r2);
      std::memcpy(&r3, in + 3 * from_stride + x, sizeof r3);
      const Float4 t0 = __builtin_shufflevector(r0, r1, 0, 4, 1, 5);  // r0[0] r1[0] r0[1] r1[1]
      const Float4 t1 = __builtin_shufflevector(r2, r3, 0, 4, 1, 5);
      const Float4 t2 = __builtin_shufflevector(r0, r1, 2, 6, 3, 7);
      const Float4 t3 = __builtin_shufflevector(r2, r3, 2, 6, 3, 7);
      const Float4 c0 = __builtin_shufflevector(t0, t1, 0, 1, 4, 5);  // column x
      const Float4 c1 = __builtin_shufflevector(t0, t1, 2, 3, 6, 7);
      const Float4 c2 = __builtin_shufflevector(t2, t3, 0, 1, 4, 5);
      const Float4 c3 = __builtin_shufflevector(t2, t3, 2, 3, 6, 7);
      std::memcpy(to + x * to_stride + y, &c0, sizeof c0);
      std::memcpy(to + (x + 1) * to_stride + y, &c1, sizeof c1);
      std::memcpy(to + (x + 2) * to_stride + y, &c2, sizeof c2);
      std::memcpy(to + (x + 3) * to_stride + y, &c3, sizeof c3);
    }
    for (; x < width; ++x) {
      for (int k = 0; k < 4; ++k) to[x * to_stride + y + k] = in[k * from_stride + x];
    }
  }
  for (; y < height; ++y) {
    for (int x = 0; x < width; ++x) to[x * to_stride + y] = from[y * from_stride + x];
  }
}

// One direction's shadow propagation over the whole grid (see ComputeLightGrid), in a memory layout
// where the swept axis is the slowest and the rows of a slice lie one after another.
struct Sweep {
  float* out;                            // depth, padded grid
  const float* sigma;                    // extinction, same layout
  int first, sign, slices, rows, count;  // slices 1..slices, rows 1..rows of count interior cells
  std::ptrdiff_t slice_stride, up, su, sv;
  float step, w00, w10, w01, w11;
};

// The hot loop of the light model. The whole of a slice, from its first interior cell to its
// last, is one loop, long enough for the vector lanes; the border cells between its rows that the
// loop also writes are set back to zero, and the other border cells are zeroed here, so the
// buffer's earlier contents do not matter. On x86-64 with GCC it is also compiled
// for AVX2 and picked at run time: eight lanes of the same IEEE single-precision operations as the
// four of SSE2 (no FMA: -ffp-contract=off), so every result is bit-identical, natively and against
// WASM.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("avx2", "default")))
#endif
void SweepSlices(const Sweep& w) {
  const std::ptrdiff_t row_stride = w.count + 2;
  const std::ptrdiff_t slice_cells = row_stride * (w.rows + 2);
  // The border slices at both ends (upstream of the first slice, and downstream of the last, which
  // the lookups read when the grid is one cell thick), and below each slice's border rows (and the
  // two border cells at the ends of the loop): every border cell ends up zero.
  std::fill_n(w.out, slice_cells, 0.0f);
  std::fill_n(w.out + (w.slices + 1) * w.slice_stride, slice_cells, 0.0f);
  const int span = static_cast<int>((w.rows - 1) * row_stride + w.count);
  for (int a = w.first; a >= 1 && a <= w.slices; a -= w.sign) {
    float* slice = w.out + a * w.slice_stride;
    std::fill_n(slice, row_stride + 1, 0.0f);
    std::fill_n(slice + slice_cells - row_stride - 1, row_stride + 1, 0.0f);
    const std::ptrdiff_t start = a * w.slice_stride + row_stride + 1;
    // The cells written and the cells read lie on different slices (or on this slice's border
    // rows, which this loop does not write): no overlap.
    float* __restrict here = w.out + start;
    const float* __restrict there = w.out + start + w.up;
    const float* __restrict own_sigma = w.sigma + start;
    for (int i = 0; i < span; ++i) {
      here[i] = own_sigma[i] * w.step + w.w00 * there[i] + w.w10 * there[i + w.su] +
                w.w01 * there[i + w.sv] + w.w11 * there[i + w.su + w.sv];
    }
    for (int o = 1; o < w.rows; ++o) {
      here[o * row_stride - 2] = 0.0f;  // last border cell of row o
      here[o * row_stride - 1] = 0.0f;  // first border cell of row o + 1
    }
  }
}

}  // namespace

Sky MakeSky(float sun_elevation_deg, float sun_azimuth_deg, float sun_weight, float zenith_ratio) {
  Sky sky;
  float total = 0.0f;
  const float golden = kPi * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < kSkyDirections; ++i) {
    // Fibonacci points on the upper hemisphere (about equal solid angle each), y up, the first at
    // the zenith so that an unshaded shoot's strongest sky light is straight up.
    float y = 1.0f - static_cast<float>(i) / kSkyDirections;
    float ring = std::sqrt(1.0f - y * y);
    float angle = golden * static_cast<float>(i);
    sky.directions.push_back(glm::vec3(ring * det::Cosf(angle), y, ring * det::Sinf(angle)));
    // Radiance 1 + (zenith_ratio - 1)·sin(elevation) (CIE overcast: ratio 3). A leaf sphere
    // receives radiance × solid angle from every side (no cosine factor, unlike a horizontal
    // surface).
    float weight = 1.0f + (zenith_ratio - 1.0f) * y;
    sky.weights.push_back(weight);
    total += weight;
  }
  for (float& w : sky.weights) w *= (1.0f - sun_weight) / total;
  sky.directions.push_back(light::SunDirection(sun_elevation_deg, sun_azimuth_deg));
  sky.weights.push_back(sun_weight);
  return sky;
}

std::vector<LightSample> ComputeLightReference(const std::vector<LeafSphere>& spheres,
                                               const Sky& sky, float opacity) {
  return ComputeLightReference(spheres, {}, sky, opacity);
}

std::vector<LightSample> ComputeLightReference(const std::vector<LeafSphere>& spheres,
                                               const std::vector<LeafSphere>& foreign,
                                               const Sky& sky, float opacity) {
  std::vector<LightSample> result(spheres.size());
  std::vector<float> transmittance(sky.directions.size());
  const float diameter_depth = DiameterDepth(opacity);
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    for (std::size_t k = 0; k < sky.directions.size(); ++k) {
      float depth = 0.0f;
      for (std::size_t j = 0; j < spheres.size(); ++j) {
        if (j == i) continue;
        float chord = ChordLength(spheres[i].center, sky.directions[k], spheres[j]);
        if (chord > 0.0f) depth += Extinction(diameter_depth, spheres[j].radius) * chord;
      }
      for (const LeafSphere& other : foreign) {
        float chord = ChordLength(spheres[i].center, sky.directions[k], other);
        if (chord > 0.0f) depth += Extinction(diameter_depth, other.radius) * chord;
      }
      transmittance[k] = det::Expf(-depth);
    }
    result[i] = Resolve(sky, transmittance.data(), 1);
  }
  return result;
}

std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres, const Sky& sky,
                                          float opacity) {
  LightGridBuffers buffers;
  return ComputeLightGrid(spheres, sky, opacity, buffers);
}

namespace {

// The grid's optical depths (see ComputeLightGrid): `occluders` rasterized into a grid over the box
// [lo, hi] (which holds every occluder and receiver), and for each of the `count` receivers and
// each sky direction k the exponent -depth into exponents[k * receiver_count + i]. With `own` the
// receivers are the occluders themselves and each one's own sphere (one radius from its centre) is
// taken off; else they add nothing to the grid. Rows of weight-0 directions are 0.
void GridExponents(const std::vector<LeafSphere>& occluders, const LeafSphere* receivers,
                   std::size_t receiver_count, bool own, glm::vec3 lo, glm::vec3 hi,
                   float radius_sum, const Sky& sky, float opacity, LightGridBuffers& buffers,
                   float* exponents) {
  const std::vector<LeafSphere>& spheres = occluders;
  // Cell about half a mean sphere radius, at most 56 cells along the longest side (48 left the
  // grid at r 0.951 against the pairwise reference on ginkgo at 8 years; 56 gives r >= 0.964 on
  // every preset at 20 % more light time than 48).
  glm::vec3 extent = hi - lo;
  float longest = std::max(extent.x, std::max(extent.y, extent.z));
  float cell = std::max(0.5f * radius_sum / static_cast<float>(spheres.size()), longest / 56.0f);
  // Interior cells 1..n per axis inside a border of empty cells, so sweeps need no bounds checks.
  const int n[3] = {std::max(1, static_cast<int>(std::ceil(extent.x / cell))),
                    std::max(1, static_cast<int>(std::ceil(extent.y / cell))),
                    std::max(1, static_cast<int>(std::ceil(extent.z / cell)))};
  const std::ptrdiff_t stride[3] = {1, n[0] + 2,
                                    static_cast<std::ptrdiff_t>(n[0] + 2) * (n[1] + 2)};
  const std::size_t volume =
      static_cast<std::size_t>(stride[2]) * static_cast<std::size_t>(n[2] + 2);
  auto index = [&](int x, int y, int z) {  // interior coordinates 0..n-1
    return static_cast<std::size_t>((x + 1) * stride[0] + (y + 1) * stride[1] +
                                    (z + 1) * stride[2]);
  };
  std::vector<float>& density = buffers.density;
  density.assign(volume, 0.0f);
  // Rasterize, conserving each sphere's extinction mass σ·V: spread over the voxels whose centres
  // lie inside it, or put in the voxel of its centre when it is smaller than a cell and hits none.
  std::vector<float>& dx2 = buffers.dx2;
  std::vector<float>& dy2 = buffers.dy2;
  std::vector<int>& spans = buffers.spans;
  const float cell_volume = cell * cell * cell;
  const float diameter_depth = DiameterDepth(opacity);
  for (const LeafSphere& s : spheres) {
    float sigma = Extinction(diameter_depth, s.radius);
    float mass =
        sigma * (4.0f / 3.0f) * static_cast<float>(det::kPi) * s.radius * s.radius * s.radius;
    glm::vec3 a = (s.center - glm::vec3(s.radius) - lo) / cell;
    glm::vec3 b = (s.center + glm::vec3(s.radius) - lo) / cell;
    int x0 = std::max(0, static_cast<int>(a.x)), x1 = std::min(n[0] - 1, static_cast<int>(b.x));
    int y0 = std::max(0, static_cast<int>(a.y)), y1 = std::min(n[1] - 1, static_cast<int>(b.y));
    int z0 = std::max(0, static_cast<int>(a.z)), z1 = std::min(n[2] - 1, static_cast<int>(b.z));
    float r2 = s.radius * s.radius;
    // Squared distance from the centre to each voxel centre, per axis (as glm::dot sums them).
    auto offset2 = [&](int i, int axis) {
      float d = lo[axis] + (static_cast<float>(i) + 0.5f) * cell - s.center[axis];
      return d * d;
    };
    dx2.clear();
    for (int x = x0; x <= x1; ++x) dx2.push_back(offset2(x, 0));
    dy2.clear();
    for (int y = y0; y <= y1; ++y) dy2.push_back(offset2(y, 1));
    const float* row_dx2 = dx2.data();
    const int width = x1 - x0 + 1;
    // Count the covered voxels, then add each one's share. The voxels of one row that a sphere
    // covers are one run [first, last] around the row's nearest voxel: along a row the computed
    // offset d rises with x (every rounding is monotonic), so d² falls then rises, and
    // (d² + dy²) + dz² <= r² holds on one interval holding the smallest d² if on any. Each run is
    // found outwards from that voxel and only the run gets the share: the same voxels and sums as
    // testing every voxel of the box (adding 0 elsewhere changed nothing).
    int nearest = 0;
    for (int i = 1; i < width; ++i) nearest = row_dx2[i] < row_dx2[nearest] ? i : nearest;
    spans.clear();
    int count = 0;
    for (int z = z0; z <= z1; ++z) {
      const float dz2 = offset2(z, 2);
      for (int y = y0; y <= y1; ++y) {
        const float row_dy2 = dy2[static_cast<std::size_t>(y - y0)];
        auto covered = [&](int i) { return row_dx2[i] + row_dy2 + dz2 <= r2; };
        int first = nearest, last = nearest - 1;  // empty unless the nearest voxel is covered
        if (width > 0 && covered(nearest)) {
          last = nearest;
          while (first > 0 && covered(first - 1)) --first;
          while (last + 1 < width && covered(last + 1)) ++last;
          count += last - first + 1;
        }
        spans.push_back(first);
        spans.push_back(last);
      }
    }
    if (count == 0) {
      glm::vec3 g = (s.center - lo) / cell;
      density[index(std::min(n[0] - 1, static_cast<int>(g.x)),
                    std::min(n[1] - 1, static_cast<int>(g.y)),
                    std::min(n[2] - 1, static_cast<int>(g.z)))] +=
          mass / (static_cast<float>(1) * cell_volume);
      continue;
    }
    const float each = mass / (static_cast<float>(count) * cell_volume);
    const int* span = spans.data();
    for (int z = z0; z <= z1; ++z) {
      for (int y = y0; y <= y1; ++y, span += 2) {
        float* row = density.data() + index(x0, y, z);
        for (int i = span[0]; i <= span[1]; ++i) row[i] += each;
      }
    }
  }

  // The sweep axis of each sky direction: the dominant component of its direction.
  const std::size_t directions = sky.directions.size();
  std::vector<int> sweep_axis(directions);
  bool axis_used[3] = {false, false, false};
  for (std::size_t k = 0; k < directions; ++k) {
    const glm::vec3& d = sky.directions[k];
    const float comp[3] = {d.x, d.y, d.z};
    int axis = 0;
    for (int c = 1; c < 3; ++c) {
      if (std::fabs(comp[c]) > std::fabs(comp[axis])) axis = c;
    }
    sweep_axis[k] = axis;
    axis_used[axis] |= sky.weights[k] != 0.0f;  // a sun of weight 0 is not swept
  }
  // One copy of the grid per sweep axis, with that axis the slowest in memory and x (or y, for the
  // x sweeps) the fastest: the slices of every sweep are contiguous, so its loop runs over long
  // stretches of memory and the compiler vectorizes it. Same values, same arithmetic per cell: only
  // the memory order differs. The z sweeps use the rasterized grid itself.
  const std::ptrdiff_t layout_stride[3][3] = {
      {static_cast<std::ptrdiff_t>(n[1] + 2) * (n[2] + 2), 1, n[1] + 2},  // x sweeps: y, z, x
      {1, static_cast<std::ptrdiff_t>(n[0] + 2) * (n[2] + 2), n[0] + 2},  // y sweeps: x, z, y
      {stride[0], stride[1], stride[2]}};                                 // z sweeps: x, y, z
  ScratchArray<float>* density_copy[2] = {&buffers.density_x_major, &buffers.density_y_major};
  const float* layout_density[3] = {nullptr, nullptr, density.data()};
  for (int axis = 0; axis < 2; ++axis) {
    if (!axis_used[axis]) continue;
    float* copy = density_copy[axis]->Resize(volume);  // every cell is written below
    layout_density[axis] = copy;
    const std::ptrdiff_t* to = layout_stride[axis];
    for (int z = 0; z < n[2] + 2; ++z) {
      if (to[0] == 1) {  // y-slowest: the x rows stay whole
        for (int y = 0; y < n[1] + 2; ++y) {
          const float* from = density.data() + y * stride[1] + z * stride[2];
          std::copy(from, from + n[0] + 2, copy + y * to[1] + z * to[2]);
        }
      } else {  // x-slowest, y fastest: the z plane transposed
        TransposePlane(density.data() + z * stride[2], stride[1], copy + z * to[2], to[0], n[0] + 2,
                       n[1] + 2);
      }
    }
  }

  // Each sphere's trilinear lookup cell and weights do not depend on the direction: computed once.
  using Lookup = LightGridBuffers::Lookup;
  const std::size_t count = receiver_count;
  Lookup* lookups = buffers.lookups.Resize(count);  // every receiver's is written below
  float* corner_weight = buffers.corner_weight.Resize(8 * count);          // all written below
  float* corner_half_sigma = buffers.corner_half_sigma.Resize(8 * count);  // all written below
  for (std::size_t i = 0; i < count; ++i) {
    const LeafSphere& receiver = receivers[i];
    Lookup& at = lookups[i];
    glm::vec3 g = (receiver.center - lo) / cell - 0.5f;
    int x = std::min(n[0] - 2, std::max(0, static_cast<int>(std::floor(g.x))));
    int y = std::min(n[1] - 2, std::max(0, static_cast<int>(std::floor(g.y))));
    int z = std::min(n[2] - 2, std::max(0, static_cast<int>(std::floor(g.z))));
    x = std::max(0, x);
    y = std::max(0, y);
    z = std::max(0, z);
    float tx = std::min(1.0f, std::max(0.0f, g.x - static_cast<float>(x)));
    float ty = std::min(1.0f, std::max(0.0f, g.y - static_cast<float>(y)));
    float tz = std::min(1.0f, std::max(0.0f, g.z - static_cast<float>(z)));
    for (int axis = 0; axis < 3; ++axis) {
      const std::ptrdiff_t* ls = layout_stride[axis];
      at.base[axis] = (x + 1) * ls[0] + (y + 1) * ls[1] + (z + 1) * ls[2];
    }
    for (std::size_t corner = 0; corner < 8; ++corner) {
      corner_weight[corner * count + i] = ((corner & 1) ? tx : 1 - tx) *
                                          (((corner >> 1) & 1) ? ty : 1 - ty) *
                                          (((corner >> 2) & 1) ? tz : 1 - tz);
    }
    for (std::size_t corner = 0; corner < 8; ++corner) {
      const int cx = static_cast<int>(corner & 1), cy = static_cast<int>((corner >> 1) & 1),
                cz = static_cast<int>((corner >> 2) & 1);
      corner_half_sigma[corner * count + i] = 0.5f * density[index(x + cx, y + cy, z + cz)];
    }
    at.own_depth = own ? Extinction(diameter_depth, receiver.radius) * receiver.radius : 0.0f;
  }

  // Shadow propagation, one direction at a time: depth(v) = σ(v)·s + depth(v + d·s), swept along
  // the dominant axis of d so that v + d·s lies on the slice swept just before (bilinear there).
  // One depth buffer per sweep axis, in that axis's layout.
  // One row of all spheres per direction, every cell written below.
  for (std::size_t k = 0; k < directions; ++k) {
    if (sky.weights[k] == 0.0f) {  // a sun of weight 0: its light adds nothing, skip the sweep
      std::fill_n(exponents + k * count, count, 0.0f);
      continue;
    }
    const glm::vec3& d = sky.directions[k];
    const float comp[3] = {d.x, d.y, d.z};
    const int axis = sweep_axis[k];
    const std::ptrdiff_t* st = layout_stride[axis];
    float* depth =
        buffers.depth[axis].Resize(volume);  // SweepSlices writes or zeroes every cell it reads
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const float along = std::fabs(comp[axis]);
    const float step = cell / along;  // path length between two slices
    // Offset (in cells) of the upstream point on the neighbouring slice: |du|, |dv| <= 1.
    const float du = comp[u] / along, dv = comp[v] / along;
    const int iu = du >= 1.0f ? 0 : static_cast<int>(std::floor(du));
    const int iv = dv >= 1.0f ? 0 : static_cast<int>(std::floor(dv));
    const float fu = du - static_cast<float>(iu), fv = dv - static_cast<float>(iv);
    const float w00 = (1 - fu) * (1 - fv), w10 = fu * (1 - fv), w01 = (1 - fu) * fv, w11 = fu * fv;
    const int sign = comp[axis] > 0 ? 1 : -1;
    const std::ptrdiff_t up = sign * st[axis] + iu * st[u] + iv * st[v];
    const std::ptrdiff_t su = st[u], sv = st[v];
    float* out = depth;
    const float* sigma = layout_density[axis];
    const int first = sign > 0 ? n[axis] : 1;  // padded slice coordinates 1..n
    // In this layout the rows of a slice run along whichever of u, v has stride 1.
    const int inner = st[u] < st[v] ? u : v, outer = inner == u ? v : u;
    SweepSlices({out, sigma, first, sign, n[axis], n[outer], n[inner], st[axis], up, su, sv, step,
                 w00, w10, w01, w11});
    // Trilinear lookup at each sphere centre, minus half of each cell's own step and the shoot's
    // own sphere (a ray from its centre crosses one radius of it).
    std::ptrdiff_t corner_offset[8];
    for (int corner = 0; corner < 8; ++corner) {
      corner_offset[corner] =
          (corner & 1) * st[0] + ((corner >> 1) & 1) * st[1] + ((corner >> 2) & 1) * st[2];
    }
    // Four spheres at a time, one per lane: each lane forms the scalar's corner terms with the
    // same IEEE operations (no FMA, -ffp-contract=off) and adds them in corner order as before.
    using simd::Float4;
    float* exponent = exponents + k * count;
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
      const float* cell0 = out + lookups[i].base[axis];
      const float* cell1 = out + lookups[i + 1].base[axis];
      const float* cell2 = out + lookups[i + 2].base[axis];
      const float* cell3 = out + lookups[i + 3].base[axis];
      Float4 sum = {0.0f, 0.0f, 0.0f, 0.0f};
      for (std::size_t corner = 0; corner < 8; ++corner) {
        const std::ptrdiff_t at = corner_offset[corner];
        const Float4 o = {cell0[at], cell1[at], cell2[at], cell3[at]};
        Float4 w, h;
        std::memcpy(&w, corner_weight + corner * count + i, sizeof w);
        std::memcpy(&h, corner_half_sigma + corner * count + i, sizeof h);
        sum += w * (o - h * step);
      }
      for (std::size_t lane = 0; lane < 4; ++lane) {
        // The exponent for now; transmittance = e^exponent for all of them at once below.
        exponent[i + lane] = -std::max(0.0f, sum[lane] - lookups[i + lane].own_depth);
      }
    }
    for (; i < count; ++i) {
      const float* cell_out = out + lookups[i].base[axis];
      float sum = 0.0f;
      for (std::size_t corner = 0; corner < 8; ++corner) {
        sum += corner_weight[corner * count + i] *
               (cell_out[corner_offset[corner]] - corner_half_sigma[corner * count + i] * step);
      }
      exponent[i] = -std::max(0.0f, sum - lookups[i].own_depth);
    }
  }
}

// The box of `spheres` grown by `lo`, `hi` (from the first sphere's centre when `first`), and the
// sum of their radii.
void GrowBox(const std::vector<LeafSphere>& spheres, bool first, glm::vec3& lo, glm::vec3& hi,
             float& radius_sum) {
  if (first && !spheres.empty()) lo = hi = spheres[0].center;
  for (const LeafSphere& s : spheres) {
    lo = glm::min(lo, s.center - glm::vec3(s.radius));
    hi = glm::max(hi, s.center + glm::vec3(s.radius));
    radius_sum += s.radius;
  }
}

}  // namespace

std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres, const Sky& sky,
                                          float opacity, LightGridBuffers& buffers) {
  static const std::vector<LeafSphere> kNone;
  return ComputeLightGrid(spheres, kNone, sky, opacity, buffers);
}

std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres,
                                          const std::vector<LeafSphere>& foreign, const Sky& sky,
                                          float opacity, LightGridBuffers& buffers) {
  std::vector<LightSample> result(spheres.size());
  if (spheres.empty()) return result;
  const std::size_t count = spheres.size(), directions = sky.directions.size();
  glm::vec3 lo, hi;
  float radius_sum = 0.0f;
  GrowBox(spheres, true, lo, hi, radius_sum);
  float* transmittance = buffers.transmittance.Resize(count * directions);  // all written below
  GridExponents(spheres, spheres.data(), count, true, lo, hi, radius_sum, sky, opacity, buffers,
                transmittance);
  if (!foreign.empty()) {
    // The foreign shade: a second grid over the box of both, holding only the foreign spheres, so
    // that the tree's own light above is the lone tree's cell for cell; the optical depths add
    // (Beer-Lambert along each ray), before the exponential.
    float foreign_sum = 0.0f;
    GrowBox(foreign, false, lo, hi, foreign_sum);
    float* extra = buffers.foreign_exponents.Resize(count * directions);  // all written below
    GridExponents(foreign, spheres.data(), count, false, lo, hi, foreign_sum, sky, opacity, buffers,
                  extra);
    for (std::size_t j = 0; j < count * directions; ++j) transmittance[j] += extra[j];
  }
  // Rows of weight-0 directions (a sun left out; it is last) are not needed by Resolve.
  std::size_t rows = directions;
  while (rows > 0 && sky.weights[rows - 1] == 0.0f) --rows;
  det::ExpfInPlace(transmittance, rows * count);
  ResolveRows(sky, transmittance, count, buffers, result.data());
  return result;
}

}  // namespace niwa

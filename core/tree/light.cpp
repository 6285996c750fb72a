// Leaf-sphere light model: pairwise reference and voxel-grid production versions (thesis 2.3.2).
#include "tree/light.h"

#include <algorithm>
#include <cmath>

#include "math/rotation.h"

namespace niwa {
namespace {

constexpr int kSkyDirections = 16;

// Extinction per cm inside a sphere: a ray through the whole diameter keeps (1 - opacity).
float Extinction(float opacity, float radius) {
  return -std::log(1.0f - opacity) / (2.0f * radius);
}

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
LightSample Resolve(const Sky& sky, const float* transmittance) {
  float light = 0.0f, strongest = -1.0f;
  glm::vec3 direction(0, 1, 0);
  for (std::size_t k = 0; k < sky.directions.size(); ++k) {
    float received = sky.weights[k] * transmittance[k];
    light += received;
    // Compare radiance (received per unit weight), so the sun is not favoured for its weight alone.
    float radiance = transmittance[k];
    if (radiance > strongest) {
      strongest = radiance;
      direction = sky.directions[k];
    }
  }
  return {std::min(1.0f, light), direction};
}

}  // namespace

Sky MakeSky(float sun_elevation_deg, float sun_azimuth_deg, float sun_weight) {
  Sky sky;
  float total = 0.0f;
  const float golden = kPi * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < kSkyDirections; ++i) {
    // Fibonacci points on the upper hemisphere (equal solid angle each), y up.
    float y = 1.0f - (static_cast<float>(i) + 0.5f) / kSkyDirections;
    float ring = std::sqrt(1.0f - y * y);
    float angle = golden * static_cast<float>(i);
    sky.directions.push_back(glm::vec3(ring * std::cos(angle), y, ring * std::sin(angle)));
    // CIE standard overcast sky: radiance ∝ (1 + 2 sin(elevation)) / 3. A leaf sphere receives
    // radiance × solid angle from every side (no cosine factor, unlike a horizontal surface).
    float weight = (1.0f + 2.0f * y) / 3.0f;
    sky.weights.push_back(weight);
    total += weight;
  }
  for (float& w : sky.weights) w *= (1.0f - sun_weight) / total;
  float elevation = Radians(sun_elevation_deg), azimuth = Radians(sun_azimuth_deg);
  sky.directions.push_back(glm::vec3(std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                                     std::cos(elevation) * std::sin(azimuth)));
  sky.weights.push_back(sun_weight);
  return sky;
}

std::vector<LightSample> ComputeLightReference(const std::vector<LeafSphere>& spheres,
                                               const Sky& sky, float opacity) {
  std::vector<LightSample> result(spheres.size());
  std::vector<float> transmittance(sky.directions.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    for (std::size_t k = 0; k < sky.directions.size(); ++k) {
      float depth = 0.0f;
      for (std::size_t j = 0; j < spheres.size(); ++j) {
        if (j == i) continue;
        float chord = ChordLength(spheres[i].center, sky.directions[k], spheres[j]);
        if (chord > 0.0f) depth += Extinction(opacity, spheres[j].radius) * chord;
      }
      transmittance[k] = std::exp(-depth);
    }
    result[i] = Resolve(sky, transmittance.data());
  }
  return result;
}

std::vector<LightSample> ComputeLightGrid(const std::vector<LeafSphere>& spheres, const Sky& sky,
                                          float opacity) {
  std::vector<LightSample> result(spheres.size());
  if (spheres.empty()) return result;
  glm::vec3 lo(spheres[0].center), hi(spheres[0].center);
  float radius_sum = 0.0f;
  for (const LeafSphere& s : spheres) {
    lo = glm::min(lo, s.center - glm::vec3(s.radius));
    hi = glm::max(hi, s.center + glm::vec3(s.radius));
    radius_sum += s.radius;
  }
  // Cell about half a mean sphere radius, at most 48 cells along the longest side.
  glm::vec3 extent = hi - lo;
  float longest = std::max(extent.x, std::max(extent.y, extent.z));
  float cell = std::max(0.5f * radius_sum / static_cast<float>(spheres.size()), longest / 48.0f);
  const int n[3] = {std::max(1, static_cast<int>(std::ceil(extent.x / cell))),
                    std::max(1, static_cast<int>(std::ceil(extent.y / cell))),
                    std::max(1, static_cast<int>(std::ceil(extent.z / cell)))};
  auto index = [&](int x, int y, int z) {
    return (static_cast<std::size_t>(z) * static_cast<std::size_t>(n[1]) +
            static_cast<std::size_t>(y)) * static_cast<std::size_t>(n[0]) +
           static_cast<std::size_t>(x);
  };
  std::vector<float> density(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0.0f);
  // Rasterize: every voxel whose centre lies in a sphere gets that sphere's extinction.
  for (const LeafSphere& s : spheres) {
    float sigma = Extinction(opacity, s.radius);
    glm::vec3 a = (s.center - glm::vec3(s.radius) - lo) / cell;
    glm::vec3 b = (s.center + glm::vec3(s.radius) - lo) / cell;
    int x0 = std::max(0, static_cast<int>(a.x)), x1 = std::min(n[0] - 1, static_cast<int>(b.x));
    int y0 = std::max(0, static_cast<int>(a.y)), y1 = std::min(n[1] - 1, static_cast<int>(b.y));
    int z0 = std::max(0, static_cast<int>(a.z)), z1 = std::min(n[2] - 1, static_cast<int>(b.z));
    float r2 = s.radius * s.radius;
    for (int z = z0; z <= z1; ++z) {
      for (int y = y0; y <= y1; ++y) {
        for (int x = x0; x <= x1; ++x) {
          glm::vec3 p = lo + (glm::vec3(x, y, z) + 0.5f) * cell;
          glm::vec3 d = p - s.center;
          if (glm::dot(d, d) <= r2) density[index(x, y, z)] += sigma;
        }
      }
    }
  }

  // Shadow propagation, one direction at a time: depth(v) = σ(v)·s + depth(v + d·s), swept along the
  // dominant axis of d so that v + d·s lies on the slice swept just before (bilinear there).
  std::vector<float> depth(density.size());
  std::vector<float> transmittance(spheres.size() * sky.directions.size());
  const std::size_t directions = sky.directions.size();
  for (std::size_t k = 0; k < directions; ++k) {
    const glm::vec3& d = sky.directions[k];
    const float comp[3] = {d.x, d.y, d.z};
    int axis = 0;
    for (int c = 1; c < 3; ++c) {
      if (std::fabs(comp[c]) > std::fabs(comp[axis])) axis = c;
    }
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    const float along = std::fabs(comp[axis]);
    const float step = cell / along;                    // path length between slices
    const float du = comp[u] / along, dv = comp[v] / along;  // offset in cells on the next slice
    const int sign = comp[axis] > 0 ? 1 : -1;
    const int iu = static_cast<int>(std::floor(du)), iv = static_cast<int>(std::floor(dv));
    const float fu = du - static_cast<float>(iu), fv = dv - static_cast<float>(iv);
    int coord[3];
    auto at = [&](int a, int b, int c) {  // axis, u, v coordinates -> index
      coord[axis] = a;
      coord[u] = b;
      coord[v] = c;
      return index(coord[0], coord[1], coord[2]);
    };
    auto upstream = [&](int a, int b, int c) -> float {  // depth on slice a, 0 outside the grid
      if (a < 0 || a >= n[axis] || b < 0 || b >= n[u] || c < 0 || c >= n[v]) return 0.0f;
      return depth[at(a, b, c)];
    };
    const int first = sign > 0 ? n[axis] - 1 : 0;
    for (int a = first; a >= 0 && a < n[axis]; a -= sign) {
      const int up = a + sign;
      for (int c = 0; c < n[v]; ++c) {
        for (int b = 0; b < n[u]; ++b) {
          float before = (1 - fu) * (1 - fv) * upstream(up, b + iu, c + iv) +
                         fu * (1 - fv) * upstream(up, b + iu + 1, c + iv) +
                         (1 - fu) * fv * upstream(up, b + iu, c + iv + 1) +
                         fu * fv * upstream(up, b + iu + 1, c + iv + 1);
          std::size_t here = at(a, b, c);
          depth[here] = density[here] * step + before;
        }
      }
    }
    // Trilinear lookup at each sphere centre, minus half of the centre cell's own step and the
    // shoot's own sphere (a ray from its centre crosses one radius of it).
    for (std::size_t i = 0; i < spheres.size(); ++i) {
      const LeafSphere& own = spheres[i];
      glm::vec3 g = (own.center - lo) / cell - 0.5f;
      int x = static_cast<int>(std::floor(g.x)), y = static_cast<int>(std::floor(g.y)),
          z = static_cast<int>(std::floor(g.z));
      float tx = g.x - static_cast<float>(x), ty = g.y - static_cast<float>(y),
            tz = g.z - static_cast<float>(z);
      float sum = 0.0f;
      for (int corner = 0; corner < 8; ++corner) {
        int cx = std::min(n[0] - 1, std::max(0, x + (corner & 1)));
        int cy = std::min(n[1] - 1, std::max(0, y + ((corner >> 1) & 1)));
        int cz = std::min(n[2] - 1, std::max(0, z + ((corner >> 2) & 1)));
        float w = ((corner & 1) ? tx : 1 - tx) * (((corner >> 1) & 1) ? ty : 1 - ty) *
                  (((corner >> 2) & 1) ? tz : 1 - tz);
        sum += w * (depth[index(cx, cy, cz)] - 0.5f * density[index(cx, cy, cz)] * step);
      }
      float own_depth = Extinction(opacity, own.radius) * own.radius;
      transmittance[i * directions + k] = std::exp(-std::max(0.0f, sum - own_depth));
    }
  }
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    result[i] = Resolve(sky, &transmittance[i * directions]);
  }
  return result;
}

}  // namespace niwa

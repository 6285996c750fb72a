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

LightSample Resolve(const Sky& sky, const float* transmittance) {
  float light = 0.0f;
  glm::vec3 resultant(0.0f);
  for (std::size_t k = 0; k < sky.directions.size(); ++k) {
    float received = sky.weights[k] * transmittance[k];
    light += received;
    resultant += sky.directions[k] * received;
  }
  float length = glm::length(resultant);
  glm::vec3 direction = length > 1e-9f ? resultant / length : glm::vec3(0, 1, 0);
  return {std::min(1.0f, light), direction};
}

}  // namespace

Sky MakeSky(float sun_elevation_deg, float sun_azimuth_deg, float sun_weight) {
  Sky sky;
  float total = 0.0f;
  const float golden = kPi * (3.0f - std::sqrt(5.0f));
  for (int i = 0; i < kSkyDirections; ++i) {
    // Fibonacci points on the upper hemisphere, y up; cos(zenith) from 1 down to ~0.03.
    float y = 1.0f - (static_cast<float>(i) + 0.5f) / kSkyDirections;
    float ring = std::sqrt(1.0f - y * y);
    float angle = golden * static_cast<float>(i);
    sky.directions.push_back(glm::vec3(ring * std::cos(angle), y, ring * std::sin(angle)));
    sky.weights.push_back(y);  // uniform overcast sky: irradiance ∝ cos(zenith)
    total += y;
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
  // Cell about half a mean sphere radius, at most 64 cells along the longest side.
  glm::vec3 extent = hi - lo;
  float longest = std::max(extent.x, std::max(extent.y, extent.z));
  float cell = std::max(0.5f * radius_sum / static_cast<float>(spheres.size()), longest / 64.0f);
  int nx = std::max(1, static_cast<int>(std::ceil(extent.x / cell)));
  int ny = std::max(1, static_cast<int>(std::ceil(extent.y / cell)));
  int nz = std::max(1, static_cast<int>(std::ceil(extent.z / cell)));
  std::vector<float> density(static_cast<std::size_t>(nx) * ny * nz, 0.0f);
  auto index = [&](int x, int y, int z) { return (static_cast<std::size_t>(z) * ny + y) * nx + x; };
  // Rasterize: every voxel whose centre lies in a sphere gets that sphere's extinction.
  for (const LeafSphere& s : spheres) {
    float sigma = Extinction(opacity, s.radius);
    glm::vec3 a = (s.center - glm::vec3(s.radius) - lo) / cell;
    glm::vec3 b = (s.center + glm::vec3(s.radius) - lo) / cell;
    int x0 = std::max(0, static_cast<int>(a.x)), x1 = std::min(nx - 1, static_cast<int>(b.x));
    int y0 = std::max(0, static_cast<int>(a.y)), y1 = std::min(ny - 1, static_cast<int>(b.y));
    int z0 = std::max(0, static_cast<int>(a.z)), z1 = std::min(nz - 1, static_cast<int>(b.z));
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
  std::vector<float> transmittance(sky.directions.size());
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    const LeafSphere& own = spheres[i];
    float own_sigma = Extinction(opacity, own.radius);
    for (std::size_t k = 0; k < sky.directions.size(); ++k) {
      const glm::vec3& dir = sky.directions[k];
      float depth = 0.0f;
      // March from the centre out of the grid, half a cell at a time.
      float step = 0.5f * cell;
      for (float t = 0.5f * step;; t += step) {
        glm::vec3 g = (own.center + dir * t - lo) / cell;
        if (g.x < 0 || g.y < 0 || g.z < 0 || g.x >= static_cast<float>(nx) ||
            g.y >= static_cast<float>(ny) || g.z >= static_cast<float>(nz)) {
          break;
        }
        int x = static_cast<int>(g.x), y = static_cast<int>(g.y), z = static_cast<int>(g.z);
        float sigma = density[index(x, y, z)];
        // The shoot's own sphere does not shade it: remove exactly what it rasterized here.
        glm::vec3 voxel_center = lo + (glm::vec3(x, y, z) + 0.5f) * cell - own.center;
        if (glm::dot(voxel_center, voxel_center) <= own.radius * own.radius) sigma -= own_sigma;
        depth += sigma * step;
      }
      depth = std::max(0.0f, depth);
      transmittance[k] = std::exp(-depth);
    }
    result[i] = Resolve(sky, transmittance.data());
  }
  return result;
}

}  // namespace niwa

// The hybrid renderer's camera (core/render/hybrid.h RenderCamera) of a page's view as the
// bindings receive it (numbers from JavaScript: eye, target in metres, fov_y radians, the drawing
// buffer's pixels), for the tree session's and the garden lab's hybridView. Does not: check the
// numbers (the worker passes finite ones) or choose anything.
#pragma once

#include <algorithm>

#include "render/hybrid.h"

namespace niwa {

inline RenderCamera ViewCamera(double ex, double ey, double ez, double tx, double ty, double tz,
                               double fov_y, int width, int height) {
  RenderCamera camera;
  camera.eye = glm::vec3(static_cast<float>(ex), static_cast<float>(ey), static_cast<float>(ez));
  camera.target = glm::vec3(static_cast<float>(tx), static_cast<float>(ty), static_cast<float>(tz));
  camera.fov_y = static_cast<float>(fov_y);
  camera.width = std::max(1, width);
  camera.height = std::max(1, height);
  return camera;
}

}  // namespace niwa

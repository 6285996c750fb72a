// Test helper: the Stanford bunny (tests/data/meshes/bunny.obj) prepared as an ivy support with the
// page's default "front" seed, as a dropped mesh is, optionally wound inward (a scan's faces).
#pragma once

#include <gtest/gtest.h>

#include <cstddef>
#include <memory>
#include <string>
#include <utility>

#include "io/mesh_reader.h"
#include "ivy/ivy_run.h"

namespace niwa::ivy::testing {

inline std::shared_ptr<const IvySupport> BunnySupport(bool inward = false) {
  const std::string path = std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/bunny.obj";
  Result<geom::TriMesh> bunny = io::ReadMeshFile(path);
  EXPECT_TRUE(bunny.ok()) << bunny.status().Line();
  if (inward) {  // a scan whose faces are wound inward
    for (std::size_t t = 0; t + 2 < bunny->indices.size(); t += 3)
      std::swap(bunny->indices[t + 1], bunny->indices[t + 2]);
    for (glm::vec3& n : bunny->normals) n = -n;
  }
  IvySupportOptions options;
  options.front_seed = true;  // the page's default seed on a dropped mesh
  Result<std::shared_ptr<const IvySupport>> support =
      IvySupport::Prepare(IvySupportInput::Mesh(*bunny, "bunny.obj", {}), options, Budget{});
  EXPECT_TRUE(support.ok()) << support.status().Line();
  return *support;
}

}  // namespace niwa::ivy::testing

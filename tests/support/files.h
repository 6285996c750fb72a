// Test helper: a whole file's bytes as a string (one copy instead of a Slurp in every test file).
#pragma once

#include <fstream>
#include <iterator>
#include <string>

namespace niwa::testing {

// The file's bytes; empty when it cannot be opened.
inline std::string Slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// A mesh under tests/data/meshes/ (the source tree's).
inline std::string MeshPath(const std::string& name) {
  return std::string(NIWA_SOURCE_DIR) + "/tests/data/meshes/" + name;
}

}  // namespace niwa::testing

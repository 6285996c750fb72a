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

}  // namespace niwa::testing

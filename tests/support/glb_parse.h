// Test helper: parses a .glb container (glTF 2.0 spec 4.4) into its JSON and BIN payload, with
// gtest checks of the header and chunk layout, and reads accessors' bytes back.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace niwa::testing {

using nlohmann::json;

inline uint32_t ReadU32(const std::vector<unsigned char>& bytes, std::size_t offset) {
  uint32_t value = 0;
  std::memcpy(&value, bytes.data() + offset, 4);  // glb is little-endian, as are both targets
  return value;
}

// A parsed .glb: its JSON and its BIN chunk payload.
struct Glb {
  json gltf;
  std::vector<unsigned char> bin;
};

// Parses the container, checking the header and chunk layout (glTF 2.0 spec, 4.4).
inline Glb ParseGlb(const std::vector<unsigned char>& bytes) {
  Glb glb;
  EXPECT_GE(bytes.size(), 20u);
  if (bytes.size() < 20) return glb;
  EXPECT_EQ(std::string(bytes.begin(), bytes.begin() + 4), "glTF");
  EXPECT_EQ(ReadU32(bytes, 4), 2u);
  EXPECT_EQ(ReadU32(bytes, 8), bytes.size());
  EXPECT_EQ(bytes.size() % 4, 0u);
  uint32_t json_length = ReadU32(bytes, 12);
  EXPECT_EQ(json_length % 4, 0u);
  EXPECT_EQ(ReadU32(bytes, 16), 0x4E4F534Au);  // "JSON"
  EXPECT_LE(20u + json_length, bytes.size());
  if (20u + json_length > bytes.size()) return glb;
  glb.gltf = json::parse(bytes.begin() + 20, bytes.begin() + 20 + json_length);
  std::size_t next = 20u + json_length;
  if (next < bytes.size()) {
    EXPECT_GE(bytes.size(), next + 8);
    uint32_t bin_length = ReadU32(bytes, next);
    EXPECT_EQ(ReadU32(bytes, next + 4), 0x004E4942u);  // "BIN\0"
    EXPECT_EQ(next + 8 + bin_length, bytes.size());
    glb.bin.assign(bytes.begin() + static_cast<std::ptrdiff_t>(next + 8), bytes.end());
  }
  return glb;
}

template <typename T>
std::vector<T> ReadAccessor(const Glb& glb, int index) {
  const json& accessor = glb.gltf["accessors"][static_cast<std::size_t>(index)];
  const json& view = glb.gltf["bufferViews"][accessor["bufferView"].get<std::size_t>()];
  std::size_t offset = view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", 0u);
  std::size_t length = view["byteLength"].get<std::size_t>();
  std::vector<T> values(length / sizeof(T));
  EXPECT_LE(offset + length, glb.bin.size());
  if (offset + length <= glb.bin.size())
    std::memcpy(values.data(), glb.bin.data() + offset, length);
  return values;
}

}  // namespace niwa::testing

// Test helper: a skinned .glb's vertices evaluated from the file alone (glTF 2.0 spec 3.7.3), for
// the sway exports' tests (tests/sway/sway_gltf_test.cpp, tests/render/tree_lod_sway_test.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <vector>

#include "support/glb_parse.h"

namespace niwa::testing {

// The skinned position of vertex v of one primitive at key k, evaluated from the .glb alone:
// sum_i w_i (translate(t_i(k)) rotate(q_i(k))) IBM_i p (glTF 2.0 spec, 3.7.3).
struct GlbSkinEval {
  const Glb* glb;
  std::vector<std::vector<float>> translation, rotation;  // per joint, keys (empty: rest)
  std::vector<std::array<float, 3>> rest, inverse_offset;
  glm::dvec3 At(std::size_t key, const std::vector<uint16_t>& joints,
                const std::vector<float>& weights, std::size_t v, const glm::dvec3& p) const {
    glm::dvec3 out(0.0);
    for (std::size_t c = 0; c < 4; ++c) {
      const double w = weights[4 * v + c];
      if (w == 0) continue;
      const std::size_t j = joints[4 * v + c];
      glm::dvec3 t(rest[j][0], rest[j][1], rest[j][2]);
      glm::dquat q(1, 0, 0, 0);
      if (!translation[j].empty()) {
        const float* a = &translation[j][3 * key];
        const float* b = &rotation[j][4 * key];
        t = glm::dvec3(a[0], a[1], a[2]);
        q = glm::dquat(b[3], b[0], b[1], b[2]);
      }
      glm::dvec3 local =
          p + glm::dvec3(inverse_offset[j][0], inverse_offset[j][1], inverse_offset[j][2]);
      out += w * (q * local + t);
    }
    return out;
  }
};

// Every vertex of primitive `primitive` of the .glb's first mesh at key `key` (the clip written
// with every key: key_error 0), skinned from the .glb alone.
inline std::vector<glm::dvec3> PrimitiveAtKey(const Glb& glb, std::size_t primitive,
                                              std::size_t key) {
  const json& gltf = glb.gltf;
  const json& skin = gltf["skins"][0];
  const std::size_t joints = skin["joints"].size();
  GlbSkinEval eval{&glb, {}, {}, {}, {}};
  eval.translation.resize(joints);
  eval.rotation.resize(joints);
  for (const json& channel : gltf["animations"][0]["channels"]) {
    const int node = channel["target"]["node"].get<int>();
    const std::size_t j = static_cast<std::size_t>(
        std::find(skin["joints"].begin(), skin["joints"].end(), node) - skin["joints"].begin());
    const json& sampler = gltf["animations"][0]["samplers"][channel["sampler"].get<std::size_t>()];
    (channel["target"]["path"] == "translation" ? eval.translation : eval.rotation)[j] =
        ReadAccessor<float>(glb, sampler["output"].get<int>());
  }
  const std::vector<float> ibm = ReadAccessor<float>(glb, skin["inverseBindMatrices"].get<int>());
  for (std::size_t j = 0; j < joints; ++j) {
    const json& node = gltf["nodes"][skin["joints"][j].get<std::size_t>()];
    std::array<float, 3> t{0, 0, 0};
    if (node.contains("translation")) {
      for (int c = 0; c < 3; ++c)
        t[static_cast<std::size_t>(c)] = node["translation"][c].get<float>();
    }
    eval.rest.push_back(t);
    eval.inverse_offset.push_back({ibm[16 * j + 12], ibm[16 * j + 13], ibm[16 * j + 14]});
  }
  const json& attributes = gltf["meshes"][0]["primitives"][primitive]["attributes"];
  const std::vector<uint16_t> j0 = ReadAccessor<uint16_t>(glb, attributes["JOINTS_0"].get<int>());
  const std::vector<float> w0 = ReadAccessor<float>(glb, attributes["WEIGHTS_0"].get<int>());
  const std::vector<float> p = ReadAccessor<float>(glb, attributes["POSITION"].get<int>());
  std::vector<glm::dvec3> out;
  for (std::size_t v = 0; 3 * v + 2 < p.size(); ++v) {
    out.push_back(eval.At(key, j0, w0, v, glm::dvec3(p[3 * v], p[3 * v + 1], p[3 * v + 2])));
  }
  return out;
}

}  // namespace niwa::testing

// TriMesh: the shared triangle mesh every study meets through (tree bark, ivy supports, moss
// stones). Positions in metres, world space; indices three per triangle; named custom per-vertex
// attributes. Does not: know trees, ivy or any study; load files (io/gltf_reader, io/obj_reader) or
// draw.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace niwa::geom {

// A named per-vertex attribute: `components` floats per vertex (e.g. "birth_step" 1, "branch_id" 1,
// "colour" 4), as Magnum's MeshData custom attributes.
struct VertexAttribute {
  std::string name;
  int components = 1;
  std::vector<float> values;  // vertex_count() * components
};

struct TriMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;  // empty, or one per vertex
  std::vector<glm::vec2> uvs;      // empty, or one per vertex
  std::vector<uint32_t> indices;   // three per triangle, counter-clockwise seen from outside
  std::vector<VertexAttribute> attributes;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
  const VertexAttribute* FindAttribute(const std::string& name) const {
    for (const VertexAttribute& a : attributes)
      if (a.name == name) return &a;
    return nullptr;
  }
  // Adds (or returns the existing) attribute, sized for the current vertex count.
  VertexAttribute& AddAttribute(const std::string& name, int components) {
    for (VertexAttribute& a : attributes)
      if (a.name == name) return a;
    attributes.push_back({name, components, std::vector<float>(vertex_count() * components, 0.0f)});
    return attributes.back();
  }
};

}  // namespace niwa::geom

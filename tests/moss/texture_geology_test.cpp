// Geology from a loaded mesh's base colour texture (core/moss/soil_cells.h over io's images):
// tests/data/meshes/textured.glb's two texels split its cells at x = 0, a material name still
// overrides, the wrap modes and the tint, ez-tree's textured flower, and hostile textures refused
// in one line naming the file (the reader for a bad header, SceneFromMesh for a bad body).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "image/png.h"
#include "io/mesh_reader.h"
#include "moss/soil_cells.h"
#include "support/files.h"

namespace niwa::moss {
namespace {

using ::niwa::testing::MeshPath;

std::map<Geology, std::size_t> CountGeology(const SoilCells& cells) {
  std::map<Geology, std::size_t> count;
  for (Geology g : cells.geology) ++count[g];
  return count;
}

// A .glb of one textured triangle (positions, indices, UVs, then the image's bytes), `image` the
// images[0] entry (its bufferView 2 is the image bytes) and `source` the texture's image.
std::string TexturedTriangleGlb(const std::string& image_bytes, const nlohmann::json& image,
                                int source = 0) {
  std::string bin(68, '\0');
  const float pos[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
  std::memcpy(bin.data(), pos, 36);
  const uint16_t idx[3] = {0, 1, 2};
  std::memcpy(bin.data() + 36, idx, 6);
  const float uv[6] = {0, 0, 1, 0, 0, 1};
  std::memcpy(bin.data() + 44, uv, 24);
  bin += image_bytes;
  while (bin.size() % 4 != 0) bin.push_back('\0');
  nlohmann::json j = {
      {"asset", {{"version", "2.0"}}},
      {"buffers", {{{"byteLength", bin.size()}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteLength", 36}},
        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}},
        {{"buffer", 0}, {"byteOffset", 68}, {"byteLength", image_bytes.size()}},
        {{"buffer", 0}, {"byteOffset", 44}, {"byteLength", 24}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}},
        {{"bufferView", 3}, {"componentType", 5126}, {"count", 3}, {"type", "VEC2"}}}},
      {"images", {image}},
      {"textures", {{{"source", source}}}},
      {"materials",
       {{{"name", "ground"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", {{"POSITION", 0}, {"TEXCOORD_0", 2}}},
            {"indices", 1},
            {"material", 0}}}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"scenes", {{{"nodes", {0}}}}}};
  std::string text = j.dump();
  while (text.size() % 4 != 0) text.push_back(' ');
  std::string glb = "glTF";
  auto u32 = [&](uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  u32(2);
  u32(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
  u32(static_cast<uint32_t>(text.size()));
  glb += "JSON" + text;
  u32(static_cast<uint32_t>(bin.size()));
  glb += std::string("BIN\0", 4) + bin;
  return glb;
}

std::string Png(int width, int height, const std::vector<unsigned char>& rgba) {
  image::Rgba8Image im;
  im.width = width;
  im.height = height;
  im.pixels = rgba;
  const std::vector<unsigned char> png = image::EncodeRgba8Png(im).value();
  return std::string(png.begin(), png.end());
}

// A PNG's signature and IHDR (8 + 25 bytes) declaring width x height, and nothing after.
std::string PngHeaderOnly(uint32_t width, uint32_t height) {
  std::string png = Png(1, 1, {1, 2, 3, 255}).substr(0, 33);
  for (int k = 0; k < 4; ++k) {
    png[16 + k] = static_cast<char>(width >> (24 - 8 * k));
    png[20 + k] = static_cast<char>(height >> (24 - 8 * k));
  }
  const uint32_t crc = image::Crc32(reinterpret_cast<const unsigned char*>(png.data()) + 12, 17);
  for (int k = 0; k < 4; ++k) png[29 + k] = static_cast<char>(crc >> (24 - 8 * k));
  return png;
}

TEST(MossTextureGeology, TheTexturesTwoHalvesSplitTheCellsAtXZero) {
  io::MeshReadStats read;
  const geom::TriMesh mesh = io::ReadMeshFile(MeshPath("textured.glb"), &read).value();
  ASSERT_EQ(read.images.size(), 1u);
  EXPECT_EQ(read.images[0].width, 2);
  EXPECT_EQ(read.images[0].height, 1);
  ASSERT_EQ(read.materials.size(), 1u);
  EXPECT_EQ(read.materials[0].base_color_image, 0);
  EXPECT_EQ(read.materials[0].wrap_s, io::kWrapClampToEdge);

  const MossScene scene = SceneFromMesh(mesh, read.materials, "textured.glb", read.images).value();
  ASSERT_EQ(scene.textures.size(), 1u);
  const SoilCells cells = MakeSoilCells(scene, SoilCellOptions{}).value();
  std::size_t checked = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const double x = cells.centroid[i].x;
    if (std::abs(x) < 1e-9) continue;  // on the seam: u = 0.5 is the right texel
    EXPECT_EQ(cells.geology[i], x < 0 ? Geology::kHumus : Geology::kSandy) << "cell " << i;
    ++checked;
  }
  std::map<Geology, std::size_t> count = CountGeology(cells);
  EXPECT_GT(checked, cells.size() * 9 / 10);
  EXPECT_EQ(count[Geology::kHumus], count[Geology::kSandy]);  // mirror-symmetric split
  EXPECT_EQ(count[Geology::kAsphalt], 0u);

  // Without its image the material is white (factor 1): every cell one geology, sandy's colour is
  // the nearest to white.
  const SoilCells plain =
      MakeSoilCells(SceneFromMesh(mesh, read.materials, "textured.glb").value(), SoilCellOptions{})
          .value();
  EXPECT_EQ(CountGeology(plain)[Geology::kSandy], plain.size());

  // A material name overrides the texture.
  std::vector<io::MeshMaterial> named = read.materials;
  named[0].name = "Asphalt slab";
  const SoilCells over =
      MakeSoilCells(SceneFromMesh(mesh, named, "textured.glb", read.images).value(),
                    SoilCellOptions{})
          .value();
  EXPECT_EQ(CountGeology(over)[Geology::kAsphalt], over.size());
  EXPECT_EQ(cells.size(), over.size());
}

TEST(MossTextureGeology, WrapModesAndTheTint) {
  SceneTexture t;
  t.texels.width = 4;
  t.texels.height = 1;
  t.texels.pixels = {0, 0, 0, 255, 1, 1, 1, 255, 2, 2, 2, 255, 3, 3, 3, 255};
  auto texel = [&](double u) { return SampleTexture(t, {u, 0.5})[0]; };
  t.wrap_s = io::kWrapRepeat;
  EXPECT_EQ(texel(0.0), 0);
  EXPECT_EQ(texel(0.26), 1);
  EXPECT_EQ(texel(0.99), 3);
  EXPECT_EQ(texel(-0.1), 3);  // 0.9
  EXPECT_EQ(texel(1.1), 0);   // 0.1
  EXPECT_EQ(texel(1.0), 0);   // 0.0
  t.wrap_s = io::kWrapClampToEdge;
  EXPECT_EQ(texel(-0.1), 0);
  EXPECT_EQ(texel(1.0), 3);
  EXPECT_EQ(texel(7.0), 3);
  t.wrap_s = io::kWrapMirroredRepeat;
  EXPECT_EQ(texel(-0.1), 0);  // mirrored to 0.1
  EXPECT_EQ(texel(1.1), 3);   // mirrored to 0.9
  EXPECT_EQ(texel(2.3), 1);   // 0.3
  EXPECT_EQ(texel(std::nan("")), 0);

  const unsigned char humus[3] = {0x4A, 0x33, 0x22}, sandy[3] = {0xC2, 0x9A, 0x5B};
  EXPECT_EQ(GeologyOfTexel(humus, glm::dvec3(1.0)), Geology::kHumus);
  EXPECT_EQ(GeologyOfTexel(sandy, glm::dvec3(1.0)), Geology::kSandy);
  // The glTF base colour is texel x factor x COLOR_0 in linear light: a sandy texel darkened to a
  // tenth is (sRGB) 0.26, 0.20, 0.10, nearest to humus; a white texel tinted with the grey of
  // linear 0.2159 is asphalt's 0x80.
  EXPECT_EQ(GeologyOfTexel(sandy, glm::dvec3(0.1)), Geology::kHumus);
  const unsigned char white[3] = {255, 255, 255};
  EXPECT_EQ(GeologyOfTexel(white, glm::dvec3(0.2159)), Geology::kAsphalt);
}

TEST(MossTextureGeology, EzTreesFlowerDecodesItsThreePngs) {
  io::MeshReadStats read;
  const geom::TriMesh mesh = io::ReadMeshFile(MeshPath("flower_blue.glb"), &read).value();
  ASSERT_EQ(read.images.size(), 3u);
  int textured = 0;
  for (const io::MeshMaterial& m : read.materials) {
    textured += m.base_color_image >= 0;
    EXPECT_EQ(m.base_color_source, m.base_color_image);  // PNGs: kept, the same index
  }
  EXPECT_EQ(textured, 3);
  const MossScene scene =
      SceneFromMesh(mesh, read.materials, "flower_blue.glb", read.images).value();
  EXPECT_EQ(scene.textures.size(), 3u);
  for (const SceneTexture& t : scene.textures) EXPECT_FALSE(t.texels.empty());
  const SoilCells cells = MakeSoilCells(scene, SoilCellOptions{}).value();
  EXPECT_GT(cells.size(), 0u);

  // rock1.glb's base colour is a WebP: kept without bytes, the material's colour is used.
  io::MeshReadStats rock;
  if (io::ReadMeshFile(MeshPath("rock1.glb"), &rock).ok()) {  // Draco: native only
    ASSERT_EQ(rock.materials.size(), 1u);
    EXPECT_EQ(rock.materials[0].base_color_image, -1);
    EXPECT_EQ(rock.materials[0].base_color_source, 1);  // Stones_1001_BaseColor, for the page
  }
}

TEST(MossTextureGeology, HostileTexturesAreRefusedNamingTheFile) {
  const std::string good = Png(2, 1, {0x4A, 0x33, 0x22, 255, 0xC2, 0x9A, 0x5B, 255});
  const nlohmann::json view = {{"bufferView", 2}, {"mimeType", "image/png"}};
  io::MeshReadStats read;
  ASSERT_TRUE(io::ReadMeshBytes(TexturedTriangleGlb(good, view), "t.glb", &read).ok());
  EXPECT_EQ(read.materials[0].base_color_image, 0);

  struct Case {
    std::string what, bytes;
    nlohmann::json image;
    int source;
    std::string says;
  };
  const std::vector<Case> cases = {
      {"bad bytes", std::string("\x89PNG\r\n\x1a\nnot a png at all", 24), view, 0, "corrupt PNG"},
      {"not an image", "hello, world", view, 0, "not a PNG or JPEG"},
      {"no bytes", "", view, 0, "has no bytes"},
      {"a missing image", good, view, 3, "names image 3, which does not exist"},
      {"0 x 0", PngHeaderOnly(0, 0), view, 0, "image 0"},
      {"huge", PngHeaderOnly(100000, 100000), view, 0, "100000 x 100000 pixels"},
      {"over the pixels", PngHeaderOnly(8192, 4096), view, 0, "at most 16777216 pixels"},
      {"an external file", good, {{"uri", "missing.png"}}, 0, "image 0"},
  };
  for (const Case& c : cases) {
    Result<geom::TriMesh> mesh =
        io::ReadMeshBytes(TexturedTriangleGlb(c.bytes, c.image, c.source), "t.glb", &read);
    if (c.what == "an external file") {
      // Bytes without a folder: not readable here, so not used (and not refused).
      ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
      EXPECT_EQ(read.materials[0].base_color_image, -1);
      continue;
    }
    ASSERT_FALSE(mesh.ok()) << c.what;
    EXPECT_EQ(mesh.status().field(), "t.glb") << c.what;
    EXPECT_NE(mesh.status().message().find(c.says), std::string::npos)
        << c.what << ": " << mesh.status().Line();
    EXPECT_EQ(mesh.status().Line().find('\n'), std::string::npos);
  }

  // A header that reads but a body that does not: refused when the moss decodes it.
  const std::string body_missing = PngHeaderOnly(2, 1);
  Result<geom::TriMesh> mesh =
      io::ReadMeshBytes(TexturedTriangleGlb(body_missing, view), "t.glb", &read);
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  Result<MossScene> scene = SceneFromMesh(*mesh, read.materials, "t.glb", read.images);
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.status().field(), "t.glb");
  EXPECT_NE(scene.status().message().find("material 0 'ground' baseColorTexture"),
            std::string::npos)
      << scene.status().Line();
}

// A .gltf's image as a file beside it: read from disk; a uri leaving the folder or naming a
// missing file is refused naming the .gltf.
TEST(MossTextureGeology, AGltfsImageFileBesideIt) {
  const std::string dir = ::testing::TempDir() + "niwa_texture_gltf";
  std::filesystem::create_directories(dir);
  const std::string png = Png(2, 1, {0x4A, 0x33, 0x22, 255, 0xC2, 0x9A, 0x5B, 255});
  std::ofstream(dir + "/tex.png", std::ios::binary) << png;
  // The .glb's JSON with its binary chunk as a data: URI buffer and the image as a uri.
  auto gltf_with = [&](const std::string& uri) {
    const std::string glb = TexturedTriangleGlb("", {{"uri", uri}});
    uint32_t json_length = 0;
    std::memcpy(&json_length, glb.data() + 12, 4);
    nlohmann::json j = nlohmann::json::parse(glb.substr(20, json_length));
    const std::string bin = glb.substr(20 + json_length + 8);
    static const char* kB64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string b64;
    for (std::size_t i = 0; i < bin.size(); i += 3) {
      uint32_t n = static_cast<unsigned char>(bin[i]) << 16;
      if (i + 1 < bin.size()) n |= static_cast<unsigned char>(bin[i + 1]) << 8;
      if (i + 2 < bin.size()) n |= static_cast<unsigned char>(bin[i + 2]);
      b64 += kB64[(n >> 18) & 63];
      b64 += kB64[(n >> 12) & 63];
      b64 += i + 1 < bin.size() ? kB64[(n >> 6) & 63] : '=';
      b64 += i + 2 < bin.size() ? kB64[n & 63] : '=';
    }
    j["buffers"][0]["uri"] = "data:application/octet-stream;base64," + b64;
    std::ofstream(dir + "/t.gltf") << j.dump();
    io::MeshReadStats read;
    Result<geom::TriMesh> mesh = io::ReadMeshFile(dir + "/t.gltf", &read);
    return std::make_pair(std::move(mesh), read);
  };
  auto [mesh, read] = gltf_with("tex.png");
  ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
  EXPECT_EQ(read.materials[0].base_color_image, 0);
  EXPECT_EQ(read.images[0].width, 2);
  EXPECT_EQ(read.images[0].bytes, png);
  auto [outside, r1] = gltf_with("../tex.png");
  ASSERT_FALSE(outside.ok());
  EXPECT_EQ(outside.status().field(), "t.gltf");
  EXPECT_NE(outside.status().message().find("must be a file beside the .gltf"), std::string::npos)
      << outside.status().Line();
  auto [missing, r2] = gltf_with("gone.png");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().field(), "t.gltf");
  EXPECT_NE(missing.status().message().find("gone.png"), std::string::npos)
      << missing.status().Line();
}

// KHR_texture_transform and a texCoord other than 0 (glTF spec: uv' = T(offset) * R(rotation) *
// S(scale) * uv on TEXCOORD_<texCoord>, the extension's texCoord overriding the textureInfo's):
// tests/support/make_texture_transform_meshes.mjs's squares, each split by its own seam. Every cell
// off the seam (1e-6 m) has the geology of its side; the counts are those of the sides (a cell on a
// seam samples whatever texel its UV rounds to, so the counts allow for those only).
TEST(MossTextureGeology, TextureTransformAndTexCoordMoveTheSeam) {
  struct Case {
    const char* file;
    int tex_coord;
    bool transform;
    // true where the cell's centroid (x, z) is humus; `seam` true within 1e-6 of a seam
    bool (*humus)(double x, double z);
    bool (*seam)(double x, double z);
  };
  const Case cases[] = {
      {"texture_offset.glb", 0, true, [](double x, double) { return x < -0.5; },
       [](double x, double) { return std::abs(x + 0.5) < 1e-6; }},
      {"texture_scale.glb", 0, true,
       [](double x, double) { return x < -0.5 || (x >= 0 && x < 0.5); },
       [](double x, double) {
         return std::abs(x + 0.5) < 1e-6 || std::abs(x) < 1e-6 || std::abs(x - 0.5) < 1e-6;
       }},
      {"texture_rotation.glb", 0, true, [](double, double z) { return z < 0; },
       [](double, double z) { return std::abs(z) < 1e-6; }},
      {"texture_texcoord1.glb", 1, false, [](double, double z) { return z < 0; },
       [](double, double z) { return std::abs(z) < 1e-6; }},
      {"texture_transform_texcoord1.glb", 1, true, [](double, double z) { return z < -0.5; },
       [](double, double z) { return std::abs(z + 0.5) < 1e-6; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.file);
    io::MeshReadStats read;
    Result<geom::TriMesh> mesh = io::ReadMeshFile(MeshPath(c.file), &read);
    ASSERT_TRUE(mesh.ok()) << mesh.status().Line();
    ASSERT_EQ(read.materials.size(), 1u);
    EXPECT_EQ(read.materials[0].base_color_image, 0);
    EXPECT_EQ(read.materials[0].base_color_tex_coord, c.tex_coord);
    EXPECT_EQ(read.materials[0].has_uv_transform, c.transform);
    ASSERT_NE(mesh->FindAttribute(io::kBaseColorUvAttribute), nullptr);
    const MossScene scene = SceneFromMesh(*mesh, read.materials, c.file, read.images).value();
    const SoilCells cells = MakeSoilCells(scene, SoilCellOptions{}).value();
    std::size_t want_humus = 0, want_sandy = 0, on_seam = 0, wrong = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const double x = cells.centroid[i].x, z = cells.centroid[i].z;
      if (c.seam(x, z)) {
        ++on_seam;
        continue;
      }
      const Geology want = c.humus(x, z) ? Geology::kHumus : Geology::kSandy;
      (want == Geology::kHumus ? want_humus : want_sandy) += 1;
      wrong += cells.geology[i] != want;
    }
    EXPECT_EQ(wrong, 0u);
    std::map<Geology, std::size_t> count = CountGeology(cells);
    EXPECT_EQ(count[Geology::kAsphalt], 0u);
    EXPECT_GE(count[Geology::kHumus], want_humus);
    EXPECT_LE(count[Geology::kHumus], want_humus + on_seam);
    EXPECT_EQ(count[Geology::kHumus] + count[Geology::kSandy], cells.size());
    EXPECT_GT(want_humus, 0u);
    EXPECT_GT(want_sandy, 0u);
    std::printf("%s: %zu cells, humus %zu, sandy %zu (%zu on a seam)\n", c.file, cells.size(),
                count[Geology::kHumus], count[Geology::kSandy], on_seam);
  }
}

// The transform applied by hand to textured.glb's TEXCOORD_0 (offset, rotation, scale in the
// spec's order T * R * S), and a texCoord naming a UV set the primitive does not have refused in
// one line naming the material and the set.
TEST(MossTextureGeology, TheTransformIsTheSpecsAndAMissingSetIsRefused) {
  io::MeshReadStats plain, shifted;
  const geom::TriMesh a = io::ReadMeshFile(MeshPath("textured.glb"), &plain).value();
  const geom::TriMesh b = io::ReadMeshFile(MeshPath("texture_rotation.glb"), &shifted).value();
  const geom::VertexAttribute* ua = a.FindAttribute(io::kBaseColorUvAttribute);
  const geom::VertexAttribute* ub = b.FindAttribute(io::kBaseColorUvAttribute);
  ASSERT_NE(ua, nullptr);
  ASSERT_NE(ub, nullptr);
  ASSERT_EQ(ua->values.size(), ub->values.size());
  // No transform: the attribute is TEXCOORD_0 itself, bit for bit.
  for (std::size_t v = 0; v < a.vertex_count(); ++v) {
    EXPECT_EQ(ua->values[2 * v], a.uvs[v].x);
    EXPECT_EQ(ua->values[2 * v + 1], a.uvs[v].y);
  }
  // Rotation pi/2: u' = cos r u + sin r v = v, v' = -sin r u + cos r v = -u.
  for (std::size_t v = 0; v < b.vertex_count(); ++v) {
    EXPECT_NEAR(ub->values[2 * v], b.uvs[v].y, 1e-6);
    EXPECT_NEAR(ub->values[2 * v + 1], -b.uvs[v].x, 1e-6);
  }
  EXPECT_NEAR(shifted.materials[0].uv_rotation, 1.5707963267948966, 1e-15);

  io::MeshReadStats read;
  Result<geom::TriMesh> missing = io::ReadMeshFile(MeshPath("texture_missing_texcoord.glb"), &read);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().field(), "texture_missing_texcoord.glb");
  EXPECT_EQ(missing.status().message(),
            "mesh 0 'ground' primitive 0: material 0 'ground' baseColorTexture reads TEXCOORD_1, "
            "which the primitive does not have");
  EXPECT_EQ(missing.status().Line().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace niwa::moss

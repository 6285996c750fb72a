// glTF, 16-bit PNG heightmap, GeoJSON and SVG of a grown terrain (see terrain_output.h).
#include "terrain/terrain_output.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "image/png.h"
#include "params/param_text.h"

namespace niwa::terrain {
namespace {

// The root contour's box (contour.h BoundsOf); all zeros for a terrain without contours.
RingBox RootBox(const Terrain& t) {
  if (t.contours.empty() || t.contours[0].ring.empty()) return {0, 0, 0, 0};
  return BoundsOf(t.contours[0].ring);
}

double TopElevation(const Terrain& t) {
  double top = t.contours.empty() ? 0 : t.contours[0].elevation;
  for (const ContourNode& c : t.contours) top = std::max(top, c.elevation);
  for (const Summit& s : t.summits) top = std::max(top, s.elevation);
  return top;
}

}  // namespace

void HypsometricColour(double t, float rgb[3]) {
  static const float stops[4][3] = {
      {0.33f, 0.52f, 0.27f}, {0.72f, 0.66f, 0.38f}, {0.52f, 0.38f, 0.26f}, {0.96f, 0.96f, 0.96f}};
  t = std::clamp(t, 0.0, 1.0) * 3.0;
  const int k = std::min(2, static_cast<int>(t));
  const float f = static_cast<float>(t - k);
  for (int c = 0; c < 3; ++c) rgb[c] = stops[k][c] + (stops[k + 1][c] - stops[k][c]) * f;
}

gltf::Document TerrainDocument(const Terrain& t, const Heightfield& hf, bool tint,
                               const std::string& extras_json) {
  gltf::Document doc;
  doc.asset_extras_json = extras_json;
  doc.scene_name = "terrain";
  double hmin = hf.h.empty() ? 0 : hf.h[0], hmax = hmin;
  for (double h : hf.h) {
    hmin = std::min(hmin, h);
    hmax = std::max(hmax, h);
  }
  // The surface: one vertex per cell centre.
  gltf::Primitive surface;
  geom::TriMesh& m = surface.mesh;
  const int w = hf.width, ht = hf.height;
  m.positions.reserve(static_cast<std::size_t>(w) * ht);
  for (int j = 0; j < ht; ++j) {
    for (int i = 0; i < w; ++i) {
      const Vec2 p = hf.Centre(i, j);
      m.positions.push_back(
          {static_cast<float>(p.x), static_cast<float>(hf.At(i, j)), static_cast<float>(-p.y)});
    }
  }
  // TEXCOORD_0 over the heightfield's extent (u east, v south: v = 0 on the north edge, as the
  // heightmap's row 0), so a texture drawn on the heightmap's grid lies on the surface.
  m.uvs.reserve(m.positions.size());
  for (int j = 0; j < ht; ++j) {
    for (int i = 0; i < w; ++i) {
      m.uvs.push_back({static_cast<float>((i + 0.5) / w), static_cast<float>((j + 0.5) / ht)});
    }
  }
  // Normals from central differences (one-sided at the border): n ∝ (−∂h/∂x, 1, −∂h/∂z), z = −y.
  m.normals.reserve(m.positions.size());
  for (int j = 0; j < ht; ++j) {
    for (int i = 0; i < w; ++i) {
      const int il = std::max(0, i - 1), ir = std::min(w - 1, i + 1);
      const int jn = std::max(0, j - 1), js = std::min(ht - 1, j + 1);
      const double dhdx = ir > il ? (hf.At(ir, j) - hf.At(il, j)) / ((ir - il) * hf.cell) : 0;
      const double dhdz = js > jn ? (hf.At(i, js) - hf.At(i, jn)) / ((js - jn) * hf.cell) : 0;
      const double len = std::sqrt(dhdx * dhdx + 1 + dhdz * dhdz);
      m.normals.push_back({static_cast<float>(-dhdx / len), static_cast<float>(1 / len),
                           static_cast<float>(-dhdz / len)});
    }
  }
  for (int j = 0; j + 1 < ht; ++j) {
    for (int i = 0; i + 1 < w; ++i) {
      const auto v = [w](int a, int b) { return static_cast<uint32_t>(b * w + a); };
      // Counter-clockwise seen from above (+y): (i,j) (i,j+1) (i+1,j), then (i+1,j) (i,j+1)
      // (i+1,j+1).
      m.indices.insert(m.indices.end(), {v(i, j), v(i, j + 1), v(i + 1, j)});
      m.indices.insert(m.indices.end(), {v(i + 1, j), v(i, j + 1), v(i + 1, j + 1)});
    }
  }
  if (tint) {
    geom::VertexAttribute& colour = m.AddAttribute("COLOR_0", 3);
    for (std::size_t k = 0; k < hf.h.size(); ++k) {
      float rgb[3];
      HypsometricColour(hmax > hmin ? (hf.h[k] - hmin) / (hmax - hmin) : 0, rgb);
      for (int c = 0; c < 3; ++c) colour.values[k * 3 + static_cast<std::size_t>(c)] = rgb[c];
    }
  }
  gltf::Material ground;
  ground.name = "terrain";
  ground.metallic_factor = 0;
  ground.roughness_factor = 0.95;
  if (!tint) ground.base_color_factor = {0.55, 0.5, 0.42, 1};
  doc.materials.push_back(ground);
  surface.material = 0;
  doc.meshes.push_back({"terrain", {std::move(surface)}});
  doc.nodes.push_back({});
  doc.nodes.back().name = "terrain";
  doc.nodes.back().mesh = 0;
  doc.scene_nodes.push_back(0);
  // The contours: LINES at their elevations.
  gltf::Primitive lines;
  lines.mode = gltf::Mode::kLines;
  for (const ContourNode& c : t.contours) {
    const uint32_t first = static_cast<uint32_t>(lines.mesh.positions.size());
    const uint32_t n = static_cast<uint32_t>(c.ring.size());
    for (const Vec2& v : c.ring)
      lines.mesh.positions.push_back(
          {static_cast<float>(v.x), static_cast<float>(c.elevation), static_cast<float>(-v.y)});
    for (uint32_t k = 0; k < n; ++k) {
      lines.mesh.indices.push_back(first + k);
      lines.mesh.indices.push_back(first + (k + 1) % n);
    }
  }
  if (!lines.mesh.positions.empty()) {
    gltf::Material ink;
    ink.name = "contours";
    ink.base_color_factor = {0.12, 0.1, 0.08, 1};
    ink.metallic_factor = 0;
    doc.materials.push_back(ink);
    lines.material = 1;
    doc.meshes.push_back({"contours", {std::move(lines)}});
    doc.nodes.push_back({});
    doc.nodes.back().name = "contours";
    doc.nodes.back().mesh = 1;
    doc.scene_nodes.push_back(1);
  }
  return doc;
}

Heightfield HeightmapGrid(const Heightfield& hf, int res) {
  int n = 1;
  while (n < res) n *= 2;
  Heightfield grid;
  grid.width = grid.height = n + 1;
  const double w = hf.width * hf.cell, h = hf.height * hf.cell;
  grid.cell = std::max(w, h) / n;  // the longer side spans N - 1 cells: half a cell over each end
  const double cx = hf.x0 + 0.5 * w, cy = hf.y1 - 0.5 * h;
  grid.x0 = cx - 0.5 * grid.width * grid.cell;
  grid.y1 = cy + 0.5 * grid.height * grid.cell;
  return grid;
}

Result<Heightmap> EncodeHeightmap(const Heightfield& hf) {
  if (hf.width <= 0 || hf.height <= 0) return Status::Error("heightmap", "empty heightfield");
  double hmin = hf.h[0], hmax = hmin;
  for (double h : hf.h) {
    hmin = std::min(hmin, h);
    hmax = std::max(hmax, h);
  }
  image::Gray16Image img;
  img.width = hf.width;
  img.height = hf.height;
  img.pixels.resize(hf.h.size());
  for (std::size_t k = 0; k < hf.h.size(); ++k) {
    const double t = hmax > hmin ? (hf.h[k] - hmin) / (hmax - hmin) : 0;
    img.pixels[k] = static_cast<uint16_t>(std::lround(std::clamp(t, 0.0, 1.0) * 65535.0));
  }
  nlohmann::ordered_json j;
  j["format"] = "niwa terrain heightmap";
  j["width"] = hf.width;
  j["height"] = hf.height;
  j["min_elevation"] = hmin;
  j["max_elevation"] = hmax;
  j["cell_size"] = hf.cell;
  j["origin"] = {{"x", hf.x0}, {"y", hf.y1}};
  j["origin_is"] = "north-west corner of pixel (0, 0); x east, y north, metres; row 0 is north";
  j["elevation"] = "min_elevation + sample / 65535 * (max_elevation - min_elevation)";
  if (hf.width == hf.height && hf.width > 2 && ((hf.width - 1) & (hf.width - 2)) == 0) {
    j["engine"] = "square 2^k + 1 samples: an engine terrain of " + std::to_string(hf.width - 1) +
                  " x " + std::to_string(hf.width - 1) + " quads of cell_size metres";
  }
  Heightmap out;
  out.sidecar_json = j.dump(2) + "\n";
  image::PngWriteOptions options;
  options.text.push_back({"niwa-heightmap", j.dump()});
  Result<std::vector<unsigned char>> png = image::EncodeGray16Png(img, options);
  if (!png.ok()) return png.status().Within("heightmap");
  out.png = std::move(png).value();
  return out;
}

std::string TerrainToGeoJson(const Terrain& t) {
  nlohmann::ordered_json features = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < t.contours.size(); ++c) {
    const ContourNode& node = t.contours[c];
    nlohmann::ordered_json ring = nlohmann::ordered_json::array();
    for (const Vec2& v : node.ring) ring.push_back({v.x, v.y});
    if (!node.ring.empty()) ring.push_back({node.ring[0].x, node.ring[0].y});
    nlohmann::ordered_json f;
    f["type"] = "Feature";
    f["properties"] = {
        {"id", c}, {"level", node.level}, {"elevation", node.elevation}, {"parent", node.parent}};
    f["geometry"] = {{"type", "Polygon"}, {"coordinates", {ring}}};
    features.push_back(f);
  }
  for (const Summit& s : t.summits) {
    nlohmann::ordered_json f;
    f["type"] = "Feature";
    f["properties"] = {{"summit_of", s.contour}, {"elevation", s.elevation}};
    f["geometry"] = {{"type", "Point"}, {"coordinates", {s.position.x, s.position.y}}};
    features.push_back(f);
  }
  nlohmann::ordered_json j;
  j["type"] = "FeatureCollection";
  j["features"] = features;
  return j.dump() + "\n";
}

std::string TerrainToSvg(const Terrain& t) {
  const RingBox b = RootBox(t);
  const double span = std::max({b.x1 - b.x0, b.y1 - b.y0, 1e-9});
  const double margin = span * 0.02;
  const double size = 800;  // px along the longer side
  const double scale = size / (span + 2 * margin);
  const double wpx = (b.x1 - b.x0 + 2 * margin) * scale, hpx = (b.y1 - b.y0 + 2 * margin) * scale;
  const auto X = [&](double x) {
    return FormatNumber(std::round((x - b.x0 + margin) * scale * 100) / 100);
  };
  const auto Y = [&](double y) {
    return FormatNumber(std::round((b.y1 + margin - y) * scale * 100) / 100);
  };
  const double h0 = t.contours.empty() ? 0 : t.contours[0].elevation;
  const double top = TopElevation(t);
  std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    FormatNumber(std::round(wpx)) + "\" height=\"" + FormatNumber(std::round(hpx)) +
                    "\" viewBox=\"0 0 " + FormatNumber(std::round(wpx)) + " " +
                    FormatNumber(std::round(hpx)) +
                    "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fbf8f1\"/>\n";
  for (std::size_t c = 0; c < t.contours.size(); ++c) {
    const ContourNode& node = t.contours[c];
    float rgb[3];
    HypsometricColour(top > h0 ? (node.elevation - h0) / (top - h0) : 0, rgb);
    char colour[16];
    std::snprintf(colour, sizeof colour, "#%02x%02x%02x", static_cast<int>(rgb[0] * 200),
                  static_cast<int>(rgb[1] * 200), static_cast<int>(rgb[2] * 200));
    std::string d;
    for (std::size_t k = 0; k < node.ring.size(); ++k)
      d += (k == 0 ? "M" : "L") + X(node.ring[k].x) + " " + Y(node.ring[k].y);
    svg += "<path data-level=\"" + std::to_string(node.level) + "\" data-elevation=\"" +
           FormatNumber(node.elevation) + "\" d=\"" + d + "Z\" fill=\"none\" stroke=\"" + colour +
           "\" stroke-width=\"1\"/>\n";
  }
  for (const Summit& s : t.summits) {
    svg += "<circle class=\"summit\" cx=\"" + X(s.position.x) + "\" cy=\"" + Y(s.position.y) +
           "\" r=\"3\" fill=\"#b22\"/>\n";
  }
  svg += "</svg>\n";
  return svg;
}

}  // namespace niwa::terrain

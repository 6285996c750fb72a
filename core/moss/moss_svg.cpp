// The moss study's photon picture: cells and stored photons painted back to front (moss_svg.h).
#include "moss/moss_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "base/markup_escape.h"

namespace niwa::moss {
namespace {

std::string PhotonFixed1(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.1f", v);
  return buffer;
}

// One thing to paint: a cell (index) or a photon (index), at its depth towards the viewer.
struct PhotonSvgItem {
  double depth;
  uint32_t index;
  bool photon;
};

}  // namespace

std::string PhotonSvg(const SoilCells& cells, const PhotonMap& map, const std::string& title) {
  // The view: towards the eye v = (0, 0.6, 1)/|.|, right (1, 0, 0), up (0, 1, −0.6)/|.|.
  const double len = std::sqrt(1.0 + 0.36);
  const glm::dvec3 toward(0, 0.6 / len, 1 / len), right(1, 0, 0), up(0, 1 / len, -0.6 / len);
  auto sx = [&](const glm::dvec3& p) { return glm::dot(p, right); };
  auto sy = [&](const glm::dvec3& p) { return -glm::dot(p, up); };
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const glm::vec3& p : cells.mesh.positions) {
    const glm::dvec3 q(p);
    x0 = std::min(x0, sx(q)), x1 = std::max(x1, sx(q));
    y0 = std::min(y0, sy(q)), y1 = std::max(y1, sy(q));
  }
  if (!(x1 > x0)) x0 = -1, x1 = 1;
  if (!(y1 > y0)) y0 = -1, y1 = 1;
  const double width = 800, margin = 10, caption = 28;
  const double scale = (width - 2 * margin) / (x1 - x0);
  const double height = std::ceil((y1 - y0) * scale + 2 * margin + caption);
  auto X = [&](const glm::dvec3& p) { return PhotonFixed1(margin + (sx(p) - x0) * scale); };
  auto Y = [&](const glm::dvec3& p) { return PhotonFixed1(margin + (sy(p) - y0) * scale); };

  std::vector<PhotonSvgItem> items;
  items.reserve(cells.size() + map.photons.size());
  for (uint32_t i = 0; i < cells.size(); ++i)
    if (glm::dot(cells.normal[i], toward) > 0)  // faces the viewer
      items.push_back({glm::dot(cells.centroid[i], toward), i, false});
  int64_t direct = 0, bounced = 0;
  for (uint32_t k = 0; k < map.photons.size(); ++k) {
    const Photon& ph = map.photons[k];
    if (glm::dot(ph.normal, toward) <= 0) continue;  // on a side turned away
    ++(ph.depth == 0 ? direct : bounced);
    // A photon lies on its face: just in front of the face's own cell in the order.
    items.push_back({glm::dot(ph.position, toward) + 1e-6, k, true});
  }
  std::stable_sort(items.begin(), items.end(), [](const PhotonSvgItem& a, const PhotonSvgItem& b) {
    return a.depth < b.depth;
  });
  const std::string escaped = XmlEscape(title);
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + PhotonFixed1(width) +
                  "\" height=\"" + PhotonFixed1(height) + "\" viewBox=\"0 0 " +
                  PhotonFixed1(width) + " " + PhotonFixed1(height) + "\">\n<title>" + escaped +
                  "</title>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  for (const PhotonSvgItem& item : items) {
    if (item.photon) {
      const Photon& ph = map.photons[item.index];
      s += "<circle cx=\"" + X(ph.position) + "\" cy=\"" + Y(ph.position) + "\" r=\"1.2\" fill=\"" +
           (ph.depth == 0 ? "#e8a317" : "#2a6fdb") + "\"/>\n";
      continue;
    }
    const std::size_t v = 3 * static_cast<std::size_t>(item.index);
    const glm::dvec3 a(cells.mesh.positions[v]), b(cells.mesh.positions[v + 1]),
        c(cells.mesh.positions[v + 2]);
    const int grey =
        120 + static_cast<int>(std::lround(
                  100.0 * std::clamp(glm::dot(cells.normal[item.index], toward), 0.0, 1.0)));
    char fill[8];
    std::snprintf(fill, sizeof fill, "#%02x%02x%02x", grey, grey, grey);
    s += "<path d=\"M" + X(a) + " " + Y(a) + "L" + X(b) + " " + Y(b) + "L" + X(c) + " " + Y(c) +
         "Z\" fill=\"" + fill + "\" stroke=\"" + fill + "\" stroke-width=\"0.3\"/>\n";
  }
  s += "<text x=\"10\" y=\"" + PhotonFixed1(height - 9) +
       "\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#222222\">" + escaped +
       ": <tspan fill=\"#e8a317\">&#9679; " + std::to_string(direct) +
       " first hits</tspan> <tspan fill=\"#2a6fdb\">&#9679; " + std::to_string(bounced) +
       " bounced</tspan></text>\n</svg>\n";
  return s;
}

}  // namespace niwa::moss

// The moss study's photon picture: cells and stored photons painted back to front (moss_svg.h).
#include "moss/moss_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "base/markup_escape.h"
#include "geom/mesh_metrics.h"

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

PhotonView PhotonViewOf(const SoilCells& cells) {
  glm::dvec3 lo(-1), hi(1);
  if (cells.mesh.triangle_count() > 0) {
    const geom::Bounds3 bounds = geom::MeshBounds(cells.mesh);
    lo = glm::dvec3(bounds.min), hi = glm::dvec3(bounds.max);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double r = std::max(1e-6, 0.5 * glm::length(hi - lo));
  // scripts/lib/figures_moss.js's camera for the thesis scene (r = 1.676 m): eye (0.45, 0.75,
  // 3.6), looking at (0, 0.45, −0.4), as offsets in units of r from the land's centre.
  PhotonView v;
  v.at = centre + r * glm::dvec3(0.0, -0.0895, -0.2387);
  v.eye = v.at + r * 2.408 * glm::normalize(glm::dvec3(0.45, 0.30, 4.0));
  return v;
}

std::string PhotonSvg(const SoilCells& cells, const PhotonMap& map, const std::string& title) {
  // A perspective view from PhotonViewOf's eye (figs 4.1/4.2's viewpoint on the thesis scene), a
  // focal of 1,000 px on an 800 × 600 frame (the figures' 700 on 560 × 420), narrowed only when
  // the land would not fit.
  const PhotonView view = PhotonViewOf(cells);
  const glm::dvec3 fwd = glm::normalize(view.at - view.eye);
  const glm::dvec3 right = glm::normalize(glm::cross(fwd, glm::dvec3(0, 1, 0)));
  const glm::dvec3 up = glm::cross(right, fwd);
  const double width = 800, frame_height = 600, margin = 10, caption = 28;
  auto depth_of = [&](const glm::dvec3& p) { return glm::dot(p - view.eye, fwd); };
  auto sx = [&](const glm::dvec3& p) { return glm::dot(p - view.eye, right) / depth_of(p); };
  auto sy = [&](const glm::dvec3& p) { return -glm::dot(p - view.eye, up) / depth_of(p); };
  double focal = 1000;
  for (const glm::vec3& p : cells.mesh.positions) {
    const glm::dvec3 q(p);
    if (depth_of(q) <= 1e-9) continue;
    const double ax = std::abs(sx(q)), ay = std::abs(sy(q));
    if (ax > 0) focal = std::min(focal, (width / 2 - margin) / ax);
    if (ay > 0) focal = std::min(focal, (frame_height / 2 - margin) / ay);
  }
  const double height = frame_height + caption;
  auto X = [&](const glm::dvec3& p) { return PhotonFixed1(width / 2 + focal * sx(p)); };
  auto Y = [&](const glm::dvec3& p) { return PhotonFixed1(frame_height / 2 + focal * sy(p)); };
  auto toward_eye = [&](const glm::dvec3& p) { return glm::normalize(view.eye - p); };

  std::vector<PhotonSvgItem> items;
  items.reserve(cells.size() + map.photons.size());
  for (uint32_t i = 0; i < cells.size(); ++i) {
    const glm::dvec3 c(cells.centroid[i]);
    if (depth_of(c) > 1e-9 && glm::dot(glm::dvec3(cells.normal[i]), toward_eye(c)) > 0)
      items.push_back({-depth_of(c), i, false});  // faces the viewer; far ones first
  }
  int64_t direct = 0, bounced = 0;
  for (uint32_t k = 0; k < map.photons.size(); ++k) {
    const Photon& ph = map.photons[k];
    const glm::dvec3 at(ph.position);
    if (depth_of(at) <= 1e-9 || glm::dot(glm::dvec3(ph.normal), toward_eye(at)) <= 0)
      continue;  // behind the eye, or on a side turned away
    ++(ph.depth == 0 ? direct : bounced);
    // A photon lies on its face: just in front of the face's own cell in the order.
    items.push_back({-depth_of(at) + 1e-6, k, true});
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
                  100.0 * std::clamp(glm::dot(glm::dvec3(cells.normal[item.index]),
                                              toward_eye(glm::dvec3(cells.centroid[item.index]))),
                                     0.0, 1.0)));
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

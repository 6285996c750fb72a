// Side view (x right, y up) of every living branch as a polyline whose stroke follows the pipe
// radius.
#include "tree/tree_svg.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "base/markup_escape.h"

namespace niwa {

std::string TreeToSvg(const Tree& tree, const SvgOptions& options) {
  float min_x = -1, max_x = 1, max_y = 1;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const glm::vec3& n : b.nodes) {
      min_x = std::min(min_x, n.x);
      max_x = std::max(max_x, n.x);
      max_y = std::max(max_y, n.y);
    }
  }
  float margin = 20.0f;
  float span = std::max(max_x - min_x, max_y);
  float scale = (static_cast<float>(std::min(options.width, options.height)) - 2 * margin) / span;
  float center_x = 0.5f * (min_x + max_x);
  auto sx = [&](float x) {
    return 0.5f * static_cast<float>(options.width) + (x - center_x) * scale;
  };
  auto sy = [&](float y) { return static_cast<float>(options.height) - margin - y * scale; };

  std::string out;
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" "
                "viewBox=\"0 0 %d %d\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
                options.width, options.height, options.width, options.height);
  out += buf;
  std::snprintf(buf, sizeof buf,
                "<line x1=\"0\" y1=\"%.2f\" x2=\"%d\" y2=\"%.2f\" stroke=\"#aaa\"/>\n", sy(0),
                options.width, sy(0));
  out += buf;
  out +=
      "<g fill=\"none\" stroke=\"#4a3520\" stroke-linecap=\"round\" stroke-linejoin=\"round\">\n";
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    float width = std::max(0.4f, 2.0f * BranchRadius(b) * scale);
    std::snprintf(buf, sizeof buf, "<polyline stroke-width=\"%.2f\" points=\"", width);
    out += buf;
    for (const glm::vec3& n : b.nodes) {
      std::snprintf(buf, sizeof buf, "%.2f,%.2f ", sx(n.x), sy(n.y));
      out += buf;
    }
    out += "\"/>\n";
  }
  out += "</g>\n";
  float leaf_len = static_cast<float>(tree.params.Get(ParamId::kLeafSize)) * scale;
  if (options.leaves) {
    out += "<g stroke=\"#3f8f3a\" stroke-width=\"1\" stroke-opacity=\"0.7\">\n";
    for (const Branch& b : tree.branches) {
      if (!b.alive) continue;
      for (const Leaf& leaf : b.leaves) {
        const glm::vec3& n = b.nodes[static_cast<std::size_t>(leaf.node)];
        glm::vec3 tip = n + leaf.direction * (leaf_len / scale);
        std::snprintf(buf, sizeof buf, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\"/>\n",
                      sx(n.x), sy(n.y), sx(tip.x), sy(tip.y));
        out += buf;
      }
    }
    out += "</g>\n";
  }
  if (options.flowers) {
    out += "<g fill=\"#f4a6c0\" stroke=\"#d0708f\" stroke-width=\"0.5\">\n";
    for (const Branch& b : tree.branches) {
      if (!b.alive) continue;
      for (int node : b.flowers) {
        const glm::vec3& n = b.nodes[static_cast<std::size_t>(node)];
        std::snprintf(buf, sizeof buf, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"2\"/>\n", sx(n.x),
                      sy(n.y));
        out += buf;
      }
    }
    out += "</g>\n";
  }
  if (!options.caption.empty()) {
    const std::string safe = XmlEscape(options.caption);  // base/markup_escape.h
    std::snprintf(buf, sizeof buf,
                  "<text x=\"10\" y=\"%d\" font-family=\"sans-serif\" font-size=\"14\">",
                  options.height - 4);
    out += buf + safe + "</text>\n";
  }
  out += "</svg>\n";
  return out;
}

}  // namespace niwa

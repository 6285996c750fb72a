// SVG line drawings of a grown ivy (front and side views), as in the paper's Fig. 3.
#include "ivy/ivy_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <limits>

namespace niwa::ivy {
namespace {

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

std::string Escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string IvySvg(const IvyModel& model, const IvyParams& params, const geom::TriMesh* support,
                   const IvySvgOptions& o) {
  const int k = o.up_to_step;
  const auto born = [k](int step) { return k < 0 || step <= k; };
  // The frame: the support's and the ivy's bounds together.
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  const auto extend = [&](const glm::dvec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  };
  if (support != nullptr)
    for (const glm::vec3& p : support->positions) extend(glm::dvec3(p));
  for (const Bud& b : model.buds) extend(b.pos);
  if (!(lo.x <= hi.x)) lo = hi = glm::dvec3(0);
  const double size = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 1e-9});
  const double margin = 16, scale = (o.panel - 2 * margin) / size;
  const int w = 2 * o.panel, h = o.panel + (o.caption.empty() ? 0 : 24);
  // view 0: front (x right, y up); view 1: side (z right, y up; looking along -x).
  const auto X = [&](int view, const glm::dvec3& p) {
    const double u = view == 0 ? p.x - lo.x : hi.z - p.z;
    return view * o.panel + margin + u * scale;
  };
  const auto Y = [&](const glm::dvec3& p) { return o.panel - margin - (p.y - lo.y) * scale; };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(w) +
                  "\" height=\"" + std::to_string(h) + "\" viewBox=\"0 0 " + std::to_string(w) +
                  " " + std::to_string(h) +
                  "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n";
  for (int view = 0; view < 2; ++view) {
    s += "<g id=\"" + std::string(view == 0 ? "front" : "side") + "\">\n";
    if (support != nullptr) {
      s += "<g fill=\"#e4e4e4\" stroke=\"#b8b8b8\" stroke-width=\"0.5\" fill-opacity=\"0.35\">\n";
      if (support->triangle_count() <= kSvgMaxSupportTriangles) {
        for (std::size_t t = 0; t < support->triangle_count(); ++t) {
          s += "<path d=\"";
          for (int c = 0; c < 3; ++c) {
            const glm::dvec3 p(
                support->positions[support->indices[3 * t + static_cast<std::size_t>(c)]]);
            s += (c == 0 ? "M" : "L") + Num(X(view, p)) + " " + Num(Y(p));
          }
          s += "Z\"/>\n";
        }
      } else {
        const glm::dvec3 a = lo, b = hi;
        const double x0 = std::min(X(view, a), X(view, b)), x1 = std::max(X(view, a), X(view, b));
        s += "<rect x=\"" + Num(x0) + "\" y=\"" + Num(Y(b)) + "\" width=\"" + Num(x1 - x0) +
             "\" height=\"" + Num(Y(a) - Y(b)) + "\"/>\n";
      }
      s += "</g>\n";
    }
    s += "<g stroke=\"#5a3b1e\" stroke-linecap=\"round\" fill=\"none\">\n";
    for (const Internode& in : model.internodes) {
      if (!born(in.step)) continue;
      const Bud& a = model.buds[static_cast<std::size_t>(in.from_bud)];
      const Bud& b = model.buds[static_cast<std::size_t>(in.to_bud)];
      const double width = b.order == 0 ? 2.0 : b.order == 1 ? 1.4 : 1.0;
      s += "<line x1=\"" + Num(X(view, a.pos)) + "\" y1=\"" + Num(Y(a.pos)) + "\" x2=\"" +
           Num(X(view, b.pos)) + "\" y2=\"" + Num(Y(b.pos)) + "\" stroke-width=\"" + Num(width) +
           "\"/>\n";
    }
    s += "</g>\n";
    if (o.leaves) {
      // A leaf per bud but the seed, a little off the stem on the side opposite the sucker.
      const double leaf = params.Get(IvyParam::kLeafSize);
      const double r = std::max(1.5, 0.35 * leaf * scale);
      s += "<g fill=\"#3f8f2f\" fill-opacity=\"0.75\">\n";
      for (const Bud& b : model.buds) {
        if (b.parent < 0 || !born(b.born_step)) continue;
        const glm::dvec3 p = b.pos + 0.5 * leaf * b.outward;
        s += "<circle cx=\"" + Num(X(view, p)) + "\" cy=\"" + Num(Y(p)) + "\" r=\"" + Num(r) +
             "\"/>\n";
      }
      s += "</g>\n";
    }
    s += "<text x=\"" + std::to_string(view * o.panel + 8) +
         "\" y=\"14\" font-family=\"sans-serif\" " + "font-size=\"12\" fill=\"#333\">" +
         (view == 0 ? "front (x-y)" : "side (z-y)") + "</text>\n";
    s += "</g>\n";
  }
  if (!o.caption.empty()) {
    s += "<text x=\"8\" y=\"" + std::to_string(h - 8) +
         "\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#111\">" + Escape(o.caption) +
         "</text>\n";
  }
  s += "</svg>\n";
  return s;
}

}  // namespace niwa::ivy

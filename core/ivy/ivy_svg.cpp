// SVG line drawings of a grown ivy (front and side views), as in the paper's Fig. 3.
#include "ivy/ivy_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <limits>
#include <vector>

#include "base/markup_escape.h"

namespace niwa::ivy {
namespace {

std::string Fixed2(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.2f", v);
  return buffer;
}

// A large support as its silhouette: the triangles rasterised (cell centres inside a projected
// triangle) into kCell-pixel cells of one panel, each row's covered runs one <rect>. Bounded output
// whatever the triangle count.
template <typename Project>
std::string Silhouette(const geom::TriMesh& mesh, Project project, int x0, int panel) {
  constexpr int kCell = 2;
  const int n = panel / kCell;
  std::vector<unsigned char> covered(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    glm::dvec2 q[3];
    for (int c = 0; c < 3; ++c) {
      q[c] = project(glm::dvec3(mesh.positions[mesh.indices[3 * t + static_cast<std::size_t>(c)]]));
      q[c].x -= x0;
    }
    const double area =
        (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
    if (area == 0) continue;
    const auto cell = [&](double v) { return std::clamp(static_cast<int>(v / kCell), 0, n - 1); };
    const int i0 = cell(std::min({q[0].x, q[1].x, q[2].x})),
              i1 = cell(std::max({q[0].x, q[1].x, q[2].x}));
    const int j0 = cell(std::min({q[0].y, q[1].y, q[2].y})),
              j1 = cell(std::max({q[0].y, q[1].y, q[2].y}));
    for (int j = j0; j <= j1; ++j) {
      for (int i = i0; i <= i1; ++i) {
        const glm::dvec2 c((i + 0.5) * kCell, (j + 0.5) * kCell);
        bool inside = true;
        for (int e = 0; e < 3 && inside; ++e) {
          const glm::dvec2 a = q[e], b = q[(e + 1) % 3];
          const double side = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
          inside = area > 0 ? side >= 0 : side <= 0;
        }
        if (inside)
          covered[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) +
                  static_cast<std::size_t>(i)] = 1;
      }
    }
  }
  // Cells no triangle centre fell in but a vertex did (thin branches thinner than a cell).
  for (const glm::vec3& v : mesh.positions) {
    glm::dvec2 q = project(glm::dvec3(v));
    const int i = static_cast<int>((q.x - x0) / kCell), j = static_cast<int>(q.y / kCell);
    if (i >= 0 && i < n && j >= 0 && j < n)
      covered[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) +
              static_cast<std::size_t>(i)] = 1;
  }
  std::string out;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n;) {
      if (!covered[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) +
                   static_cast<std::size_t>(i)]) {
        ++i;
        continue;
      }
      int k = i;
      while (k < n && covered[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) +
                              static_cast<std::size_t>(k)])
        ++k;
      out += "<rect x=\"" + std::to_string(x0 + i * kCell) + "\" y=\"" + std::to_string(j * kCell) +
             "\" width=\"" + std::to_string((k - i) * kCell) + "\" height=\"" +
             std::to_string(kCell) + "\"/>\n";
      i = k;
    }
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
            s += (c == 0 ? "M" : "L") + Fixed2(X(view, p)) + " " + Fixed2(Y(p));
          }
          s += "Z\"/>\n";
        }
      } else {
        s += Silhouette(
            *support, [&](const glm::dvec3& p) { return glm::dvec2(X(view, p), Y(p)); },
            view * o.panel, o.panel);
      }
      s += "</g>\n";
    }
    s += "<g stroke=\"#5a3b1e\" stroke-linecap=\"round\" fill=\"none\">\n";
    for (const Internode& in : model.internodes) {
      if (!born(in.step)) continue;
      const Bud& a = model.buds[static_cast<std::size_t>(in.from_bud)];
      const Bud& b = model.buds[static_cast<std::size_t>(in.to_bud)];
      const double width = b.order == 0 ? 2.0 : b.order == 1 ? 1.4 : 1.0;
      s += "<line x1=\"" + Fixed2(X(view, a.pos)) + "\" y1=\"" + Fixed2(Y(a.pos)) + "\" x2=\"" +
           Fixed2(X(view, b.pos)) + "\" y2=\"" + Fixed2(Y(b.pos)) + "\" stroke-width=\"" + Fixed2(width) +
           "\"/>\n";
    }
    s += "</g>\n";
    // §2.2's second trigger made visible (issue 31 item 6): a red ring where an apex ended by p3
    // (an ending bud with no child), an orange dot at the base of a lateral born after its parent
    // axis's apex died (the dormant bud that apex woke). Drawn only when there are any.
    std::string marks;
    for (const Bud& b : model.buds) {
      if (b.kind != BudKind::kEnding || b.child[0] >= 0 || b.child[1] >= 0 || b.died_step < 0 ||
          !born(b.died_step))
        continue;
      marks += "<circle cx=\"" + Fixed2(X(view, b.pos)) + "\" cy=\"" + Fixed2(Y(b.pos)) +
               "\" r=\"5\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"1.5\"/>\n";
    }
    for (const Axis& a : model.axes) {
      if (a.order == 0 || !born(a.born_step)) continue;
      const Axis& parent = model.axes[static_cast<std::size_t>(a.parent_axis)];
      if (parent.death_step < 0 || a.born_step <= parent.death_step) continue;
      const Bud& base = model.buds[static_cast<std::size_t>(a.base_bud)];
      marks += "<circle cx=\"" + Fixed2(X(view, base.pos)) + "\" cy=\"" + Fixed2(Y(base.pos)) +
               "\" r=\"4\" fill=\"#ff9f1c\" stroke=\"#8a4b00\" stroke-width=\"0.8\"/>\n";
    }
    if (!marks.empty()) s += "<g id=\"p3-marks\">\n" + marks + "</g>\n";
    if (o.leaves) {
      // A leaf per bud but the seed, a little off the stem on the side opposite the sucker.
      const double leaf = params.Get(IvyParam::kLeafSize);
      const double r = std::max(1.5, 0.35 * leaf * scale);
      s += "<g fill=\"#3f8f2f\" fill-opacity=\"0.75\">\n";
      for (const Bud& b : model.buds) {
        if (b.parent < 0 || !born(b.born_step)) continue;
        const glm::dvec3 p = b.pos + 0.5 * leaf * b.outward;
        s += "<circle cx=\"" + Fixed2(X(view, p)) + "\" cy=\"" + Fixed2(Y(p)) + "\" r=\"" + Fixed2(r) +
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
         "\" font-family=\"sans-serif\" font-size=\"13\" fill=\"#111\">" + XmlEscape(o.caption) +
         "</text>\n";
  }
  s += "</svg>\n";
  return s;
}

}  // namespace niwa::ivy

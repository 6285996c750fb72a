// L-string printing and turtle re-interpretation (Table 1).
#include "ivy/lstring.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <tuple>

namespace niwa::ivy {
namespace {

std::string Exact(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string BudText(const Bud& b) {
  return std::string(1, BudSymbol(b.kind)) + "(" + Exact(b.pos.x) + "," + Exact(b.pos.y) + "," +
         Exact(b.pos.z) + ";" + Exact(b.N) + ")";
}

}  // namespace

std::string PrintLString(const IvyModel& model) {
  std::string out;
  // Items: a bud to visit (>= 0) or a literal token (encoded as -1 - index into tokens).
  std::vector<std::string> tokens;
  for (int root : model.roots) {
    std::vector<int> stack{root};
    while (!stack.empty()) {
      int item = stack.back();
      stack.pop_back();
      if (item < 0) {
        out += tokens[static_cast<std::size_t>(-1 - item)];
        continue;
      }
      const Bud& b = model.buds[static_cast<std::size_t>(item)];
      out += BudText(b);
      auto token = [&](const std::string& t) {
        tokens.push_back(t);
        return -static_cast<int>(tokens.size());
      };
      // Pushed in reverse: [ R I <lateral> ] then I <continuation>.
      if (b.child[0] >= 0) {
        stack.push_back(b.child[0]);
        stack.push_back(token("I"));
      }
      if (b.child[1] >= 0) {
        const Bud& lat = model.buds[static_cast<std::size_t>(b.child[1])];
        const auto& rot = model.axes[static_cast<std::size_t>(lat.axis)].rotation;
        stack.push_back(token("]"));
        stack.push_back(b.child[1]);
        stack.push_back(token("I"));
        stack.push_back(token("R(" + Exact(rot[0]) + "," + Exact(rot[1]) + "," + Exact(rot[2]) + ")"));
        stack.push_back(token("["));
      }
    }
    out += "\n";
  }
  return out;
}

Result<std::vector<std::pair<glm::dvec3, glm::dvec3>>> InterpretLString(const std::string& text) {
  std::vector<std::pair<glm::dvec3, glm::dvec3>> out;
  struct Turtle {
    glm::dvec3 pos{0.0};
    bool has_pos = false;
    bool pending_i = false;
  };
  Turtle t;
  std::vector<Turtle> stack;
  std::size_t i = 0;
  auto error = [&](const std::string& what) {
    return Status::Error("lsys", what + " at character " + std::to_string(i));
  };
  while (i < text.size()) {
    const char c = text[i];
    if (c == 'A' || c == 'D' || c == 'Z') {
      if (i + 1 >= text.size() || text[i + 1] != '(') return error("bud without '('");
      std::size_t close = text.find(')', i);
      if (close == std::string::npos) return error("bud without ')'");
      std::string body = text.substr(i + 2, close - i - 2);
      glm::dvec3 p;
      const char* s = body.c_str();
      char* end = nullptr;
      for (int k = 0; k < 3; ++k) {
        p[k] = std::strtod(s, &end);
        if (end == s) return error("bad coordinate");
        s = end + 1;
      }
      if (t.pending_i) {
        if (!t.has_pos) return error("I without a start");
        out.push_back({t.pos, p});
        t.pending_i = false;
      }
      t.pos = p;
      t.has_pos = true;
      i = close + 1;
    } else if (c == 'I') {
      t.pending_i = true;
      ++i;
    } else if (c == '[') {
      stack.push_back(t);
      ++i;
    } else if (c == ']') {
      if (stack.empty()) return error("']' without '['");
      t = stack.back();
      stack.pop_back();
      ++i;
    } else if (c == 'R') {
      std::size_t close = text.find(')', i);
      if (close == std::string::npos) return error("R without ')'");
      i = close + 1;
    } else if (c == '\n') {
      if (!stack.empty()) return error("unclosed '['");
      t = Turtle();
      ++i;
    } else {
      return error(std::string("unknown symbol '") + c + "'");
    }
  }
  if (!stack.empty()) return error("unclosed '['");
  return out;
}

LStringCounts CountSymbols(const std::string& text) {
  LStringCounts c;
  int depth = 0;  // parentheses: their contents are parameters
  for (char ch : text) {
    if (ch == '(') ++depth;
    if (ch == ')') --depth;
    if (depth > 0) continue;
    c.A += ch == 'A';
    c.D += ch == 'D';
    c.Z += ch == 'Z';
    c.I += ch == 'I';
    c.open += ch == '[';
    c.close += ch == ']';
    c.R += ch == 'R';
  }
  return c;
}

bool LStringMatchesModel(const IvyModel& model) {
  auto drawn = InterpretLString(PrintLString(model));
  if (!drawn.ok()) return false;
  using Key = std::tuple<double, double, double, double, double, double>;
  std::vector<Key> a, b;
  for (const auto& [p, q] : *drawn) a.emplace_back(p.x, p.y, p.z, q.x, q.y, q.z);
  for (const Internode& in : model.internodes) {
    const glm::dvec3& p = model.buds[static_cast<std::size_t>(in.from_bud)].pos;
    const glm::dvec3& q = model.buds[static_cast<std::size_t>(in.to_bud)].pos;
    b.emplace_back(p.x, p.y, p.z, q.x, q.y, q.z);
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  return a == b;
}

}  // namespace niwa::ivy

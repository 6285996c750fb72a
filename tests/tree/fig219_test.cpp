// Fig. 2.19 (thesis 2.5.4): the three species at 15 years show the forms the thesis describes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "tree/growth.h"
#include "tree/presets.h"
#include "trunk_line.h"

namespace niwa {
namespace {

// The preset grown 15 years from `seed`, or from its own seed, with `changes` to its parameters.
Tree Grow15(const std::string& name, std::uint64_t seed,
            std::initializer_list<std::pair<ParamId, double>> changes = {}) {
  const Preset* preset = FindPreset(name);
  EXPECT_NE(preset, nullptr) << name;
  GrowRequest r;
  r.preset = name;
  r.params = preset->params;
  for (const auto& [id, value] : changes) EXPECT_EQ(r.params.Set(id, value).Line(), "");
  r.seed = seed;
  r.years = 15;
  return GrowTree(r);
}
Tree Grow15(const std::string& name) { return Grow15(name, FindPreset(name)->seed); }

float Length(const Branch& b) {
  float sum = 0.0f;
  for (std::size_t i = 1; i < b.nodes.size(); ++i) sum += glm::length(b.nodes[i] - b.nodes[i - 1]);
  return sum;
}

// Lengths of the tree's living shoots (not the seedling), long and dwarf apart.
struct ShootLengths {
  std::vector<float> long_shoots, dwarf;
};
ShootLengths LongAndDwarf(const Tree& tree) {
  ShootLengths out;
  for (const Branch& b : tree.branches) {
    if (!b.alive || b.parent < 0) continue;
    (b.dwarf ? out.dwarf : out.long_shoots).push_back(Length(b));
  }
  return out;
}

float Median(std::vector<float> v) {
  if (v.empty()) return 0.0f;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

struct Shape {
  float height = 0, width = 0, lean_deg = 0;
};

glm::vec3 Centroid(const Tree& tree) {
  glm::vec3 sum(0.0f);
  double count = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const glm::vec3& n : b.nodes) {
      sum += n;
      count += 1;
    }
  }
  return sum / static_cast<float>(count);
}

Shape ShapeOf(const Tree& tree) {
  glm::vec3 lo(1e9f), hi(-1e9f), sum(0.0f);
  double count = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    for (const glm::vec3& n : b.nodes) {
      lo = glm::min(lo, n);
      hi = glm::max(hi, n);
      sum += n;
      count += 1;
    }
  }
  glm::vec3 c = sum / static_cast<float>(count);
  Shape s;
  s.height = hi.y;
  s.width = std::max(hi.x - lo.x, hi.z - lo.z);
  s.lean_deg = std::atan2(std::hypot(c.x, c.z), c.y) * 180.0f / 3.14159265f;
  return s;
}

// (a) "長枝と短枝の長さが非常に異なる。長枝は数10cmにもなるが、短枝は1cmにも満たないことが多い";
// "頂生枝が長枝となって勢いよく伸びており、側生枝はごく短い短枝になることが多い"; dwarfing occurs
// "主に側生枝に" (2.3.3 e).
TEST(Fig219, SakuraHasLongTerminalShootsAndVeryShortDwarfShoots) {
  Tree tree = Grow15("sakura-thesis");
  std::vector<float> dwarf, terminal_long;
  int terminals = 0, terminal_dwarfs = 0, laterals = 0, lateral_dwarfs = 0, dwarfs = 0;
  float longest = 0.0f;
  for (const Branch& b : tree.branches) {
    if (!b.alive || b.parent < 0) continue;
    float length = Length(b);
    if (b.dwarf) {
      dwarf.push_back(length);
      ++dwarfs;
    }
    // A long shoot's terminal bud grows a long shoot; a dwarf shoot's grows a dwarf shoot again.
    const bool parent_long = !tree.branches[static_cast<std::size_t>(b.parent)].dwarf;
    if (b.kind == ShootKind::kTerminal && parent_long) {
      ++terminals;
      if (b.dwarf)
        ++terminal_dwarfs;
      else
        terminal_long.push_back(length);
      longest = std::max(longest, length);
    }
    if (b.kind == ShootKind::kLateral) {
      ++laterals;
      if (b.dwarf) ++lateral_dwarfs;
    }
  }
  ASSERT_GT(dwarfs, 0);
  // Dwarf shoots barely grow: "短枝は1cmにも満たないことが多い" (2.5.4), mostly under 1 cm, none
  // over 2 cm.
  EXPECT_LE(*std::max_element(dwarf.begin(), dwarf.end()), 2.0f);
  EXPECT_LT(Median(dwarf), 1.0f);
  const auto under_1cm =
      std::count_if(dwarf.begin(), dwarf.end(), [](float l) { return l < 1.0f; });
  EXPECT_GE(3 * under_1cm, 2 * static_cast<long>(dwarf.size()));  // at least two thirds
  // Long terminal shoots several tens of cm at most, and typically many times a dwarf shoot.
  EXPECT_GE(longest, 30.0f);
  EXPECT_GE(Median(terminal_long), 5.0f * Median(dwarf));
  // Terminal shoots of long shoots are long (apical dominance); dwarfing falls mainly on lateral
  // shoots.
  EXPECT_LE(terminal_dwarfs, terminals / 10);
  EXPECT_GE(3 * lateral_dwarfs, 2 * dwarfs);
  EXPECT_GE(4 * lateral_dwarfs, laterals);  // at least a quarter of the lateral shoots are dwarf
}

// (b) "初めは幹を伸ばすために側芽の発芽を抑制しているので分枝せずに幹が長く伸びているが、その後枝が
// 細かく分枝しており、全体にホウキを逆さに立てたような樹形".
TEST(Fig219, KeyakiIsABareTrunkUnderAFinelyBranchedBroom) {
  Tree tree = Grow15("keyaki-thesis");
  Shape s = ShapeOf(tree);
  int shoots = 0, leaves = 0, low_leaves = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    ++shoots;
    for (const Leaf& leaf : b.leaves) {
      ++leaves;
      if (b.nodes[static_cast<std::size_t>(leaf.node)].y < s.height / 3.0f) ++low_leaves;
    }
  }
  EXPECT_GE(shoots, 1000);              // fine branching, not a few long stems
  EXPECT_GE(s.width, 0.4f * s.height);  // a broom head, not a whip
  EXPECT_LE(low_leaves * 20, leaves);   // the lower third is bare trunk (under 5 % of leaves)
}

// (b) again: the trunk "grows long" at first. Its line of terminal shoots stays long (H^0 >= H_s)
// for at least its first eight years in seeds 1-3. Under table 2.2's keyaki values a line stays
// long only where L >= 0.80 (eqs. 2.1-2.2 in steady state), so this fails if L cannot reach that
// (it did with light_scale 0.6: the line turned dwarf in year 3).
TEST(Fig219, KeyakiTrunkLineStaysLongForEightYears) {
  for (std::uint32_t seed : {1u, 2u, 3u}) {
    Tree tree = Grow15("keyaki-thesis", seed);
    int id = 0, long_years = 0;
    while (id >= 0 && !tree.branches[static_cast<std::size_t>(id)].dwarf) {
      ++long_years;
      id = LiveTerminalChild(tree, id);
    }
    EXPECT_GE(long_years, 8) << "seed " << seed;
  }
}

// 2.5.4 lists "長枝の長さは短枝の数倍程度" for keyaki. Under table 2.2 every keyaki lateral is
// dwarf (α_l·H ≤ 0.34 × 0.69 < H_s), so its long shoots are its trunk line, and with fig. 2.5
// linear in H⁰ (length_step 0) they are only 1.3 times its dwarf shoots. length_step 0.5 moves the
// two apart to 2.4 times, but the leader then outgrows the crown for all 15 years and the broom
// becomes a narrow spire; the preset keeps 0 (docs/FIGURES.md, fig. 2.19). If a change makes both
// hold, this fails and the preset should take the step.
TEST(Fig219, KeyakiLengthStepTradesTheBroomForSeveralTimesLongerLongShoots) {
  Tree tree =
      Grow15("keyaki-thesis", FindPreset("keyaki-thesis")->seed, {{ParamId::kLengthStep, 0.5}});
  const auto [long_shoots, dwarf] = LongAndDwarf(tree);
  ASSERT_FALSE(long_shoots.empty());
  ASSERT_FALSE(dwarf.empty());
  EXPECT_GE(Median(long_shoots), 2.2f * Median(dwarf));
  Shape s = ShapeOf(tree);
  EXPECT_LT(s.width, 0.5f * s.height);
}

// (c) "長枝、短枝の差があまりなく、全体に丸い樹形".
TEST(Fig219, TsutsujiIsRoundWithLittleLongDwarfDifference) {
  Tree tree = Grow15("tsutsuji-thesis");
  Shape s = ShapeOf(tree);
  const auto [long_shoots, dwarf] = LongAndDwarf(tree);
  EXPECT_GE(s.width, 0.8f * s.height);
  ASSERT_FALSE(dwarf.empty());
  ASSERT_FALSE(long_shoots.empty());
  EXPECT_LE(Median(long_shoots), 2.5f * Median(dwarf));
}

// The thesis's trees stand upright: with the default sky light (no sun) none leans to one side.
// Each seed's tree leans a few degrees its own way; a sun would lean them all the same way, so the
// lean of the centroid averaged over three seeds is checked (keyaki's sympodial zig-zag, which
// starts the same way for every seed, leaves it 2.3 deg).
TEST(Fig219, ThesisSpeciesDoNotLean) {
  for (const char* name : {"sakura-thesis", "keyaki-thesis", "tsutsuji-thesis"}) {
    glm::vec3 mean(0.0f);
    for (std::uint64_t seed = 1; seed <= 3; ++seed) mean += Centroid(Grow15(name, seed)) / 3.0f;
    float lean_deg = std::atan2(std::hypot(mean.x, mean.z), mean.y) * 180.0f / 3.14159265f;
    EXPECT_LE(lean_deg, 5.0f) << name;  // with a sun of weight 0.1 they leaned 11-12 deg
  }
}

}  // namespace
}  // namespace niwa

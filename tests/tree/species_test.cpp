// Tests that each species preset beyond the thesis grows the branching rule that defines it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <map>
#include <string>
#include <vector>

#include "tree/growth.h"
#include "tree/presets.h"

namespace niwa {
namespace {

Tree GrowPreset(const std::string& name, int years) {
  const Preset* preset = FindPreset(name);
  EXPECT_NE(preset, nullptr) << name;
  GrowRequest r;
  r.preset = name;
  if (preset) {
    r.params = preset->params;
    r.seed = preset->seed;
  }
  r.years = years;
  return GrowTree(r);
}

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

// Unit direction of the internode that ends at `node`.
glm::vec3 NodeDirection(const Branch& b, int node) {
  auto i = static_cast<std::size_t>(node);
  return glm::normalize(b.nodes[i] - b.nodes[i - 1]);
}

// Unit side on which a bud sits: its direction with the shoot's own direction at the node removed.
glm::vec3 BudSide(const Branch& b, const Bud& bud) {
  glm::vec3 d = NodeDirection(b, bud.node);
  glm::vec3 side = bud.direction - d * glm::dot(bud.direction, d);
  return glm::normalize(side);
}

TEST(Species, NewPresetsLoadAndSayWhereTheirValuesComeFrom) {
  for (const char* name : {"ginkgo", "maple", "pine", "weeping"}) {
    const Preset* preset = FindPreset(name);
    ASSERT_NE(preset, nullptr) << name;
    EXPECT_GT(preset->source.size(), 40u) << name;
    EXPECT_GE(preset->years, 10) << name;
    EXPECT_LE(preset->years, 20) << name;
  }
}

// Every new preset grows at its default age to a tree of sensible size, fast enough to share.
TEST(Species, NewPresetsGrowToAReasonableSize) {
  for (const char* name : {"ginkgo", "maple", "pine", "weeping"}) {
    const Preset* preset = FindPreset(name);
    ASSERT_NE(preset, nullptr) << name;
    Tree t = GrowPreset(name, preset->years);
    TreeStats s = ComputeStats(t);
    EXPECT_FALSE(t.truncated) << name;
    EXPECT_LE(s.internodes, 40000) << name;
    EXPECT_GE(s.height, 100.0) << name;
    EXPECT_LE(s.height, 800.0) << name;
  }
}

// Maple: decussate phyllotaxis. Each node of a shoot carries two lateral buds on opposite sides,
// each pair turned a quarter turn from the pair below, and the tip carries an opposite pair of
// terminally-lateral buds.
TEST(Species, MapleLateralBudsComeInOppositeDecussatePairs) {
  Tree t = GrowPreset("maple", 6);
  int pairs = 0, shoots = 0;
  for (const Branch& b : t.branches) {
    if (!b.alive || b.buds.empty()) continue;
    ++shoots;
    int tip = static_cast<int>(b.nodes.size()) - 1;
    std::map<int, std::vector<glm::vec3>> lateral_sides, tl_sides;
    for (const Bud& bud : b.buds) {
      if (bud.kind == ShootKind::kLateral) lateral_sides[bud.node].push_back(BudSide(b, bud));
      if (bud.kind == ShootKind::kTerminallyLateral) tl_sides[bud.node].push_back(BudSide(b, bud));
    }
    for (int node = 1; node < tip; ++node) {
      const std::vector<glm::vec3>& sides = lateral_sides[node];
      ASSERT_EQ(sides.size(), 2u) << "branch " << b.id << " node " << node;
      EXPECT_LT(glm::dot(sides[0], sides[1]), -0.99f) << "branch " << b.id << " node " << node;
      ++pairs;
      if (node > 1) {  // decussate: a quarter turn from the pair below
        float turn = glm::dot(sides[0], lateral_sides[node - 1][0]);
        EXPECT_LT(std::fabs(turn), 0.3f) << "branch " << b.id << " node " << node;
      }
    }
    ASSERT_EQ(tl_sides.size(), 1u) << "branch " << b.id;
    EXPECT_EQ(tl_sides.begin()->first, tip);
    ASSERT_EQ(tl_sides.begin()->second.size(), 2u);
    EXPECT_LT(glm::dot(tl_sides[tip][0], tl_sides[tip][1]), -0.99f);
  }
  EXPECT_GT(shoots, 20);
  EXPECT_GT(pairs, 100);
}

// Pine: the tip of every long shoot carries a whorl of B_tl terminally-lateral buds spaced evenly
// around it, lateral buds never make shoots, and the leader stays upright and on top.
TEST(Species, PineBranchesOnlyInWhorlsAtShootTipsAroundAnUprightLeader) {
  const Preset* pine = FindPreset("pine");
  ASSERT_NE(pine, nullptr);
  int whorl = pine->params.GetInt(ParamId::kBTl);
  ASSERT_GE(whorl, 4);
  Tree t = GrowPreset("pine", pine->years);
  int long_shoots = 0, whorl_shoots = 0;
  for (const Branch& b : t.branches) {
    EXPECT_NE(b.kind, ShootKind::kLateral) << "branch " << b.id;
    if (b.kind == ShootKind::kTerminallyLateral) ++whorl_shoots;
    if (!b.alive || b.dwarf) continue;
    ++long_shoots;
    int tip = static_cast<int>(b.nodes.size()) - 1;
    glm::vec3 sum(0.0f);
    int count = 0;
    for (const Bud& bud : b.buds) {
      EXPECT_NE(bud.kind, ShootKind::kLateral) << "branch " << b.id;
      if (bud.kind != ShootKind::kTerminallyLateral) continue;
      EXPECT_EQ(bud.node, tip) << "branch " << b.id;
      sum += BudSide(b, bud);
      ++count;
    }
    EXPECT_EQ(count, whorl) << "branch " << b.id;
    EXPECT_LT(glm::length(sum), 0.05f) << "branch " << b.id << ": whorl not spaced evenly";
  }
  EXPECT_GT(long_shoots, 50);
  EXPECT_GT(whorl_shoots, 100);

  // The leader: the chain of terminal shoots from the seedling.
  const Branch* leader = &t.branches[0];
  for (;;) {
    const Branch* next = nullptr;
    for (int c : leader->children) {
      const Branch& child = t.branches[static_cast<std::size_t>(c)];
      if (child.alive && child.kind == ShootKind::kTerminal) next = &child;
    }
    if (!next) break;
    leader = next;
  }
  EXPECT_EQ(leader->year, t.years);
  glm::vec3 top = leader->nodes.back();
  EXPECT_GT(glm::dot(glm::normalize(top - leader->nodes.front()), kUp), 0.95f);
  EXPECT_NEAR(static_cast<double>(top.y), ComputeStats(t).height, 5.0);
}

// Ginkgo: most shoots are spur (dwarf) shoots, much shorter than the long shoots, and spurs keep
// growing as spurs from year to year.
TEST(Species, GinkgoGrowsMostlyShortSpurShoots) {
  const Preset* ginkgo = FindPreset("ginkgo");
  ASSERT_NE(ginkgo, nullptr);
  Tree t = GrowPreset("ginkgo", ginkgo->years);
  int dwarf = 0, total = 0, spur_on_spur = 0;
  double dwarf_length = 0, long_length = 0;
  for (const Branch& b : t.branches) {
    if (!b.alive || b.parent < 0) continue;
    ++total;
    double length = glm::length(b.nodes.back() - b.nodes.front());
    if (b.dwarf) {
      ++dwarf;
      dwarf_length += length;
      if (t.branches[static_cast<std::size_t>(b.parent)].dwarf) ++spur_on_spur;
    } else {
      long_length += length;
    }
  }
  ASSERT_GT(total, 200);
  ASSERT_GT(dwarf, 0);
  ASSERT_LT(dwarf, total);
  EXPECT_GT(static_cast<double>(dwarf) / total, 0.5);
  double mean_dwarf = dwarf_length / dwarf, mean_long = long_length / (total - dwarf);
  EXPECT_LT(mean_dwarf, 0.1 * mean_long);
  EXPECT_GT(spur_on_spur, dwarf / 3);
}

// Weeping: after some years most long shoots (apart from the upright leader) hang: their tip is
// below their base.
TEST(Species, WeepingShootsHangBelowTheirBases) {
  const Preset* weeping = FindPreset("weeping");
  ASSERT_NE(weeping, nullptr);
  Tree t = GrowPreset("weeping", 10);
  int hanging = 0, total = 0;
  for (const Branch& b : t.branches) {
    if (!b.alive || b.dwarf || b.kind == ShootKind::kSeedling) continue;
    if (b.kind == ShootKind::kTerminal && b.parent >= 0 &&
        t.branches[static_cast<std::size_t>(b.parent)].kind == ShootKind::kSeedling)
      continue;
    ++total;
    if (b.nodes.back().y < b.nodes.front().y) ++hanging;
  }
  ASSERT_GT(total, 100);
  EXPECT_GT(static_cast<double>(hanging) / total, 0.7);
}

}  // namespace
}  // namespace niwa

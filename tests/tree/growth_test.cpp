// Tests of the growth model: hand-computed equations, properties of grown trees, pruning,
// determinism.
#include "tree/growth.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "math/rotation.h"
#include "tree/presets.h"

namespace niwa {
namespace {

GrowRequest RequestFor(const std::string& preset, int years, uint64_t seed = 1) {
  GrowRequest r;
  r.preset = preset;
  r.params = FindPreset(preset)->params;
  r.years = years;
  r.seed = seed;
  return r;
}

TEST(HormoneRamp, InterpolatesTableRangesByHormone) {
  TreeParams p = FindPreset("sakura-thesis")->params;  // N 6 ~ 25, H_sat 0.58
  EXPECT_FLOAT_EQ(HormoneRamp(p, 0.0f, ParamId::kNLow, ParamId::kNHigh), 6.0f);
  EXPECT_FLOAT_EQ(HormoneRamp(p, 0.29f, ParamId::kNLow, ParamId::kNHigh), 15.5f);
  EXPECT_FLOAT_EQ(HormoneRamp(p, 3.0f, ParamId::kNLow, ParamId::kNHigh), 25.0f);
  EXPECT_FLOAT_EQ(HormoneRamp(p, 0.29f, ParamId::kBLLow, ParamId::kBLHigh), 0.065f);  // 0.12 ~ 0.01
  EXPECT_TRUE(p.Set(ParamId::kUseHormone, 0).ok());
  EXPECT_FLOAT_EQ(HormoneRamp(p, 0.0f, ParamId::kNLow, ParamId::kNHigh), 25.0f);
}

TEST(ShootLengthRamp, LengthStepMovesLongAndDwarfShootsApartAtTheThreshold) {
  TreeParams p = FindPreset("keyaki-thesis")->params;  // N 7 ~ 10, D 2 ~ 5 cm, H_sat 0.69
  const float h = 0.276f;                              // share t = 0.4 of the ranges
  // length_step 0 (every preset): HormoneRamp's value for long and dwarf shoots alike.
  for (bool dwarf : {false, true}) {
    EXPECT_FLOAT_EQ(ShootLengthRamp(p, h, dwarf, ParamId::kNLow, ParamId::kNHigh),
                    HormoneRamp(p, h, ParamId::kNLow, ParamId::kNHigh));
  }
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, h, false, ParamId::kDLow, ParamId::kDHigh), 3.2f);
  EXPECT_TRUE(p.Set(ParamId::kLengthStep, 0.5).ok());
  // Long: t + 0.5 (1 - t) = 0.7 -> D 2 + 3 x 0.7 = 4.1 cm, N 9.1; dwarf: 0.5 t = 0.2 -> 2.6 cm,
  // N 7.6.
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, h, false, ParamId::kDLow, ParamId::kDHigh), 4.1f);
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, h, false, ParamId::kNLow, ParamId::kNHigh), 9.1f);
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, h, true, ParamId::kDLow, ParamId::kDHigh), 2.6f);
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, h, true, ParamId::kNLow, ParamId::kNHigh), 7.6f);
  EXPECT_TRUE(
      p.Set(ParamId::kLengthStep, 1).ok());  // a pure step: dwarf shoots at 'a', long shoots at 'b'
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, 0.01f, false, ParamId::kDLow, ParamId::kDHigh), 5.0f);
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, 0.6f, true, ParamId::kDLow, ParamId::kDHigh), 2.0f);
  EXPECT_TRUE(
      p.Set(ParamId::kUseHormone, 0).ok());  // hormone off: every shoot long, at 'b' (2.5.1)
  EXPECT_FLOAT_EQ(ShootLengthRamp(p, 0.0f, false, ParamId::kNLow, ParamId::kNHigh), 10.0f);
}

TEST(BreakProbability, FollowsFig28AroundTheDwarfThreshold) {
  // Below H_s at most P^s, above at least P^s, reaching P^l at H_sat.
  EXPECT_FLOAT_EQ(BreakProbability(0.05f, 0.1f, 1.0f, 0.3f, 1.0f), 0.15f);
  EXPECT_FLOAT_EQ(BreakProbability(0.1f, 0.1f, 1.0f, 0.3f, 1.0f), 0.3f);
  EXPECT_FLOAT_EQ(BreakProbability(0.55f, 0.1f, 1.0f, 0.3f, 1.0f), 0.65f);
  EXPECT_FLOAT_EQ(BreakProbability(2.0f, 0.1f, 1.0f, 0.3f, 1.0f), 1.0f);
  EXPECT_FLOAT_EQ(BreakProbability(0.0f, 0.1f, 1.0f, 0.3f, 1.0f), 0.0f);
}

TEST(HormoneModel, Equations21To23OnTheBinaryTreeByHand) {
  // binary: alpha_t 1, alpha_tl 0.4, beta_c 0.8, beta_p 0, h_s 0.1, h_l 0.3, gamma 0.5, H_s 0.5,
  // light off (L = 1), H_init 1.
  Grower grower(RequestFor("binary", 2));
  grower.GrowYear();
  const Branch& seedling = grower.tree().branches[0];
  EXPECT_FLOAT_EQ(seedling.hormone_initial, 1.0f);
  EXPECT_FALSE(seedling.dwarf);
  EXPECT_FLOAT_EQ(seedling.hormone, 0.8f * 1.0f + 0.3f * 1.0f);  // eq. 2.2, long shoot
  grower.GrowYear();
  const Tree& tree = grower.tree();
  ASSERT_EQ(tree.branches.size(), 3u);  // P_tl at H >= H_sat is P_tl^l = 1: both buds break
  const Branch& terminal = tree.branches[1];
  const Branch& lateral = tree.branches[2];
  EXPECT_EQ(terminal.kind, ShootKind::kTerminal);
  EXPECT_EQ(lateral.kind, ShootKind::kTerminallyLateral);
  EXPECT_FLOAT_EQ(terminal.hormone_initial, 1.0f * 1.1f);  // eq. 2.1, alpha_t
  EXPECT_FLOAT_EQ(lateral.hormone_initial, 0.4f * 1.1f);   // eq. 2.1, alpha_tl
  EXPECT_TRUE(lateral.dwarf);                              // 0.44 < H_s = 0.5
  EXPECT_FLOAT_EQ(terminal.hormone, 0.8f * 1.1f + 0.3f);   // eq. 2.2, long
  EXPECT_FLOAT_EQ(lateral.hormone, 0.8f * 0.44f + 0.1f);   // eq. 2.2, dwarf
  EXPECT_FLOAT_EQ(tree.branches[0].hormone,
                  0.0f * 1.1f + 0.5f * (terminal.hormone + lateral.hormone));  // eq. 2.3
  EXPECT_FLOAT_EQ(tree.branches[0].hormone_previous, 1.1f);
}

TEST(Branching, BinaryTreeSplitsInTwoWithTheTableAngles) {
  Tree tree = GrowTree(RequestFor("binary", 2));
  const Branch& parent = tree.branches[0];
  glm::vec3 up = glm::normalize(parent.nodes[1] - parent.nodes[0]);
  for (const Branch& child : {tree.branches[1], tree.branches[2]}) {
    float angle = AngleBetween(up, child.bud_direction) * 180.0f / kPi;
    EXPECT_NEAR(angle, child.kind == ShootKind::kTerminal ? 10.0f : 30.0f, 1e-3f);
    EXPECT_EQ(child.nodes[0], parent.nodes[1]);
  }
  // psi_t = -10 turns the terminal shoot away from the terminally-lateral side.
  EXPECT_LT(glm::dot(tree.branches[1].bud_direction - up, tree.branches[2].bud_direction - up),
            0.0f);
}

// Straight shoot (no light, no bending) with lateral buds on every node.
Tree StraightShoot(double phi, int buds_per_node) {
  GrowRequest r = RequestFor("sakura-thesis", 1);
  EXPECT_TRUE(r.params.Set(ParamId::kUseLight, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kUseHormone, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBGLow, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBGHigh, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBLLow, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBLHigh, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kPhi, phi).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBL, buds_per_node).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kPsiL, 90).ok());
  return GrowTree(r);
}

float AzimuthDegrees(const glm::vec3& v) { return std::atan2(v.z, v.x) * 180.0f / kPi; }

float TurnBetween(const glm::vec3& a, const glm::vec3& b) {
  float turn = AzimuthDegrees(b) - AzimuthDegrees(a);
  while (turn < 0) turn += 360.0f;
  while (turn >= 360.0f) turn -= 360.0f;
  return std::min(turn, 360.0f - turn);  // divergence angle, either sense of the spiral
}

TEST(Phyllotaxis, AlternateTwoFifthsTurns144DegreesPerNode) {
  Tree tree = StraightShoot(0.4, 1);
  std::vector<glm::vec3> laterals;
  for (const Bud& bud : tree.branches[0].buds) {
    if (bud.kind == ShootKind::kLateral) laterals.push_back(bud.direction);
  }
  ASSERT_EQ(laterals.size(), 24u);  // N = 25 nodes, laterals on nodes 1..24
  for (std::size_t i = 1; i < laterals.size(); ++i) {
    EXPECT_NEAR(TurnBetween(laterals[i - 1], laterals[i]), 144.0f, 1e-2f) << i;
    EXPECT_NEAR(laterals[i].y, 0.0f, 1e-4f);  // psi_l = 90: horizontal
  }
}

TEST(Phyllotaxis, DecussatePairsAreOppositeAndCrossed) {
  Tree tree = StraightShoot(0.25, 2);
  std::vector<glm::vec3> laterals;
  for (const Bud& bud : tree.branches[0].buds) {
    if (bud.kind == ShootKind::kLateral) laterals.push_back(bud.direction);
  }
  ASSERT_EQ(laterals.size(), 48u);
  for (std::size_t i = 0; i + 3 < laterals.size(); i += 2) {
    EXPECT_NEAR(TurnBetween(laterals[i], laterals[i + 1]), 180.0f, 1e-2f);
    EXPECT_NEAR(TurnBetween(laterals[i], laterals[i + 2]), 90.0f, 1e-2f);
  }
}

// The spiral runs on across the yearly shoots: with φ = 1/2 the terminal shoot's first node is
// opposite its parent's tip node, so its first lateral bud sits on the side of the parent's last
// lateral bud (two steps of 180°), not opposite it.
TEST(Phyllotaxis, TerminalShootContinuesTheSpiral) {
  GrowRequest r = RequestFor("sakura-thesis", 2);
  for (auto [id, value] : {std::pair{ParamId::kUseLight, 0.0},
                           {ParamId::kUseHormone, 0.0},
                           {ParamId::kBGLow, 0.0},
                           {ParamId::kBGHigh, 0.0},
                           {ParamId::kBLLow, 0.0},
                           {ParamId::kBLHigh, 0.0},
                           {ParamId::kPhi, 0.5},
                           {ParamId::kPsiL, 90.0},
                           {ParamId::kPsiT, 0.0},
                           {ParamId::kPTlL, 0.0},
                           {ParamId::kPLYoung, 0.0}}) {
    ASSERT_EQ(r.params.Set(id, value).Line(), "");
  }
  Tree tree = GrowTree(r);
  const Branch& parent = tree.branches[0];
  const Branch* child = nullptr;
  for (const Branch& b : tree.branches) {
    if (b.parent == 0 && b.kind == ShootKind::kTerminal) child = &b;
  }
  ASSERT_NE(child, nullptr);
  auto lateral_bud = [](const Branch& b, bool first) {  // the first or the last one
    const Bud* pick = nullptr;
    for (const Bud& bud : b.buds) {
      if (bud.kind == ShootKind::kLateral && (pick == nullptr || !first)) pick = &bud;
    }
    return pick->direction;
  };
  EXPECT_NEAR(TurnBetween(lateral_bud(parent, false), lateral_bud(*child, true)), 0.0f, 1e-2f);
}

TEST(Bending, StepCapsOfEquations27And29Hold) {
  GrowRequest r = RequestFor("sakura-thesis", 6);
  EXPECT_TRUE(r.params.Set(ParamId::kBLLow, 1).ok());  // strong phototropism so the caps bind
  EXPECT_TRUE(r.params.Set(ParamId::kBLHigh, 1).ok());
  Tree tree = GrowTree(r);
  float cap_b = 20.0f, cap_n = 15.0f;
  int checked = 0;
  for (const Branch& b : tree.branches) {
    if (!b.alive) continue;
    glm::vec3 previous = b.bud_direction;
    for (std::size_t i = 1; i < b.nodes.size(); ++i) {
      glm::vec3 d = glm::normalize(b.nodes[i] - b.nodes[i - 1]);
      float bend = AngleBetween(previous, d) * 180.0f / kPi;
      EXPECT_LE(bend, (i == 1 ? cap_b : cap_n) + 1e-2f);
      previous = d;
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(LightDeath, ShootsBelowKTimesHalfAlwaysDieAndAboveKNeverDo) {
  GrowRequest r = RequestFor("sakura-thesis", 8);
  EXPECT_TRUE(r.params.Set(ParamId::kKDeath, 0.5).ok());
  Tree tree = GrowTree(r);
  int dead = 0;
  for (const Branch& b : tree.branches) {
    if (b.parent < 0) continue;
    if (b.alive) {
      EXPECT_GE(b.light, 0.5f * 0.5f) << b.id;
    }
    if (b.light >= 0.5f) {
      EXPECT_TRUE(b.alive || !tree.branches[static_cast<std::size_t>(b.parent)].alive);
    }
    dead += b.alive ? 0 : 1;
  }
  EXPECT_GT(dead, 0);
  EXPECT_TRUE(r.params.Set(ParamId::kKDeath, 0.0).ok());
  for (const Branch& b : GrowTree(r).branches) EXPECT_TRUE(b.alive);
}

// light_scale multiplies L: the lone first-year shoot sees the open sky (light 1 before scaling),
// and a dimmer L (less hormone by eq. 2.2, more deaths) grows a smaller tree.
TEST(LightScale, MultipliesTheLightOfEveryShoot) {
  GrowRequest r = RequestFor("sakura-thesis", 1);
  EXPECT_TRUE(r.params.Set(ParamId::kLightScale, 1.0).ok());
  float open_sky = GrowTree(r).branches[0].light;
  EXPECT_NEAR(open_sky, 1.0f, 1e-3f);  // the grid removes the shoot's own sphere approximately
  EXPECT_TRUE(r.params.Set(ParamId::kLightScale, 0.6).ok());
  EXPECT_FLOAT_EQ(GrowTree(r).branches[0].light, 0.6f * open_sky);
  r.years = 10;
  std::size_t dim = GrowTree(r).branches.size();
  EXPECT_TRUE(r.params.Set(ParamId::kLightScale, 1.0).ok());
  EXPECT_LT(2 * dim, GrowTree(r).branches.size());
}

void ExpectConsistentTree(const Tree& tree) {
  for (const Branch& b : tree.branches) {
    ASSERT_GE(b.nodes.size(), 2u);
    for (const glm::vec3& n : b.nodes) ASSERT_TRUE(std::isfinite(n.x + n.y + n.z)) << b.id;
    for (std::size_t i = 1; i < b.nodes.size(); ++i) {
      EXPECT_NEAR(glm::length(b.nodes[i] - b.nodes[i - 1]), b.internode_length,
                  1e-3f * b.internode_length + 1e-5f);
      EXPECT_GT(b.internode_length, 0.0f);
    }
    EXPECT_TRUE(std::isfinite(b.hormone));
    EXPECT_GE(b.hormone, 0.0f);
    EXPECT_GE(b.light, 0.0f);
    EXPECT_LE(b.light, 1.0f);
    EXPECT_GT(b.cross_section, -1e-9f);
    if (b.parent >= 0) {
      const Branch& parent = tree.branches[static_cast<std::size_t>(b.parent)];
      EXPECT_LT(parent.id, b.id);
      // A shoot on node 0 of its parent is a basal shoot (basal_shoots, docs/tree-species.md): a
      // stem of its own beside the seedling, from year 1 on, outside the seedling's pipe.
      const bool basal = b.parent_node == 0;
      if (basal) {
        EXPECT_GT(tree.params.GetInt(ParamId::kBasalShoots), 0) << b.id;
        EXPECT_EQ(b.parent, 0) << b.id;
      } else {
        EXPECT_LT(parent.year, b.year);
      }
      EXPECT_EQ(b.nodes[0], parent.nodes[static_cast<std::size_t>(b.parent_node)]);
      EXPECT_NE(std::find(parent.children.begin(), parent.children.end(), b.id),
                parent.children.end());
      if (b.alive) {
        EXPECT_TRUE(parent.alive) << b.id;
      }
      if (b.alive && !basal) {
        EXPECT_GE(parent.cross_section, b.cross_section);  // pipe model
      }
    }
  }
}

TEST(Properties, EveryPresetGrowsAConsistentTree) {
  for (const Preset& preset : Presets()) {
    SCOPED_TRACE(preset.name);
    Tree tree = GrowTree(RequestFor(preset.name, 8, 3));
    ExpectConsistentTree(tree);
    TreeStats stats = ComputeStats(tree);
    EXPECT_GT(stats.internodes, 1);
    EXPECT_GT(stats.height, 0.0);
  }
}

TEST(Determinism, SameSeedSameTreeOtherSeedOtherTree) {
  Tree a = GrowTree(RequestFor("sakura-thesis", 8, 5));
  Tree b = GrowTree(RequestFor("sakura-thesis", 8, 5));
  Tree c = GrowTree(RequestFor("sakura-thesis", 8, 6));
  ASSERT_EQ(a.branches.size(), b.branches.size());
  for (std::size_t i = 0; i < a.branches.size(); ++i) {
    EXPECT_EQ(a.branches[i].nodes, b.branches[i].nodes);
    EXPECT_EQ(a.branches[i].alive, b.branches[i].alive);
  }
  EXPECT_NE(ComputeStats(a).internodes, ComputeStats(c).internodes);
}

TEST(Pruning, CutPartsNeverReturnAndRegrowthComesFromDormancyBreak) {
  GrowRequest r = RequestFor("binary", 13);
  r.prunes.push_back({10, -1, 7});  // fig. 2.15: at year 10 remove all growth since year 7
  Grower grower(r);
  while (grower.year() < 10) grower.GrowYear();
  std::vector<char> alive_after_prune;
  int internodes_after_prune = ComputeStats(grower.tree()).internodes;
  for (const Branch& b : grower.tree().branches) {
    alive_after_prune.push_back(b.alive);
    if (b.alive) {
      EXPECT_LT(b.year, 7);
    }
  }
  while (grower.year() < 13) grower.GrowYear();
  const Tree& tree = grower.tree();
  for (std::size_t i = 0; i < alive_after_prune.size(); ++i) {
    if (!alive_after_prune[i]) {
      EXPECT_FALSE(tree.branches[i].alive) << "branch " << i << " came back";
    }
  }
  EXPECT_GT(ComputeStats(tree).internodes, internodes_after_prune);

  // Without dormancy break there is nothing left to grow from.
  EXPECT_TRUE(r.params.Set(ParamId::kDeltaL, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kDeltaD, 0).ok());
  Grower still(r);
  while (still.year() < 10) still.GrowYear();
  int before = ComputeStats(still.tree()).internodes;
  while (still.year() < 13) still.GrowYear();
  EXPECT_EQ(ComputeStats(still.tree()).internodes, before);
}

TEST(Pruning, BranchSelectorRemovesTheBranchAndEverythingAbove) {
  GrowRequest r = RequestFor("sakura-thesis", 6);
  Tree full = GrowTree(r);
  int target = full.branches[1].id;
  r.prunes.push_back({6, target, -1});
  Tree cut = GrowTree(r);
  EXPECT_FALSE(cut.branches[static_cast<std::size_t>(target)].alive);
  for (int child : cut.branches[static_cast<std::size_t>(target)].children) {
    EXPECT_FALSE(cut.branches[static_cast<std::size_t>(child)].alive);
  }
  EXPECT_LT(ComputeStats(cut).internodes, ComputeStats(full).internodes);
}

// A prune that cuts nothing is reported (the CLI fails with it, the page shows it); the ones that
// cut are not.
TEST(Pruning, IdlePrunesAreNamedWithTheReason) {
  GrowRequest r = RequestFor("sakura-thesis", 6);
  Tree tree = GrowTree(r);
  std::size_t by_year_3 = 0;
  while (tree.branches[by_year_3].year <= 3) ++by_year_3;
  EXPECT_EQ(IdlePruneReason({6, 1, -1}, tree).message(), "");
  EXPECT_EQ(IdlePruneReason({6, -1, 4}, tree).message(), "");
  EXPECT_EQ(IdlePruneReason({3, static_cast<int>(by_year_3) - 1, -1}, tree).message(), "");
  EXPECT_EQ(IdlePruneReason({7, 1, -1}, tree).message(), "year 7 is after the last year grown (6)");
  // The first shoot of year 4 did not exist yet at year 3.
  EXPECT_EQ(IdlePruneReason({3, static_cast<int>(by_year_3), -1}, tree).message(),
            "the tree had no branch b" + std::to_string(by_year_3) + " by year 3 (ids 0 to " +
                std::to_string(by_year_3 - 1) + ")");
  EXPECT_EQ(
      IdlePruneReason({5, 999999, -1}, tree).message().rfind("the tree had no branch b999999", 0),
      0u);
  EXPECT_EQ(IdlePruneReason({4, -1, 5}, tree).message(),
            "nothing had grown since year 5 by year 4");
}

TEST(Limits, MaxInternodesStopsGrowthAndFlagsTruncation) {
  GrowRequest r = RequestFor("sakura-thesis", 15);
  EXPECT_TRUE(r.params.Set(ParamId::kMaxInternodes, 1000).ok());
  Tree tree = GrowTree(r);
  EXPECT_TRUE(tree.truncated);
  EXPECT_LE(ComputeStats(tree).internodes, 1000);
}

TEST(Flowers, SakuraDwarfShootLateralsBloom) {
  Tree tree = GrowTree(RequestFor("sakura-thesis", 12));
  EXPECT_GT(ComputeStats(tree).flowers, 0);
  for (const Branch& b : tree.branches) {
    for (const Bud& bud : b.buds) {
      if (bud.flower) {
        EXPECT_TRUE(b.dwarf && bud.kind == ShootKind::kLateral);
      }
    }
  }
  GrowRequest r = RequestFor("sakura-thesis", 12);
  EXPECT_TRUE(r.params.Set(ParamId::kDwarfLateralFlowers, 0).ok());
  EXPECT_EQ(ComputeStats(GrowTree(r)).flowers, 0);
}

}  // namespace
}  // namespace niwa

namespace niwa {
namespace {

// Sakura without light (L = 1), pruned back to the seedling after year 3: in year 4 the seedling's
// hormone falls to β_p·H' (eq. 2.3 with no living children), which is what triggers dormancy break.
struct CutBack {
  Tree tree;
  float hormone_before_cut;  // the seedling's H after year 3 (H')
  float hormone_after_cut;   // its H after year 4, which next year's shoots inherit from
};

CutBack GrowCutBack(double threshold, double drop_ratio, int most) {
  GrowRequest r = RequestFor("sakura-thesis", 5);
  EXPECT_TRUE(r.params.Set(ParamId::kUseLight, 0).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kHBL, threshold).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kDeltaL, 1).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBBL, most).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kHBD, drop_ratio).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kDeltaD, 1).ok());
  EXPECT_TRUE(r.params.Set(ParamId::kBBD, most).ok());
  r.prunes.push_back({3, -1, 2});  // after year 3 remove all growth since year 2
  Grower grower(r);
  while (grower.year() < 3) grower.GrowYear();
  float before = grower.tree().branches[0].hormone;
  grower.GrowYear();
  float after = grower.tree().branches[0].hormone;
  grower.GrowYear();
  return {grower.TakeTree(), before, after};
}

// Eq. 2.1 share for a shoot of this kind (sakura: α_t 0.7, α_tl 0.55, α_l 0.4).
float SakuraAlpha(ShootKind kind) {
  return kind == ShootKind::kLateral ? 0.4f : kind == ShootKind::kTerminallyLateral ? 0.55f : 0.7f;
}

int SproutsInYear5(const Tree& tree) {
  int count = 0;
  for (const Branch& b : tree.branches) count += (b.parent == 0 && b.year == 5) ? 1 : 0;
  return count;
}

TEST(DormancyBreak, SuddenDropBreaksAtMostBbDormantBudsWithExtraHormone) {
  CutBack cut = GrowCutBack(/*threshold=*/0, /*drop_ratio=*/2, /*most=*/3);
  const Branch& seedling = cut.tree.branches[0];
  // Year 4: H = β_p·H' + γ·(what survived) falls below H'/2, so 3 dormant buds break (δ_d = 1,
  // B_b^d = 3).
  ASSERT_LT(cut.hormone_after_cut, cut.hormone_before_cut / 2);
  EXPECT_EQ(SproutsInYear5(cut.tree), 3);
  for (const Branch& b : cut.tree.branches) {
    if (b.parent == 0 && b.year == 5) {
      // Eq. 2.1 plus H_n^d = 0.4.
      EXPECT_NEAR(b.hormone_initial, SakuraAlpha(b.kind) * cut.hormone_after_cut + 0.4f, 1e-5f);
    }
  }
  EXPECT_GT(seedling.buds.size(), 3u);
}

TEST(DormancyBreak, ThresholdBreaksWhenHormoneCrossesBelowIt) {
  // A threshold between H after the cut and H' before it: a crossing (δ_l = 1, B_b^l = 2).
  CutBack probe = GrowCutBack(0, 0, 2);
  double threshold = 0.5 * (probe.hormone_before_cut + probe.hormone_after_cut);
  CutBack cut = GrowCutBack(threshold, /*drop_ratio=*/0, /*most=*/2);
  ASSERT_LT(cut.hormone_after_cut, threshold);
  ASSERT_GE(cut.hormone_before_cut, threshold);
  EXPECT_EQ(SproutsInYear5(cut.tree), 2);
  for (const Branch& b : cut.tree.branches) {
    if (b.parent == 0 && b.year == 5) {
      // Eq. 2.1 plus H_n^l = 0.3.
      EXPECT_NEAR(b.hormone_initial, SakuraAlpha(b.kind) * cut.hormone_after_cut + 0.3f, 1e-5f);
    }
  }
}

TEST(DormancyBreak, NothingBreaksWithBothTriggersOff) {
  EXPECT_EQ(SproutsInYear5(GrowCutBack(0, 0, 3).tree), 0);
}

}  // namespace
}  // namespace niwa

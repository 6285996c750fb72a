// Tests that each species preset beyond the thesis grows the branching rule that defines it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <glm/geometric.hpp>
#include <map>
#include <string>
#include <vector>

#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_report.h"

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

// The form as issue 17 measures it on the exported .glb, here on the TreeMesh the .glb writes
// (metres): height = vertical extent, width = the larger horizontal extent, of every vertex.
struct MeshForm {
  double bottom = 0, top = 0, height = 0, width = 0;
  double lowest_leaf = 0;             // lowest leaf vertex
  double top_x = 0, top_z = 0;        // horizontal position of the highest vertex
  double centre_x = 0, centre_z = 0;  // middle of the horizontal extents (trunk foot: 0, 0)
  double leaf_x = 0, leaf_z = 0;      // horizontal centroid of the leaf vertices (trunk foot: 0, 0)
  std::vector<double> band_width;     // width of the vertices in each tenth of the height
};

MeshForm MeasureMesh(const TreeMesh& mesh) {
  MeshForm f;
  double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
  f.lowest_leaf = 1e9;
  for (const MeshBuffers* m : {&mesh.bark, &mesh.leaves, &mesh.flowers}) {
    for (std::size_t i = 0; i + 2 < m->positions.size(); i += 3) {
      for (std::size_t k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], double(m->positions[i + k]));
        hi[k] = std::max(hi[k], double(m->positions[i + k]));
      }
      if (m->positions[i + 1] >= hi[1]) {
        f.top_x = m->positions[i];
        f.top_z = m->positions[i + 2];
      }
      if (m == &mesh.leaves) {
        f.lowest_leaf = std::min(f.lowest_leaf, double(m->positions[i + 1]));
        f.leaf_x += double(m->positions[i]) / double(m->vertex_count());
        f.leaf_z += double(m->positions[i + 2]) / double(m->vertex_count());
      }
    }
  }
  f.bottom = lo[1];
  f.top = hi[1];
  f.height = hi[1] - lo[1];
  f.width = std::max(hi[0] - lo[0], hi[2] - lo[2]);
  f.centre_x = 0.5 * (lo[0] + hi[0]);
  f.centre_z = 0.5 * (lo[2] + hi[2]);
  const int bands = 10;
  std::vector<double> bx0(bands, 1e9), bx1(bands, -1e9), bz0(bands, 1e9), bz1(bands, -1e9);
  for (const MeshBuffers* m : {&mesh.bark, &mesh.leaves}) {
    for (std::size_t i = 0; i + 2 < m->positions.size(); i += 3) {
      int band = static_cast<int>((m->positions[i + 1] - f.bottom) / f.height * bands);
      band = std::min(std::max(band, 0), bands - 1);
      auto b = static_cast<std::size_t>(band);
      bx0[b] = std::min(bx0[b], double(m->positions[i]));
      bx1[b] = std::max(bx1[b], double(m->positions[i]));
      bz0[b] = std::min(bz0[b], double(m->positions[i + 2]));
      bz1[b] = std::max(bz1[b], double(m->positions[i + 2]));
    }
  }
  for (std::size_t b = 0; b < bands; ++b) {
    f.band_width.push_back(bx1[b] < bx0[b] ? 0.0 : std::max(bx1[b] - bx0[b], bz1[b] - bz0[b]));
  }
  return f;
}

MeshForm PresetForm(const std::string& name, int years, Tree* grown = nullptr) {
  Tree t = GrowPreset(name, years);
  MeshForm f = MeasureMesh(BuildTreeMesh(t));
  if (grown) *grown = std::move(t);
  return f;
}

// Stems from the base: living shoots that start within the lowest 10 % of the tree and whose
// own subtree reaches above 40 % of its height (the trunk itself counts as one).
int StemsFromBase(const Tree& t) {
  double height = ComputeStats(t).height;
  int stems = 0;
  for (const Branch& b : t.branches) {
    if (!b.alive || b.nodes.front().y > 0.1 * height) continue;
    if (b.parent >= 0 &&
        t.branches[static_cast<std::size_t>(b.parent)].nodes.front().y <= 0.1 * height &&
        b.kind == ShootKind::kTerminal)
      continue;  // the continuation of a low shoot is the same stem
    double reach = 0;
    std::vector<int> stack = {b.id};
    while (!stack.empty()) {
      const Branch& c = t.branches[static_cast<std::size_t>(stack.back())];
      stack.pop_back();
      if (!c.alive) continue;
      for (const glm::vec3& n : c.nodes) reach = std::max(reach, double(n.y));
      for (int child : c.children) stack.push_back(child);
    }
    if (reach > 0.4 * height) ++stems;
  }
  return stems;
}

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

// The three --stats form fields on a hand-built tree whose answers are known.
TEST(SpeciesForm, TreeFormFieldsFollowTheirDefinitions) {
  Tree t;
  t.years = 3;
  auto add = [&t](int year, bool alive, std::vector<glm::vec3> nodes, std::vector<int> leaf_nodes) {
    Branch b{};
    b.id = static_cast<int>(t.branches.size());
    b.parent = b.id == 0 ? -1 : 0;
    b.year = year;
    b.alive = alive;
    b.nodes = std::move(nodes);
    for (int n : leaf_nodes) b.leaves.push_back({n, kUp});
    t.branches.push_back(b);
  };
  add(1, true, {{0, 0, 0}, {0, 100, 0}, {0, 200, 0}}, {2});         // trunk, leaf at 200
  add(3, true, {{0, 100, 0}, {60, 120, 0}, {90, 110, 0}}, {1, 2});  // tip points down
  add(3, true, {{0, 150, 0}, {0, 160, -40}, {0, 170, -70}}, {1});   // tip points up
  add(3, true, {{0, 200, 0}, {-30, 190, 10}}, {});                  // one internode, down
  add(3, false, {{0, 50, 0}, {500, 10, 500}}, {1});                 // dead: ignored
  add(2, true, {{0, 120, 0}, {-50, 80, 0}, {-60, 70, 0}}, {1, 2});  // old year: no tip count
  TreeForm f = ComputeTreeForm(t);
  EXPECT_DOUBLE_EQ(f.crown_width, 150.0);              // x from -60 to 90 (z spans 80)
  EXPECT_DOUBLE_EQ(f.crown_base_height, 70.0);         // the lowest leaf node: (-60, 70, 0)
  EXPECT_DOUBLE_EQ(f.drooping_tips_share, 2.0 / 3.0);  // of the three living year-3 shoots
  t.branches.clear();
  f = ComputeTreeForm(t);
  EXPECT_EQ(f.crown_width, 0.0);
  EXPECT_EQ(f.crown_base_height, 0.0);
  EXPECT_EQ(f.drooping_tips_share, 0.0);
}

// ---- Issue 17 item 1: the forms people know, measured as on the .glb ----

// Sakura (Somei-yoshino) at 20 years: 5-9 m tall, crown at least as wide as tall, clear trunk.
TEST(SpeciesForm, SakuraIsASpreadingSomeiYoshinoWithAClearTrunk) {
  MeshForm f = PresetForm("sakura", 20);
  EXPECT_GE(f.height, 5.0);
  EXPECT_LE(f.height, 9.0);
  EXPECT_GE(f.width, f.height);
  EXPECT_GE(f.lowest_leaf - f.bottom, 0.25 * f.height);
}

// Weeping (shidare-zakura) at 20 years: at least half of the last year's shoot tips point below
// the horizontal, crown wider than 0.8 x height.
TEST(SpeciesForm, WeepingCherryHangsAndSpreads) {
  Tree t;
  MeshForm f = PresetForm("weeping", 20, &t);
  EXPECT_GE(ComputeTreeForm(t).drooping_tips_share, 0.5);
  EXPECT_GT(f.width, 0.8 * f.height);
  EXPECT_GE(f.bottom, -0.05) << "hanging shoots go below the ground";
}

// Pine at 15 years: conical, widest in its lower third, narrowing to the top.
TEST(SpeciesForm, PineIsConicalAndWidestInItsLowerThird) {
  MeshForm f = PresetForm("pine", 15);
  std::size_t widest = 0;
  for (std::size_t b = 0; b < f.band_width.size(); ++b) {
    if (f.band_width[b] > f.band_width[widest]) widest = b;
  }
  EXPECT_LE(widest, 3u) << "widest band " << widest << " of 10";
  EXPECT_LT(f.band_width[8], 0.6 * f.band_width[widest]);
}

// Tsutsuji at 15 years: a low mound at most 1.5 m tall and 1.2 x as wide, several stems from the
// base, leaves down to the ground.
TEST(SpeciesForm, TsutsujiIsALowMoundOfSeveralStemsLeafyToTheGround) {
  Tree t;
  MeshForm f = PresetForm("tsutsuji", 15, &t);
  EXPECT_LE(f.height, 1.5);
  EXPECT_GE(f.width, 1.2 * f.height);
  EXPECT_LE(f.lowest_leaf - f.bottom, 0.1 * f.height);
  EXPECT_GE(StemsFromBase(t), 3);
}

// Keyaki at 15 years and the default sun: the vase stands upright (the middle of the crown's
// extents within 4 % of its height of the trunk's foot, horizontally, and so the centroid of its
// foliage within 5 %) and is wider than a third of its height.
TEST(SpeciesForm, KeyakiIsAnUprightVase) {
  MeshForm f = PresetForm("keyaki", 15);
  EXPECT_LT(std::hypot(f.centre_x, f.centre_z), 0.04 * f.height)
      << "crown centre at " << f.centre_x << ", " << f.centre_z << " m, height " << f.height;
  EXPECT_LT(std::hypot(f.leaf_x, f.leaf_z), 0.05 * f.height)
      << "foliage centroid at " << f.leaf_x << ", " << f.leaf_z << " m, height " << f.height;
  EXPECT_GT(f.width, 0.33 * f.height);
}

// Maple (Acer palmatum) at 15 years: a rounded, spreading crown, at least 0.7 x as wide as tall.
TEST(SpeciesForm, MapleHasARoundedSpreadingCrown) {
  MeshForm f = PresetForm("maple", 15);
  EXPECT_GE(f.width, 0.7 * f.height);
  EXPECT_LE(f.height, 8.0);
}

// Ginkgo at 15 years: young ginkgos are upright and sparse, taller than wide.
TEST(SpeciesForm, GinkgoIsUprightWhenYoung) {
  MeshForm f = PresetForm("ginkgo", 15);
  EXPECT_GT(f.height, f.width);
}

// The leader: the seedling and its chain of terminal shoots, from the ground up.
std::vector<const Branch*> LeaderChain(const Tree& t) {
  std::vector<const Branch*> chain = {&t.branches[0]};
  for (;;) {
    const Branch* next = nullptr;
    for (int c : chain.back()->children) {
      const Branch& child = t.branches[static_cast<std::size_t>(c)];
      if (child.alive && child.kind == ShootKind::kTerminal) next = &child;
    }
    if (!next) break;
    chain.push_back(next);
  }
  return chain;
}

// Weeping (shidare-zakura) at 20 years hangs from a trained standard: the leader is straight and
// vertical up to standard_height (3 m), the tree is 3.5-6 m tall, and the crown is carried high
// (no leaves below 40 cm, the trim; the widest tenth of the height in the upper half).
TEST(SpeciesForm, WeepingCherryHangsFromAStandardTrunk) {
  const Preset* weeping = FindPreset("weeping");
  ASSERT_NE(weeping, nullptr);
  const double standard = weeping->params.Get(ParamId::kStandardHeight);
  ASSERT_GE(standard, 250.0);
  Tree t;
  MeshForm f = PresetForm("weeping", 20, &t);
  EXPECT_GE(f.height, 3.5);
  EXPECT_LE(f.height, 6.0);
  int straight = 0;  // leader nodes up to the first above the stake (then it may arch over)
  bool above = false;
  for (const Branch* b : LeaderChain(t)) {
    for (const glm::vec3& n : b->nodes) {
      if (above || n.y > standard) {
        above = true;
        break;
      }
      EXPECT_LT(std::hypot(double(n.x), double(n.z)), 0.5) << "leader node at y " << n.y;
      ++straight;
    }
  }
  EXPECT_TRUE(above) << "the leader reaches the top of the stake";
  EXPECT_GT(straight, 10);
  // The trim cuts a shoot whose tip hangs below 40 cm; its leaf cards hang below the tip: a card
  // of leaf_spray 2 reaches 1.3 leaf lengths (12 cm) from its node, the single 9 cm leaf 9 cm (the
  // floor was 0.35 then; 0.347 with the spray).
  EXPECT_GE(f.lowest_leaf - f.bottom, 0.30);
  std::size_t widest = 0;
  for (std::size_t b = 0; b < f.band_width.size(); ++b) {
    if (f.band_width[b] > f.band_width[widest]) widest = b;
  }
  EXPECT_GE(widest, 5u) << "widest band " << widest << " of 10";
}

// Tsutsuji: the stems from the root collar (the seedling and the basal shoots on its node 0)
// are several and none carries the plant: the thickest has at most 40 % of their summed
// cross-section (the thesis's tsutsuji stands on one stem: 100 %).
TEST(SpeciesForm, TsutsujiStandsOnSeveralStemsOfSimilarThickness) {
  Tree t = GrowPreset("tsutsuji", 15);
  std::vector<double> areas = {t.branches[0].cross_section};
  for (int c : t.branches[0].children) {
    const Branch& b = t.branches[static_cast<std::size_t>(c)];
    if (b.alive && b.parent_node == 0) areas.push_back(b.cross_section);
  }
  EXPECT_GE(areas.size(), 5u);
  double total = 0, thickest = 0;
  for (double a : areas) {
    total += a;
    thickest = std::max(thickest, a);
  }
  EXPECT_LE(thickest, 0.4 * total) << areas.size() << " stems";
  Tree thesis = GrowPreset("tsutsuji-thesis", 15);
  for (int c : thesis.branches[0].children) {
    EXPECT_NE(thesis.branches[static_cast<std::size_t>(c)].parent_node, 0);
  }
}

// Pine: the whorl limbs (the terminally-lateral shoots of the leader, followed along their own
// terminal chain) spread in tiers: their median chord from base to tip rises less than 45 degrees
// (without plagiotropism, b_h 0, they rise at about 73 degrees into a column).
double MedianWhorlLimbElevation(const Tree& t) {
  std::vector<double> elevations;
  for (const Branch* leader : LeaderChain(t)) {
    for (int c : leader->children) {
      const Branch* limb = &t.branches[static_cast<std::size_t>(c)];
      if (!limb->alive || limb->kind != ShootKind::kTerminallyLateral) continue;
      const glm::vec3 base = limb->nodes.front();
      const Branch* end = limb;
      for (bool more = true; more;) {
        more = false;
        for (int k : end->children) {
          const Branch& next = t.branches[static_cast<std::size_t>(k)];
          if (next.alive && next.kind == ShootKind::kTerminal) {
            end = &next;
            more = true;
          }
        }
      }
      const glm::vec3 tip = end->nodes.back();
      elevations.push_back(std::atan2(double(tip.y - base.y),
                                      std::hypot(double(tip.x - base.x), double(tip.z - base.z))) *
                           180.0 / 3.14159265358979);
    }
  }
  if (elevations.empty()) return 90.0;
  std::sort(elevations.begin(), elevations.end());
  return elevations[elevations.size() / 2];
}

TEST(SpeciesForm, PineWhorlLimbsSpreadInTiers) {
  Tree t = GrowPreset("pine", 15);
  EXPECT_GE(LeaderChain(t).size(), 12u) << "one whorl per year on the leader";
  EXPECT_LT(MedianWhorlLimbElevation(t), 45.0);
  const Preset* pine = FindPreset("pine");
  ASSERT_NE(pine, nullptr);
  GrowRequest r;
  r.preset = "pine";
  r.params = pine->params;
  r.seed = pine->seed;
  r.years = 15;
  ASSERT_TRUE(r.params.Set(ParamId::kBH, 0.0).ok());
  EXPECT_GT(MedianWhorlLimbElevation(GrowTree(r)), 55.0) << "b_h makes the tiers";
}

// Issue 17 item 7's time goal (each species at 15 years within 2x sakura-thesis) is a speed goal:
// scripts/bench reports it (bench/report.mjs), not a timed test here.

}  // namespace
}  // namespace niwa

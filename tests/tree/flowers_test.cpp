// Tests of the flowers per species (issue 17): the flower_colour, flower_form and terminal_flowers
// rows, the azalea's flowers at its shoot tips, each colour's texture, and the presets that use
// them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "tree/growth.h"
#include "tree/mesh.h"
#include "tree/presets.h"
#include "tree/tree_gltf.h"
#include "tree/tree_look.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

GrowRequest PresetRequest(const std::string& name, int years) {
  const Preset* preset = FindPreset(name);
  EXPECT_NE(preset, nullptr) << name;
  GrowRequest r;
  r.preset = name;
  if (preset) {
    r.params = preset->params;
    r.seed = preset->seed;
  }
  r.years = years;
  return r;
}

int FlowerCount(const Tree& tree) {
  int count = 0;
  for (const Branch& b : tree.branches) count += static_cast<int>(b.flowers.size());
  return count;
}

// Mean r, g, b (0..255) of the pixels with alpha >= 128, and their share of the image.
struct Opaque {
  double r = 0, g = 0, b = 0, share = 0;
};
Opaque MeanOpaque(const Rgba8Image& image) {
  Opaque o;
  int n = 0;
  for (std::size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
    if (image.pixels[i + 3] < 128) continue;
    o.r += image.pixels[i];
    o.g += image.pixels[i + 1];
    o.b += image.pixels[i + 2];
    ++n;
  }
  if (n > 0) {
    o.r /= n;
    o.g /= n;
    o.b /= n;
  }
  o.share = static_cast<double>(n) / (image.width * image.height);
  return o;
}

TreeLook FlowerLook(FlowerColour colour, FlowerForm form) {
  TreeLook look;
  look.flower_colour = colour;
  look.flower_form = form;
  return look;
}

TEST(SpeciesFlowers, TerminalFlowersAddFlowersAtLastYearsTipsAndChangeNothingElse) {
  GrowRequest off = PresetRequest("tsutsuji", 8);
  ASSERT_TRUE(off.params.Set(TreeParam::kTerminalFlowers, 0).ok());
  GrowRequest on = off;
  ASSERT_TRUE(on.params.Set(TreeParam::kTerminalFlowers, 1).ok());
  const Tree a = GrowTree(off), b = GrowTree(on);
  ASSERT_EQ(a.branches.size(), b.branches.size());
  int newest = 0;  // the year of this year's shoots; last year's are one less
  for (const Branch& y : b.branches) newest = std::max(newest, y.year);
  int last_year_tips = 0;
  for (std::size_t i = 0; i < a.branches.size(); ++i) {
    const Branch &x = a.branches[i], &y = b.branches[i];
    EXPECT_EQ(x.nodes, y.nodes) << "branch " << i;  // the same wood, bit for bit
    EXPECT_EQ(x.alive, y.alive);
    EXPECT_EQ(x.leaves.size(), y.leaves.size());
    EXPECT_TRUE(x.flowers.empty());  // the azalea has no dwarf-shoot flowers
    const bool tip = y.alive && y.year == newest - 1 && y.nodes.size() >= 2;
    last_year_tips += tip ? 1 : 0;
    if (tip) {
      ASSERT_EQ(y.flowers.size(), 1u) << "branch " << i;
      EXPECT_EQ(y.flowers[0], static_cast<int>(y.nodes.size()) - 1);  // at the shoot's tip
    } else {
      EXPECT_TRUE(y.flowers.empty()) << "branch " << i << " year " << y.year;
    }
  }
  EXPECT_GT(last_year_tips, 20);
  EXPECT_EQ(FlowerCount(b), last_year_tips);
  EXPECT_EQ(FlowerCount(a), 0);
  EXPECT_EQ(ComputeStats(b).flowers, last_year_tips);
}

TEST(SpeciesFlowers, TsutsujiFlowersCoverTheMoundInSpring) {
  GrowRequest r = PresetRequest("tsutsuji", 15);
  ASSERT_TRUE(r.params.Set(TreeParam::kSeason, static_cast<int>(Season::kSpring)).ok());
  const Tree tree = GrowTree(r);
  const TreeMesh mesh = BuildTreeMesh(tree);
  EXPECT_EQ(mesh.look.flower_form, FlowerForm::kAzalea);
  EXPECT_EQ(mesh.look.flower_colour, FlowerColour::kMagenta);
  EXPECT_GT(mesh.leaves.vertex_count(), 0u);  // evergreen: leaves and flowers together
  const std::size_t flowers = mesh.flower_branch_id.size() / 22;  // 22 vertices a flower card
  EXPECT_GT(flowers, 300u);
  // Over the whole mound: flowers from the lower third up to the top, out to its edges.
  double lo_y = 1e9, hi_y = -1e9, lo_x = 1e9, hi_x = -1e9, top = -1e9, left = 1e9, right = -1e9;
  for (std::size_t i = 0; i + 2 < mesh.flowers.positions.size(); i += 3) {
    lo_y = std::min(lo_y, double(mesh.flowers.positions[i + 1]));
    hi_y = std::max(hi_y, double(mesh.flowers.positions[i + 1]));
    lo_x = std::min(lo_x, double(mesh.flowers.positions[i]));
    hi_x = std::max(hi_x, double(mesh.flowers.positions[i]));
  }
  for (std::size_t i = 0; i + 2 < mesh.leaves.positions.size(); i += 3) {
    top = std::max(top, double(mesh.leaves.positions[i + 1]));
    left = std::min(left, double(mesh.leaves.positions[i]));
    right = std::max(right, double(mesh.leaves.positions[i]));
  }
  EXPECT_LT(lo_y, top / 3.0);
  EXPECT_GT(hi_y, 0.85 * top);
  EXPECT_GT(hi_x - lo_x, 0.8 * (right - left));
}

TEST(SpeciesFlowers, EachColourHasItsOwnHue) {
  const Opaque pale =
      MeanOpaque(MakeFlowerTexture(FlowerLook(FlowerColour::kPalePink, FlowerForm::kCherry), 128));
  const Opaque deep =
      MeanOpaque(MakeFlowerTexture(FlowerLook(FlowerColour::kDeepPink, FlowerForm::kCherry), 128));
  const Opaque magenta =
      MeanOpaque(MakeFlowerTexture(FlowerLook(FlowerColour::kMagenta, FlowerForm::kAzalea), 128));
  const Opaque red =
      MeanOpaque(MakeFlowerTexture(FlowerLook(FlowerColour::kRed, FlowerForm::kAzalea), 128));
  const Opaque white =
      MeanOpaque(MakeFlowerTexture(FlowerLook(FlowerColour::kWhite, FlowerForm::kCherry), 128));
  // Pale pink: light, a little more red than green; deep pink: clearly pinker (lower green).
  EXPECT_GT(pale.g, 170);
  EXPECT_GT(pale.r - pale.g, 15);
  EXPECT_LT(deep.g, pale.g - 25);
  EXPECT_GT(deep.r - deep.g, pale.r - pale.g + 20);
  // Magenta: red and blue well above green; red: red far above both.
  EXPECT_GT(magenta.r - magenta.g, 80);
  EXPECT_GT(magenta.b - magenta.g, 40);
  EXPECT_GT(red.r - red.g, 100);
  EXPECT_LT(std::abs(red.b - red.g), 30);
  // White: every channel high, nearly grey.
  EXPECT_GT(std::min({white.r, white.g, white.b}), 200);
  EXPECT_LT(std::max({white.r, white.g, white.b}) - std::min({white.r, white.g, white.b}), 30);
}

TEST(SpeciesFlowers, AzaleaTrussIsNotTheCherryUmbel) {
  const Rgba8Image cherry =
      MakeFlowerTexture(FlowerLook(FlowerColour::kMagenta, FlowerForm::kCherry), 256);
  const Rgba8Image azalea =
      MakeFlowerTexture(FlowerLook(FlowerColour::kMagenta, FlowerForm::kAzalea), 256);
  EXPECT_NE(cherry.pixels, azalea.pixels);
  // Both fill about half the card (three large flowers against seven small ones).
  EXPECT_GT(MeanOpaque(azalea).share, 0.35);
  EXPECT_GT(MeanOpaque(cherry).share, 0.35);
  // The spotted upper lobe and the anthers: a share of the opaque pixels far darker than the petal.
  int dark = 0, opaque = 0;
  for (std::size_t i = 0; i + 3 < azalea.pixels.size(); i += 4) {
    if (azalea.pixels[i + 3] < 128) continue;
    ++opaque;
    dark += azalea.pixels[i] < 150 ? 1 : 0;  // the petal's red is 219
  }
  EXPECT_GT(dark, opaque / 50);
  EXPECT_LT(dark, opaque / 3);
}

TEST(SpeciesFlowers, DefaultLookKeepsTheCherryBlossomPixels) {
  // The thesis presets' flowers (the table's defaults) are the same pixels as before the rows.
  EXPECT_EQ(MakeFlowerTexture(TreeLook{}).pixels, MakeBlossomClusterTexture().pixels);
  EXPECT_EQ(ImageDigest(MakeFlowerTexture(TreeLook{})), "48b8b94065b4126f");
}

TEST(SpeciesFlowers, PresetsCarryTheirSpeciesFlowers) {
  auto look = [](const char* name) { return LookFromParams(FindPreset(name)->params); };
  EXPECT_EQ(look("sakura").flower_colour, FlowerColour::kPalePink);
  EXPECT_EQ(look("sakura").flower_form, FlowerForm::kCherry);
  EXPECT_EQ(look("weeping").flower_colour, FlowerColour::kDeepPink);
  EXPECT_EQ(look("weeping").flower_form, FlowerForm::kCherry);
  EXPECT_EQ(look("tsutsuji").flower_colour, FlowerColour::kMagenta);
  EXPECT_EQ(look("tsutsuji").flower_form, FlowerForm::kAzalea);
  EXPECT_TRUE(FindPreset("tsutsuji")->params.GetBool(TreeParam::kTerminalFlowers));
  for (const char* thesis : {"sakura-thesis", "keyaki-thesis", "tsutsuji-thesis"}) {
    EXPECT_EQ(look(thesis).flower_colour, FlowerColour::kPalePink) << thesis;
    EXPECT_EQ(look(thesis).flower_form, FlowerForm::kCherry) << thesis;
    EXPECT_FALSE(FindPreset(thesis)->params.GetBool(TreeParam::kTerminalFlowers)) << thesis;
  }
}

TEST(SpeciesFlowers, TheGlbNamesTheFlowersLook) {
  GrowRequest r = PresetRequest("tsutsuji", 6);
  ASSERT_TRUE(r.params.Set(TreeParam::kSeason, static_cast<int>(Season::kSpring)).ok());
  const TreeMesh mesh = BuildTreeMesh(GrowTree(r));
  ASSERT_GT(mesh.flowers.indices.size(), 0u);
  Result<gltf::Document> doc = TreeGltfDocument(mesh);
  ASSERT_TRUE(doc.ok()) << doc.status().Line();
  bool found = false;
  for (const gltf::Material& m : doc->materials) {
    if (m.name != "flowers") continue;
    found = true;
    EXPECT_EQ(m.extras_json, "{\"flower_colour\":\"magenta\",\"flower_form\":\"azalea\"}");
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace niwa

// How a grown tree is dressed when it is meshed and textured: its leaf shape and the leaves on each
// card, the season, its autumn colour and its flowers' colour and form (the tree table's
// leaf_shape, leaf_spray, season, autumn_colour, flower_colour and flower_form rows). Does not:
// grow anything, build meshes (tree/mesh) or paint textures (tree/tree_textures).
#pragma once

#include <optional>
#include <string_view>

#include "tree/tree_params.h"

namespace niwa {

// The leaf_shape row: the blade drawn on each leaf quad (and the quad's proportions).
enum class LeafShape : int {
  kBroad = 0,    // elliptic blade (sakura, keyaki, tsutsuji)
  kNeedle = 1,   // a fascicle of needles fanning from the base (pine)
  kPalmate = 2,  // seven-lobed palmate blade (Acer palmatum)
  kFan = 3,      // bilobed fan with radial veins (Ginkgo biloba)
};
constexpr int kLeafShapeCount = 4;

// The season row (a view setting: the tree is not regrown).
enum class Season : int {
  kSpring = 0,  // fresh green leaves; a deciduous tree that flowers blossoms on bare wood
  kSummer = 1,  // leaves and flowers as grown (the default)
  kAutumn = 2,  // leaves in the autumn colour, no flowers
  kWinter = 3,  // bare wood (evergreens keep their leaves), no flowers
};
constexpr int kSeasonCount = 4;

// The autumn_colour row: the colour a deciduous tree's leaves turn, or evergreen.
enum class AutumnColour : int {
  kEvergreen = 0,    // keeps green leaves through autumn and winter (pine, tsutsuji)
  kRedOrange = 1,    // Somei-yoshino
  kRed = 2,          // momiji (Acer palmatum)
  kYellow = 3,       // ginkgo
  kOrangeBrown = 4,  // keyaki
};
constexpr int kAutumnColourCount = 5;

// The flower_colour row: the petals' colour (sources in the presets that use them).
enum class FlowerColour : int {
  kPalePink = 0,  // Somei-yoshino: pale pink, fading to white
  kDeepPink = 1,  // beni-shidare (a deep pink shidare-zakura)
  kMagenta = 2,   // Hirado 'Omurasaki', many Kurume azaleas
  kRed = 3,       // Kurume azalea 'Hinode-giri' (crimson)
  kWhite = 4,
};
constexpr int kFlowerColourCount = 5;

// The flower_form row: what the flower card's texture shows.
enum class FlowerForm : int {
  kCherry = 0,  // an umbel of seven flat five-petal blossoms with notched petal tips
  kAzalea = 1,  // a truss of three funnel flowers: five round lobes, spotted upper lobe, stamens
};
constexpr int kFlowerFormCount = 2;

// The leaf_spray row's largest value: leaves painted on one card (a twig with that many leaves).
constexpr int kMaxLeafSpray = 12;

struct TreeLook {
  LeafShape leaf_shape = LeafShape::kBroad;
  Season season = Season::kSummer;
  AutumnColour autumn = AutumnColour::kRedOrange;
  FlowerColour flower_colour = FlowerColour::kPalePink;
  FlowerForm flower_form = FlowerForm::kCherry;
  int leaf_spray = 1;  // the leaf_spray row: leaves painted on each card (1..kMaxLeafSpray)
};

// The look the rows of `params` ask for (values outside the rows' ranges are clamped).
TreeLook LookFromParams(const TreeParams& params);

// Whether leaves are drawn in this look; `has_flowers`: the tree bears flowers this year (a
// flowering deciduous tree shows its blossom before its leaves in spring, as cherries do).
bool ShowsLeaves(const TreeLook& look, bool has_flowers);
// Whether flowers are drawn (spring and summer).
bool ShowsFlowers(const TreeLook& look);

// Width of a leaf quad over its length, per shape: broad 0.5, needle 0.8, palmate 1, fan 1.2.
float LeafQuadAspect(LeafShape shape);
// Length of the card drawn for each leaf, cm: leaf_size (the light model's leaf) times leaf_card
// (the mesh and the hybrid view's cards alike).
float LeafCardLength(const TreeParams& params);

// "broad", "spring", "red", ... (the names in the rows' help and the .glb's extras).
const char* LeafShapeName(LeafShape shape);
const char* SeasonName(Season season);
const char* AutumnColourName(AutumnColour colour);
const char* FlowerColourName(FlowerColour colour);  // "pale-pink", "deep-pink", "magenta", ...
const char* FlowerFormName(FlowerForm form);        // "cherry", "azalea"

// The value of a name above ("winter" -> kWinter); nullopt for another text.
std::optional<Season> ParseSeason(std::string_view name);
std::optional<LeafShape> ParseLeafShape(std::string_view name);

}  // namespace niwa

// The tree's look (leaf shape, season, autumn colour, flower colour and form) from its table rows,
// and what each season shows.
#include "tree/tree_look.h"

#include <algorithm>

namespace niwa {
namespace {

int Clamped(const TreeParams& params, TreeParam id, int count) {
  return std::min(count - 1, std::max(0, params.GetInt(id)));
}

}  // namespace

TreeLook LookFromParams(const TreeParams& params) {
  TreeLook look;
  look.leaf_shape = static_cast<LeafShape>(Clamped(params, TreeParam::kLeafShape, kLeafShapeCount));
  look.season = static_cast<Season>(Clamped(params, TreeParam::kSeason, kSeasonCount));
  look.autumn =
      static_cast<AutumnColour>(Clamped(params, TreeParam::kAutumnColour, kAutumnColourCount));
  look.flower_colour =
      static_cast<FlowerColour>(Clamped(params, TreeParam::kFlowerColour, kFlowerColourCount));
  look.flower_form =
      static_cast<FlowerForm>(Clamped(params, TreeParam::kFlowerForm, kFlowerFormCount));
  look.leaf_spray = std::min(kMaxLeafSpray, std::max(1, params.GetInt(TreeParam::kLeafSpray)));
  return look;
}

bool ShowsLeaves(const TreeLook& look, bool has_flowers) {
  const bool evergreen = look.autumn == AutumnColour::kEvergreen;
  switch (look.season) {
    case Season::kSpring:
      return evergreen || !has_flowers;
    case Season::kWinter:
      return evergreen;
    case Season::kSummer:
    case Season::kAutumn:
    default:
      return true;
  }
}

bool ShowsFlowers(const TreeLook& look) {
  return look.season == Season::kSpring || look.season == Season::kSummer;
}

float LeafCardLength(const TreeParams& params) {
  return static_cast<float>(params.Get(TreeParam::kLeafSize) * params.Get(TreeParam::kLeafCard));
}

float LeafQuadAspect(LeafShape shape) {
  switch (shape) {
    case LeafShape::kNeedle:
      return 0.8f;
    case LeafShape::kPalmate:
      return 1.0f;
    case LeafShape::kFan:
      return 1.2f;
    case LeafShape::kBroad:
    default:
      return 0.5f;
  }
}

const char* LeafShapeName(LeafShape shape) {
  static const char* const kNames[] = {"broad", "needle", "palmate", "fan"};
  return kNames[static_cast<int>(shape)];
}

const char* SeasonName(Season season) {
  static const char* const kNames[] = {"spring", "summer", "autumn", "winter"};
  return kNames[static_cast<int>(season)];
}

const char* AutumnColourName(AutumnColour colour) {
  static const char* const kNames[] = {"evergreen", "red-orange", "red", "yellow", "orange-brown"};
  return kNames[static_cast<int>(colour)];
}

const char* FlowerColourName(FlowerColour colour) {
  static const char* const kNames[] = {"pale-pink", "deep-pink", "magenta", "red", "white"};
  return kNames[static_cast<int>(colour)];
}

const char* FlowerFormName(FlowerForm form) {
  static const char* const kNames[] = {"cherry", "azalea"};
  return kNames[static_cast<int>(form)];
}

std::optional<Season> ParseSeason(std::string_view name) {
  for (int k = 0; k < kSeasonCount; ++k) {
    if (name == SeasonName(static_cast<Season>(k))) return static_cast<Season>(k);
  }
  return std::nullopt;
}

std::optional<LeafShape> ParseLeafShape(std::string_view name) {
  for (int k = 0; k < kLeafShapeCount; ++k) {
    if (name == LeafShapeName(static_cast<LeafShape>(k))) return static_cast<LeafShape>(k);
  }
  return std::nullopt;
}

}  // namespace niwa

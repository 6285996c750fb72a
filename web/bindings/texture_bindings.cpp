// The tree's procedural textures for the page (core/tree/tree_textures.h): the same pixels the .glb
// embeds, so the page's viewer and the exported model look alike. One function, copied out of the
// WASM heap into a fresh Uint8Array (the worker caches and transfers it).
// Does not: keep textures, know GL, or decide the look (TreeSession::lookJson does).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <string>

#include "image_val.h"
#include "tree/tree_look.h"
#include "tree/tree_textures.h"

namespace niwa {
namespace {

int Clamp(int value, int count) { return value < 0 ? 0 : (value >= count ? count - 1 : value); }

// treeTexture(kind, leafShape, season, autumnColour, flowerColour, flowerForm, leafSpray) ->
// {width, height, pixels: Uint8Array RGBA, row 0 = v 0} for kind "bark" | "barkNormal" | "leaf" |
// "flower"; null for another kind.
emscripten::val TreeTexture(const std::string& kind, int leaf_shape, int season, int autumn,
                            int flower_colour, int flower_form, int leaf_spray) {
  TreeLook look;
  look.leaf_shape = static_cast<LeafShape>(Clamp(leaf_shape, kLeafShapeCount));
  look.season = static_cast<Season>(Clamp(season, kSeasonCount));
  look.autumn = static_cast<AutumnColour>(Clamp(autumn, kAutumnColourCount));
  look.flower_colour = static_cast<FlowerColour>(Clamp(flower_colour, kFlowerColourCount));
  look.flower_form = static_cast<FlowerForm>(Clamp(flower_form, kFlowerFormCount));
  look.leaf_spray = 1 + Clamp(leaf_spray - 1, kMaxLeafSpray);
  Rgba8Image image;
  if (kind == "bark") {
    image = MakeBarkTexture();
  } else if (kind == "barkNormal") {
    image = MakeBarkNormalMap();
  } else if (kind == "leaf") {
    image = MakeLeafTexture(look);
  } else if (kind == "flower") {
    image = MakeFlowerTexture(look);
  } else {
    return emscripten::val::null();
  }
  emscripten::val out = ImageToJs(image);
  out.set("digest", ImageDigest(image));
  return out;
}

}  // namespace
}  // namespace niwa

EMSCRIPTEN_BINDINGS(niwa_tree_textures) { emscripten::function("treeTexture", &niwa::TreeTexture); }

// Procedural RGBA8 textures of the tree's exported and drawn materials (bark colour and normal
// map, one leaf blade or a spray of them per leaf shape in its season's colour, flowers per colour
// and form), as
// image::Rgba8Image (row 0 is texture coordinate v = 0, glTF's top-left origin; PNG encoding is
// image/png.h). The .glb (tree/tree_gltf) and the page (web/bindings/texture_bindings.cpp) use the
// same pixels. Deterministic: integer hashing and det:: math only, so the native and WASM builds
// give the same bytes. Why no library: none of the header-only image libraries here (stb) paints;
// this is a few noise and distance functions. Does not: encode files, or texture anything but the
// tree.
#pragma once

#include <string>

#include "image/image.h"
#include "tree/tree_look.h"

namespace niwa {

using image::Rgba8Image;

constexpr int kTreeTextureSize = 512;  // every default texture is 512 × 512

// Bark: brown with vertical furrows, opaque, tileable in u (around the tube) and in v (along it).
// One repeat spans u 0..1 (the whole circumference) and v 0..1 (one metre of wood).
Rgba8Image MakeBarkTexture(int width = kTreeTextureSize, int height = kTreeTextureSize);

// The bark's tangent-space normal map (glTF normalTexture: RGB = (n + 1) / 2, +x along u, +y along
// v, +z out of the wood) from the same furrow relief as MakeBarkTexture; tileable; alpha 255.
Rgba8Image MakeBarkNormalMap(int width = kTreeTextureSize, int height = kTreeTextureSize);

// The drawn leaf card of a look, in leaf lengths (leaf_size × leaf_card): its width across and its
// length from the base (the node it hangs on, at u = 0.5, v = 0) to the far edge. leaf_spray 1:
// the blade's quad (LeafQuadAspect(shape) × 1); n > 1: the box around the spray's twig and leaves.
struct LeafCardSize {
  float width = 0.5f;
  float length = 1.0f;
};
LeafCardSize LeafCardOf(const TreeLook& look);

// The texture of one leaf card. leaf_spray 1: one leaf blade in the leaf quad's UV space, u across
// (midrib at u = 0.5), v from the base (v = 0) to the tip (v = 1), for the quad's proportions
// (LeafQuadAspect). leaf_spray n > 1: a spray on the card LeafCardOf gives, a brown twig from the
// base (u = 0.5, v = 0) with n blades of the same shape, colour and length: alternate along the
// twig (broad; fan, farther apart, as on a ginkgo's long shoot), in opposite pairs on long
// petioles (palmate), or fascicles pointing forward (needle). Alpha 0 outside the silhouettes. The
// colour is the look's: summer green, spring's fresh green, the autumn colour, or an evergreen's
// darker green in autumn and winter.
Rgba8Image MakeLeafTexture(const TreeLook& look, int size = kTreeTextureSize);

// One five-petal cherry blossom around (0.5, 0.5) (notched petal tips at 90°, 162°, ...), with a
// darker centre and stamens; alpha 0 between and outside the petals.
Rgba8Image MakeBlossomTexture(int size = kTreeTextureSize);

// The flower card's texture: seven five-petal blossoms packed in the unit disc (an umbel seen from
// above), so that a flower node reads from a distance; alpha 0 outside the blossoms. The default
// look's flowers (pale pink cherry): MakeFlowerTexture(TreeLook{}, size).
Rgba8Image MakeBlossomClusterTexture(int size = kTreeTextureSize);

// The flower card's texture of a look's flower_colour and flower_form: the cherry umbel above in
// that colour, or (azalea) a truss of three funnel flowers with round lobes, a spotted upper lobe
// and long stamens; alpha 0 outside the flowers.
Rgba8Image MakeFlowerTexture(const TreeLook& look, int size = kTreeTextureSize);

// FNV-1a digest of an image's size and pixels ("%016llx"), for native == WASM checks.
std::string ImageDigest(const Rgba8Image& image);

}  // namespace niwa

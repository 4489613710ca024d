// The brick wall the surface lab is built around, made here: a height field of bevelled bricks in
// running bond with recessed mortar, the tangent-space normal map of exactly that field, and a
// colour map. The normal map is baked for one depth: a height of 1 is `depthPerUv` world units
// above 0 when one unit of UV spans one world unit, which is how the lab's scenes lay it out.
#pragma once
#include "app/scene/scene.h"

namespace shadelab {

struct BrickTextures {
  ImageSource color;   // sRGB
  ImageSource height;  // red channel: 0 mortar floor .. 1 brick faces (white = high)
  ImageSource normal;  // tangent space, OpenGL convention (+Y along +v)
};

BrickTextures makeBrickTextures(int size, float depthPerUv);

// The normal map of any height field stored in `height` (red channel, rows top-down), for a depth
// of `depthPerUv` world units per unit of height when one UV unit spans one world unit.
ImageSource normalMapFromHeight(const ImageSource& height, float depthPerUv);

}  // namespace shadelab

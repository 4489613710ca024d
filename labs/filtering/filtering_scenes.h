// The texture-filtering lab's scenes and the textures it makes for them: a long ground plane seen
// at a grazing angle (every level of minification in one picture), a zone plate (every spatial
// frequency up to the texture's Nyquist limit), a tiny texture blown up to fill the screen
// (magnification), Spot's own texture on Spot, and the sizes that break careless code (NPOT,
// 1 x 1, a plane to the horizon).
#pragma once
#include <vector>

#include "app/scene/scene_catalog.h"

namespace shadelab {

// Procedural images (sRGB, rows top-down), made here.
ImageSource makeTileImage(int size, int tiles);   // black and white tiles, each outlined by a thin red line
ImageSource makeZonePlateImage(glm::ivec2 size);  // cos(pi r^2 / N): frequency rising to Nyquist at the edge
ImageSource makePixelArtImage();                  // a 16 x 16 icon of lines, a ring and dots
ImageSource makeSolidImage(glm::vec4 srgb);       // one texel

std::vector<SceneRecipe> filteringScenes();

}  // namespace shadelab

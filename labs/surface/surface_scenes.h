// The surface-detail lab's scenes: a brick wall (procedural, or LearnOpenGL's bricks2 from the
// shared data), bricks on a sphere (curved tangent frames, a UV seam, two poles), a long brick
// floor for grazing views, and Spot wearing the bricks (UV seams and stretched charts).
#pragma once
#include <vector>

#include "app/scene/scene_catalog.h"

namespace shadelab {

// The depth the procedural normal maps are baked for: a height of 1 is this many world units
// above 0 on a surface where one UV unit spans one world unit. The lab's height scale defaults
// to it, so normal mapping and displacement describe the same wall.
inline constexpr float kBrickDepth = 0.04f;

std::vector<SceneRecipe> surfaceScenes();

}  // namespace shadelab

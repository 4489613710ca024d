// The denoising lab's scenes: the Guided Mesh Normal Filtering pairs (clean + published noisy,
// from ../shared/data when present), a subdivided cube whose six faces are six UV charts (sharp
// edges to keep, seams to crack), and a mesh of everything degenerate for the stress runs.
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "app/scene/scene_catalog.h"

namespace shadelab {

std::vector<SceneRecipe> denoiseScenes();
std::string_view denoiseDefaultScene();  // fandisk-0.3 with the data, else denoise-cube
// The published pairs whose files are not in dataDirectory() (a fresh clone: all of them).
std::vector<std::string> missingDenoisePairs();
// The published noisy twin of a data-set scene. False (error empty) when the scene has none.
bool loadPublishedTwin(const std::string& sceneId, MeshData& twin, std::string& error);

}  // namespace shadelab

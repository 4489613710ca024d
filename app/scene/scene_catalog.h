// Scenes by name: the project's procedural ones, the shared real meshes when the data folder
// is present, or any .gltf/.glb/.obj/.off/.ply path.
#pragma once
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "app/scene/scene.h"

namespace shadelab {

struct SceneEntry {
  std::string id;
  std::string description;
};

// A scene a lab brings with it (a brick wall, a long grazing plane, a denoising benchmark pair):
// listed and built like the project's own, while that lab is the current one.
struct SceneRecipe {
  std::string id;
  std::string description;
  // Fills `out` for `needs` (tessellation, scale and attribute pruning are applied afterwards, as
  // for every scene). Returns "" or a one-line error naming the file or what is missing.
  std::function<std::string(Scene& out, const SceneNeeds& needs)> build;
};

// $SHADELAB_DATA, else ../shared/data beside the source tree, else data/ in it (where
// tools/get_data.sh puts the files); empty if none exists.
std::filesystem::path dataDirectory();
// The project's scenes whose files are not in dataDirectory(), and the one command that gets them.
std::vector<std::string> missingDataScenes();
inline constexpr const char* kGetDataCommand = "tools/get_data.sh";

// The current lab's scenes first, then the project's.
std::vector<SceneEntry> listScenes(std::span<const SceneRecipe> labScenes = {});
// Builds `idOrPath` with exactly what `needs` asks for. Returns "" or a one-line error that
// lists the valid scene names.
std::string buildScene(const std::string& idOrPath, const SceneNeeds& needs, Scene& out,
                       std::span<const SceneRecipe> labScenes = {});

}  // namespace shadelab

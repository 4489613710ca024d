// Scenes by name: the project's procedural ones, the shared real meshes when the data folder
// is present, or any .gltf/.glb/.obj/.off path.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace shadelab {

struct SceneEntry {
  std::string id;
  std::string description;
};

// ../shared/data beside the source tree, or $SHADELAB_DATA; empty if neither exists.
std::filesystem::path dataDirectory();

std::vector<SceneEntry> listScenes();
// Builds `idOrPath` with exactly what `needs` asks for. Returns "" or a one-line error that
// lists the valid scene names.
std::string buildScene(const std::string& idOrPath, const SceneNeeds& needs, Scene& out);

}  // namespace shadelab

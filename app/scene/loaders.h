// Scene files: glTF 2.0 (.gltf/.glb), Wavefront OBJ (+MTL textures), OFF and PLY.
// Each returns "" or a one-line error that names the file and what went wrong. Images are
// recorded, not decoded: decoding waits until a lab's needs ask for textures.
#pragma once
#include <filesystem>
#include <string>

#include "app/scene/scene.h"

namespace shadelab {

std::string loadGltf(const std::filesystem::path& file, Scene& scene);
std::string loadObj(const std::filesystem::path& file, Scene& scene);
std::string loadOff(const std::filesystem::path& file, Scene& scene);
std::string loadPly(const std::filesystem::path& file, Scene& scene);  // ASCII or binary

// By extension; the error lists the valid ones for anything else.
std::string loadSceneFile(const std::filesystem::path& file, Scene& scene);

}  // namespace shadelab

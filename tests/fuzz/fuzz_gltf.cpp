// glTF 2.0, JSON (.gltf) or binary (.glb, chosen by its "glTF" magic), through the scene loader
// exactly as a dropped file is loaded. External URIs resolve beside the scratch file.
#include "app/scene/loaders.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes = shadelab::fuzz::asText(data, size);
  const bool binary = bytes.substr(0, 4) == "glTF";
  const auto file = shadelab::fuzz::writeScratch(binary ? "model.glb" : "model.gltf", bytes);
  shadelab::Scene scene;
  (void)shadelab::loadSceneFile(file, scene);
  return 0;
}

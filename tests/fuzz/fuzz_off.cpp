// OFF meshes (the denoising benchmarks' format), as the scene loader reads a user's file.
#include "app/scene/loaders.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = shadelab::fuzz::writeScratch("mesh.off", shadelab::fuzz::asText(data, size));
  shadelab::Scene scene;
  (void)shadelab::loadSceneFile(file, scene);
  return 0;
}

// Wavefront OBJ with its MTL library: the input is the OBJ, then (after a line "#--mtl--") the
// MTL it may name as "mtllib model.mtl".
#include "app/scene/loaders.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto [obj, mtl] = shadelab::fuzz::splitAt(shadelab::fuzz::asText(data, size), "#--mtl--\n");
  shadelab::fuzz::writeScratch("model.mtl", mtl);
  const auto file = shadelab::fuzz::writeScratch("model.obj", obj);
  shadelab::Scene scene;
  (void)shadelab::loadSceneFile(file, scene);
  return 0;
}

// Preset JSON (saved beside every screenshot, applied by --preset and by a dropped .json): the
// file is parsed and checked, then its params are set on a fresh lab of the kind it names and its
// camera is parsed, which is everything applying it does short of drawing.
#include "app/host/preset.h"
#include "app/lab/lab.h"
#include "app/scene/camera.h"
#include "fuzz_files.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const auto file = shadelab::fuzz::writeScratch("preset.json", shadelab::fuzz::asText(data, size));
  shadelab::Preset preset;
  if (!shadelab::readPreset(file, preset).empty()) return 0;
  auto lab = shadelab::makeLab(preset.lab.value_or("shading"));
  if (!lab) return 0;
  for (auto& [key, value] : preset.params) {
    shadelab::SetFromString set(lab->id(), key, value);
    lab->visitParams(set);
    (void)set.result();
  }
  shadelab::OrbitCamera camera;
  if (preset.camera) (void)camera.parse(*preset.camera);
  return 0;
}

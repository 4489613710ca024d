#include "ui/platform.h"

namespace shadelab {

void runMainLoop(std::function<bool()> frame) {
  while (frame()) {
  }
}

const char* imguiGlslVersion() { return "#version 330 core"; }

}  // namespace shadelab

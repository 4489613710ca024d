#include "ui/platform.h"

#include <emscripten.h>

#include <memory>

namespace shadelab {

namespace {

void callFrame(void* arg) {
  auto* frame = static_cast<std::function<bool()>*>(arg);
  if (!(*frame)()) emscripten_cancel_main_loop();
}

}  // namespace

void runMainLoop(std::function<bool()> frame) {
  // The page owns the loop from here on: the function lives as long as the page.
  auto* kept = new std::function<bool()>(std::move(frame));
  emscripten_set_main_loop_arg(callFrame, kept, 0, true);
}

const char* imguiGlslVersion() { return "#version 300 es"; }

}  // namespace shadelab

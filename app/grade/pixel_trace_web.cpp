// The page's pixel trace: WebGL 2 has no shader storage buffers (grade/pixel_trace.h).
#include "app/grade/pixel_trace.h"

namespace shadelab {

namespace {
constexpr const char* kNone = "WebGL 2 has no shader storage buffers, which the pixel trace writes into";
}

bool pixelTraceSupported(std::string& why) {
  why = kNone;
  return false;
}

std::string drawIntoStorageBuffer(unsigned, std::vector<float>&, const std::function<void()>&) { return kNone; }

}  // namespace shadelab

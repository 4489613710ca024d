// Where GL commands go. Labs never see this: they draw into offscreen render targets, and a
// front end either shows the target in a window (GLFW) or reads it back (OSMesa, EGL).
#pragma once
#include <memory>
#include <string>
#include <string_view>

namespace shadelab {

class GlContext {
 public:
  virtual ~GlContext() = default;
  virtual void makeCurrent() = 0;
  // "OSMesa: llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"
  std::string describe() const;
};

// Headless back ends by name: "osmesa" (software, everywhere) or "egl" (surfaceless Mesa, or an
// NVIDIA device on a GPU server). Returns null and sets `error` to one line on failure.
std::unique_ptr<GlContext> createHeadlessContext(std::string_view backend, std::string& error);
inline constexpr std::string_view kHeadlessBackends = "osmesa, egl";

// Per back end, so their system headers never meet the loader's.
std::unique_ptr<GlContext> createOsMesaContext(std::string& error);
std::unique_ptr<GlContext> createEglContext(std::string& error);

}  // namespace shadelab

// OSMesa: Mesa's off-screen software context. We render into FBOs, so the context's own
// colour buffer is a token 16x16 one that nothing reads.
#include <GL/osmesa.h>

#include <vector>

#include "app/context/gl_context.h"
#include "app/gl/load_gl.h"

namespace shadelab {
namespace {

ShlGlProc osmesaProc(const char* name) { return reinterpret_cast<ShlGlProc>(OSMesaGetProcAddress(name)); }

class OsMesaContext final : public GlContext {
 public:
  explicit OsMesaContext(OSMesaContext ctx) : ctx_(ctx), buffer_(16 * 16 * 4) {}
  ~OsMesaContext() override { OSMesaDestroyContext(ctx_); }
  void makeCurrent() override { OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, 16, 16); }

 private:
  OSMesaContext ctx_;
  std::vector<unsigned char> buffer_;
};

}  // namespace

std::unique_ptr<GlContext> createOsMesaContext(std::string& error) {
  OSMesaContext ctx = nullptr;
  for (const gl::Version v : gl::kContextVersions) {
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           v.major,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           v.minor,
                           0};
    if ((ctx = OSMesaCreateContextAttribs(attribs, nullptr))) break;
  }
  if (!ctx) {
    error = "osmesa: could not create an OpenGL 4.1 or 3.3 core context (is libosmesa6 installed?)";
    return nullptr;
  }
  auto context = std::make_unique<OsMesaContext>(ctx);
  context->makeCurrent();
  const char* missing = "";
  if (!gl::loadFunctions(osmesaProc, &missing)) {
    error = std::string("osmesa: the context lacks core function ") + missing;
    return nullptr;
  }
  return context;
}

}  // namespace shadelab

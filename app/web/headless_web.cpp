// The page has one context, the browser's WebGL2 canvas; headless back ends are desktop-only.
#include "app/context/gl_context.h"

namespace shadelab {

std::unique_ptr<GlContext> createOsMesaContext(std::string& error) {
  error = "osmesa: the page draws with the browser's WebGL2; headless rendering is desktop-only";
  return nullptr;
}

std::unique_ptr<GlContext> createEglContext(std::string& error) {
  error = "egl: the page draws with the browser's WebGL2; headless rendering is desktop-only";
  return nullptr;
}

}  // namespace shadelab

// The loader's entry point, declared without any GL header: for the files that include
// <GL/osmesa.h> or <EGL/egl.h>, whose GL declarations clash with the core-profile loader's.
#pragma once

using ShlGlProc = void (*)(void);
using ShlGetProcAddress = ShlGlProc (*)(const char*);

namespace gl {

// Fills the loader through the context's getProcAddress. Returns false (with the name of the
// first missing function in `missing`) when the context lacks a core function we rely on.
bool loadFunctions(ShlGetProcAddress getProc, const char** missing = nullptr);

// The core versions every context asks for, best first: 4.1 is what the surface and filtering
// labs' shaders are written in (tessellation, textureQueryLod) and the loader's ceiling; where a
// driver offers only 3.3, the shading and shadows labs run in full and the others report their
// shaders' errors. Tests run under both (tests/CMakeLists.txt: the gl_version_* tests).
struct Version {
  int major, minor;
};
inline constexpr Version kContextVersions[] = {{4, 1}, {3, 3}};

}  // namespace gl

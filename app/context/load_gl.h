// The loader's entry point, declared without any GL header: for the files that include
// <GL/osmesa.h> or <EGL/egl.h>, whose GL declarations clash with the core-profile loader's.
#pragma once

using ShlGlProc = void (*)(void);
using ShlGetProcAddress = ShlGlProc (*)(const char*);

namespace gl {
bool loadFunctions(ShlGetProcAddress getProc, const char** missing);
}

// The one include for OpenGL in ShadeLab: the generated core-profile loader plus the few
// extension tokens the labs use. Raw GL calls belong in app/gl/ and in a lab's render().
#pragma once
#include <string>

#include "app/gl/load_gl.h"
#include "gl_loader.h"

#ifndef GL_TEXTURE_MAX_ANISOTROPY
#define GL_TEXTURE_MAX_ANISOTROPY 0x84FE  // ARB_texture_filter_anisotropic (core in 4.6)
#define GL_MAX_TEXTURE_MAX_ANISOTROPY 0x84FF
#endif

namespace gl {

// The current context draws in software (llvmpipe, softpipe, SwiftShader): fragment work costs
// 10-50x a GPU's, so timers and the choice of truth tracer differ.
bool softwareRenderer();
// Whether GL_RENDERER names `name` ("llvmpipe"): for a driver's known behaviour.
bool rendererIs(const char* name);

// An OpenGL ES or WebGL context (the page's): what differs there is asked through the functions below.
bool esContext();

// Geometry shaders (core in 3.2): OpenGL ES 3.0 and WebGL2 have none, so a lab draws what it would
// draw with one in several passes, or says the option needs one.
bool hasGeometryShaders();
// GL_CLAMP_TO_BORDER and a border colour: not in OpenGL ES 3.0 and WebGL2 (clamp to edge there).
bool hasBorderColor();
// 16-bit normalized textures (GL_R16): not in OpenGL ES 3.0 and WebGL2.
bool hasNorm16Textures();

// Tessellation stages (core in 4.0): a 3.3 context has none, so labs check before using them.
bool hasTessellation();

const char* errorString(GLenum error);  // "GL_INVALID_ENUM", ...
// Drains glGetError; returns "" or a comma-separated list such as "GL_INVALID_ENUM".
std::string drainErrors();

}  // namespace gl

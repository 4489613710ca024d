// The one include for OpenGL in ShadeLab: the generated core-profile loader plus the few
// extension tokens the labs use. Raw GL calls belong in app/gl/ and in a lab's render().
#pragma once
#include <string>

#include "context/load_gl.h"
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

// llvmpipe (Mesa 22.3) keeps textures alive after they and their framebuffers are deleted: the
// one last cleared through a framebuffer, and the layers of the one whose mipmaps were generated
// last, until another texture takes its place. A lab that leaves with a 1 GB shadow map cleared
// last, or 360 MB of mipmapped moment maps, would hold that memory while the next lab runs. This
// clears a 512^2 texture through a framebuffer of its own and generates the mipmaps of a 512^2
// array of eight layers (both deleted again, both one byte a texel), which moves those references
// onto them (the driver then holds about 3 MB of them). Smaller ones did not always reach every
// rasteriser thread: at 128^2 half the runs kept the old 360 MB. It also holds the textures the
// last draw sampled, unit by unit, so on a desktop context one pixel is drawn sampling a 1x1
// stand-in on each of sixteen units (a point light's fill map on units 4 and 5 kept 256 MB). The
// host calls it when a lab is torn down. Leaves framebuffer 0 and no texture bound on the active
// unit.
void releaseDriverHeldTextures();

}  // namespace gl

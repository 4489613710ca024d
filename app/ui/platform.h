// What differs between the desktop window and the browser page: platform_desktop.cpp and
// platform_web.cpp, one of which is built (CMakeLists.txt, cmake/web.cmake).
#pragma once
#include <functional>

namespace shadelab {

// Calls `frame` once a display refresh until it returns false. The desktop loops here (frames
// paced by the swap); the browser hands it to the page's animation frames and returns at once,
// so `frame` must own everything it uses.
void runMainLoop(std::function<bool()> frame);

// The #version line Dear ImGui's OpenGL backend writes into its shaders.
const char* imguiGlslVersion();

}  // namespace shadelab

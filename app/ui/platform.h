// What differs between the desktop window and the browser page: platform_desktop.cpp and
// platform_web.cpp, one of which is built (CMakeLists.txt, cmake/web.cmake).
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "app/gl/load_gl.h"

struct GLFWwindow;

namespace shadelab {

// Calls `frame` once a display refresh until it returns false. The desktop loops here (frames
// paced by the swap); the browser hands it to the page's animation frames and returns at once,
// so `frame` must own everything it uses.
void runMainLoop(std::function<bool()> frame);

// Waits up to `seconds` for a window event (input, a resize, an expose) and handles it; the page,
// whose animation frames pace it, only handles what is pending.
void waitForEvents(double seconds);

// A file the user asked to save (a screenshot, its preset): on the desktop it is already where
// they will look; the page hands it to the browser as a download.
void offerDownload(const std::string& path);

// Puts a link to the frame on the clipboard (`fragment`: what follows '#'), and returns the link
// as the user will paste it: the page's own address in the browser; "index.html#..." on the
// desktop, for the course's copy of the page.
std::string copyLink(const std::string& fragment);

// After the in-app editor saved a file into the student's folder: the page copies the folder into
// the browser's storage (it survives a reload); on the desktop the file is already on disk.
void persistStudentFiles();

// The exercise open in the section (`id`, "" for none), its statement (Markdown) and the last
// Check's lines ("" before one): the page writes them into its document beside the canvas
// (web/exercise.js), as text; the desktop's window shows them in the section only.
void showExerciseText(const std::string& id, const std::string& statement, const std::string& checkLines);

// What to tell a user about the data scenes that are not here (real meshes fetched by the
// desktop's tools/get_data.sh): how to fetch them, or that the page does not carry them.
const char* missingDataAdvice();

// Where the GL loader finds each function of the window's context: GLFW's on the desktop; in the
// page, WebGL2's own functions before WebGL1's extensions of the same name (glGenQueries is core in
// WebGL2, not EXT_disjoint_timer_query's).
ShlGetProcAddress glProcLoader();

// After the window's context is current: the browser's WebGL2 extensions the labs draw with (float
// render targets and their blending, float filtering, anisotropy, timer queries) are switched on;
// nothing to do on the desktop.
void enableContextFeatures();

// The page's canvas fills the browser's window and follows it when it is resized (the layout
// follows the framebuffer every frame); the desktop's window is the user's to size.
void followPageSize(GLFWwindow* window);

// Course folders the page opened on its own since the last call: zips dropped on it, unpacked by
// web/course.js (a folder, or the one-line problem that kept it from opening). Never any on the
// desktop, where a dropped course folder arrives as any other drop.
struct OpenedCourse {
  std::string folder, problem;
};
std::vector<OpenedCourse> takeOpenedCourses();

// The #version line Dear ImGui's OpenGL backend writes into its shaders.
const char* imguiGlslVersion();

// The monitor's content scale (2 on a high-DPI screen), for text as large as on any other; 1 in the
// page, whose canvas is laid out in CSS pixels.
float contentScale(GLFWwindow* window);

}  // namespace shadelab

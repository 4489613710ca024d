#include "app/ui/platform.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <utility>

#include <GLFW/glfw3.h>

#include "app/shader/preprocessor.h"
#include "app/ui/window_events.h"

extern "C" void* emscripten_webgl1_get_proc_address(const char* name);  // emscripten's system/lib/gl
extern "C" void* emscripten_webgl2_get_proc_address(const char* name);

namespace shadelab {

namespace {

void callFrame(void* arg) {
  auto* frame = static_cast<std::function<bool()>*>(arg);
  try {
    if (!(*frame)()) emscripten_cancel_main_loop();
  } catch (const std::exception& e) {  // what the desktop's main() would print: the page shows it
    std::fprintf(stderr, "shadelab: %s\n", e.what());
    EM_ASM({ Module.onAbort(UTF8ToString($0)); }, e.what());
    emscripten_cancel_main_loop();
  }
  EM_ASM(Module.shadelabFrames = (Module.shadelabFrames || 0) + 1);  // the page's tests wait on it
}

ShlGlProc webglProc(const char* name) {
  if (void* f = emscripten_webgl2_get_proc_address(name)) return reinterpret_cast<ShlGlProc>(f);
  return reinterpret_cast<ShlGlProc>(emscripten_webgl1_get_proc_address(name));
}

}  // namespace

// JavaScript inside, which clang-format would take for C++:
// clang-format off
std::string copyLink(const std::string& fragment) {
  const std::string link =
      std::string(emscripten_run_script_string("location.origin + location.pathname")) + "#" + fragment;
  // The address bar shows it too, so that reloading the page keeps the frame.
  EM_ASM(
      {
        const url = UTF8ToString($0);
        history.replaceState(null, '', url);
        if (navigator.clipboard) navigator.clipboard.writeText(url).catch(() => {});
      },
      link.c_str());
  return link;
}
// clang-format on

// JavaScript inside, which clang-format would take for C++:
// clang-format off
void persistStudentFiles() {
  EM_ASM({
    FS.syncfs(false, (err) => {
      if (err) console.warn("shadelab: your shaders could not be kept in the browser's storage: " + err);
    });
  });
}
// clang-format on

namespace {
std::vector<OpenedCourse>& openedCourses() {
  static std::vector<OpenedCourse> opened;
  return opened;
}
}  // namespace

std::vector<OpenedCourse> takeOpenedCourses() { return std::exchange(openedCourses(), {}); }

const char* missingDataAdvice() {
  return "The page does not carry them (the desktop build fetches them with tools/get_data.sh); drop a mesh file "
         "of your own on the page instead.";
}

void waitForEvents(double) { glfwPollEvents(); }

// JavaScript inside, which clang-format would take for C++:
// clang-format off
void offerDownload(const std::string& path) {
  // The file's bytes from the page's file system, as a Blob the browser saves under its name.
  // Module.shadelabSaved lists what was offered (the page's tests read the files back).
  EM_ASM(
      {
        const path = UTF8ToString($0);
        const bytes = FS.readFile(path);
        const type = path.endsWith('.png') ? 'image/png'
                   : path.endsWith('.json') ? 'application/json' : 'application/octet-stream';
        const url = URL.createObjectURL(new Blob([bytes], {type : type}));
        const a = document.createElement('a');
        a.href = url;
        a.download = path.substring(path.lastIndexOf('/') + 1);
        document.body.appendChild(a);
        a.click();
        a.remove();
        setTimeout(() => URL.revokeObjectURL(url), 10000);
        Module.shadelabSaved = (Module.shadelabSaved || []).concat([path]);
      },
      path.c_str());
}
// clang-format on

ShlGetProcAddress glProcLoader() { return webglProc; }

void runMainLoop(std::function<bool()> frame) {
  // The page owns the loop from here on: the function lives as long as the page.
  auto* kept = new std::function<bool()>(std::move(frame));
  emscripten_set_main_loop_arg(callFrame, kept, 0, true);
}

void enableContextFeatures() {
  setGlslDialect(GlslDialect::Es300);
  const EMSCRIPTEN_WEBGL_CONTEXT_HANDLE context = emscripten_webgl_get_current_context();
  for (const char* name : {"EXT_color_buffer_float", "EXT_float_blend", "OES_texture_float_linear",
                           "EXT_texture_filter_anisotropic", "EXT_disjoint_timer_query_webgl2"})
    if (!emscripten_webgl_enable_extension(context, name))
      std::fprintf(stderr, "shadelab: the browser has no %s\n", name);
}

void showExerciseText(const std::string& id, const std::string& statement, const std::string& checkLines) {
  // A page without web/exercise.js (a site copied without it) keeps the text in the canvas only.
  EM_ASM(
      {
        if (typeof ShadeLabExercise == 'object')
          ShadeLabExercise.show(UTF8ToString($0), UTF8ToString($1), UTF8ToString($2));
      },
      id.c_str(), statement.c_str(), checkLines.c_str());
}

void followPageSize(GLFWwindow* window) {
  const auto fit = [](int, const EmscriptenUiEvent*, void* w) -> EM_BOOL {
    // The canvas takes the width the exercise's text (web/exercise.js) leaves it.
    const int width = EM_ASM_INT(const text = document.getElementById('exercise');
                                 return window.innerWidth - (text ? text.offsetWidth : 0)),
              height = EM_ASM_INT(return window.innerHeight);
    glfwSetWindowSize(static_cast<GLFWwindow*>(w), std::max(width, 240), std::max(height, 240));
    return EM_FALSE;
  };
  fit(0, nullptr, window);
  emscripten_set_resize_callback(EMSCRIPTEN_EVENT_TARGET_WINDOW, window, EM_FALSE, fit);
}

const char* imguiGlslVersion() { return "#version 300 es"; }

float contentScale(GLFWwindow*) { return 1.0f; }

}  // namespace shadelab

// web/course.js, once a dropped zip is unpacked (on the page's main thread, between frames).
extern "C" EMSCRIPTEN_KEEPALIVE void shadelab_course_opened(const char* folder, const char* problem) {
  shadelab::openedCourses().push_back({folder, problem});
  shadelab::countWindowEvent(nullptr);  // a window that waits for events draws again
}

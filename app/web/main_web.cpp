// The page's entry point: the window front end, configured by the link that opened it.
//   index.html#lab=shadows&scene=learnopengl&shadows.filter=pcss&camera=yaw=30,pitch=20
// lab, scene and camera as the desktop's --lab, --scene and --camera; every "lab.key=value" a --set;
// "measure" presses Measure once the first frames are timed (--measure); "exercise=shading/blinn-phong"
// opens the Exercises section on it and "check" presses its Check; "course=week3.zip" adds a course zip of the
// same site (web/course.js); "builtin" leaves the student's
// folder out of the search (the page's reload after a shader lost the WebGL context). What the link gets wrong is
// shown in the page's Messages panel.
#include <emscripten.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli/options.h"
#include "app/grade/rubric.h"
#include "app/host/share_link.h"
#include "app/ui/window_app.h"

int main() {
  using namespace shadelab;
  const OpenedLink link = openLink(emscripten_run_script_string("location.hash.slice(1)"));
  // The student's folder: the page's own, kept in the browser's storage (web/index.html mounts it
  // before main runs); the in-page editor saves there and it is searched before the lab's shaders.
  // With "builtin" (the page's reload after a shader lost the WebGL context) the folder is not
  // searched, only edited: the student fixes the file, then opens the page without "builtin".
  std::vector<std::string> args{"shadelab"};
  if (!link.builtin) args.insert(args.end(), {"--shaders", "/student"});
  // A course folder built into the site (./web.sh --exercises DIR): listed before the built-in exercises;
  // the link's course zip, unpacked by the page before main (web/course.js), before that.
  std::string problems;
  WindowOptions window;
  if (!link.course.empty()) {
    const std::string folder = emscripten_run_script_string("(Module.shadelabLinkCourse || {}).folder || ''");
    if (!folder.empty()) {
      args.insert(args.end(), {"--exercises", folder});
      window.linkCourse = {link.course, folder};
    } else
      problems = emscripten_run_script_string("(Module.shadelabLinkCourse || {}).problem || 'the course did not open'");
  }
  std::error_code ec;
  if (std::filesystem::is_directory("/shadelab/course", ec)) {
    args.insert(args.end(), {"--exercises", "/shadelab/course"});
    window.siteCourse = "/shadelab/course";
  }
  for (auto [key, value] : {std::pair{"--lab", &link.lab},
                            {"--scene", &link.scene},
                            {"--camera", &link.camera},
                            {"--exercise", &link.exercise}})
    if (!value->empty()) args.insert(args.end(), {key, *value});
  for (auto& s : link.sets) args.insert(args.end(), {"--set", s});
  if (link.measure) args.push_back("--measure");
  for (auto& p : link.problems) problems += (problems.empty() ? "" : "\n") + p;
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  Options options;
  if (auto err = parseOptions(int(argv.size()), argv.data(), options); !err.empty())
    problems += (problems.empty() ? "" : "\n") + ("the link: " + err);
  setCourseFolders({options.exerciseDirs.begin(), options.exerciseDirs.end()});
  window.message = problems;
  window.check = link.check;
  window.present = link.present;
  window.exitAfterFrames = link.frames;
  window.cycleLabs = link.cycle;
  if (link.builtin) {
    window.editFolder = "/student";
    window.message += std::string(window.message.empty() ? "" : "\n") +
                      "your folder /student is not searched (the link's 'builtin', after the WebGL context was lost): "
                      "the lab's own shaders draw; fix your file in the editor, then open the page without 'builtin'";
  }
  try {
    return runWindow(options, window);
  } catch (const std::exception& e) {  // the page shows it (web/index.html) instead of a bare abort
    std::fprintf(stderr, "shadelab: %s\n", e.what());
    EM_ASM({ Module.onAbort(UTF8ToString($0)); }, e.what());
    return 1;
  }
}

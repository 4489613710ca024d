// The page's entry point: the window front end, configured by the link that opened it.
//   index.html#lab=shadows&scene=learnopengl&shadows.filter=pcss&camera=yaw=30,pitch=20
// lab, scene and camera as the desktop's --lab, --scene and --camera; every "lab.key=value" a --set;
// "measure" presses Measure once the first frames are timed (--measure). What the link gets wrong is
// shown in the page's Messages panel.
#include <emscripten.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli/options.h"
#include "ui/window_app.h"

int main() {
  using namespace shadelab;
  const std::string hash = emscripten_run_script_string(
      "location.hash.slice(1).split('&').filter(s => s.length > 0)"
      ".map(s => decodeURIComponent(s.replace(/\\+/g, ' '))).join('\\n')");
  // The student's folder: the page's own, kept in the browser's storage (web/index.html mounts it
  // before main runs); the in-page editor saves there and it is searched before the lab's shaders.
  std::vector<std::string> args{"shadelab", "--shaders", "/student"};
  std::string problems;
  const auto problem = [&](const std::string& p) { problems += (problems.empty() ? "" : "\n") + p; };
  std::istringstream lines(hash);
  for (std::string item; std::getline(lines, item);) {
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (key == "lab" || key == "scene" || key == "camera") {
      args.insert(args.end(), {"--" + key, value});
    } else if (key == "measure") {
      args.push_back("--measure");
    } else if (key.find('.') != std::string::npos) {
      args.insert(args.end(), {"--set", item});
    } else {
      problem("the link's key '" + key + "' is unknown (valid: lab, scene, camera, measure, LAB.KEY)");
    }
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  Options options;
  if (auto err = parseOptions(int(argv.size()), argv.data(), options); !err.empty()) problem("the link: " + err);
  WindowOptions window;
  window.message = problems;
  try {
    return runWindow(options, window);
  } catch (const std::exception& e) {  // the page shows it (web/index.html) instead of a bare abort
    std::fprintf(stderr, "shadelab: %s\n", e.what());
    EM_ASM({ Module.onAbort(UTF8ToString($0)); }, e.what());
    return 1;
  }
}

// The page's entry point: the window front end, configured by the link that opened it.
//   index.html#lab=shadows&scene=learnopengl&shadows.filter=pcss&camera=yaw=30,pitch=20
// lab, scene and camera as the desktop's --lab, --scene and --camera; every "lab.key=value" a --set.
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
  std::vector<std::string> args{"shadelab"};
  std::istringstream lines(hash);
  for (std::string item; std::getline(lines, item);) {
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq);
    const std::string value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (key == "lab" || key == "scene" || key == "camera") {
      args.insert(args.end(), {"--" + key, value});
    } else if (key.find('.') != std::string::npos) {
      args.insert(args.end(), {"--set", item});
    } else {
      std::fprintf(stderr, "shadelab: the link's key '%s' is unknown (valid: lab, scene, camera, LAB.KEY)\n",
                   key.c_str());
    }
  }
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  Options options;
  if (auto err = parseOptions(int(argv.size()), argv.data(), options); !err.empty())
    std::fprintf(stderr, "shadelab: %s\n", err.c_str());
  try {
    return runWindow(options, WindowOptions{});
  } catch (const std::exception& e) {  // the page shows it (web/index.html) instead of a bare abort
    std::fprintf(stderr, "shadelab: %s\n", e.what());
    EM_ASM({ Module.onAbort(UTF8ToString($0)); }, e.what());
    return 1;
  }
}

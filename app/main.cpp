// shadelab: the window by default, or a headless subcommand (see --help).
#include <cstdio>
#include <cstdlib>

#include "cli/commands.h"
#include "ui/window_app.h"

int main(int argc, char** argv) {
  using namespace shadelab;
  // Window-only switches for tests and demos, taken out before the shared parser sees them.
  WindowOptions window;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--exit-after" && i + 1 < argc) window.exitAfterFrames = std::atoi(argv[++i]);
    else if (a == "--screenshot" && i + 1 < argc) window.screenshot = argv[++i];
    else if (a == "--cycle-labs") window.cycleLabs = true;
    else args.push_back(argv[i]);
  }
  Options o;
  if (auto err = parseOptions(int(args.size()), args.data(), o); !err.empty()) {
    std::fprintf(stderr, "shadelab: %s\n", err.c_str());
    return 1;
  }
  if (o.help) {
    std::printf("%s", usage().c_str());
    return 0;
  }
  if (o.command == "render") return runRender(o);
  if (o.command == "sweep") return runSweep(o);
  if (o.command == "stress") return runStress(o);
  if (o.command == "list") return runList(o);
  if (o.command == "check-shaders") return runCheckShaders(o);

  const int rc = runWindow(o, window);
  if (rc != 2) return rc;
  // No display: say so, and do the next most useful thing.
  std::fprintf(stderr, "shadelab: no display to open a window on (DISPLAY=%s); rendering headless instead\n",
               std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "unset");
  if (o.out.empty()) {
    std::filesystem::create_directories("out");
    o.out = "out/shadelab.png";
  }
  return runRender(o);
}

// shadelab: the window by default, or a headless subcommand (see --help).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "app/cli/commands.h"
#include "app/cli/options.h"
#include "app/grade/rubric.h"
#include "app/util/process_memory.h"
#ifdef SHADELAB_HAS_WINDOW
#include "app/ui/window_app.h"
#endif

namespace {

int run(int argc, char** argv) {
  using namespace shadelab;
  std::vector<char*> args;
#ifdef SHADELAB_HAS_WINDOW
  // Window-only switches for tests and demos, taken out before the shared parser sees them.
  WindowOptions window;
  for (int i = 0; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--exit-after" && i + 1 < argc)
      window.exitAfterFrames = std::atoi(argv[++i]);
    else if (a == "--screenshot" && i + 1 < argc)
      window.screenshot = argv[++i];
    else if (a == "--cycle-labs")
      window.cycleLabs = true;
    else if (a == "--auto-measure")
      window.autoMeasure = true;
    else if (a == "--soak" && i + 1 < argc)
      window.soakMinutes = std::atof(argv[++i]);
    else if (a == "--soak-seed" && i + 1 < argc)
      window.soakSeed = unsigned(std::atol(argv[++i]));
    else if (a == "--present")
      window.present = true;
    else if (a == "--check")
      window.check = true;
    else if (a == "--inspect" && i + 1 < argc) {
      if (!parsePixel(argv[++i], window.inspect)) {
        std::fprintf(stderr, "shadelab: --inspect: '%s' is not X,Y with X, Y >= 0 (a pixel of the viewport)\n",
                     argv[i]);
        return 1;
      }
    } else if (a == "--window-size" && i + 1 < argc) {
      if (auto err = parseSize("--window-size", argv[++i], window.size, 240); !err.empty()) {
        std::fprintf(stderr, "shadelab: %s\n", err.c_str());
        return 1;
      }
    } else if (a == "--ui-scale" && i + 1 < argc) {
      const std::string text = argv[++i];
      char* end = nullptr;
      window.uiScale = std::strtof(text.c_str(), &end);
      if (end == text.c_str() || *end != '\0' || !(window.uiScale >= 0.5f && window.uiScale <= 4.0f)) {
        std::fprintf(stderr, "shadelab: --ui-scale: invalid value '%s' (valid: a number in [0.5, 4])\n", text.c_str());
        return 1;
      }
    } else
      args.push_back(argv[i]);
  }
#else
  args.assign(argv, argv + argc);
#endif
  Options o;
  if (auto err = parseOptions(int(args.size()), args.data(), o); !err.empty()) {
    std::fprintf(stderr, "shadelab: %s\n", err.c_str());
    return o.command == "grade" ? 2 : 1;  // grade's 1 means "below the pass mark"; 2 is "could not grade"
  }
  if (o.help) {
    std::printf("%s", usage().c_str());
    return 0;
  }
  setCourseFolders({o.exerciseDirs.begin(), o.exerciseDirs.end()});
  if (o.command == "render") return runRender(o);
  if (o.command == "sweep") return runSweep(o);
  if (o.command == "stress") return runStress(o);
  if (o.command == "list") return runList(o);
  if (o.command == "check-shaders") return runCheckShaders(o);
  if (o.command == "compare") return runCompare(o);
  if (o.command == "grade") return runGrade(o);
  if (o.command == "random") return runRandom(o);
  if (o.command == "soak") return runSoak(o);
  if (o.command == "exercise") return runExercise(o);
  if (o.command == "inspect") return runInspect(o);

#ifdef SHADELAB_HAS_WINDOW
  const int rc = runWindow(o, window);
  if (rc != 2) return rc;
  // No display: say so, and do the next most useful thing.
  std::fprintf(stderr, "shadelab: no display to open a window on (DISPLAY=%s); rendering headless instead\n",
               std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "unset");
#else
  std::fprintf(stderr, "shadelab: built without a window (SHADELAB_WINDOW=OFF); rendering headless instead\n");
#endif
  if (o.out.empty()) {
    std::filesystem::create_directories("out");
    o.out = "out/shadelab.png";
  }
  return runRender(o);
}

}  // namespace

// What no command could handle (a render target the driver cannot allocate) ends the run with one
// line and a non-zero exit, never an abort.
int main(int argc, char** argv) {
  shadelab::keepLargeBlocksApart();
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "shadelab: %s\n", e.what());
    return 1;
  }
}

// The window front end: GLFW + Dear ImGui around a LabHost.
#pragma once
#include <filesystem>

#include "app/cli/options.h"
#include "app/host/share_link.h"

namespace shadelab {

struct WindowOptions {
  int exitAfterFrames = 0;           // 0 = run until closed (tests: run N frames, then exit 0)
  bool cycleLabs = false;            // tests: switch to every lab in turn while running
  std::string screenshot;            // tests: save the whole window (UI included) here before exiting
  bool autoMeasure = false;          // start with auto-measure on (where the truth is cheap)
  double soakMinutes = 0;            // --soak M: random use for M minutes (host/soak.h), then exit 0 or 1
  unsigned soakSeed = 1;             // --soak-seed N
  float uiScale = 0;                 // --ui-scale S: text and widgets (0: the monitor's content scale)
  bool present = false;              // --present: start in presentation mode (F11)
  glm::ivec2 size{1280, 800};        // --window-size WxH: the window's size at start
  bool check = false;                // --check: press Check for --exercise once the first frames are drawn
  glm::ivec2 inspect{-1};            // --inspect X,Y: press I over that viewport pixel once the first frames are drawn
  std::string editFolder;            // where the editor saves when it is not a searched folder (the page's "builtin")
  std::string message;               // shown in the Messages panel from the start (the page: what its link got wrong)
  LinkCourse linkCourse;             // the page: the course zip its link opened (Copy link carries it on)
  std::filesystem::path siteCourse;  // the page: the course its site was built with (./web.sh --exercises)
};

// Returns the exit code; 2 when no window could be opened (no display), having printed why.
int runWindow(const Options& options, const WindowOptions& window);

}  // namespace shadelab

// What a run of the window does besides drawing its frame: the screenshot key, and the modes tests
// and soaks run it in (--check, --cycle-labs, --soak, --exit-after with --screenshot). Each is a
// driver the frame calls at three points; WindowSession::drawFrame draws and these decide.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/ui/app_state.h"
#include "app/ui/window_app.h"

namespace shadelab {

class SoakDriver;

struct FrameEvent {
  LabHost& host;
  AppState& app;
  int frame;        // frames drawn before this one
  float dtMs;       // since the last frame
  double labGpuMs;  // the lab's passes this frame (after the lab's frame)
};

class WindowMode {
 public:
  virtual ~WindowMode() = default;
  virtual void beforeLabFrame(FrameEvent&) {}  // events handled; the lab has not drawn
  virtual void afterLabFrame(FrameEvent&) {}   // the lab drew; the UI has not
  // The UI drew into the window's framebuffer (`framebuffer` pixels); it has not been swapped.
  virtual void afterUi(FrameEvent&, glm::ivec2 /*framebuffer*/) {}
  // Whether the window must draw every frame (no idle wait) for this mode now.
  virtual bool keepsDrawing(const AppState&) const { return true; }

  bool wantsClose = false;  // the run is over: close the window after this frame
  int exitCode = 0;         // and exit with this
};

// The modes `wopt` asks for, the screenshot key always; `soak` is the session's driver (or null).
std::vector<std::unique_ptr<WindowMode>> windowModes(const WindowOptions& wopt, SoakDriver* soak,
                                                     std::vector<std::string> labs);

}  // namespace shadelab

#include "app/ui/window_modes.h"

#include <cstdio>

#include "app/host/lab_host.h"
#include "app/host/soak.h"
#include "app/ui/window_files.h"

namespace shadelab {
namespace {

// F12 (or the page's button): the lab's frame as it is, saved to a file; the message says where.
class ScreenshotKey final : public WindowMode {
 public:
  void afterLabFrame(FrameEvent& e) override {
    if (!e.app.screenshotRequested) return;
    e.app.message = saveScreenshot(e.host, e.app.viewport);
    std::printf("%s\n", e.app.message.text.c_str());
    std::fflush(stdout);
    e.app.screenshotRequested = false;
  }
  bool keepsDrawing(const AppState& app) const override { return app.screenshotRequested; }
};

// --check: presses Check for --exercise once the first frames are drawn.
class CheckOnStart final : public WindowMode {
 public:
  void beforeLabFrame(FrameEvent& e) override {
    if (e.frame == 2) e.app.exercises.checkRequested = true;
    done_ = e.frame >= 2;
  }
  bool keepsDrawing(const AppState&) const override { return !done_; }

 private:
  bool done_ = false;
};

// --inspect X,Y: presses I over that pixel of the viewport once the first frames are drawn.
class InspectOnStart final : public WindowMode {
 public:
  explicit InspectOnStart(glm::ivec2 pixel) : pixel_(pixel) {}
  void beforeLabFrame(FrameEvent& e) override {
    if (e.frame == 2) requestInspection(e.app.exercises, pixel_, e.app.viewport);
    done_ = e.frame >= 2;
  }
  bool keepsDrawing(const AppState&) const override { return !done_; }

 private:
  glm::ivec2 pixel_;
  bool done_ = false;
};

// --cycle-labs: every lab in turn, one every three frames.
class CycleLabs final : public WindowMode {
 public:
  explicit CycleLabs(std::vector<std::string> labs) : labs_(std::move(labs)) {}
  void beforeLabFrame(FrameEvent& e) override {
    if (e.frame % 3 == 0)
      e.app.message = StatusLine::failed(e.host.selectLab(labs_[size_t(e.frame / 3) % labs_.size()]));
  }

 private:
  std::vector<std::string> labs_;
};

// --soak M: random use of the window for M minutes (host/soak.h), then its verdict as exit code.
class Soak final : public WindowMode {
 public:
  Soak(SoakDriver& driver, double minutes) : driver_(driver), minutes_(minutes) {}
  void afterLabFrame(FrameEvent& e) override {
    driver_.afterFrame(e.host);
    if (e.frame % 2 == 0) driver_.step(e.host);
    // Measure pressed now and then (later steps supersede it), never between a lab switch and its count
    if (e.frame % 97 == 0 && !driver_.countingLabEntry()) e.app.measure.requested = true;
    if (driver_.seconds() < minutes_ * 60.0 || wantsClose) return;
    const auto csv = driver_.scratch().parent_path() / (driver_.scratch().filename().string() + "-window.csv");
    const SoakDriver::Verdict verdict = driver_.finish(csv, minutes_ >= 10.0);
    std::printf("%s", verdict.report.c_str());
    exitCode = verdict.passed ? 0 : 1;
    wantsClose = true;
  }

 private:
  SoakDriver& driver_;
  double minutes_;
};

// --exit-after N [--screenshot FILE]: N frames, their responsiveness reported, the whole window
// saved, then close.
class ExitAfter final : public WindowMode {
 public:
  ExitAfter(int frames, std::string screenshot) : frames_(frames), screenshot_(std::move(screenshot)) {}
  void afterLabFrame(FrameEvent& e) override {
    if (e.frame <= 2) return;  // the first frames build programs and scenes: no frame time yet
    (e.host.jobs().busy() ? e.app.responsiveness.busyMs : e.app.responsiveness.idleMs).push_back(e.dtMs);
    e.app.responsiveness.labMs.push_back(float(e.labGpuMs));
  }
  void afterUi(FrameEvent& e, glm::ivec2 framebuffer) override {
    if (e.frame + 1 < frames_) return;
    e.app.responsiveness.report();
    if (!screenshot_.empty()) {  // the window as it is, and beside it the preset of the lab's frame (as F12)
      if (auto err = saveWindowImage(screenshot_, framebuffer); !err.empty()) {
        std::fprintf(stderr, "shadelab: %s\n", err.c_str());
        exitCode = 1;
      }
      if (auto err = saveScreenshotPreset(e.host, screenshot_); !err.empty())
        std::fprintf(stderr, "shadelab: the preset beside the screenshot: %s\n", err.c_str());
    }
    wantsClose = true;
  }

 private:
  int frames_;
  std::string screenshot_;
};

}  // namespace

std::vector<std::unique_ptr<WindowMode>> windowModes(const WindowOptions& wopt, SoakDriver* soak,
                                                     std::vector<std::string> labs) {
  std::vector<std::unique_ptr<WindowMode>> modes;
  modes.push_back(std::make_unique<ScreenshotKey>());
  if (wopt.check) modes.push_back(std::make_unique<CheckOnStart>());
  if (wopt.inspect.x >= 0) modes.push_back(std::make_unique<InspectOnStart>(wopt.inspect));
  if (wopt.cycleLabs) modes.push_back(std::make_unique<CycleLabs>(std::move(labs)));
  if (soak) modes.push_back(std::make_unique<Soak>(*soak, wopt.soakMinutes));
  if (wopt.exitAfterFrames > 0) modes.push_back(std::make_unique<ExitAfter>(wopt.exitAfterFrames, wopt.screenshot));
  return modes;
}

}  // namespace shadelab

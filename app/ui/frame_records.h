// What the window records about its frames: the costs of the configuration on screen (for the
// error-against-cost scatter) and how long frames took with and without jobs running (reported when
// a test or benchmark run ends).
#pragma once
#include <chrono>
#include <deque>
#include <string>
#include <vector>

#include "app/gl/pass_timer.h"
#include "app/lab/lab.h"  // Metrics

namespace shadelab {

// The costs of the configuration on screen: medians of its recent frames, restarted whenever the
// settings, the camera or the viewport change.
struct ConfigurationCosts {
  std::string signature;
  std::chrono::steady_clock::time_point since = std::chrono::steady_clock::now();
  std::deque<double> gpu, cpu;

  void push(const std::string& now, const std::vector<gl::PassTiming>& passes);
  // Empty until three frames of this configuration ran: the first pays for shader compiles.
  Metrics costs() const;
};

// Frame times with and without jobs running (the UI must stay responsive while they work), and the
// lab's own passes per frame, so that a frame can be compared with the same lab's frame elsewhere
// (tools/web_bench.sh: the page against the desktop). Kept only in runs of a set number of frames
// (--exit-after), which report them: an open-ended session would grow them frame by frame.
struct Responsiveness {
  std::vector<float> idleMs, busyMs, labMs;
  // "frames: N, M while jobs ran; median frame ... ms idle, ... ms while jobs ran; the lab's passes ... ms"
  void report() const;
};

}  // namespace shadelab

// Per-pass cost: GPU time and the CPU time spent issuing the same commands.
//
// Two clocks, chosen once per context:
//  - GpuQuery: GL_TIME_ELAPSED queries, the GPU's own clock (NVIDIA, AMD, Intel drivers).
//  - Finish:   wall time from a glFinish before the pass to a glFinish after it. On llvmpipe the
//              rasteriser runs deferred on worker threads and its GL_TIME_ELAPSED leaves that
//              work out (it reported 0.2 ms for a 1280x720 frame that takes over 10 ms), so the
//              honest figure there is the synchronised wall time.
//  - Readback: the same with a one-pixel read of a framebuffer of the timer's own in place of
//              glFinish, in WebGL: there finish() returns at once (the browser's GPU process runs
//              the commands later), while a read of pixels is answered only when everything
//              before it has run. In a 1280x720 page, finish() timed every lab's passes at
//              0.1-0.4 ms in frames of 100-220 ms (tools/web_bench.sh).
// Either way the frame waits for its own numbers when it ends: that costs the CPU/GPU overlap a
// game would keep, and buys exact per-pass cost for the very frame on screen.
// SHADELAB_TIMER=query|finish|readback overrides the choice.
#pragma once
#include <string>
#include <vector>

#include "app/gl/handle.h"

namespace gl {

struct PassTiming {
  std::string name;
  double gpuMs = 0.0;
  double cpuMs = 0.0;
};

class PassTimer {
 public:
  enum class Clock { GpuQuery, Finish, Readback };

  // Picks the clock from GL_RENDERER and GL_VERSION (software rasterisers get Finish, WebGL Readback).
  PassTimer();
  Clock clock() const { return clock_; }
  const char* clockName() const;

  void beginFrame();
  void begin(std::string name);  // passes are sequential: GL_TIME_ELAPSED queries cannot nest
  void end();
  // Resolves this frame's times and returns its passes in the order they ran.
  const std::vector<PassTiming>& endFrame();
  const std::vector<PassTiming>& lastFrame() const { return last_; }

 private:
  struct Open {
    PassTiming timing;
    double start = 0.0;
  };
  Clock clock_ = Clock::GpuQuery;
  std::vector<Query> pool_;
  std::vector<Open> passes_;
  std::vector<PassTiming> last_;
  bool inPass_ = false;
  // Readback: what is read (made on first use)
  void sync();
  TextureName syncTexture_;
  FramebufferName syncTarget_;
};

// Scope guard for one pass: `auto pass = timer.scope("lighting");`
class PassScope {
 public:
  PassScope(PassTimer& t, std::string name) : t_(t) { t_.begin(std::move(name)); }
  ~PassScope() { t_.end(); }
  PassScope(const PassScope&) = delete;
  PassScope& operator=(const PassScope&) = delete;

 private:
  PassTimer& t_;
};

}  // namespace gl

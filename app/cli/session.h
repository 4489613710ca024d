// A headless session: context + host, configured from the command line in a fixed order
// (preset, lab, scene, --set, camera), so `render`, `sweep` and `stress` agree on a frame.
#pragma once
#include <memory>
#include <string>

#include "app/cli/options.h"
#include "app/context/gl_context.h"
#include "app/host/configure.h"
#include "app/host/lab_host.h"

namespace shadelab {

struct Session {
  std::unique_ptr<GlContext> context;
  std::unique_ptr<LabHost> host;
  glm::ivec2 size{960, 540};  // --size, else the preset's "size", else the default
  float time = 0.0f;          // --time, else the preset's "time"
};

ShaderSearchPath shaderSearchPath(const Options& o);
// Returns "" or the one-line error to print; `s` is usable only on success.
std::string openSession(const Options& o, Session& s);

struct TimedFrames {
  double gpuMs = 0;  // median over the timed frames of the frame's summed pass times
  double cpuMs = 0;
  std::vector<gl::PassTiming> passes;  // per pass, medians
};
// Waits for the lab's jobs, renders `warmup` untimed frames, then `frames` timed ones.
TimedFrames renderTimed(LabHost& host, glm::ivec2 size, float time, int warmup, int frames);

// "[#######.......] 7/15 label" on stderr, redrawn in place.
void progress(int done, int total, const std::string& label);
// A command's error: "shadelab: message" on stderr; returns the exit code 1.
int fail(const std::string& message);
// "smoothing bunny 45% (iteration 4/10)" for the jobs running now, joined by "; ".
std::string describeJobs(const std::vector<JobStatus>& jobs);

}  // namespace shadelab

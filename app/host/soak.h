// A soak: long random use of one LabHost, as a class of students would use it in a week,
// compressed. Each step is one of: switch lab, draw random parameters from the lab's own list
// (extremes included), write one of the frame's shader files broken into a scratch student
// folder and fix it again, load a mesh and drop it, start jobs and supersede them. After each
// frame it checks for non-finite pixels and GL errors, and every few seconds it records resident
// memory, live GL objects (the RAII handles' count) and running jobs.
//
// The same driver runs headless (`shadelab soak`) and in the real window (`--soak MINUTES`).
#pragma once
#include <filesystem>
#include <array>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "host/lab_host.h"

namespace shadelab {

class SoakDriver {
 public:
  // `scratch`: an empty student folder the driver writes broken and fixed shaders into; the host
  // must search it first (pass it as the first shader root).
  SoakDriver(std::filesystem::path scratch, unsigned seed);
  // A fresh scratch folder under out/soak/ (or $SHADELAB_OUT/soak/).
  static std::filesystem::path makeScratch();
  const std::filesystem::path& scratch() const { return scratch_; }

  // One random step on `host`; returns what it did, for the log.
  std::string step(LabHost& host);
  // After each frame the host rendered: checks it, and records a sample every `sampleSeconds`.
  void afterFrame(LabHost& host, bool readPixels = true);

  struct Sample {
    double seconds;
    double residentMb;
    int glObjects;
    int jobs;
    long frames, steps;
  };
  const std::vector<Sample>& samples() const { return samples_; }
  // Bad frames and GL errors, one line each (the first few of each kind).
  const std::vector<std::string>& problems() const { return problems_; }
  std::string writeCsv(const std::filesystem::path& file) const;
  // The summary: steps, frames, memory slope after warm-up, GL objects at each lab's entry.
  // `judgeSlope`: whether the slope goal (under 1 MB per 10 minutes) decides pass or fail.
  std::string summary(bool judgeSlope, bool& passed) const;
  double seconds() const;

 private:
  void switchLab(LabHost& host);
  void breakOrFixShader(LabHost& host);
  void loadOrDropMesh(LabHost& host);

  std::filesystem::path scratch_;
  std::mt19937 rng_;
  double start_;
  double nextSample_ = 0.0;
  double sampleSeconds_ = 5.0;
  long frames_ = 0, steps_ = 0, nonFiniteFrames_ = 0, glErrors_ = 0, labSwitches_ = 0, shaderEdits_ = 0,
       meshLoads_ = 0, supersedes_ = 0;
  std::string brokenFile_;   // relative path of the scratch file now broken, or ""
  bool countAfterSwitch_ = false;
  // lab -> live GL objects of each kind after the lab's first frame, once per time it is entered
  std::map<std::string, std::vector<std::vector<int>>> glObjectsOnEntry_;
  // lab -> (seconds, resident MB) at the same moments, after the allocator returned its free pages:
  // the same state each time, so growth here is memory kept, not the current scene's size.
  std::map<std::string, std::vector<std::pair<double, double>>> residentOnEntry_;
  // The same moments: MB the C/C++ heap holds in use (mallinfo2), to tell memory the program and the
  // driver keep allocated from pages the allocator or the driver's JIT keeps mapped.
  std::map<std::string, std::vector<std::pair<double, double>>> heapOnEntry_;
  std::vector<Sample> samples_;
  std::vector<std::string> problems_;
};

}  // namespace shadelab

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
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "app/host/lab_host.h"
#include "app/util/process_memory.h"

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

  // Writes the samples to `csv` (seconds, resident MB, GL objects, jobs, frames, steps) and judges
  // the run: steps, bad frames and GL errors, memory and GL objects on lab entries, one line each,
  // then "soak: samples in CSV; passed" or "...; FAILED". `judgeSlope`: whether the memory slope
  // goal (under 1 MB per 10 minutes) decides, which only a run of 10 minutes or more can tell.
  struct Verdict {
    std::string report;
    bool passed = false;
  };
  Verdict finish(const std::filesystem::path& csv, bool judgeSlope) const;
  double seconds() const;
  // A lab was entered and its entry is counted after the next frame: nothing that starts jobs of
  // its own (the window's Measure) should begin before then.
  bool countingLabEntry() const { return countAfterSwitch_; }

 private:
  void settle(LabHost& host);  // host.settle(), its time left out of the longest step
  void switchLab(LabHost& host);
  void breakOrFixShader(LabHost& host);
  void loadOrDropMesh(LabHost& host);

  std::filesystem::path scratch_;
  std::mt19937 rng_;
  double start_;
  double nextSample_ = 0.0;
  double sampleSeconds_ = 5.0;
  long frames_ = 0, steps_ = 0, nonFiniteFrames_ = 0, glErrors_ = 0, labSwitches_ = 0, shaderEdits_ = 0, meshLoads_ = 0,
       supersedes_ = 0;
  // The largest resident set seen after any frame, and the state that drew it: a transient of
  // gigabytes names its configuration so that it can be reproduced and capped.
  double peakMb_ = 0.0, peakSeconds_ = 0.0;
  std::string peakState_;
  // The longest wait between two frames (a step and its frame), and the state that ended it; the
  // soak's own waits for jobs to end are left out.
  double lastFrameAt_ = 0.0, slowestSeconds_ = 0.0;
  std::string slowestState_;
  std::string brokenFile_;  // relative path of the scratch file now broken, or ""
  bool countAfterSwitch_ = false;
  std::string leftState_;                      // describeState() just before the last lab switch
  std::vector<std::filesystem::path> meshes_;  // what loadOrDropMesh picks from besides the lab's scenes
  // Each time a lab is entered, after its first frame (a fresh lab, its default scene): the same
  // state every time, so what grows here is kept, not the current scene's size.
  struct LabEntry {
    double seconds;
    double residentMb;           // after the allocator returned its free pages (malloc_trim)
    double heapMb;               // allocated and in use (mallinfo2): tells memory kept from pages kept
    ResidentParts resident;      // residentMb as anonymous and file-backed pages
    std::vector<int> glObjects;  // live GL objects of each gl::Kind
    size_t programs = 0;         // distinctProgramsLinked() then: the driver's compiler keeps some per program
    std::string left;            // the state of the lab left for this one: an entry far above the
                                 // lab's others names what to reproduce
  };
  std::map<std::string, std::vector<LabEntry>> entries_;  // lab -> its entries in order
  // finish()'s parts: the CSV files, the memory's slopes, the GL objects per lab entry.
  std::string writeRecords(const std::filesystem::path& csv, const std::filesystem::path& entriesCsv) const;
  bool reportMemory(std::ostringstream& s, bool judgeSlope) const;
  bool reportGlObjects(std::ostringstream& s) const;
  std::vector<Sample> samples_;
  std::vector<std::string> problems_;  // bad frames and GL errors (the first few of each), one line each
};

}  // namespace shadelab

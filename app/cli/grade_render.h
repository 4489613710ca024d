// The part of grading that draws: one rubric configuration, rendered in a child process (see
// grade/watchdog.h) first with the built-in shaders (the solution, and the lab's ground truth when
// a check needs it), then with the student's folders searched first (grade/configuration_frames.h
// draws both). Results go to files beside the report so that what was finished survives a
// watchdog kill:
//   <stem>-solution.png, <stem>-student.png, <stem>-diff.png      images for the report
//   <stem>-solution.json, <stem>-student.json                    numbers and build errors
//   <stem>-slips.json                                            the student's frame against the slips
//   <stem>-trace.json                                            their function traced in the draw
#pragma once
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/grade/rubric.h"
#include "app/grade/solution_cache.h"

namespace shadelab {

struct ConfigurationJob {
  const Exercise* exercise = nullptr;
  const Configuration* configuration = nullptr;
  std::vector<std::filesystem::path> studentDirs;
  std::string backend;
  std::filesystem::path dir;  // the report folder
  std::string stem;           // file names: dir/stem-*.png
  // The built-in side (solution frame, truths, the solution's numbers) is taken from here when it
  // holds an entry for `cacheKey` + the renderer, and stored there when it did not.
  SolutionCache cache;
  std::string cacheKey;       // solutionKeyBase(): everything but the renderer
  bool solutionOnly = false;  // fill the cache and stop (a class run does this once per configuration;
                              // with `slips`, grade --prepare, the slips as well)
  // The second pass, when the diagnosis asks for the solution's slips (grade/diagnosis.h:
  // slipsNeeded): draw them unless the cache holds them (and keep them there), draw the student's
  // frame again and write its distances to them, <stem>-slips.json (slipDistances).
  bool slips = false;
  // After the student's frame, the phase "trace": where it differs from the solution's, their
  // function traced in the lab's draw (grade/configuration_frames.h: traceStudentFrame), written
  // to <stem>-trace.json.
  bool traceInDraw = false;
};

// The part of a configuration's cache key known before a context exists: the built-in shaders,
// the rubric, the starter (drawn as a mistake), the configuration's index and the executable.
std::string solutionKeyBase(const Exercise& ex, size_t configuration);

// Runs in the child. `enter` announces the phases "solution", "student" and "trace". Exit code 0, or 2
// when the rubric or the built-in solution is at fault (the message is in <stem>-solution.json,
// whose "from_cache" says whether the built-in side was rendered or read back).
int renderConfiguration(const ConfigurationJob& job, const std::function<void(const std::string&)>& enter);

// What the child wrote: {} when the file is absent (the child never got there).
nlohmann::json readResult(const ConfigurationJob& job, const std::string& phase);

}  // namespace shadelab

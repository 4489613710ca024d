// The frames one rubric configuration is graded on, drawn in the GL context current on the calling
// thread: first the lab's built-in shaders (the solution's frame, and the lab's ground truth when a
// check needs it), then the student's folders searched first. `shadelab grade` draws them in a
// watched child process (cli/grade_render.h); the window's Check button draws them in its own
// context between frames (grade/exercise_check.h). Both score what comes out with scoreChecks.
#pragma once
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/grade/grading.h"
#include "app/grade/mutants.h"
#include "app/grade/rubric.h"
#include "app/grade/solution_cache.h"
#include "app/host/lab_host.h"

namespace shadelab {

// Which of the exercise's files the student's folders hold, looked up as the shaders will be
// (inside the sandbox: a link leading out of the folder is never read here; its build says why).
// Fills out.missingFiles, and out.notes for a file identical to the lab's own.
void lookUpSubmission(const Exercise& ex, const std::vector<std::filesystem::path>& studentDirs, ExerciseResult& out);

// A host made with the configuration's lab and scene (no other lab's or scene's build on the way),
// then its settings and camera. `error` is "" or what the rubric asked that could not be applied.
std::unique_ptr<LabHost> configuredHost(const std::vector<std::filesystem::path>& roots, const Exercise& ex,
                                        const Configuration& c, std::string& error);

// The errors of the programs the host's last frame used (the first 20), at file:line:col with the caret.
std::vector<std::string> buildErrors(LabHost& host);

// The built-in side: `out.frame`, and when a check needs them `out.truths` and out.numbers["vs_truth"].
// Returns "" or why it could not be drawn (the rubric's or the lab's fault, never the student's).
std::string drawSolution(const Exercise& ex, const Configuration& c, CachedSolution& out);

// The solution's slips: its TODO region changed in one place each (grade/mutants.h: an operator or
// comparison turned round, a constant changed, a call dropped, ...), at most kMostSlips, spread
// over the kinds. Evidence like the rubric's mistakes, with no list to write: a student's frames
// that are a slip's in every configuration name that slip. None for a whole-file starter.
constexpr size_t kMostSlips = 30;
std::vector<Mutant> solutionSlips(const Exercise& ex);
// Each slip drawn in the configuration; those that build and draw differently from `out.frame`
// kept in out.slips (at half size; a probe's table whole) with their numbers in out.numbers["slips"].
// Returns "" or why the rubric is at fault. Drawn only when a diagnosis asks for them
// (slipsNeeded), then kept with the solution's frame: in the cache by `shadelab grade`, in memory
// by the window's Check.
std::string drawSlips(const Exercise& ex, const Configuration& c, CachedSolution& out);
// The student's frame against the slips: {"distance": to the solution's, "to": [to each slip]}, both
// at the slips' size; null when the slips were not drawn.
nlohmann::json slipDistances(const Configuration& c, const ImageF& image, const CachedSolution& solution);
// The student's frame drawn again (their folders first) and its slipDistances in `out`; the slips
// must be drawn. Returns "" or why the rubric is at fault.
std::string studentSlipDistances(const Exercise& ex, const Configuration& c,
                                 const std::vector<std::filesystem::path>& studentDirs, const CachedSolution& solution,
                                 nlohmann::json& out);

// The solution drawn with one of the configuration's settings at another value each (the values
// a setting is tried at when a student's frame may ignore or misuse it: the lab's default, the
// values the rubric's other configurations give it, and for a number 0, 1, half, twice and the
// reciprocal), likeliest first, at most kMostSettingFrames, those that build. A student's frame
// that nothing else explains is measured against them (the "settings" of drawStudent). They depend
// on the solution alone, so they are drawn once per configuration, never once per student: kept
// in the cache beside the solution's entry by `shadelab grade`, in memory by the window's Check.
struct SettingFrames {
  struct Tried {
    size_t setting = 0;  // its place in the configuration's settings
    std::string value;   // "": the setting left at the lab's default
  };
  std::vector<Tried> tried;
  std::vector<ImageF> frames;  // one for each of `tried`
};
constexpr int kMostSettingFrames = 40;
// A budget in frames keeps the set the same on a slow machine; a time limit (10 s) is the safety
// net that keeps it inside the watchdog's. A value the parameter does not take is left out.
// Returns false when the time limit cut the set short: such a set serves the student at hand
// and is never kept for others.
bool drawSettingFrames(const Exercise& ex, const Configuration& c, SettingFrames& out);
// As the cache keeps them ({"tried": [{setting, value}]} and the frames), and back: false when the
// kept entry does not read as a set of them.
CachedFrames keptSettingFrames(const SettingFrames& frames);
bool settingFramesFromKept(const CachedFrames& kept, SettingFrames& out);
// Where drawStudent gets them when it needs them: drawn, or read back from where they were kept;
// null when they cannot be had (then no setting is named).
using SettingFramesSource = std::function<const SettingFrames*()>;

// The student's side against the solution's: their frame in `image` and its numbers
// {"errors": [...], "vs_solution": {rmse, covered_rmse, max_error, bad_pixel_pct, the frame's
//  properties}, "distance", "mistakes": [distances], "properties": {NaN and Inf pixels, where, edges},
//  "vs_truth": {the lab's metrics}, "settings": [{key, value, distance}]}; "vs_truth" only when a
// check needs it and the frame built, "settings" only for a frame that differs and that nothing else
// explains (`settingFrames` is asked then). `error` receives what the rubric asked that could not
// be applied.
nlohmann::json drawStudent(const Exercise& ex, const Configuration& c,
                           const std::vector<std::filesystem::path>& studentDirs, const CachedSolution& solution,
                           const SettingFramesSource& settingFrames, ImageF& image, std::string& error);

// The student's function traced in the lab's draw where their frame (`image`, whose numbers
// drawStudent gave as `student`) differs most from the solution's (grade/pixel_trace.h:
// traceWhereFramesDiffer): {"trace": the finding} or {"trace_unavailable": why}; null where the
// frame did not build or does not differ.
nlohmann::json traceStudentFrame(const Exercise& ex, const Configuration& c,
                                 const std::vector<std::filesystem::path>& studentDirs, const nlohmann::json& student,
                                 const ImageF& image, const CachedSolution& solution);

// Whether the next configuration's frame is traced so (traceStudentFrame), given the
// configurations graded before it: for an exercise whose function no probe holds (its
// trace is the probe's, grade/probe_trace.h), until a trace finds where the values part or
// kMostDrawTraces frames were traced. A frame that does not differ is not traced.
constexpr int kMostDrawTraces = 2;
bool traceInDrawNext(const Exercise& ex, const std::vector<ConfigurationResult>& before);

}  // namespace shadelab

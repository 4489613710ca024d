// Checking an exercise where the student works: the window's (and the page's) Check button. The
// rubric's configurations are drawn one per step() in the window's own GL context, between its
// frames, and scored exactly as `shadelab grade` scores them (grade/configuration_frames.h, then
// scoreChecks, then the diagnosis), so the lines, hints and diagnosis are the grader's. The
// solution's side (its frame, truth and the mistakes' frames) is kept for the next Check: after the
// first one only the student's frames are drawn.
//
// A configuration the rubric hides ("visibility" other than visible) is neither drawn nor named
// here: the grader counts it, and the result's notes say that such checks exist.
//
// There is no watchdog here: a shader that never returns stalls the window (in the page the
// browser stops it and the context is lost, which the page reports). The desktop `shadelab grade`,
// with its child processes, stays the course's official grader.
#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "app/grade/configuration_frames.h"
#include "app/grade/grading.h"
#include "app/grade/solution_cache.h"

namespace shadelab {

// The exercise's starter files copied into the student's `folder`, never over a file already there
// (their work). `copied` and `kept` receive the files' names. "" or why not (a file the rubric
// names outside a shader folder, a starter missing, a folder that cannot be written).
std::string copyStarter(const Exercise& ex, const std::filesystem::path& folder, std::vector<std::string>& copied,
                        std::vector<std::string>& kept);

// The student's files of `ex` set back to the starter's. Each file of theirs is first renamed to a
// dated copy beside it ("shadows/pcf.kept-20261128-172005.glsl"), never deleted; `kept` receives
// the copies' names. "" or why not.
std::string resetToStarter(const Exercise& ex, const std::filesystem::path& folder, std::vector<std::string>& kept);

class ExerciseCheck {
 public:
  // Starts checking exercise `id` with `studentDirs` searched before the built-in shaders. "" or
  // why it cannot (an unknown exercise, a rubric that does not read).
  std::string start(const std::string& id, std::vector<std::filesystem::path> studentDirs);
  bool running() const { return running_; }
  // Every configuration scored (not stopped by an error): the total means something.
  bool finished() const {
    return !running_ && error_.empty() && result_.configurations.size() == exercise_.configurations.size();
  }
  // Draws and scores the next configuration (one call can take a while: a truth to trace). When
  // every configuration is scored and the diagnosis asks for the solution's slips (slipsNeeded),
  // the next steps draw them, one configuration each, and the diagnosis is made again with them.
  void step();
  // Drawing the slips after every configuration was scored.
  bool drawingSlips() const { return running_ && slipStep_ >= 0; }

  const std::string& id() const { return exercise_.id; }
  size_t configurationsDone() const { return result_.configurations.size(); }
  size_t configurations() const { return exercise_.configurations.size(); }
  const ExerciseResult& result() const { return result_; }
  // The exercise as checked here: its hidden configurations left out.
  const Exercise& exercise() const { return exercise_; }
  size_t hiddenConfigurations() const { return hidden_; }
  // For each configuration checked so far that lost points, what the student compares: their
  // frame, the solution's and the difference amplified (diffImage); empty frames where it lost none
  // or was not drawn. Indexed as result().configurations.
  struct Pictures {
    ImageF student, solution, difference;
  };
  const std::vector<Pictures>& pictures() const { return pictures_; }
  // Bumped by every start(): a panel that made textures of the pictures knows when to make new ones.
  int generation() const { return generation_; }
  // Why the check stopped without a score: the rubric's or the lab's fault, never the student's.
  const std::string& error() const { return error_; }
  // The grader's lines for what is done so far: errors once each, one line per check with its
  // hint under it when it lost points, and the total when finished.
  std::vector<std::string> lines() const;

 private:
  void stepSlips();
  Exercise exercise_;
  std::vector<std::filesystem::path> studentDirs_;
  ExerciseResult result_;
  std::vector<Pictures> pictures_;
  std::vector<ImageF> studentFrames_;  // every configuration's, kept for the slips
  long slipStep_ = -1;                 // the configuration whose slips the next step draws; -1: not yet
  size_t hidden_ = 0;
  int generation_ = 0;
  std::string error_;
  bool running_ = false;
  std::string shadersHash_;                             // the built-in shaders and exercises they were drawn from
  std::map<std::string, CachedSolution> solutions_;     // "id#configuration" -> the built-in side
  std::map<std::string, SettingFrames> settingFrames_;  // ... -> the solution at other settings, once asked for
};

}  // namespace shadelab

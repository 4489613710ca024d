#include "app/grade/exercise_check.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "app/grade/configuration_frames.h"
#include "app/grade/diagnosis.h"
#include "app/lab/host_batch.h"
#include "app/measure/image.h"
#include "app/shader/preprocessor.h"
#include "app/util/contained_path.h"
#include "app/util/format.h"
#include "app/util/output_files.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

// Where the student's copy of the exercise's `file` lives in `folder`; "" or why the rubric's name
// is not one inside a shader folder.
std::string studentCopy(const Exercise& ex, const std::string& file, const fs::path& folder, fs::path& mine) {
  const fs::path name = containedName(file);
  if (name.empty())
    return (ex.dir / "rubric.json").string() + ": \"files\": '" + file + "' is not a name inside a shader folder";
  mine = folder / name;
  return {};
}

}  // namespace

std::string copyStarter(const Exercise& ex, const fs::path& folder, std::vector<std::string>& copied,
                        std::vector<std::string>& kept) {
  for (auto& file : ex.files) {
    fs::path mine;
    if (auto e = studentCopy(ex, file, folder, mine); !e.empty()) return e;
    std::error_code ec;
    if (fs::exists(mine, ec) || fs::is_symlink(mine, ec)) {
      kept.push_back(file);
      continue;
    }
    const fs::path starter = ex.dir / "starter" / containedName(file);
    if (!fs::is_regular_file(starter, ec))
      return starter.string() + " is missing: the exercise has no starter for " + file;
    if (auto e = writeTextFile(mine.string(), readWholeFile(starter)); !e.empty()) return e;
    copied.push_back(file);
  }
  return {};
}

std::string resetToStarter(const Exercise& ex, const fs::path& folder, std::vector<std::string>& kept) {
  const std::string stamp = localTimeNow("kept-%Y%m%d-%H%M%S");
  for (auto& file : ex.files) {
    fs::path mine;
    if (auto e = studentCopy(ex, file, folder, mine); !e.empty()) return e;
    std::error_code ec;
    if (!fs::exists(mine, ec)) continue;
    fs::path copy = mine;
    copy.replace_filename(mine.stem().string() + "." + stamp + mine.extension().string());
    if (fs::exists(copy, ec)) return copy.string() + " is there already: try again in a second";
    fs::rename(mine, copy, ec);
    if (ec) return mine.string() + ": cannot be set aside (" + ec.message() + ")";
    kept.push_back(fs::relative(copy, folder, ec).string());
  }
  std::vector<std::string> copied, unchanged;
  return copyStarter(ex, folder, copied, unchanged);
}

std::string ExerciseCheck::start(const std::string& id, std::vector<fs::path> studentDirs) {
  running_ = false;
  error_.clear();
  result_ = ExerciseResult{};
  pictures_.clear();
  studentFrames_.clear();
  slipStep_ = -1;
  ++generation_;
  Exercise ex;
  if (auto e = loadExercise(id, ex); !e.empty()) return error_ = e;
  hidden_ = dropHiddenConfigurations(ex.configurations);
  exercise_ = std::move(ex);
  studentDirs_ = std::move(studentDirs);
  // The kept solutions (and mistakes) hold only while the built-in shaders and the exercises (rubrics,
  // starters) they were drawn from are unchanged.
  ContentHash content;
  content.addTree(builtinShaderDir());
  for (const auto& root : exerciseRoots()) content.add("\nexercises ").addTree(root);
  const std::string hash = content.hex();
  if (hash != shadersHash_) solutions_.clear();
  // The solution at other settings is large (tens of frames a configuration): kept for the
  // exercise being checked only.
  std::erase_if(settingFrames_,
                [&](const auto& kept) { return hash != shadersHash_ || kept.first.rfind(exercise_.id + "#", 0) != 0; });
  shadersHash_ = hash;
  result_.id = exercise_.id;
  result_.title = exercise_.title;
  result_.lab = exercise_.lab;
  result_.total = exercise_.totalPoints();
  result_.passMark = exercise_.passMark;
  lookUpSubmission(exercise_, studentDirs_, result_);
  if (hidden_ > 0)
    result_.notes.push_back(std::to_string(hidden_) + (hidden_ == 1 ? " configuration" : " configurations") +
                            " of this exercise " + (hidden_ == 1 ? "is" : "are") +
                            " hidden by your teacher: graded by the course's grader, not shown here");
  running_ = !exercise_.configurations.empty();
  return {};
}

void ExerciseCheck::step() {
  if (!running_) return;
  const HostBatch batch;  // the hosts of one configuration (solution, mistakes, slips, student) share its work
  if (slipStep_ >= 0) return stepSlips();
  const size_t i = result_.configurations.size();
  const Configuration& c = exercise_.configurations[i];
  ConfigurationResult out;
  Pictures picturesOf;
  ImageF studentFrame;
  out.name = c.name;
  out.description = describeConfiguration(c);
  out.visibility = c.visibility;
  const auto stop = [&](const std::string& why) {
    error_ = why;
    running_ = false;
  };
  if (!result_.missingFiles.empty()) {
    notSubmitted(c, result_.missingFiles.front() + " is not in your folder: open the starter", out);
  } else {
    const std::string key = exercise_.id + "#" + std::to_string(i);
    auto kept = solutions_.find(key);
    if (kept == solutions_.end()) {
      CachedSolution built;
      if (auto e = drawSolution(exercise_, c, built); !e.empty()) return stop(e);
      kept = solutions_.emplace(key, std::move(built)).first;
    }
    ImageF image;
    std::string configError;
    const SettingFramesSource settingFrames = [&]() -> const SettingFrames* {
      auto [frames, fresh] = settingFrames_.try_emplace(key);
      if (fresh) drawSettingFrames(exercise_, c, frames->second);
      return &frames->second;
    };
    nlohmann::json student = drawStudent(exercise_, c, studentDirs_, kept->second, settingFrames, image, configError);
    if (!configError.empty()) return stop(configError);
    if (traceInDrawNext(exercise_, result_.configurations))
      if (const nlohmann::json trace = traceStudentFrame(exercise_, c, studentDirs_, student, image, kept->second);
          !trace.is_null())
        student.update(trace);
    if (auto e = scoreChecks(exercise_, c, kept->second.numbers, student, {}, out); !e.empty()) return stop(e);
    if (std::any_of(out.checks.begin(), out.checks.end(),
                    [](const CheckResult& r) { return r.grade != Grade::Full; }) &&
        !image.rgba.empty() && image.size == kept->second.frame.size)
      picturesOf = {image, kept->second.frame, diffImage(image, kept->second.frame)};
    studentFrame = std::move(image);
  }
  pictures_.push_back(std::move(picturesOf));
  studentFrames_.push_back(std::move(studentFrame));
  for (auto& r : out.checks) result_.earned += r.earned;
  result_.configurations.push_back(std::move(out));
  running_ = result_.configurations.size() < exercise_.configurations.size();
  if (running_) return;
  diagnose(exercise_, result_);
  if (slipsNeeded(result_)) {
    slipStep_ = 0;
    running_ = true;
  }
}

void ExerciseCheck::stepSlips() {
  const size_t i = size_t(slipStep_);
  ConfigurationResult& out = result_.configurations[i];
  if (out.drawn && !out.slipsDrawn) {
    const Configuration& c = exercise_.configurations[i];
    CachedSolution& kept = solutions_.at(exercise_.id + "#" + std::to_string(i));
    if (!kept.numbers.contains("slips"))
      if (auto e = drawSlips(exercise_, c, kept); !e.empty()) {
        error_ = e;
        running_ = false;
        return;
      }
    addSlipEvidence(kept.numbers, slipDistances(c, studentFrames_[i], kept), out);
  }
  if (size_t(++slipStep_) < result_.configurations.size()) return;
  running_ = false;
  diagnose(exercise_, result_);
}

std::vector<std::string> ExerciseCheck::lines() const {
  std::vector<std::string> out = diagnosisLines(result_), printed;
  for (auto& c : result_.configurations)
    for (auto& line : configurationLines(c, printed)) out.push_back(std::move(line));
  for (auto& n : result_.notes) out.push_back("  note: " + n);
  if (finished()) out.push_back(exerciseTotalLine(result_));
  return out;
}

}  // namespace shadelab

// The grader's parts that need no GL: rubrics, scoring, the watchdog, and the exercises' starters
// staying copies of the lab's shaders outside their TODO regions.
#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <fstream>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "app/grade/grading.h"
#include "app/grade/rubric.h"
#include "app/grade/watchdog.h"
#include "app/shader/preprocessor.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> lines(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

Check check(const std::string& full, const std::string& partial) {
  Check c;
  c.name = "c";
  c.metric = "rmse";
  c.points = 2;
  EXPECT_EQ(parseThreshold(full, c.full), "");
  EXPECT_EQ(parseThreshold(partial, c.partial), "");
  return c;
}

}  // namespace

TEST(Grade, ThresholdsAreNumbersOrRelativeToTheSolution) {
  Threshold t;
  EXPECT_EQ(parseThreshold("0.02", t), "");
  EXPECT_DOUBLE_EQ(t.bound(5.0), 0.02);
  EXPECT_EQ(parseThreshold("solution+0.5", t), "");
  EXPECT_DOUBLE_EQ(t.bound(2.0), 2.5);
  EXPECT_EQ(t.text(), "solution+0.5");
  EXPECT_EQ(parseThreshold("solution*1.5", t), "");
  EXPECT_DOUBLE_EQ(t.bound(2.0), 3.0);
  EXPECT_NE(parseThreshold("solution-1", t), "");
  EXPECT_NE(parseThreshold("-1", t), "");
  EXPECT_NE(parseThreshold("lots", t), "");
}

TEST(Grade, ChecksScoreFullPartialOrNothing) {
  const Check c = check("solution+0.1", "solution+1");
  EXPECT_EQ(scoreCheck(c, 1.05, 1.0).grade, Grade::Full);
  EXPECT_DOUBLE_EQ(scoreCheck(c, 1.05, 1.0).earned, 2.0);
  const CheckResult partial = scoreCheck(c, 1.5, 1.0);
  EXPECT_EQ(partial.grade, Grade::Partial);
  EXPECT_DOUBLE_EQ(partial.earned, 1.0);
  EXPECT_EQ(scoreCheck(c, 2.5, 1.0).grade, Grade::Fail);
  const CheckResult nan = scoreCheck(c, std::nan(""), 1.0);
  EXPECT_EQ(nan.grade, Grade::Fail);
  EXPECT_NE(nan.message.find("NaN"), std::string::npos);
}

TEST(Grade, ACheckCountsOnlyWhenTheCheckItRequiresDoesNotFail) {
  Check shadow = check("1", "1"), acne = check("1", "1");
  shadow.name = "shadow";
  acne.name = "acne";
  acne.requiredCheck = "shadow";
  std::vector<CheckResult> results = {scoreCheck(shadow, 100.0, 0.0), scoreCheck(acne, 0.0, 0.0)};
  applyRequirements(results);
  EXPECT_EQ(results[1].grade, Grade::Fail);
  EXPECT_NE(results[1].message.find("'shadow'"), std::string::npos);
  results = {scoreCheck(shadow, 0.5, 0.0), scoreCheck(acne, 0.0, 0.0)};
  applyRequirements(results);
  EXPECT_EQ(results[1].grade, Grade::Full);
}

TEST(Grade, EveryExerciseLoadsWithAStatementAndItsStarterFiles) {
  const auto ids = listExercises();
  ASSERT_GE(ids.size(), 5u);
  for (auto& id : ids) {
    SCOPED_TRACE(id);
    Exercise ex;
    ASSERT_EQ(loadExercise(id, ex), "");
    EXPECT_TRUE(fs::is_regular_file(ex.dir / "statement.md"));
    EXPECT_GT(ex.totalPoints(), 0.0);
    for (auto& f : ex.files) EXPECT_TRUE(fs::is_regular_file(ex.dir / "starter" / f)) << f;
    // The built-in exercises' own standard (`shadelab exercise check` holds each to its rubric):
    // at least five mistakes students make, and three right answers written differently.
    EXPECT_GE(ex.mistakes.size(), 6u) << "the starter and at least five mistakes students make";
    EXPECT_GE(ex.correct.size(), 3u) << "three correct submissions written differently from the lab's file";
  }
}

// A starter is the lab's file with one region replaced: the lines before its TODO begin marker and
// after its end marker are the built-in file's first and last lines, so a change to the lab's
// shader that the starter misses fails here.
TEST(Grade, StartersAreTheLabsShadersOutsideTheirTodoRegion) {
  for (auto& id : listExercises()) {
    Exercise ex;
    ASSERT_EQ(loadExercise(id, ex), "");
    for (auto& f : ex.files) {
      SCOPED_TRACE(id + ": " + f);
      const auto starter = lines(ex.dir / "starter" / f), builtin = lines(builtinShaderDir() / f);
      const std::string begin = "TODO(exercise " + id + "): begin", end = "TODO(exercise " + id + "): end";
      size_t b = starter.size(), e = starter.size(), markers = 0;
      for (size_t i = 0; i < starter.size(); ++i) {
        if (starter[i].find(begin) != std::string::npos) b = i, ++markers;
        if (starter[i].find(end) != std::string::npos) e = i, ++markers;
      }
      ASSERT_EQ(markers, 2u) << "one begin and one end marker";
      // The exercised function alone, in its own include: not a copy of a whole shader of the lab's.
      EXPECT_LE(starter.size(), 40u);
      ASSERT_LT(b, e);
      const size_t after = starter.size() - e - 1;
      ASSERT_LE(b + after, builtin.size());
      for (size_t i = 0; i < b; ++i) ASSERT_EQ(starter[i], builtin[i]) << "line " << i + 1;
      for (size_t i = 0; i < after; ++i)
        ASSERT_EQ(starter[starter.size() - 1 - i], builtin[builtin.size() - 1 - i]) << "line " << starter.size() - i;
    }
  }
}

// A check of no points is a condition: refused unless a check requires it, and a rubric whose
// checks all have no points is refused too; required, it gates without earning.
TEST(Grade, ACheckOfNoPointsIsAConditionOthersRequire) {
  const fs::path root = fs::temp_directory_path() / "shadelab-condition-test";
  fs::remove_all(root);
  fs::create_directories(root / "shadows" / "c");
  const auto rubric = [&](const std::string& checks) {
    std::ofstream(root / "shadows" / "c" / "rubric.json")
        << R"({"title": "t", "lab": "shadows", "files": ["shadows/shadow_lookup.glsl"], "configurations": [
               {"name": "a", "range": [0, 1], "checks": [)" +
               checks + "]}]}";
    Exercise ex;
    return loadExercise(root, "shadows/c", ex);
  };
  const std::string range = R"({"name": "in range", "metric": "out_of_range_pct", "full": 0.5, "points": 0})";
  const std::string edges = R"({"name": "edges", "metric": "covered_rmse", "full": 0.004, "requires": "in range"})";
  std::string err = rubric(range + ", " + R"({"name": "edges", "metric": "covered_rmse", "full": 0.004})");
  EXPECT_NE(err.find("'in range' has no points and no check requires it"), std::string::npos) << err;
  err = rubric(R"({"name": "in range", "metric": "out_of_range_pct", "full": 0.5, "points": 0, "requires": "more"},
                  {"name": "more", "metric": "rmse", "full": 1, "points": 0, "requires": "in range"})");
  EXPECT_NE(err.find("no check has points"), std::string::npos) << err;
  err = rubric(R"({"name": "x", "metric": "rmse", "full": 1, "points": -1})");
  EXPECT_NE(err.find("\"points\" must be a number >= 0"), std::string::npos) << err;
  err = rubric(range + ", " + edges);
  EXPECT_EQ(err, "");
  fs::remove_all(root);

  Check inRange = check("0.5", "0.5"), hard = check("1", "1");
  inRange.name = "in range";
  inRange.points = 0;
  hard.name = "edges";
  hard.requiredCheck = "in range";
  std::vector<CheckResult> results = {scoreCheck(inRange, 40.0, 0.0), scoreCheck(hard, 0.0, 0.0)};
  applyRequirements(results);
  EXPECT_EQ(results[0].earned, 0.0);
  EXPECT_EQ(results[1].grade, Grade::Fail);
  EXPECT_EQ(results[1].earned, 0.0);
  ConfigurationResult c;
  c.name = "a";
  EXPECT_NE(checkLine(c, scoreCheck(inRange, 0.0, 0.0)).find("condition"), std::string::npos);
}

TEST(Grade, ABadRubricNamesItsFileAndKey) {
  const fs::path root = fs::temp_directory_path() / "shadelab-rubric-test";
  fs::remove_all(root);
  fs::create_directories(root / "shading" / "bad");
  std::ofstream(root / "shading" / "bad" / "rubric.json")
      << R"({"title": "t", "lab": "shading", "files": ["common/lighting.glsl"], "configurations": [
             {"name": "a", "checks": [{"name": "x", "metric": "psnr", "against": "solution", "full": 1}]}]})";
  Exercise ex;
  const std::string err = loadExercise(root, "shading/bad", ex);
  EXPECT_NE(err.find("rubric.json"), std::string::npos) << err;
  EXPECT_NE(err.find("metric 'psnr'"), std::string::npos) << err;
  EXPECT_NE(loadExercise(root, "shading/none", ex).find("valid: shading/bad"), std::string::npos);
  fs::remove_all(root);
}

TEST(Watchdog, AChildThatFinishesReportsItsExitCodeAndPhase) {
  const fs::path log = fs::temp_directory_path() / "shadelab-watchdog-exit.log";
  const WatchedRun run = runWatched(
      [](const auto& enter) {
        enter("solution");
        enter("student");
        return 3;
      },
      [](const std::string&) { return 30.0; }, log.string());
  EXPECT_EQ(run.end, WatchedRun::End::Exited);
  EXPECT_EQ(run.status, 3);
  EXPECT_EQ(run.phase, "student");
}

TEST(Watchdog, AChildStuckInAPhaseIsStoppedAtThatPhasesLimit) {
  const fs::path log = fs::temp_directory_path() / "shadelab-watchdog-loop.log";
  const auto start = std::chrono::steady_clock::now();
  const WatchedRun run = runWatched(
      [](const auto& enter) -> int {
        enter("solution");
        std::this_thread::sleep_for(std::chrono::milliseconds(600));  // longer than the student's limit: not counted
        enter("student");
        std::atomic<unsigned> spins{0};
        for (;;) spins.fetch_add(1u, std::memory_order_relaxed);  // never returns
      },
      [](const std::string& phase) { return phase == "student" ? 0.3 : 30.0; }, log.string());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(run.end, WatchedRun::End::TimedOut);
  EXPECT_EQ(run.phase, "student");
  EXPECT_GE(run.phaseSeconds, 0.3);
  EXPECT_GE(seconds, 0.9);  // the solution's phase ran to its end
  EXPECT_NE(run.describe().find("watchdog"), std::string::npos);
}

TEST(Watchdog, AChildThatCrashesIsReportedWithItsSignal) {
  const fs::path log = fs::temp_directory_path() / "shadelab-watchdog-crash.log";
  const WatchedRun run = runWatched(
      [](const auto&) {
        std::raise(SIGABRT);
        return 0;
      },
      [](const std::string&) { return 30.0; }, log.string());
  EXPECT_EQ(run.end, WatchedRun::End::Signalled);
  EXPECT_EQ(run.status, SIGABRT);
}

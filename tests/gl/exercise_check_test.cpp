// The window's Check: an exercise graded in place, in the window's own context, scored as
// `shadelab grade` scores it; the window's own frame is the same after a Check as before it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <fstream>

#include "app/grade/exercise_check.h"
#include "app/measure/image.h"
#include "app/measure/report.h"

#include <nlohmann/json.hpp>
#include "app/util/read_file.h"
#include "gl_test.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

const fs::path kShaders = fs::path(SHADELAB_SOURCE_DIR) / "shaders";
constexpr const char* kExercise = "shading/blinn-phong";
constexpr const char* kFile = "common/specular.glsl";

class Check : public ::testing::Test {
 protected:
  void SetUp() override {
    student = fs::temp_directory_path() / ("shadelab_check_" + std::to_string(::getpid()));
    fs::remove_all(student);
    fs::create_directories(student / "common");
  }
  void TearDown() override { fs::remove_all(student); }

  void submit(const std::string& text) { std::ofstream(student / kFile, std::ios::trunc) << text; }

  // Checks the exercise to the end, one step a call as the window does.
  const ExerciseResult& run(ExerciseCheck& check) {
    EXPECT_EQ(check.start(kExercise, {student}), "");
    int steps = 0;
    while (check.running() && steps++ < 100) check.step();
    EXPECT_FALSE(check.running());
    EXPECT_EQ(check.error(), "");
    EXPECT_EQ(check.configurationsDone(), check.configurations());
    return check.result();
  }

  fs::path student;
};

TEST_F(Check, TheLabsOwnFileScoresFullMarks) {
  submit(readWholeFile(kShaders / kFile));
  ExerciseCheck check;
  const ExerciseResult& r = run(check);
  EXPECT_TRUE(r.passed());
  EXPECT_DOUBLE_EQ(r.earned, r.total);
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes.front().find("the lab's own file, unchanged"), std::string::npos);
  EXPECT_NE(check.lines().back().find("passed"), std::string::npos) << check.lines().back();
}

TEST_F(Check, TheStarterScoresNothingAndEveryCheckSaysWhy) {
  submit(readWholeFile(builtinExercisesRoot() / kExercise / "starter" / kFile));
  ExerciseCheck check;
  const ExerciseResult& r = run(check);
  EXPECT_FALSE(r.passed());
  EXPECT_LT(r.percent(), 30.0);
  for (auto& c : r.configurations)
    for (auto& k : c.checks)
      if (k.grade != Grade::Full) EXPECT_FALSE(k.message.empty()) << c.name << ": " << k.check.name;
  EXPECT_NE(check.lines().back().find("NOT PASSED"), std::string::npos) << check.lines().back();
  // What Check shows beside the lines: per configuration that lost points, the student's frame, the
  // solution's and their difference, all of one size and not the same picture. The function probed
  // by itself has no checks and no pictures: it is evidence for the diagnosis.
  ASSERT_EQ(check.pictures().size(), r.configurations.size());
  for (size_t i = 0; i < r.configurations.size(); ++i) {
    const auto& p = check.pictures()[i];
    if (r.configurations[i].function) {
      EXPECT_TRUE(r.configurations[i].checks.empty());
      EXPECT_TRUE(p.student.rgba.empty()) << r.configurations[i].name;
      continue;
    }
    ASSERT_FALSE(p.student.rgba.empty()) << r.configurations[i].name;
    EXPECT_EQ(p.solution.size, p.student.size);
    EXPECT_EQ(p.difference.size, p.student.size);
    EXPECT_GT(compareImages(p.student, p.solution).rmse, 0.0) << r.configurations[i].name;
  }
}

// A configuration the rubric hides is graded by the course's grader, not drawn or named here; the
// result says that hidden checks exist.
TEST_F(Check, AHiddenConfigurationIsNeitherDrawnNorNamed) {
  const fs::path course = student.parent_path() / ("shadelab_hidden_course_" + std::to_string(::getpid()));
  fs::remove_all(course);
  fs::create_directories(course / "shading");
  fs::copy(builtinExercisesRoot() / kExercise, course / "shading" / "hidden-blinn", fs::copy_options::recursive);
  const fs::path rubricFile = course / "shading" / "hidden-blinn" / "rubric.json";
  nlohmann::json rubric = nlohmann::json::parse(readWholeFile(rubricFile));
  rubric["configurations"][1]["visibility"] = "hidden";
  const std::string hiddenName = rubric["configurations"][1]["name"];
  std::ofstream(rubricFile, std::ios::trunc) << rubric.dump(2);
  const fs::path starter = course / "shading" / "hidden-blinn" / "starter" / kFile;
  std::string text = readWholeFile(starter);  // its TODO region names the exercise
  for (size_t at; (at = text.find(kExercise)) != std::string::npos;)
    text.replace(at, std::strlen(kExercise), "shading/hidden-blinn");
  std::ofstream(starter, std::ios::trunc) << text;
  addCourseFolder(course);
  submit(text);
  ExerciseCheck check;
  ASSERT_EQ(check.start("shading/hidden-blinn", {student}), "");
  while (check.running()) check.step();
  EXPECT_EQ(check.hiddenConfigurations(), 1u);
  // The rubric's configurations but the hidden one, and each probe of the function by itself.
  EXPECT_EQ(check.configurations(),
            rubric["configurations"].size() - 1 + rubric.value("probes", nlohmann::json::array()).size());
  for (auto& c : check.result().configurations) EXPECT_NE(c.name, hiddenName);
  for (auto& line : check.lines()) EXPECT_EQ(line.find(hiddenName), std::string::npos) << line;
  bool said = false;
  for (auto& n : check.result().notes) said |= n.find("hidden by your teacher") != std::string::npos;
  EXPECT_TRUE(said);
  fs::remove_all(course);
}

// The classic mistake the hint names: H not normalised turns the highlight into a white disc.
TEST_F(Check, AnUnnormalisedHalfVectorLosesTheHighlightsPoints) {
  std::string text = readWholeFile(kShaders / kFile);
  const std::string half = "safeNormalize(L + V, N)";
  const size_t at = text.find(half);
  ASSERT_NE(at, std::string::npos) << "the solution's half vector is written differently now";
  text.replace(at, half.size(), "(L + V)");
  submit(text);
  ExerciseCheck check;
  const ExerciseResult& r = run(check);
  ASSERT_FALSE(r.configurations.empty());
  const CheckResult& highlight = r.configurations.front().checks.front();
  EXPECT_EQ(highlight.grade, Grade::Fail) << highlight.value;
  EXPECT_GT(highlight.value, 0.05);
}

// A slip no rubric lists (the clamp's 0 turned into 1: every specular factor at least 1): the
// Check draws the solution's slips once the diagnosis asks for them, and names it as the grader does.
TEST_F(Check, ASlipNoRubricListsIsNamedAfterTheSlipsAreDrawn) {
  std::string text = readWholeFile(kShaders / kFile);
  const std::string clamp = "safeNormalize(L + V, N)), 0.0)";
  const size_t at = text.find(clamp);
  ASSERT_NE(at, std::string::npos) << "the solution's clamp is written differently now";
  text.replace(at, clamp.size(), "safeNormalize(L + V, N)), 1.0)");
  submit(text);
  ExerciseCheck check;
  ASSERT_EQ(check.start(kExercise, {student}), "");
  bool drewSlips = false;
  for (int steps = 0; check.running() && steps < 100; ++steps) {
    check.step();
    drewSlips |= check.drawingSlips();
  }
  EXPECT_TRUE(drewSlips);
  const ExerciseResult& r = check.result();
  EXPECT_EQ(r.explanation, "slip:constant") << r.diagnosis;
  // The safe normalisation's arguments exchanged normalises N instead: N.N is 1 as well, so the
  // evidence cannot tell the two slips apart and names both, as `shadelab grade` does.
  EXPECT_NE(r.diagnosis.find("two slips draw them alike: either one constant at another value (in the solution's "
                             "terms, 1.0 where 0.0 belongs), or the first two arguments of safeNormalize exchanged"),
            std::string::npos)
      << r.diagnosis;
  for (auto& c : r.configurations) EXPECT_TRUE(!c.drawn || c.slipsDrawn) << c.name;

  // Checked again, the slips are kept with the solution's frames: none is drawn a second time.
  ASSERT_EQ(check.start(kExercise, {student}), "");
  while (check.running()) {
    check.step();
    EXPECT_FALSE(check.drawingSlips());
  }
  EXPECT_EQ(check.result().explanation, "slip:constant");
}

// A function no probe holds (PCF takes the lab's maps and structs) is traced in the lab's own draw
// by the Check as by `shadelab grade` (tests/grade/grade_test.cpp makes the same change): the slip
// it is, and the line of the change traced at the pixel where the frames differ most.
TEST_F(Check, AFunctionNoProbeHoldsIsTracedInTheLabsDraw) {
  std::string text = readWholeFile(kShaders / "shadows/pcf.glsl");
  const std::string centred = "vec2(i, j) - 0.5 * float(PCF_SIZE - 1));";
  const size_t at = text.find(centred);
  ASSERT_NE(at, std::string::npos) << "the solution's taps are written differently now";
  text.replace(at, centred.size(), "vec2(i, j) - float(PCF_SIZE - 1));");
  fs::create_directories(student / "shadows");
  std::ofstream(student / "shadows/pcf.glsl") << text;
  ExerciseCheck check;
  ASSERT_EQ(check.start("shadows/pcf", {student}), "");
  for (int steps = 0; check.running() && steps < 200; ++steps) check.step();
  ASSERT_EQ(check.error(), "");
  const ExerciseResult& r = check.result();
  EXPECT_EQ(r.explanation, "slip:constant") << r.diagnosis;
  EXPECT_NE(r.diagnosis.find("Traced line by line in the lab's draw: Line 9 of shadows/pcf.glsl"), std::string::npos)
      << r.diagnosis;
}

TEST_F(Check, AMissingFileIsNotSubmitted) {
  ExerciseCheck check;
  const ExerciseResult& r = run(check);
  EXPECT_EQ(r.outcome(), Outcome::NotSubmitted);
  EXPECT_EQ(r.earned, 0.0);
  ASSERT_FALSE(r.configurations.empty());
  EXPECT_NE(r.configurations.front().checks.front().message.find(kFile), std::string::npos);
}

TEST_F(Check, AFileThatDoesNotCompileIsNamedAtItsLine) {
  submit("float specularFactor(vec3 N, vec3 L, vec3 V) {\n  return max(dot(N, normalize(L + V)), 0.0)\n}\n");
  ExerciseCheck check;
  const ExerciseResult& r = run(check);
  EXPECT_EQ(r.outcome(), Outcome::DidNotBuild);
  EXPECT_EQ(r.earned, 0.0);
  bool named = false;
  for (auto& line : check.lines())
    named |= line.find(kFile) != std::string::npos && line.find("error") != std::string::npos;
  EXPECT_TRUE(named);
}

// Open the starter: copied where the student has no file, never over one they have (their work),
// and then Check grades what was copied.
TEST_F(Check, TheStarterIsCopiedOnlyWhereTheStudentHasNoFile) {
  Exercise ex;
  ASSERT_EQ(loadExercise(kExercise, ex), "");
  fs::remove_all(student);
  std::vector<std::string> copied, kept;
  ASSERT_EQ(copyStarter(ex, student, copied, kept), "");
  EXPECT_EQ(copied, std::vector<std::string>{kFile});
  EXPECT_TRUE(kept.empty());
  EXPECT_EQ(readWholeFile(student / kFile), readWholeFile(ex.dir / "starter" / kFile));

  submit("// my work\n" + readWholeFile(kShaders / kFile));
  copied.clear();
  ASSERT_EQ(copyStarter(ex, student, copied, kept), "");
  EXPECT_TRUE(copied.empty());
  EXPECT_EQ(kept, std::vector<std::string>{kFile});
  EXPECT_EQ(readWholeFile(student / kFile).rfind("// my work\n", 0), 0u) << "the student's file was overwritten";

  ExerciseCheck check;
  EXPECT_TRUE(run(check).passed());  // their (correct) work, not the starter, is what is graded

  // A rubric naming a file outside the shader folders is refused, and nothing is written.
  Exercise bad = ex;
  bad.files = {"../outside.glsl"};
  copied.clear();
  EXPECT_NE(copyStarter(bad, student, copied, kept).find("is not a name inside a shader folder"), std::string::npos);
  EXPECT_FALSE(fs::exists(student.parent_path() / "outside.glsl"));
}

TEST(CheckStart, AnUnknownExerciseSaysWhichAreThere) {
  ExerciseCheck check;
  const std::string e = check.start("shading/nope", {});
  EXPECT_NE(e.find("unknown exercise 'shading/nope'"), std::string::npos) << e;
  EXPECT_NE(e.find(kExercise), std::string::npos) << e;
  EXPECT_FALSE(check.running());
}

// The Check draws between the window's frames in the window's context: what it binds and enables
// must not leak into the window's next frame.
TEST_F(Check, TheWindowsFrameIsTheSameAfterACheck) {
  auto host = test::labHost("shadows", nullptr, {});
  const glm::ivec2 size{320, 240};
  host->renderFrame(size);
  const ImageF before = host->readImage();
  submit(readWholeFile(kShaders / kFile));
  ExerciseCheck check;
  run(check);
  host->renderFrame(size);
  const ImageF after = host->readImage();
  EXPECT_LT(compareImages(after, before).maxError, 1e-6);
}

}  // namespace

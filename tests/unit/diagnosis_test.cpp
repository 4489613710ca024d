// The evidence a diagnosis rests on, on images made here: non-finite pixels counted and boxed,
// values out of the view's range, umbra and lit levels, an edge shifted or widened against the
// solution's; then which mistake explains a set of frames, and hints that need evidence.
#include "app/grade/diagnosis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "app/grade/frame_properties.h"

using namespace shadelab;

namespace {

// A visibility frame: 0 left of the edge at `edge`, 1 right of it, a linear ramp `width` wide.
ImageF edgeImage(float edge, float width, glm::ivec2 size = {64, 48}) {
  ImageF img;
  img.size = size;
  img.rgba.resize(size_t(size.x) * size.y * 4);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const float v = width > 0 ? std::clamp((float(x) + 0.5f - edge) / width + 0.5f, 0.0f, 1.0f) : float(x >= edge);
      float* p = img.at(x, y);
      p[0] = p[1] = p[2] = v;
      p[3] = 1.0f;
    }
  return img;
}

const ViewRange kVisibility{true, 0.0f, 1.0f};

}  // namespace

TEST(FrameProperties, NanAndInfAreCountedApartWithTheirBox) {
  const ImageF solution = edgeImage(32, 8);
  ImageF student = solution;
  student.at(5, 7)[0] = std::nanf("");
  student.at(9, 3)[1] = std::nanf("");
  student.at(20, 30)[2] = std::numeric_limits<float>::infinity();
  const FrameProperties p = measureFrameProperties(student, solution, nullptr, kVisibility);
  EXPECT_EQ(p.nanPixels, 2u);
  EXPECT_EQ(p.infPixels, 1u);
  EXPECT_EQ(p.nonFiniteBox, glm::ivec4(5, 3, 20, 30));
  EXPECT_EQ(p.nonFiniteText(), "2 NaN and 1 Inf pixels in x 5-20, y 3-30");
  EXPECT_TRUE(measureFrameProperties(solution, solution, nullptr, kVisibility).nonFiniteText().empty());
}

TEST(FrameProperties, ASumInsteadOfAnAverageLeavesTheRange) {
  const ImageF solution = edgeImage(32, 8);
  ImageF student = solution;
  for (auto& v : student.rgba) v *= 25.0f;  // alpha too: still covered
  const FrameProperties p = measureFrameProperties(student, solution, nullptr, kVisibility);
  EXPECT_GT(p.outOfRangePct, 40.0);
  // Unbounded views (shaded colour) have no range to leave.
  EXPECT_EQ(measureFrameProperties(student, solution, nullptr, {}).outOfRangePct, 0.0);
}

TEST(FrameProperties, UmbraAndLitLevelsSayHowFarTheRegionsStayFromTheirEnds) {
  const ImageF solution = edgeImage(32, 4);
  ImageF lifted = solution;
  for (size_t i = 0; i < lifted.rgba.size(); i += 4)
    lifted.rgba[i] = lifted.rgba[i + 1] = lifted.rgba[i + 2] = 0.3f + 0.4f * lifted.rgba[i];
  const FrameProperties p = measureFrameProperties(lifted, solution, nullptr, kVisibility);
  EXPECT_NEAR(p.umbraLevel, 0.3, 1e-6);
  EXPECT_NEAR(p.litLevel, 0.3, 1e-6);
  // The truth narrows the masks: where it disagrees with the solution, nothing is asked.
  ImageF truth = solution;
  for (auto& v : truth.rgba) v = 0.5f;
  for (size_t i = 3; i < truth.rgba.size(); i += 4) truth.rgba[i] = 1.0f;
  const FrameProperties none = measureFrameProperties(lifted, solution, &truth, kVisibility);
  EXPECT_EQ(none.umbraLevel, 0.0);
  EXPECT_EQ(none.litLevel, 0.0);
}

TEST(FrameProperties, AShiftedEdgeIsFoundByItsBestMatchingShift) {
  const FrameProperties shifted = measureFrameProperties(edgeImage(35, 6), edgeImage(32, 6), nullptr, kVisibility);
  EXPECT_EQ(shifted.edgeShift, glm::ivec2(3, 0));
  EXPECT_DOUBLE_EQ(shifted.edgeShiftPx, 3.0);
  const FrameProperties same = measureFrameProperties(edgeImage(32, 6), edgeImage(32, 6), nullptr, kVisibility);
  EXPECT_EQ(same.edgeShiftPx, 0.0);
}

TEST(FrameProperties, AWiderOrAHardEdgeChangesTheWidthRatio) {
  EXPECT_NEAR(measureFrameProperties(edgeImage(32, 16), edgeImage(32, 8), nullptr, kVisibility).edgeWidthRatio, 2.0,
              0.3);
  EXPECT_NEAR(measureFrameProperties(edgeImage(32, 0), edgeImage(32, 8), nullptr, kVisibility).edgeWidthRatio, 0.0,
              1e-9);
  // No edge in the solution: nothing to compare, the ratio reads as right.
  EXPECT_EQ(measureFrameProperties(edgeImage(32, 8), edgeImage(-10, 0), nullptr, kVisibility).edgeWidthRatio, 1.0);
}

TEST(FrameProperties, FrameDistanceCountsANanAgainstAFiniteValueAsTheLargestDifference) {
  const ImageF a = edgeImage(32, 8);
  ImageF b = a;
  EXPECT_EQ(frameDistance(a, b), 0.0);
  for (auto& v : b.rgba) v = std::nanf("");
  EXPECT_NEAR(frameDistance(a, b), 1.0, 1e-9);
  EXPECT_EQ(frameDistance(b, b), 0.0) << "NaN where the other frame has NaN too";
}

namespace {

// An exercise with two configurations and the starter plus two mistakes.
Exercise twoMistakes() {
  Exercise ex;
  ex.id = "test/two";
  for (const char* name : {"starter", "sign", "scale"}) {
    Mistake m;
    m.name = name;
    m.starter = m.name == "starter";
    m.diagnosis = std::string("because ") + name;
    ex.mistakes.push_back(m);
  }
  return ex;
}

ConfigurationResult drawn(const std::string& name, double toSolution, std::vector<double> toMistakes,
                          std::vector<double> separations, double earned = 0.0) {
  ConfigurationResult c;
  c.name = name;
  c.drawn = true;
  c.distance = toSolution;
  c.mistakeDistances = std::move(toMistakes);
  c.mistakeSeparations = std::move(separations);
  CheckResult r;
  r.check.name = "match";
  r.check.metric = "covered_rmse";
  r.check.points = 1.0;
  r.earned = earned;
  r.grade = earned >= 1.0 ? Grade::Full : Grade::Fail;
  c.checks.push_back(r);
  return c;
}

}  // namespace

TEST(Diagnosis, TheMistakeClearlyCloserThanTheSolutionWhereItDiffersExplainsTheFrames) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  // "sign" differs from the solution in both configurations; the student sits on it.
  e.configurations = {drawn("a", 0.10, {0.2, 0.001, 0.09}, {0.2, 0.1, 0.02}),
                      drawn("b", 0.12, {0.2, 0.002, 0.12}, {0.2, 0.12, 0.0})};
  diagnose(ex, e);
  EXPECT_EQ(e.mistake, "sign");
  EXPECT_EQ(e.diagnosis, "because sign");
  // "scale" differs only in "a", where the student is not much nearer to it than to the solution.
  EXPECT_EQ(explainingMistake(ex, e), 1);
}

TEST(Diagnosis, NothingCloseEnoughFallsBackToTheEvidence) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  e.configurations = {drawn("a", 0.10, {0.2, 0.09, 0.12}, {0.2, 0.1, 0.05}),
                      drawn("b", 0.0, {0.2, 0.1, 0.0}, {0.2, 0.1, 0.0}, 1.0)};
  e.configurations[0].nanPixels = 12;
  e.configurations[0].nonFiniteText = "12 NaN pixels in x 1-4, y 2-5";
  diagnose(ex, e);
  EXPECT_TRUE(e.mistake.empty());
  EXPECT_NE(e.diagnosis.find("12 NaN pixels in x 1-4, y 2-5"), std::string::npos) << e.diagnosis;
  // No NaN: the one configuration that lost points is named.
  e.configurations[0].nanPixels = 0;
  diagnose(ex, e);
  EXPECT_EQ(e.diagnosis.rfind("Only 'a' loses points", 0), 0u) << e.diagnosis;
  // Full marks: no diagnosis at all.
  e.configurations[0].checks[0].earned = 1.0;
  e.configurations[0].checks[0].grade = Grade::Full;
  e.earned = 2.0;
  diagnose(ex, e);
  EXPECT_TRUE(e.diagnosis.empty());
}

TEST(Diagnosis, AHintIsShownOnlyWhenTheChecksItNeedsWentAsTheRubricSays) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  e.configurations = {drawn("directional", 0.1, {}, {}), drawn("point", 0.1, {}, {})};
  CheckResult& cube = e.configurations[1].checks[0];
  cube.check.hint = "the cube map";
  cube.check.hintIfPassed = {"directional: match"};
  cube.message = cube.check.hint;
  diagnose(ex, e);
  EXPECT_EQ(e.configurations[1].checks[0].message, "") << "the directional configuration failed too";
  e.configurations[0].checks[0].grade = Grade::Full;
  e.configurations[0].checks[0].earned = 1.0;
  e.earned = 1.0;
  e.configurations[1].checks[0].message = "the cube map";
  diagnose(ex, e);
  EXPECT_EQ(e.configurations[1].checks[0].message, "the cube map");
}

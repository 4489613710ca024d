// The evidence a diagnosis rests on, on images made here: non-finite pixels counted and boxed,
// values out of the view's range, umbra and lit levels, an edge shifted or widened against the
// solution's; then which mistake explains a set of frames, and hints that need evidence.
#include "app/grade/diagnosis.h"
#include "app/grade/frame_causes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "app/grade/frame_properties.h"
#include "app/grade/frame_relations.h"

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
  EXPECT_NEAR(p.outsideMedian, 25.0, 1e-4) << "the lit half, 1 x 25: where the values went";
  // The cause names the range and where the values went, whatever the lab.
  ConfigurationResult c;
  c.name = "lit";
  c.outOfRangePct = p.outOfRangePct;
  c.outsideMedian = p.outsideMedian;
  const std::string said = propertyCause(c, kVisibility).text;
  EXPECT_NE(said.find("range, [0, 1], in 'lit'"), std::string::npos) << said;
  EXPECT_NE(said.find("their median is 25"), std::string::npos) << said;
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

TEST(FrameProperties, DrawnDistanceCountsWhatOnlyOneFrameDrawsButNotAMovedSilhouette) {
  const auto disc = [](float cx, bool drawn) {
    ImageF im;
    im.size = {32, 32};
    im.rgba.assign(32 * 32 * 4, 0.0f);
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        if (drawn && (x - cx) * (x - cx) + (y - 16.0f) * (y - 16.0f) < 64.0f) {
          float* p = im.at(x, y);
          p[0] = p[1] = p[2] = 0.5f;
          p[3] = 1.0f;
        }
    return im;
  };
  // Nothing drawn against a drawn disc: frameDistance sees no pixel both cover; drawnDistance the largest.
  EXPECT_EQ(frameDistance(disc(16, false), disc(16, true)), 0.0);
  EXPECT_DOUBLE_EQ(drawnDistance(disc(16, false), disc(16, true)), 1.0);
  // The same disc a pixel to the side: every pixel one covers alone touches the other's surface.
  EXPECT_EQ(drawnDistance(disc(16, true), disc(17, true)), 0.0);
  EXPECT_GT(drawnDistance(disc(12, true), disc(20, true)), 0.3);
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
  EXPECT_TRUE(e.notes.empty()) << "a listed mistake named: no word on the evidence it lacked";
  EXPECT_EQ(e.explanation, "mistake:sign");
  EXPECT_EQ(e.diagnosis.rfind("because sign (Evidence: where this mistake shows, in 'a' and 'b', your frames are its "
                              "frames.)",
                              0),
            0u)
      << e.diagnosis;
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
  // No probe of the function in this exercise: the report says the frames are all it had, once.
  ASSERT_EQ(e.notes.size(), 1u);
  EXPECT_NE(e.notes[0].find("rests on the frames alone"), std::string::npos) << e.notes[0];
  // No NaN: the one configuration that lost points is named.
  e.configurations[0].nanPixels = 0;
  diagnose(ex, e);
  EXPECT_EQ(e.diagnosis.rfind("Only 'a' loses points", 0), 0u) << e.diagnosis;
  EXPECT_EQ(e.notes.size(), 1u);
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

namespace {

// A frame with structure in x, y and every channel, so that no relation holds by accident.
ImageF pattern(glm::ivec2 size = {64, 48}) {
  ImageF img;
  img.size = size;
  img.rgba.resize(size_t(size.x) * size.y * 4);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      float* p = img.at(x, y);
      p[0] = 0.1f + 0.8f * float(x) / float(size.x);
      p[1] = 0.2f + 0.6f * float(y) / float(size.y);
      p[2] = 0.5f + 0.4f * std::sin(0.3f * float(x) + 0.2f * float(y));
      p[3] = 1.0f;
    }
  return img;
}

template <class F>
ImageF mapped(const ImageF& in, F f) {
  ImageF out = in;
  for (size_t i = 0; i < out.rgba.size(); i += 4) f(&out.rgba[i]);
  return out;
}

std::string bestRelation(const ImageF& student, const ImageF& solution, const ViewRange& range = kVisibility) {
  const auto r = relateFrames(student, solution, range);
  return r.empty() ? "" : r.front().kind;
}

}  // namespace

TEST(FrameRelations, EachTransformOfTheSolutionIsFoundAsItself) {
  const ImageF solution = pattern();
  EXPECT_EQ(bestRelation(solution, solution), "") << "equal frames relate trivially";
  EXPECT_EQ(bestRelation(mapped(solution,
                                [](float* p) {
                                  for (int c = 0; c < 3; ++c) p[c] = 1.0f - p[c];
                                }),
                         solution),
            "complement");
  const auto scaled = relateFrames(mapped(solution,
                                          [](float* p) {
                                            for (int c = 0; c < 3; ++c) p[c] *= 0.5f;
                                          }),
                                   solution, kVisibility);
  ASSERT_FALSE(scaled.empty());
  EXPECT_EQ(scaled.front().kind, "affine");
  EXPECT_NEAR(scaled.front().a, 0.5, 1e-3);
  EXPECT_NEAR(scaled.front().b, 0.0, 1e-3);
  EXPECT_EQ(describeRelation(scaled.front(), kVisibility, "red, green, blue"), "the solution's scaled by 0.5");
  EXPECT_EQ(bestRelation(mapped(solution,
                                [](float* p) {
                                  for (int c = 0; c < 3; ++c) p[c] *= p[c];
                                }),
                         solution),
            "squared");
  EXPECT_EQ(bestRelation(mapped(solution, [](float* p) { std::swap(p[0], p[1]); }), solution), "swapped-rg");
  const ImageF flipped = mapped(solution, [](float* p) { p[1] = 1.0f - p[1]; });
  const auto f = relateFrames(flipped, solution, kVisibility);
  ASSERT_FALSE(f.empty());
  EXPECT_EQ(f.front().kind, "flipped-g");
  EXPECT_EQ(describeRelation(f.front(), kVisibility, "the normal's x, y, z"),
            "the solution's with its y turned over (x becomes 1 - x)")
      << "the channels are named in the exercise's terms";
  ImageF mirrored = solution;
  for (int y = 0; y < solution.size.y; ++y)
    for (int x = 0; x < solution.size.x; ++x)
      std::copy(solution.at(solution.size.x - 1 - x, y), solution.at(solution.size.x - 1 - x, y) + 4,
                mirrored.at(x, y));
  EXPECT_EQ(bestRelation(mirrored, solution), "mirrored-x");
  const auto shifted = relateFrames(edgeImage(35, 6), edgeImage(32, 6), kVisibility);
  ASSERT_FALSE(shifted.empty());
  EXPECT_EQ(shifted.front().kind, "shifted");
  EXPECT_EQ(shifted.front().a, 3.0);
  // Noise is no relation: a frame unrelated to the solution's matches none.
  const ImageF other = mapped(solution, [](float* p) {
    p[0] = std::fmod(p[0] * 7.3f, 1.0f);
    p[2] = 0.3f;
  });
  EXPECT_EQ(bestRelation(other, solution), "");
}

namespace {

// A relation to the solution's frame found in configuration c, with its residual.
void withRelation(ConfigurationResult& c, const std::string& kind, double residual) {
  FrameRelation r;
  r.kind = kind;
  r.residual = residual;
  c.relations.push_back(r);
}

}  // namespace

TEST(Diagnosis, ARelationThatFitsFarBetterThanAnyMistakeIsNamedInstead) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  // The student's frames lie nearer "sign" than the solution (0.3 of the way), but the solution turned
  // over is theirs exactly: the mistake is not named.
  e.configurations = {drawn("a", 0.5, {0.6, 0.15, 0.5}, {0.6, 0.5, 0.0}),
                      drawn("b", 0.4, {0.6, 0.12, 0.4}, {0.6, 0.4, 0.0})};
  withRelation(e.configurations[0], "complement", 0.0);
  withRelation(e.configurations[1], "complement", 0.001);
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "relation:complement") << e.diagnosis;
  EXPECT_TRUE(e.mistake.empty());
  EXPECT_NE(e.diagnosis.find("turned over"), std::string::npos) << e.diagnosis;
  EXPECT_NE(e.diagnosis.find("in every configuration"), std::string::npos) << e.diagnosis;
  // A relation must hold in every configuration that lost points; without it the mistake, which
  // agrees where it shows, is named.
  e.configurations[1].relations.clear();
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "like:sign") << "close to the mistake's frames, not on them: " << e.diagnosis;
  EXPECT_EQ(e.diagnosis.find("Your frames come close to what a known mistake draws"), 0u) << e.diagnosis;
}

TEST(Diagnosis, AMistakeIsNotNamedWhereTheStudentLosesPointsItCannotExplain) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  // "scale" differs only in "a"; the student sits on it there but loses points in "b" too.
  e.configurations = {drawn("a", 0.1, {0.3, 0.1, 0.001}, {0.3, 0.0, 0.1}),
                      drawn("b", 0.2, {0.3, 0.2, 0.2}, {0.3, 0.0, 0.0})};
  diagnose(ex, e);
  EXPECT_TRUE(e.mistake.empty()) << e.diagnosis;
  EXPECT_EQ(e.explanation, "evidence") << e.diagnosis;
  EXPECT_EQ(e.diagnosis.find("No known mistake"), 0u) << e.diagnosis;
}

TEST(Diagnosis, TwoMistakesMadeTogetherAreBothNamed) {
  Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 3.0;
  // "sign" shows alone in "a", "scale" alone in "b", both in "c".
  e.configurations = {drawn("a", 0.1, {0.3, 0.0, 0.1}, {0.3, 0.1, 0.0}),
                      drawn("b", 0.2, {0.3, 0.2, 0.001}, {0.3, 0.0, 0.2}),
                      drawn("c", 0.3, {0.3, 0.2, 0.1}, {0.3, 0.1, 0.2})};
  // Where both show, the student's frame must be the two changes together.
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "evidence") << e.diagnosis;
  e.configurations[2].pairDistances = {{1, 2, 0.01}};
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "mistakes:sign+scale") << e.diagnosis;
  EXPECT_NE(e.diagnosis.find("because sign"), std::string::npos);
  EXPECT_NE(e.diagnosis.find("because scale"), std::string::npos);
}

TEST(Diagnosis, TheStarterIsNamedOnlyWhenTheFileIsTheStarters) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  e.configurations = {drawn("a", 0.3, {0.0, 0.3, 0.3}, {0.3, 0.1, 0.1}),
                      drawn("b", 0.3, {0.0, 0.3, 0.3}, {0.3, 0.1, 0.1})};
  e.starterUnchanged = true;
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "starter");
  EXPECT_EQ(e.diagnosis, "because starter");
  e.starterUnchanged = false;
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "starter-result");
  EXPECT_EQ(e.diagnosis.find("Your frames are the starter's, though your file is not"), 0u) << e.diagnosis;
}

TEST(Diagnosis, WhereTheFramesDifferIsSaidAsTheSettingThatSetsThoseConfigurationsApart) {
  Exercise ex = twoMistakes();
  for (const char* light : {"directional", "spot", "spot"}) {
    Configuration c;
    c.name = std::string(light) + std::to_string(ex.configurations.size());
    c.settings = {{"filter", "hard"}, {"light_type", light}};
    ex.configurations.push_back(c);
  }
  ExerciseResult e;
  e.total = 3.0;
  e.configurations = {drawn(ex.configurations[0].name, 0.0, {}, {}, 1.0), drawn(ex.configurations[1].name, 0.2, {}, {}),
                      drawn(ex.configurations[2].name, 0.2, {}, {})};
  e.earned = 1.0;
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "where:light_type=spot") << e.diagnosis;
  EXPECT_NE(e.diagnosis.find("differ only where light_type is spot ('spot1' and 'spot2')"), std::string::npos)
      << e.diagnosis;
}

TEST(Diagnosis, AFromScratchExerciseIsToldTheCauseAndNotTheFix) {
  Exercise ex = twoMistakes();
  ex.mistakes[1].fix = "Write it so.";
  ExerciseResult e;
  e.total = 1.0;
  e.configurations = {drawn("a", 0.1, {0.3, 0.0, 0.1}, {0.3, 0.1, 0.0})};
  ex.reveal = "cause";
  diagnose(ex, e);
  EXPECT_EQ(e.diagnosis.find("Write it so."), std::string::npos) << e.diagnosis;
  ex.reveal = "cause-and-fix";
  diagnose(ex, e);
  EXPECT_EQ(e.diagnosis.find("because sign Write it so."), 0u) << e.diagnosis;
}

namespace {

// Slip `index` of the solution drawn in configuration c: its frame `separation` from the solution's,
// the student's `distance` from it; `base` the student's from the solution's at the slips' size.
void withSlip(ConfigurationResult& c, int index, const std::string& kind, double separation, double distance,
              double base) {
  c.slipsDrawn = true;
  c.slipBase = base;
  c.slips.push_back({index, kind, "cause " + kind, "cause " + kind + " and its fix", separation, distance});
}

}  // namespace

TEST(Diagnosis, ASlipOfTheSolutionWhoseFramesAreTheStudentsIsNamedWithoutAList) {
  Exercise ex = twoMistakes();
  ex.reveal = "cause";
  ExerciseResult e;
  e.total = 3.0;
  // The student loses points in "a" and "b" and matches in "c"; no listed mistake comes near.
  e.configurations = {drawn("a", 0.3, {0.4, 0.3, 0.3}, {0.4, 0.0, 0.0}),
                      drawn("b", 0.2, {0.4, 0.2, 0.2}, {0.4, 0.0, 0.0}),
                      drawn("c", 0.0, {0.4, 0.0, 0.0}, {0.4, 0.0, 0.0}, 1.0)};
  withSlip(e.configurations[0], 3, "comparison", 0.3, 0.001, 0.3);
  withSlip(e.configurations[1], 3, "comparison", 0.2, 0.0, 0.2);
  e.configurations[2].slipsDrawn = true;  // the slip draws the solution's frame in "c", as the student does
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "slip:comparison") << e.diagnosis;
  EXPECT_TRUE(e.mistake.empty());
  EXPECT_EQ(e.diagnosis.find("Your frames are the solution's with one slip: cause comparison."), 0u) << e.diagnosis;
  EXPECT_NE(e.diagnosis.find("in 'a' and 'b', your frames are its frames; where it draws the solution's"),
            std::string::npos)
      << e.diagnosis;
  // Where the exercise reveals fixes, the slip's sentence with what the solution has in its place.
  ex.reveal = "cause-and-fix";
  diagnose(ex, e);
  EXPECT_NE(e.diagnosis.find("cause comparison and its fix"), std::string::npos) << e.diagnosis;

  // A second slip drawing the same frames with another cause: both are named, neither alone.
  withSlip(e.configurations[0], 7, "operator", 0.3, 0.001, 0.3);
  withSlip(e.configurations[1], 7, "operator", 0.2, 0.001, 0.2);
  diagnose(ex, e);
  EXPECT_NE(e.diagnosis.find("either cause comparison and its fix, or cause operator and its fix"), std::string::npos)
      << e.diagnosis;

  // The slips also change "c", where the student's frame is the solution's: not the student's slip.
  for (int index : {3, 7}) withSlip(e.configurations[2], index, "comparison", 0.1, 0.1, 0.0);
  diagnose(ex, e);
  EXPECT_NE(e.explanation.rfind("slip:", 0), 0u) << e.diagnosis;

  // Frames near a slip's but not on it (a tenth of the distance or more away) name no slip.
  e.configurations[2].slips.clear();
  for (auto& c : e.configurations)
    for (auto& s : c.slips) s.distance = 0.5 * c.slipBase;
  diagnose(ex, e);
  EXPECT_NE(e.explanation.rfind("slip:", 0), 0u) << e.diagnosis;

  // Slips not drawn for a configuration the student drew (the window draws them on demand): no slip
  // is named, and the diagnosis asks for them.
  for (auto& c : e.configurations)
    for (auto& s : c.slips) s.distance = 0.0;
  e.configurations[2].slipsDrawn = false;
  diagnose(ex, e);
  EXPECT_NE(e.explanation.rfind("slip:", 0), 0u) << e.diagnosis;
}

TEST(Diagnosis, ASlipOnTheFramesBeatsAListedMistakeThatIsOnlyNearThem) {
  const Exercise ex = twoMistakes();
  ExerciseResult e;
  e.total = 2.0;
  // "sign" agrees loosely (the student 0.3 of the way from it); a slip draws the student's frames.
  e.configurations = {drawn("a", 0.5, {0.6, 0.15, 0.5}, {0.6, 0.5, 0.0}),
                      drawn("b", 0.4, {0.6, 0.12, 0.4}, {0.6, 0.4, 0.0})};
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "like:sign") << e.diagnosis;
  EXPECT_TRUE(slipsNeeded(e)) << "a mistake only near the frames: the window draws the slips";
  withSlip(e.configurations[0], 0, "constant", 0.5, 0.0, 0.5);
  withSlip(e.configurations[1], 0, "constant", 0.4, 0.0, 0.4);
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "slip:constant") << e.diagnosis;
  EXPECT_TRUE(e.mistake.empty());
  EXPECT_FALSE(slipsNeeded(e));
}

TEST(Diagnosis, SlipsOfOneCauseWithDifferentFixesAreToldTheCauseAlone) {
  const Exercise ex = twoMistakes();  // reveals fixes
  ExerciseResult e;
  e.total = 1.0;
  e.configurations = {drawn("a", 0.3, {0.4, 0.3, 0.3}, {0.4, 0.0, 0.0})};
  // Either sign of a difference of two samples turned round makes it zero: same cause, two fixes.
  withSlip(e.configurations[0], 0, "operator", 0.3, 0.0, 0.3);
  withSlip(e.configurations[0], 4, "operator", 0.3, 0.0, 0.3);
  e.configurations[0].slips[1].causeAndFix = "cause operator and another fix";
  diagnose(ex, e);
  EXPECT_EQ(e.explanation, "slip:operator") << e.diagnosis;
  EXPECT_EQ(e.diagnosis.find("Your frames are the solution's with one slip: cause operator. "), 0u) << e.diagnosis;
}

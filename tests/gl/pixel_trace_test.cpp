// The inspector's trace (grade/pixel_trace.h): the exercised function traced in the lab's own
// draw at one pixel, the student's beside the solution's.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "app/grade/configuration_frames.h"
#include "app/grade/pixel_trace.h"
#include "app/util/read_file.h"
#include "gl_test.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// The lines of `changed` (1-based, inclusive) that differ from `original`: the rest is their
// common head and tail.
std::pair<int, int> changedLines(const std::string& original, const std::string& changed) {
  const std::vector<std::string> a = linesOf(original), b = linesOf(changed);
  size_t head = 0, tail = 0;
  while (head < a.size() && head < b.size() && a[head] == b[head]) ++head;
  while (tail < a.size() - head && tail < b.size() - head && a[a.size() - 1 - tail] == b[b.size() - 1 - tail]) ++tail;
  return {int(head) + 1, int(b.size() - tail)};
}

ImageF frameOf(const Exercise& ex, const Configuration& c, const std::vector<fs::path>& roots) {
  std::string error;
  const auto host = configuredHost(roots, ex, c, error);
  EXPECT_EQ(error, "");
  host->settle();
  host->renderFrame(ex.size);
  return host->readImage();
}

// Whether point `from` is on a changed line or made, through the values it reads, of one set on
// a changed line: a value the mistake makes may still be one the solution computes elsewhere (a
// coordinate without its half-texel shift is the solution's before it shifts), and then the first
// value that is no longer the solution's lies after it.
bool madeOfTheChange(const std::vector<TracePoint>& points, std::vector<int> open, std::pair<int, int> changed) {
  std::vector<bool> seen(points.size(), false);
  while (!open.empty()) {
    const int k = open.back();
    open.pop_back();
    if (seen[size_t(k)]) continue;
    seen[size_t(k)] = true;
    if (points[size_t(k)].line >= changed.first && points[size_t(k)].line <= changed.second) return true;
    for (int q : points[size_t(k)].from) open.push_back(q);
  }
  return false;
}

// The points the departure names.
std::vector<int> departurePoints(const PixelInspection& in) {
  std::vector<int> out;
  const std::vector<TracePoint>& points = in.student.values.points;
  for (size_t k = 0; k < points.size(); ++k)
    if (points[k].line == in.departure.line &&
        (points[k].name == in.departure.name || points[k].statement == in.departure.name))
      out.push_back(int(k));
  return out;
}

// The configuration whose frame the mistake changes most, and the pixel where it does.
std::pair<size_t, glm::ivec2> whereItShows(const Exercise& ex, const fs::path& mistake) {
  size_t best = 0;
  glm::ivec2 pixel{0};
  float most = -1.0f;
  for (size_t i = 0; i < ex.configurations.size(); ++i) {
    const Configuration& c = ex.configurations[i];
    if (c.function >= 0) continue;
    const ImageF a = frameOf(ex, c, {mistake, builtinShaderDir()}), b = frameOf(ex, c, {builtinShaderDir()});
    const glm::ivec2 p = mostDifferentPixel(a, b);
    float d = 0.0f;
    for (int k = 0; k < 3; ++k) d += std::abs(a.at(p.x, p.y)[k] - b.at(p.x, p.y)[k]);
    if (d > most) {
      most = d;
      best = i;
      pixel = p;
    }
  }
  return {best, pixel};
}

struct Case {
  const char* exercise;
  const char* mistake;
  // Whether the mistake reaches the marked value through values (data) rather than through a
  // branch it turns (control): a count that a turned comparison stops incrementing is wrong on
  // its own line, which the comparison is not part of.
  bool throughValues = true;
};

class PixelTrace : public ::testing::TestWithParam<Case> {};

// A listed mistake, inspected at the pixel where its frames differ most from the solution's (in
// the configuration where they do): the line the inspector marks, or the first it names when none
// stands out, is never before the mistake and is made of what it changed; where it names none, it
// says that it cannot. The solution's own file, inspected at the same pixel, departs nowhere.
TEST_P(PixelTrace, AListedMistakeDepartsOnALineItChanged) {
  Exercise ex;
  ASSERT_EQ(loadExercise(GetParam().exercise, ex), "");
  const auto m = std::find_if(ex.mistakes.begin(), ex.mistakes.end(),
                              [](const Mistake& m) { return m.name == GetParam().mistake; });
  ASSERT_NE(m, ex.mistakes.end()) << GetParam().mistake;
  const fs::path dir = fs::temp_directory_path() / ("shadelab_pixel_" + std::to_string(getpid()));
  fs::remove_all(dir);
  ASSERT_EQ(writeMistakeFolder(ex, *m, dir), "");
  const std::string file = ex.files.front();
  const std::pair<int, int> changed = changedLines(labText(ex, file), readWholeFile(dir / file));
  const auto [config, pixel] = whereItShows(ex, dir);

  PixelInspection mine;
  ASSERT_EQ(inspectPixel(ex, config, {dir}, pixel, mine), "");
  const std::string text = formatInspection(mine);
  std::printf("%s", text.c_str());  // the table as a student reads it, in the test's log
  EXPECT_TRUE(mine.note.empty()) << text;
  const std::string where =
      "lines " + std::to_string(changed.first) + "-" + std::to_string(changed.second) + " changed:\n" + text;
  const std::vector<TracePoint>& points = mine.student.values.points;
  if (mine.departure.found) {
    EXPECT_GE(mine.departure.line, changed.first) << where;
    if (GetParam().throughValues) EXPECT_TRUE(madeOfTheChange(points, departurePoints(mine), changed)) << where;
    EXPECT_NE(text.find("> line " + std::to_string(mine.departure.line)), std::string::npos)
        << "the departure is marked in the table:\n"
        << text;
  } else if (mine.firstUnmatched >= 0) {
    EXPECT_GE(points[size_t(mine.firstUnmatched)].line, changed.first) << where;
    if (GetParam().throughValues) EXPECT_TRUE(madeOfTheChange(points, {mine.firstUnmatched}, changed)) << where;
  } else {
    EXPECT_TRUE(text.find("cannot single out") != std::string::npos || text.find("not traced") != std::string::npos)
        << text;
  }

  fs::remove_all(dir);
  fs::create_directories((dir / file).parent_path());
  { std::ofstream(dir / file) << labText(ex, file); }
  PixelInspection theirs;
  ASSERT_EQ(inspectPixel(ex, config, {dir}, pixel, theirs), "");
  EXPECT_FALSE(theirs.departure.found) << formatInspection(theirs);
  EXPECT_LT(theirs.firstUnmatched, 0) << formatInspection(theirs);
  EXPECT_EQ(toJson(theirs)["lines"].size(), theirs.student.values.points.size());
  fs::remove_all(dir);
}

// The denoise lab applies its map per vertex: no pixel holds the function's values, and the
// inspector says so rather than showing a table of nothing.
TEST(PixelTraceStages, AFunctionOfAnotherStageIsNamedSo) {
  Exercise ex;
  ASSERT_EQ(loadExercise("denoise/apply-map", ex), "");
  const fs::path dir = fs::temp_directory_path() / ("shadelab_pixel_stage_" + std::to_string(getpid()));
  fs::remove_all(dir);
  ASSERT_EQ(writeMistakeFolder(ex, ex.mistakes.front(), dir), "");
  PixelInspection in;
  ASSERT_EQ(inspectPixel(ex, 0, {dir}, ex.size / 2, in), "");
  EXPECT_NE(in.note.find("another stage"), std::string::npos) << formatInspection(in);
  EXPECT_FALSE(in.departure.found);
  fs::remove_all(dir);
}

// Pixels of a picture's two sides that both computed, and those of them that differ.
std::pair<int, int> reachedAndDiffering(const VariablePicture& p) {
  int reached = 0, differing = 0;
  for (int y = 0; y < p.yours.size.y; ++y)
    for (int x = 0; x < p.yours.size.x; ++x) {
      const float *a = p.yours.at(x, y), *b = p.solutions.at(x, y);
      if (a[3] <= 0.0f || b[3] <= 0.0f) continue;
      ++reached;
      differing += std::abs(a[0] - b[0]) > 1e-4f;
    }
  return {reached, differing};
}

// A variable over the whole frame: the uncentred PCF grid's running sum differs from the
// solution's along the shadows' edges alone (a thin share of the floor); the solution's own file
// differs nowhere; a name the function does not use is refused with the names it does.
TEST(PixelTracePicture, AVariableDiffersFromTheSolutionsOnlyWhereTheMistakeActs) {
  Exercise ex;
  ASSERT_EQ(loadExercise("shadows/pcf", ex), "");
  const fs::path mistake = fs::path(SHADELAB_SOURCE_DIR) / "tests/data/inspect_pcf";
  VariablePicture lit;
  ASSERT_EQ(drawVariable(ex, 0, {mistake}, "lit", 0, lit), "");
  ASSERT_TRUE(lit.solutionHas);
  const auto [reached, differing] = reachedAndDiffering(lit);
  const int pixels = ex.size.x * ex.size.y;
  EXPECT_GT(reached, pixels / 3) << "the floor and the posts run the loop";
  EXPECT_GT(differing, 50);
  EXPECT_LT(differing, reached / 5) << "only along the edges";
  EXPECT_EQ(variableImage(lit).size, glm::ivec2(3 * ex.size.x + 8, ex.size.y));

  const fs::path dir = fs::temp_directory_path() / ("shadelab_picture_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "shadows");
  { std::ofstream(dir / "shadows/pcf.glsl") << labText(ex, "shadows/pcf.glsl"); }
  VariablePicture same;
  ASSERT_EQ(drawVariable(ex, 0, {dir}, "return", 0, same), "");
  EXPECT_GT(reachedAndDiffering(same).first, pixels / 3);
  EXPECT_EQ(reachedAndDiffering(same).second, 0);
  VariablePicture none;
  const std::string e = drawVariable(ex, 0, {dir}, "nowhere", 0, none);
  EXPECT_NE(e.find("no value named 'nowhere'"), std::string::npos) << e;
  EXPECT_NE(e.find("`lit`"), std::string::npos) << e;
  fs::remove_all(dir);
}

// With no exercise open: the lab's own pass at a pixel. The shadows lab's PCF taps at 3 x 3 are
// nine comparisons, each lit or not, with the offsets of a centred grid; its camera pass's main()
// shows the normal and the position it shades.
TEST(PixelTraceLab, TheLabsOwnPassShowsItsNamedValues) {
  LabPixelRequest taps{"shadows",
                       "shadow-test",
                       "",
                       {"shadows.filter=pcf", "shadows.pcf_size=3"},
                       "shadows/shadow_filters.glsl",
                       "tapCompare",
                       {320, 240},
                       {160, 150}};
  LabInspection in;
  ASSERT_EQ(inspectLabPixel(taps, {}, in), "");
  const std::string text = formatLabInspection(in);
  std::printf("%s", text.c_str());
  ASSERT_TRUE(in.note.empty()) << text;
  int returns = 0;
  for (size_t k = 0; k < in.side.values.points.size(); ++k) {
    const TracePoint& p = in.side.values.points[k];
    if (p.kind == TracePoint::Kind::Param && p.name == "offsetTexels") {
      ASSERT_EQ(in.side.iterations[k].size(), 9u) << text;
      EXPECT_EQ(glm::vec2(in.side.iterations[k].front()), glm::vec2(-1.0f, -1.0f)) << text;
      EXPECT_EQ(glm::vec2(in.side.iterations[k].back()), glm::vec2(1.0f, 1.0f)) << text;
    }
    if (p.kind != TracePoint::Kind::Returned) continue;
    for (auto& v : in.side.iterations[k]) EXPECT_TRUE(v.x == 0.0f || v.x == 1.0f) << text;
    returns += int(in.side.iterations[k].size());
  }
  EXPECT_EQ(returns, 9) << text;

  LabInspection pass;
  ASSERT_EQ(inspectLabPixel({"shadows", "shadow-test", "", {}, "", "", {320, 240}, {160, 150}}, {}, pass), "");
  EXPECT_EQ(pass.request.file, "shadows/lit.frag");
  EXPECT_NE(formatLabInspection(pass).find("  N = (0 1 0)"), std::string::npos) << formatLabInspection(pass);
  LabInspection none;
  EXPECT_NE(inspectLabPixel({"nowhere", "", "", {}, "", "", {32, 32}, {1, 1}}, {}, none).find("valid: "),
            std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    EveryLab, PixelTrace,
    ::testing::Values(
        Case{"shadows/pcf", "grid-not-centred"}, Case{"shading/blinn-phong", "half-vector-from-difference"},
        Case{"filtering/bilinear", "no-half-texel-shift"}, Case{"surface/bump", "slope-sign"},
        Case{"surface/normal-map", "not-decoded"}, Case{"shadows/shadow-lookup", "texture-origin-flipped"},
        Case{"filtering/mip-level", "natural-log"}, Case{"surface/pom", "march-direction"},
        Case{"shadows/point-light", "no-bias"}, Case{"shadows/pcss-blocker", "comparison-inverted", false},
        Case{"shadows/pcss-penumbra", "light-size-left-out"}, Case{"filtering/trilinear", "weights-reversed"},
        Case{"shading/perspective-correct", "no-divide-back"}, Case{"surface/screen-tbn", "u-and-v-swapped"}),
    [](const auto& info) {
      std::string name = std::string(info.param.exercise) + "_" + info.param.mistake;
      for (char& ch : name)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
      return name;
    });

}  // namespace

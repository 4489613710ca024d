#include <gtest/gtest.h>

#include <cmath>

#include "app/measure/image.h"
#include "app/measure/report.h"

using namespace shadelab;

static ImageF flat(int w, int h, float v) {
  ImageF img;
  img.size = {w, h};
  img.rgba.assign(size_t(w) * h * 4, v);
  return img;
}

TEST(ImageMetrics, RmseMaxAndBadPixels) {
  ImageF a = flat(4, 4, 0.5f), b = flat(4, 4, 0.5f);
  EXPECT_DOUBLE_EQ(compareImages(a, b).rmse, 0.0);
  b.at(0, 0)[0] = 1.0f;  // one channel of one pixel off by 0.5
  const ImageError e = compareImages(a, b);
  EXPECT_NEAR(e.rmse, std::sqrt(0.25 / 48.0), 1e-9);
  EXPECT_DOUBLE_EQ(e.maxError, 0.5);
  EXPECT_DOUBLE_EQ(e.badPixelPct, 100.0 / 16.0);
  EXPECT_DOUBLE_EQ(compareImages(a, flat(2, 2, 0.5f)).rmse, 1.0);  // size mismatch is maximal error
}

TEST(ImageMetrics, NonFiniteCountedAndDownsampleAverages) {
  ImageF a = flat(4, 4, 0.0f);
  a.at(1, 1)[2] = NAN;
  a.at(2, 2)[0] = INFINITY;
  EXPECT_EQ(countNonFinite(a), 2u);
  ImageF b = flat(4, 4, 0.0f);
  b.at(0, 0)[0] = 1.0f;
  const ImageF d = downsample(b, 2);
  EXPECT_EQ(d.size, glm::ivec2(2, 2));
  EXPECT_FLOAT_EQ(d.at(0, 0)[0], 0.25f);
}

// The difference picture shows what the display hides: 2 against 1 is a difference, and a NaN is
// the largest one.
TEST(ImageMetrics, TheDifferenceIsOfTheValuesAsDrawn) {
  ImageF a = flat(2, 1, 1.0f), b = flat(2, 1, 1.0f);
  a.at(0, 0)[0] = 2.0f;
  a.at(1, 0)[1] = NAN;
  const ImageF d = diffImage(a, b, 4.0f);
  EXPECT_EQ(d.at(0, 0)[0], 1.0f);
  EXPECT_EQ(d.at(0, 0)[1], 0.0f);
  EXPECT_EQ(d.at(1, 0)[1], 1.0f);
  EXPECT_EQ(d.at(1, 0)[3], 1.0f);
}

// A frame that draws nothing where the other draws a surface: covered_rmse (both cover) sees no
// pixel and reads 0; drawnRmse counts what the other drew, yet not a silhouette moved by a pixel.
TEST(ImageMetrics, DrawnRmseCountsWhatOneFrameLeavesOut) {
  ImageF surface = flat(8, 8, 0.0f), empty = flat(8, 8, 0.0f);
  for (int y = 2; y < 6; ++y)
    for (int x = 2; x < 6; ++x) {
      float* p = surface.at(x, y);
      p[0] = p[1] = p[2] = 0.8f;
      p[3] = 1.0f;
    }
  EXPECT_DOUBLE_EQ(compareImages(empty, surface).coveredRmse, 0.0);
  EXPECT_NEAR(drawnRmse(empty, surface), 0.8, 1e-6);
  EXPECT_NEAR(drawnRmse(surface, empty), 0.8, 1e-6);
  EXPECT_DOUBLE_EQ(drawnRmse(surface, surface), 0.0);
  ImageF wider = surface;  // one more column at the silhouette: touches the other's surface
  for (int y = 2; y < 6; ++y) {
    float* p = wider.at(6, y);
    p[0] = p[1] = p[2] = 0.8f;
    p[3] = 1.0f;
  }
  EXPECT_DOUBLE_EQ(drawnRmse(wider, surface), 0.0);
  ImageF stray = surface;  // a pixel two away from the surface counts
  stray.at(0, 0)[0] = stray.at(0, 0)[1] = stray.at(0, 0)[2] = 0.8f;
  stray.at(0, 0)[3] = 1.0f;
  EXPECT_NEAR(drawnRmse(stray, surface), std::sqrt(3 * 0.64 / (17.0 * 3)), 1e-6);
  EXPECT_DOUBLE_EQ(drawnRmse(surface, flat(4, 4, 0.0f)), 1.0);
}

TEST(Report, ParetoFrontCsvAndHtml) {
  SweepReport r;
  r.plots = {{"rmse"}};
  auto row = [](const char* label, double err, double ms) {
    SweepRow s;
    s.label = label;
    s.group = label;
    s.params = {{"mode", label}};
    s.values = {{"rmse", err}, {"gpu_ms", ms}};
    return s;
  };
  r.rows = {row("a", 0.3, 1.0), row("b", 0.1, 5.0), row("c", 0.4, 6.0), row("d", 0.05, 9.0)};
  EXPECT_EQ(paretoFront(r, r.plots[0]), (std::vector<size_t>{0, 1, 3}));  // c is beaten by b on both axes
  EXPECT_EQ(sweepCsv(r), "mode,truth,rmse,gpu_ms\na,,0.3,1\nb,,0.1,5\nc,,0.4,6\nd,,0.05,9\n");
  r.command = "shadelab sweep --lab x <&>";
  const std::string html = sweepHtml(r);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_NE(html.find("shadelab sweep --lab x &lt;&amp;&gt;"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);  // self-contained and static
}

TEST(Report, EachTruthGetsItsOwnParetoFront) {
  // Hard filters judged against a point light, PCSS against an area light: one front each.
  SweepReport r;
  r.plots = {{"visibility_rmse"}};
  auto row = [](const char* label, const char* truth, double err, double ms) {
    SweepRow s;
    s.label = s.group = label;
    s.truth = truth;
    s.values = {{"visibility_rmse", err}, {"gpu_ms", ms}};
    return s;
  };
  r.rows = {row("hard", "point light", 0.02, 1.0), row("pcf", "point light", 0.03, 2.0),
            row("pcss", "area light", 0.01, 3.0), row("pcss-32", "area light", 0.008, 5.0)};
  EXPECT_EQ(truthsOf(r), (std::vector<std::string>{"point light", "area light"}));
  EXPECT_EQ(paretoFront(r, r.plots[0], "point light"), (std::vector<size_t>{0}));
  EXPECT_EQ(paretoFront(r, r.plots[0], "area light"), (std::vector<size_t>{2, 3}));
  // Mixed in one front, PCSS would wrongly push the hard filters off it.
  EXPECT_EQ(paretoFront(r, r.plots[0]), (std::vector<size_t>{0, 2, 3}));
  const std::string html = sweepHtml(r);
  EXPECT_NE(html.find("(truth: point light)"), std::string::npos);
  EXPECT_NE(html.find("(truth: area light)"), std::string::npos);
  EXPECT_EQ(sweepPlotSvg(r, r.plots[0], "area light").find("hard"), std::string::npos);
}

// Where a sweep's values span decades (bias-0 runs at 100x the error, moment maps at 100x the cost),
// the plot's axes are logarithmic, so the front is not squeezed into a corner; where they do not,
// they stay linear.
TEST(Report, AxesAreLogarithmicWhereTheDataSpansDecades) {
  auto report = [](std::vector<std::pair<double, double>> points) {
    SweepReport r;
    r.plots = {{"rmse"}};
    for (auto [err, ms] : points) {
      SweepRow s;
      s.label = s.group = "c" + std::to_string(r.rows.size());
      s.values = {{"rmse", err}, {"gpu_ms", ms}};
      r.rows.push_back(s);
    }
    return r;
  };
  const SweepReport wide = report({{0.001, 2.0}, {0.01, 20.0}, {0.5, 900.0}});
  const std::string svg = sweepPlotSvg(wide, wide.plots[0], "");
  EXPECT_NE(svg.find("gpu_ms (median of the frame's passes, lower is cheaper), log scale"), std::string::npos);
  EXPECT_NE(svg.find(">rmse (log scale)</text>"), std::string::npos);
  EXPECT_NE(svg.find(">100</text>"), std::string::npos);  // decade ticks
  EXPECT_NE(svg.find(">0.01</text>"), std::string::npos);
  const SweepReport narrow = report({{0.02, 10.0}, {0.03, 14.0}, {0.05, 20.0}});
  EXPECT_EQ(sweepPlotSvg(narrow, narrow.plots[0], "").find("log scale"), std::string::npos);
  // A zero error has no logarithm: that axis stays linear from 0.
  const SweepReport exact = report({{0.0, 2.0}, {0.5, 900.0}});
  const std::string exactSvg = sweepPlotSvg(exact, exact.plots[0], "");
  EXPECT_EQ(exactSvg.find(">rmse (log scale)"), std::string::npos);
  EXPECT_NE(exactSvg.find("cheaper), log scale"), std::string::npos);
}

// A sweep's outliers (a run ten times dearer than the front, an error a hundred times the front's)
// are drawn hollow on the frame's edge, and the axes frame the Pareto front and what lies near it.
TEST(Report, ThePlotFramesTheParetoFrontAndMarksOutliersAtTheEdge) {
  SweepReport r;
  r.plots = {{"rmse"}};
  for (auto [err, ms] : std::vector<std::pair<double, double>>{
           {0.1, 1.0}, {0.05, 2.0}, {0.02, 4.0}, {0.08, 3.0}, {0.5, 1000.0}, {9.0, 2.0}}) {
    SweepRow s;
    s.label = s.group = "c" + std::to_string(r.rows.size());
    s.values = {{"rmse", err}, {"gpu_ms", ms}};
    r.rows.push_back(s);
  }
  const std::string svg = sweepPlotSvg(r, r.plots[0], "");
  EXPECT_NE(svg.find("c4: rmse 0.5, gpu_ms 1000 (beyond the frame)"), std::string::npos);
  EXPECT_NE(svg.find("c5: rmse 9, gpu_ms 2 (beyond the frame)"), std::string::npos);
  EXPECT_EQ(svg.find("c3: rmse 0.08, gpu_ms 3 (beyond"), std::string::npos) << "near the front: inside";
  EXPECT_NE(svg.find(">2 beyond the frame</text>"), std::string::npos);
  EXPECT_EQ(svg.find("log scale"), std::string::npos) << "framed on 1..4 ms and 0.02..0.1: linear axes";
  EXPECT_EQ(svg.find(">1000</text>"), std::string::npos);
}

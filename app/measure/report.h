// Error-against-cost reports: a CSV and one self-contained HTML page (inline SVG plots, images
// embedded as data URIs, the command line that made it) that opens anywhere, offline.
#pragma once
#include <string>
#include <vector>

#include "app/measure/image.h"

namespace shadelab {

// One error-against-cost plot: keys of the measured values.
struct PlotSpec {
  std::string error;
  std::string cost = "gpu_ms";
};

struct SweepRow {
  std::vector<std::pair<std::string, std::string>> params;  // every lab param, as text
  std::vector<std::pair<std::string, double>> values;       // metrics and costs, e.g. rmse, gpu_ms
  std::string label;                                        // the varied params, "mode=phong tessellation=8"
  std::string group;                                        // colours the points (first varied param)
  std::string truth;                                        // what it was judged against ("point light")
  ImageF thumbnail;                                         // small copy of the rendered frame
  double value(const std::string& key) const;
};

struct SweepReport {
  std::string title;
  std::string command;                                      // the exact command line
  std::string renderer;                                     // GL_RENDERER / GL_VERSION
  std::vector<std::pair<std::string, std::string>> truths;  // truth -> what it is, in order of appearance
  std::string costClock;                                    // how gpu_ms was measured (queries or glFinish wall time)
  std::vector<PlotSpec> plots;
  std::vector<std::pair<std::string, std::string>> metricNotes;  // metric -> what it is divided by
  std::vector<SweepRow> rows;
  std::vector<std::pair<std::string, ImageF>> referenceThumbnails;  // per truth, when it is an image
};

// Rows judged against different truths are never compared: every plot and Pareto front is drawn
// once per truth, over that truth's rows.
std::vector<std::string> truthsOf(const SweepReport& r);
std::string sweepCsv(const SweepReport& r);
std::string sweepHtml(const SweepReport& r);
// One plot over the rows of `truth` ("" = every row), as a standalone SVG (also in the HTML).
std::string sweepPlotSvg(const SweepReport& r, const PlotSpec& plot, const std::string& truth);
// Indices of the rows of `truth` ("" = all) on the lower-left Pareto front of (cost, error).
std::vector<size_t> paretoFront(const SweepReport& r, const PlotSpec& plot, const std::string& truth = "");
// Text for HTML element content and attribute values.
std::string htmlEscape(const std::string& s);
// The image as an 8-bit PNG data URI ("" for an empty image), for self-contained pages.
std::string pngDataUri(const ImageF& image);
// Writes text atomically (temporary file + rename). Returns "" or an error naming the file.
std::string writeTextFile(const std::string& path, const std::string& text);

}  // namespace shadelab

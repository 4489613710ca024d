// Error-against-cost reports: a CSV and one self-contained HTML page (inline SVG plots, images
// embedded as data URIs, the command line that made it) that opens anywhere, offline.
#pragma once
#include <string>
#include <vector>

#include "measure/image.h"

namespace shadelab {

struct SweepRow {
  std::vector<std::pair<std::string, std::string>> params;  // every lab param, as text
  std::vector<std::pair<std::string, double>> values;       // metrics and costs, e.g. rmse, gpu_ms
  std::string label;                                        // the varied params, "mode=phong tessellation=8"
  std::string group;                                        // colours the points (first varied param)
  ImageF thumbnail;                                         // small copy of the rendered frame
  double value(const std::string& key) const;
};

struct SweepReport {
  std::string title;
  std::string command;       // the exact command line
  std::string renderer;      // GL_RENDERER / GL_VERSION
  std::string reference;     // what the errors are measured against
  std::string costKey = "gpu_ms";
  std::string costClock;     // how gpu_ms was measured (queries or glFinish wall time)
  std::vector<std::string> errorKeys;  // one plot each, against costKey
  std::vector<SweepRow> rows;
  ImageF referenceThumbnail;
};

std::string sweepCsv(const SweepReport& r);
std::string sweepHtml(const SweepReport& r);
// One plot of `errorKey` against the cost, as a standalone SVG (also embedded in the HTML).
std::string sweepPlotSvg(const SweepReport& r, const std::string& errorKey);
// Indices of the rows on the lower-left Pareto front of (cost, error).
std::vector<size_t> paretoFront(const SweepReport& r, const std::string& errorKey);
// Writes text atomically (temporary file + rename). Returns "" or an error naming the file.
std::string writeTextFile(const std::string& path, const std::string& text);

}  // namespace shadelab

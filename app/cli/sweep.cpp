// shadelab sweep: every combination of the varied parameters, each rendered, timed and measured
// against the lab's ground truth (host/measurer.h); CSV + HTML report with error-against-cost
// plots, one Pareto front per truth.
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

#include "app/cli/commands.h"
#include "app/cli/session.h"
#include "app/host/measurer.h"
#include "app/measure/report.h"

namespace shadelab {

static std::string parseVary(const std::string& text, SweepAxis& axis) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq + 1 >= text.size()) return "--vary: '" + text + "' is not key=a,b,c";
  axis.key = text.substr(0, eq);
  if (const auto dot = axis.key.find('.'); dot != std::string::npos) axis.key = axis.key.substr(dot + 1);
  std::stringstream ss(text.substr(eq + 1));
  std::string v;
  while (std::getline(ss, v, ',')) axis.values.push_back(v);
  return {};
}

// "v" sets key=v; "v:k2=v2:..." also sets the linked parameters (a PCF kernel with its filter).
static std::string applyAxisValue(LabHost& host, const std::string& key, const std::string& value) {
  std::stringstream ss(value);
  std::string part;
  bool first = true;
  while (std::getline(ss, part, ':')) {
    if (auto err = host.set(first ? key + "=" + part : part); !err.empty()) return err;
    first = false;
  }
  return {};
}

// "area light" -> "area_light", for file names.
static std::string slug(const std::string& text) {
  std::string s;
  for (char c : text) s += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
  return s;
}

static ImageF thumbnail(const ImageF& image) {
  int f = 1;
  while (image.size.x / (f + 1) >= 200) ++f;  // about 200-400 px wide
  return downsample(image, f);
}

// The command that makes this sweep again, for the report.
static std::string sweepCommand(const Options& o, const std::string& labId, const std::string& sceneId) {
  std::string cmd = "shadelab sweep --lab " + labId + " --scene " + sceneId + " --size " + std::to_string(o.size.x) +
                    "x" + std::to_string(o.size.y) + " --frames " + std::to_string(o.frames);
  for (auto& v : o.varies) cmd += " --vary " + v;
  for (auto& v : o.sets) cmd += " --set " + v;
  if (!o.camera.empty()) cmd += " --camera '" + o.camera + "'";
  return cmd + " --out " + o.out;
}

// Row `index` of the sweep's grid: each axis's value applied (the last axis varies fastest).
static std::string applyGridPoint(LabHost& host, const std::vector<SweepAxis>& axes, size_t index) {
  std::vector<std::string> parts(axes.size());
  for (size_t a = axes.size(); a-- > 0;) {
    const std::string& v = axes[a].values[index % axes[a].values.size()];
    index /= axes[a].values.size();
    applyAxisValue(host, axes[a].key, v);
    parts[a] = axes[a].key + "=" + v;
  }
  std::string label;
  for (auto& part : parts) label += (label.empty() ? "" : " ") + part;
  return label;
}

// The CSV, the HTML page and one SVG per plot and truth; "" or what could not be written.
static std::string writeSweep(const SweepReport& report, const std::string& out, const std::string& labId) {
  if (auto err = writeTextFile(out + "/" + labId + "_sweep.csv", sweepCsv(report)); !err.empty()) return err;
  if (auto err = writeTextFile(out + "/" + labId + "_sweep.html", sweepHtml(report)); !err.empty()) return err;
  const auto truths = truthsOf(report);
  for (auto& plot : report.plots)
    for (auto& truth : truths) {
      std::string file = out + "/" + labId + "_" + plot.error;
      if (truths.size() > 1) file.append("_").append(slug(truth));
      file += ".svg";
      if (auto err = writeTextFile(file, sweepPlotSvg(report, plot, truth)); !err.empty()) return err;
    }
  return {};
}

// The table on stdout: every plotted error and cost once, in plot order.
static void printSweep(const SweepReport& report) {
  std::vector<std::string> columns;
  for (auto& plot : report.plots)
    for (auto& key : {plot.error, plot.cost})
      if (std::find(columns.begin(), columns.end(), key) == columns.end()) columns.push_back(key);
  std::printf("%-44s", "configuration");
  for (auto& key : columns) std::printf(" %14s", key.c_str());
  std::printf("  truth\n");
  for (auto& row : report.rows) {
    std::printf("%-44s", row.label.c_str());
    for (auto& key : columns) std::printf(" %14.5f", row.value(key));
    std::printf("  %s\n", row.truth.c_str());
  }
}

int runSweep(const Options& o) {
  if (o.out.empty()) return fail("sweep: --out DIR is required");
  Session s;
  if (auto err = openSession(o, s); !err.empty()) return fail(err);
  LabHost& host = *s.host;
  const std::string labId(host.lab().id());
  const Judge* judge = host.lab().judge();
  if (!judge) return fail("sweep: lab " + labId + " has no truth to measure against");

  std::vector<SweepAxis> axes;
  for (auto& v : o.varies) {
    SweepAxis a;
    if (auto err = parseVary(v, a); !err.empty()) return fail(err);
    axes.push_back(a);
  }
  if (axes.empty()) axes = judge->standardSweep();
  if (axes.empty()) return fail("sweep: lab " + labId + " has no standard sweep; give --vary key=a,b,c");

  // Validate every value before rendering anything.
  const Settings base = host.currentSettings();
  for (auto& a : axes)
    for (auto& v : a.values)
      if (auto err = applyAxisValue(host, a.key, v); !err.empty()) return fail("--vary: " + err);
  host.applySettings(base);

  std::error_code ec;
  std::filesystem::create_directories(o.out, ec);
  if (!std::filesystem::is_directory(o.out, ec)) return fail(o.out + ": cannot create the output folder");

  size_t total = 1;
  for (auto& a : axes) total *= a.values.size();
  SweepReport report;
  report.title = "ShadeLab sweep: " + labId + " on " + host.sceneId() + " at " + std::to_string(o.size.x) + "x" +
                 std::to_string(o.size.y);
  report.renderer = s.context->describe();
  report.costClock = host.timerClock();
  report.metricNotes = judge->metricNotes();
  report.plots = judge->plots();
  report.command = sweepCommand(o, labId, host.sceneId());

  Measurer measurer(host);  // caches each truth: rows that share one trace or render it once
  std::vector<std::string> shaderErrorRows;
  for (size_t index = 0; index < total; ++index) {
    host.applySettings(base);
    const std::string label = applyGridPoint(host, axes, index);
    auto jobProgress = [&](const std::vector<JobStatus>& jobs) {
      progress(int(index), int(total), label + (jobs.empty() ? "" : ": " + describeJobs(jobs)));
    };
    progress(int(index), int(total), label);

    host.settle(jobProgress);  // the lab's own jobs (a smoothing, a bake) for these settings
    const TimedFrames t = renderTimed(host, o.size, o.time, o.warmup, o.frames);
    const ImageF shown = host.readImage();  // what the student sees; the metrics may use another view
    auto m = measurer.measureNow(o.size, o.time, {{"gpu_ms", t.gpuMs}, {"cpu_ms", t.cpuMs}}, jobProgress);
    if (!m) return fail("sweep: " + label + ": " + labId + " has no ground truth for this configuration");

    SweepRow row;
    row.params = m->settings;
    row.label = label;
    // Colour by the first axis's value without its linked settings: "method=explicit", not
    // "method=explicit:lambda=0.1" (the point's tooltip names everything).
    row.group = label.substr(0, std::min(label.find(' '), label.find(':')));
    row.truth = m->truth;
    row.values = m->values;
    row.values.push_back({"non_finite", double(countNonFinite(m->image.rgba.empty() ? shown : m->image))});
    int failedPrograms = 0;  // a student's broken shader: the row shows a fallback, and says so
    for (auto& p : host.lab().activePrograms()) failedPrograms += p->lastBuildFailed() || !p->hasGoodProgram();
    row.values.push_back({"shader_errors", double(failedPrograms)});
    if (failedPrograms) shaderErrorRows.push_back(label);
    row.thumbnail = thumbnail(shown);
    char name[32];
    std::snprintf(name, sizeof name, "/frame_%03zu.png", index);
    writePng(o.out + name, shown);
    const bool newTruth =
        std::none_of(report.truths.begin(), report.truths.end(), [&](auto& t) { return t.first == m->truth; });
    if (newTruth) {
      report.truths.emplace_back(m->truth, judge->reference().description);
      if (!m->reference.rgba.empty()) {
        report.referenceThumbnails.emplace_back(m->truth, thumbnail(m->reference));
        writePng(o.out + "/reference_" + slug(m->truth) + ".png", m->reference);
      }
    }
    report.rows.push_back(std::move(row));
  }
  progress(int(total), int(total), "done");

  if (auto err = writeSweep(report, o.out, labId); !err.empty()) return fail(err);
  printSweep(report);
  std::printf("wrote %s/%s_sweep.csv and %s_sweep.html\n", o.out.c_str(), labId.c_str(), labId.c_str());
  for (auto& label : shaderErrorRows)
    std::fprintf(stderr, "warning: %s: a program did not build; that row shows a fallback (shader_errors > 0)\n",
                 label.c_str());
  return 0;
}

}  // namespace shadelab

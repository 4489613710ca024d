#include "app/grade/configuration_frames.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "app/grade/frame_properties.h"
#include "app/grade/frame_relations.h"
#include "app/grade/function_probe.h"
#include "app/grade/mutants.h"
#include "app/grade/pixel_trace.h"
#include "app/grade/probe_trace.h"
#include "app/host/configure.h"
#include "app/host/measurer.h"
#include "app/measure/report.h"
#include "app/util/format.h"
#include "app/util/read_file.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

nlohmann::json metricsJson(const Metrics& metrics) {
  nlohmann::json j = nlohmann::json::object();
  for (auto& [k, v] : metrics) j[k] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
  return j;
}

std::string where(const Exercise& ex, const Configuration& c) {
  return (ex.dir / "rubric.json").string() + ": configuration '" + c.name + "'";
}

// A folder removed however the loop that fills it ends.
struct ScratchFolder {
  fs::path dir;
  explicit ScratchFolder(const std::string& name)
      : dir(fs::temp_directory_path() / ("shadelab-" + name + "-" + std::to_string(getpid()))) {}
  ~ScratchFolder() {
    std::error_code ec;
    fs::remove_all(dir, ec);
  }
};

// The configuration drawn with `roots` searched for the shaders: its frame (a function probe's
// table for a probe configuration) and the build errors. Returns "" or why the rubric is at fault.
std::string drawChanged(const Exercise& ex, const Configuration& c, const std::vector<fs::path>& roots, ImageF& frame,
                        std::vector<std::string>& errors) {
  if (c.function >= 0) {
    if (auto e = drawFunctionProbe(ex.probes[size_t(c.function)], roots, frame, errors); !e.empty())
      return where(ex, c) + ": " + e;
    return {};
  }
  std::string configError;
  const auto host = configuredHost(roots, ex, c, configError);
  if (!configError.empty()) return where(ex, c) + ": " + configError;
  host->settle();
  host->renderFrame(ex.size);
  frame = host->readImage();
  errors = buildErrors(*host);
  return {};
}

// Each of the rubric's mistakes drawn in the configuration: the solution with that one change,
// from a shader folder of its own searched before the built-in one.
std::string drawMistakes(const Exercise& ex, const Configuration& c, CachedSolution& out) {
  out.mistakes.clear();
  out.numbers["mistakes"] = nlohmann::json::array();
  const ScratchFolder scratch("mistakes");
  for (auto& m : ex.mistakes) {
    const fs::path dir = scratch.dir / m.name;
    if (auto e = writeMistakeFolder(ex, m, dir); !e.empty()) return e;
    ImageF frame;
    std::vector<std::string> errors;
    if (auto e = drawChanged(ex, c, {dir, builtinShaderDir()}, frame, errors); !e.empty()) return e;
    if (!errors.empty())
      return (ex.dir / "rubric.json").string() + ": mistake '" + m.name + "' does not build: " + errors.front();
    out.numbers["mistakes"].push_back({{"name", m.name}, {"distance", frameDistance(frame, out.frame)}});
    out.mistakes.push_back(std::move(frame));
  }
  return {};
}

// The values a setting is tried at when a student's frame may ignore or misuse it, likeliest
// first: the lab's default (the key left out) and the values the rubric's other configurations
// give it (a kernel size written in as a literal); then for a number 0, 1, half, twice and the
// reciprocal (a divide for a multiply).
std::vector<std::string> otherValues(const Exercise& ex, const std::string& key, const std::string& value,
                                     bool likeliest) {
  std::vector<std::string> out;
  if (likeliest) {
    out.push_back("");  // "": left at the lab's default
    for (auto& c : ex.configurations)
      for (auto& [k, v] : c.settings)
        if (k == key && v != value && std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
    return out;
  }
  char* end = nullptr;
  const double v = std::strtod(value.c_str(), &end);
  if (end == value.c_str() || *end != '\0' || !std::isfinite(v)) return out;
  for (double o : {0.0, 1.0, 0.5 * v, 2.0 * v, v != 0.0 ? 1.0 / v : 0.0})
    if (std::abs(o - v) > 1e-9 * std::max(1.0, std::abs(v))) {
      const std::string text = formatSignificant(o);
      if (std::find(out.begin(), out.end(), text) == out.end()) out.push_back(text);
    }
  return out;
}

// Which setting the student's frame behaves as if it had: of the solution's frames at other
// settings (drawSettingFrames), each setting's best value kept when it lies far closer to the
// student's frame than the solution's does. Asked only for a frame that differs and that nothing
// else explains, so a class that makes the listed mistakes pays nothing.
nlohmann::json settingMatches(const Configuration& c, const SettingFrames& frames, const ImageF& image,
                              double distance) {
  std::vector<double> best(c.settings.size(), kFrameFit * distance);
  std::vector<std::string> bestValue(c.settings.size());
  std::vector<bool> found(c.settings.size(), false);
  for (size_t k = 0; k < frames.tried.size(); ++k) {
    const auto& [i, value] = frames.tried[k];
    if (i >= c.settings.size()) continue;
    const double d = frameDistance(image, frames.frames[k]);
    // Of values that draw the student's frame equally, a number the student can read beats
    // "the lab's default".
    if (d < best[i] || (d <= best[i] && found[i] && bestValue[i].empty() && !value.empty())) {
      best[i] = d;
      bestValue[i] = value;
      found[i] = true;
    }
  }
  nlohmann::json out = nlohmann::json::array();
  for (size_t i = 0; i < c.settings.size(); ++i)
    if (found[i]) out.push_back({{"key", c.settings[i].first}, {"value", bestValue[i]}, {"distance", best[i]}});
  return out;
}

}  // namespace

bool drawSettingFrames(const Exercise& ex, const Configuration& c, SettingFrames& out) {
  out = {};
  constexpr auto kMostTime = std::chrono::seconds(10);
  const auto start = std::chrono::steady_clock::now();
  int frames = 0;
  for (const bool likeliest : {true, false})
    for (size_t i = 0; i < c.settings.size(); ++i)
      for (const std::string& value : otherValues(ex, c.settings[i].first, c.settings[i].second, likeliest)) {
        if (++frames > kMostSettingFrames) return true;
        if (std::chrono::steady_clock::now() - start > kMostTime) return false;
        Configuration other = c;
        if (value.empty())
          other.settings.erase(other.settings.begin() + std::ptrdiff_t(i));
        else
          other.settings[i].second = value;
        std::string error;
        const auto host = configuredHost({builtinShaderDir()}, ex, other, error);
        if (!error.empty()) continue;  // a value the parameter does not take
        host->settle();
        host->renderFrame(ex.size);
        if (!buildErrors(*host).empty()) continue;
        out.tried.push_back({i, value});
        out.frames.push_back(host->readImage());
      }
  return true;
}

CachedFrames keptSettingFrames(const SettingFrames& frames) {
  CachedFrames out{{{"tried", nlohmann::json::array()}}, frames.frames};
  for (auto& t : frames.tried) out.numbers["tried"].push_back({{"setting", t.setting}, {"value", t.value}});
  return out;
}

bool settingFramesFromKept(const CachedFrames& kept, SettingFrames& out) {
  out = {};
  const nlohmann::json& tried = kept.numbers.is_object() ? kept.numbers.value("tried", nlohmann::json()) : nullptr;
  if (!tried.is_array() || tried.size() != kept.frames.size()) return false;
  for (auto& t : tried) {
    if (!t.is_object() || !t.value("setting", nlohmann::json()).is_number_unsigned() ||
        !t.value("value", nlohmann::json()).is_string())
      return false;
    out.tried.push_back({t["setting"].get<size_t>(), t["value"].get<std::string>()});
  }
  out.frames = kept.frames;
  return true;
}

namespace {

// The student's side of a function probe: their table, its distance to the solution's and to
// each mistake's, and what it says against them (grade/function_probe.h).
nlohmann::json probeStudent(const Exercise& ex, const Configuration& c, const std::vector<fs::path>& roots,
                            const CachedSolution& solution, ImageF& image, std::string& error) {
  const FunctionProbe& probe = ex.probes[size_t(c.function)];
  std::vector<std::string> errors;
  if (auto e = drawFunctionProbe(probe, roots, image, errors); !e.empty()) {
    error = where(ex, c) + ": " + e;
    return {};
  }
  nlohmann::json student{{"errors", errors}};
  student["vs_solution"] = nlohmann::json::object();
  student["distance"] = frameDistance(image, solution.frame);
  student["mistakes"] = nlohmann::json::array();
  for (auto& m : solution.mistakes) student["mistakes"].push_back(frameDistance(image, m));
  student["pairs"] = student["relations"] = nlohmann::json::array();
  student["properties"] = {
      {"nan_pixels", 0}, {"inf_pixels", 0}, {"non_finite", ""}, {"edge_shift", {0, 0}}, {"edge_width_ratio", 1.0}};
  student["probe"] = nlohmann::json::array();
  if (errors.empty())
    for (auto& f :
         analyseProbe(probe, image, solution.frame, solution.mistakes.empty() ? nullptr : &solution.mistakes[0]))
      student["probe"].push_back({{"kind", f.kind}, {"key", f.key}, {"text", f.text}, {"fit", f.fit}});
  if (errors.empty()) student["slips"] = slipDistances(c, image, solution);
  // Where the tables differ, the function traced line by line beside the solution's.
  // (traceOnProbe finds nothing to trace where no block's values differ beyond rounding.)
  if (errors.empty() && student["distance"].get<double>() > 0.0) {
    TraceFinding finding;
    if (auto why = traceOnProbe(ex, probe, roots, image, solution.frame, finding); !why.empty())
      student["trace_unavailable"] = why;
    else
      student["trace"] = toJson(finding);
  }
  return student;
}

}  // namespace

void lookUpSubmission(const Exercise& ex, const std::vector<fs::path>& studentDirs, ExerciseResult& out) {
  const ShaderSearchPath submitted(studentDirs);
  out.starterUnchanged = true;
  for (auto& file : ex.files) {
    const ShaderSearchPath::Lookup found = submitted.find(file);
    if (found.file.empty() && found.refused.empty())
      out.missingFiles.push_back(file);
    else if (!found.file.empty() && readWholeFile(found.file) == readWholeFile(builtinShaderDir() / file))
      out.notes.push_back(found.file.string() + " is the lab's own file, unchanged");
    if (found.file.empty() || readWholeFile(found.file) != readWholeFile(ex.dir / "starter" / file))
      out.starterUnchanged = false;
  }
}

std::unique_ptr<LabHost> configuredHost(const std::vector<fs::path>& roots, const Exercise& ex, const Configuration& c,
                                        std::string& error) {
  auto host = std::make_unique<LabHost>(ShaderSearchPath(roots), ex.lab, c.scene);
  std::vector<std::string> sets;
  for (auto& [key, value] : c.settings) sets.push_back(key + "=" + value);
  error = configureHost(*host, ex.lab, host->sceneId() == c.scene ? std::string() : c.scene, sets, {}, c.camera);
  return host;
}

std::vector<std::string> buildErrors(LabHost& host) {
  constexpr size_t kMostErrors = 20;  // a file that makes thousands of errors: its first ones say enough
  std::vector<std::string> out;
  size_t more = 0;
  for (auto& p : host.lab().activePrograms()) {
    if (!p->lastBuildFailed() && p->hasGoodProgram()) continue;
    for (auto& d : p->diagnostics())
      if (d.isError) {
        const std::string text = p->spec().name + ": " + d.formatWithCaret();
        if (std::find(out.begin(), out.end(), text) != out.end()) continue;
        if (out.size() < kMostErrors)
          out.push_back(text);
        else
          ++more;
      }
    if (p->diagnostics().empty()) out.push_back(p->spec().name + ": did not build (no message from the driver)");
  }
  if (more) out.push_back("... and " + std::to_string(more) + " more errors");
  return out;
}

std::string drawSolution(const Exercise& ex, const Configuration& c, CachedSolution& out) {
  if (c.function >= 0) {
    std::vector<std::string> errors;
    if (auto e = drawFunctionProbe(ex.probes[size_t(c.function)], {builtinShaderDir()}, out.frame, errors); !e.empty())
      return where(ex, c) + ": " + e;
    if (!errors.empty())
      return where(ex, c) + ": the probe does not build with the lab's own shaders: " + errors.front();
    return drawMistakes(ex, c, out);
  }
  std::string configError;
  const auto solutionHost = configuredHost({builtinShaderDir()}, ex, c, configError);
  if (!configError.empty()) return where(ex, c) + ": " + configError;
  LabHost& host = *solutionHost;
  host.settle();
  host.renderFrame(ex.size);
  out.frame = host.readImage();
  if (auto errors = buildErrors(host); !errors.empty())
    return where(ex, c) + ": the lab's own shaders did not build: " + errors.front();
  if (auto e = drawMistakes(ex, c, out); !e.empty()) return e;
  if (c.needsTruth()) {
    Measurer measurer(host);
    auto m = measurer.measureNow(ex.size, 0.0f, {});
    if (!m) return where(ex, c) + ": this configuration has no ground truth to check against";
    out.truths = m->references;
    out.numbers["vs_truth"] = metricsJson(m->values);
  }
  return {};
}

std::vector<Mutant> solutionSlips(const Exercise& ex) {
  std::string before, region, after;
  if (ex.files.empty() || !solutionRegion(ex, ex.files.front(), before, region, after)) return {};
  return mutate(region, kMostSlips);
}

namespace {

// A slip's frame as it is kept: a picture at half size (the pixels a change moves come in areas),
// a probe's table as it is (each pixel its own input).
ImageF slipFrame(const Configuration& c, const ImageF& frame) { return c.function >= 0 ? frame : downsample(frame, 2); }

}  // namespace

std::string drawSlips(const Exercise& ex, const Configuration& c, CachedSolution& out) {
  out.slips.clear();
  out.numbers["slips"] = nlohmann::json::array();
  const ImageF solution = slipFrame(c, out.frame);
  const ScratchFolder scratch("slips");
  const std::vector<Mutant> slips = solutionSlips(ex);
  for (size_t i = 0; i < slips.size(); ++i) {
    Mistake m;
    m.name = "slip-" + std::to_string(i);
    m.file = ex.files.front();
    m.body = slips[i].text;
    const fs::path dir = scratch.dir / m.name;
    if (auto e = writeMistakeFolder(ex, m, dir); !e.empty()) return e;
    ImageF frame;
    std::vector<std::string> errors;
    if (auto e = drawChanged(ex, c, {dir, builtinShaderDir()}, frame, errors); !e.empty()) return e;
    if (!errors.empty() || frame.size != out.frame.size) continue;  // a slip that does not build is no evidence
    frame = slipFrame(c, frame);
    const double separation = drawnDistance(frame, solution);
    if (separation <= kFramesDiffer) continue;  // draws the solution's frame here
    out.numbers["slips"].push_back({{"index", i},
                                    {"kind", slips[i].kind},
                                    {"cause", describeSlip(slips[i], false)},
                                    {"cause_and_fix", describeSlip(slips[i], true)},
                                    {"separation", separation}});
    out.slips.push_back(std::move(frame));
  }
  return {};
}

nlohmann::json slipDistances(const Configuration& c, const ImageF& image, const CachedSolution& solution) {
  if (!solution.numbers.contains("slips")) return nullptr;
  const ImageF student = slipFrame(c, image);
  nlohmann::json to = nlohmann::json::array();
  for (auto& slip : solution.slips) to.push_back(drawnDistance(student, slip));
  return {{"distance", drawnDistance(student, slipFrame(c, solution.frame))}, {"to", to}};
}

std::string studentSlipDistances(const Exercise& ex, const Configuration& c, const std::vector<fs::path>& studentDirs,
                                 const CachedSolution& solution, nlohmann::json& out) {
  std::vector<fs::path> roots = studentDirs;
  roots.push_back(builtinShaderDir());
  ImageF image;
  std::vector<std::string> errors;
  if (auto e = drawChanged(ex, c, roots, image, errors); !e.empty()) return e;
  out = errors.empty() ? slipDistances(c, image, solution) : nlohmann::json();
  return {};
}

bool traceInDrawNext(const Exercise& ex, const std::vector<ConfigurationResult>& before) {
  if (std::any_of(ex.configurations.begin(), ex.configurations.end(),
                  [](const Configuration& c) { return c.function >= 0; }))
    return false;
  int traced = 0;
  for (auto& c : before) {
    if (c.trace.found) return false;
    traced += c.traceTried;
  }
  return traced < kMostDrawTraces;
}

nlohmann::json drawStudent(const Exercise& ex, const Configuration& c, const std::vector<fs::path>& studentDirs,
                           const CachedSolution& solution, const SettingFramesSource& settingFrames, ImageF& image,
                           std::string& error) {
  std::vector<fs::path> roots = studentDirs;
  roots.push_back(builtinShaderDir());
  if (c.function >= 0) return probeStudent(ex, c, roots, solution, image, error);
  std::string configError;
  const auto studentHost = configuredHost(roots, ex, c, configError);
  if (!configError.empty()) {
    error = where(ex, c) + ": " + configError;
    return {};
  }
  LabHost& host = *studentHost;
  host.settle();
  host.renderFrame(ex.size);
  image = host.readImage();
  nlohmann::json student{{"errors", buildErrors(host)}};
  const ImageError e = compareImages(image, solution.frame);
  const FrameProperties properties = measureFrameProperties(
      image, solution.frame, solution.truths.empty() ? nullptr : &solution.truths.front(), {c.bounded, c.low, c.high});
  Metrics vsSolution{{"rmse", e.rmse},
                     {"covered_rmse", drawnRmse(image, solution.frame)},
                     {"max_error", e.maxError},
                     {"bad_pixel_pct", e.badPixelPct}};
  for (auto& m : properties.metrics(image)) vsSolution.push_back(m);
  student["vs_solution"] = metricsJson(vsSolution);
  // The evidence a diagnosis rests on: how far the frame lies from the solution's and from each
  // mistake's, and what its properties say.
  student["distance"] = frameDistance(image, solution.frame);
  student["mistakes"] = nlohmann::json::array();
  for (size_t i = 0; i < solution.mistakes.size(); ++i)
    student["mistakes"].push_back(frameDistance(image, solution.mistakes[i]));
  // Two mistakes made together, where both show: the solution with both mistakes' changes to it
  // added (exact where their changes touch different pixels, as a far-plane test and a texture
  // coordinate do), against the student's frame.
  student["pairs"] = nlohmann::json::array();
  std::vector<bool> shows(solution.mistakes.size());
  for (size_t i = 1; i < solution.mistakes.size() && i < solution.numbers["mistakes"].size(); ++i)
    shows[i] = solution.numbers["mistakes"][i].value("distance", 0.0) > kFramesDiffer;
  for (size_t i = 1; i < solution.mistakes.size(); ++i)
    for (size_t j = i + 1; j < solution.mistakes.size(); ++j)
      if (shows[i] && shows[j])
        student["pairs"].push_back(
            {i, j,
             frameDistance(image, composeChanges(solution.frame, solution.mistakes[i], solution.mistakes[j],
                                                 {c.bounded, c.low, c.high}))});
  student["relations"] = nlohmann::json::array();
  for (auto& r : relateFrames(image, solution.frame, {c.bounded, c.low, c.high}))
    student["relations"].push_back({{"kind", r.kind}, {"a", r.a}, {"b", r.b}, {"residual", r.residual}});
  const double distance = student["distance"].get<double>();
  // Nothing else explains the frame: no listed mistake draws it (within kFramesDiffer) and no
  // relation to the solution's fits closely.
  const bool explained =
      distance <= kFramesDiffer ||
      std::any_of(student["relations"].begin(), student["relations"].end(),
                  [&](const nlohmann::json& r) { return r["residual"].get<double>() <= 0.1 * distance; }) ||
      std::any_of(student["mistakes"].begin(), student["mistakes"].end(),
                  [&](const nlohmann::json& d) { return d.get<double>() <= kFramesDiffer; });
  if (!explained && student["errors"].empty() && properties.nonFinitePixels() == 0)
    if (const SettingFrames* frames = settingFrames ? settingFrames() : nullptr)
      student["settings"] = settingMatches(c, *frames, image, distance);
  if (student["errors"].empty()) student["slips"] = slipDistances(c, image, solution);
  student["properties"] = {{"nan_pixels", properties.nanPixels},
                           {"inf_pixels", properties.infPixels},
                           {"non_finite", properties.nonFiniteText()},
                           {"edge_shift", {properties.edgeShift.x, properties.edgeShift.y}},
                           {"edge_width_ratio", properties.edgeWidthRatio},
                           {"outside_median", properties.outsideMedian}};
  if (c.needsTruth() && student["errors"].empty()) {
    const Judge& judge = *host.lab().judge();  // the solution was measured against its truth: the lab judges
    if (referenceOf(host.lab()).kind == TruthKind::Mesh) {
      // A mesh truth: the lab's numbers on the mesh the student's shaders made (read back by the
      // lab's own job, which settle() waited for), as the solution's were measured.
      student["vs_truth"] = metricsJson(judge.meshMetrics());
    } else {
      std::vector<ImageF> views;
      for (auto& view : judge.measuredViews()) views.push_back(host.renderView(ex.size, 0.0f, view.settings));
      student["vs_truth"] = metricsJson(judge.viewMetrics(views, solution.truths));
    }
  }
  return student;
}

nlohmann::json traceStudentFrame(const Exercise& ex, const Configuration& c, const std::vector<fs::path>& studentDirs,
                                 const nlohmann::json& student, const ImageF& image, const CachedSolution& solution) {
  if (!student.is_object() || !student.value("errors", nlohmann::json::array()).empty() ||
      !(student.value("distance", 0.0) > kFramesDiffer))
    return nullptr;
  TraceFinding finding;
  const size_t index = size_t(&c - ex.configurations.data());
  if (auto why = traceWhereFramesDiffer(ex, index, studentDirs, image, solution.frame, finding); !why.empty())
    return {{"trace_unavailable", why}};
  return {{"trace", toJson(finding)}};
}

}  // namespace shadelab

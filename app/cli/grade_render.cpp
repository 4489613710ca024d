#include "cli/grade_render.h"

#include <cmath>
#include <fstream>

#include "cli/session.h"
#include "host/measurer.h"
#include "measure/report.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

// A host made with the configuration's lab and scene (a child draws one configuration: no other
// lab's or scene's build on the way), then its settings and camera.
std::unique_ptr<LabHost> configuredHost(const std::vector<fs::path>& roots, const Exercise& ex, const Configuration& c,
                                        std::string& error) {
  auto host = std::make_unique<LabHost>(ShaderSearchPath(roots), ex.lab, c.scene);
  std::vector<std::string> sets;
  for (auto& [key, value] : c.settings) sets.push_back(key + "=" + value);
  error = configureHost(*host, ex.lab, host->sceneId() == c.scene ? std::string() : c.scene, sets, {}, c.camera);
  return host;
}

void writeResult(const ConfigurationJob& job, const std::string& phase, const nlohmann::json& j) {
  writeTextFile((job.dir / (job.stem + "-" + phase + ".json")).string(), j.dump(2) + "\n");
}

nlohmann::json metricsJson(const Metrics& metrics) {
  nlohmann::json j = nlohmann::json::object();
  for (auto& [k, v] : metrics) j[k] = std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
  return j;
}

// The errors of the programs this frame used (the first 20), at the student's file:line with the caret.
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
        if (out.size() < kMostErrors) out.push_back(text);
        else ++more;
      }
    if (p->diagnostics().empty()) out.push_back(p->spec().name + ": did not build (no message from the driver)");
  }
  if (more) out.push_back("... and " + std::to_string(more) + " more errors");
  return out;
}

}  // namespace

std::string solutionKeyBase(const Exercise& ex, size_t configuration) {
  static const std::string program = ContentHash().addFile("/proc/self/exe").hex();  // once per process
  return ContentHash()
      .add("shaders ")
      .addTree(builtinShaderDir())
      .add("\nrubric ")
      .add(ex.id)
      .addFile(ex.dir / "rubric.json")
      .add("\nconfiguration " + std::to_string(configuration) + "\nprogram " + program)
      .hex();
}

nlohmann::json readResult(const ConfigurationJob& job, const std::string& phase) {
  std::ifstream in(job.dir / (job.stem + "-" + phase + ".json"));
  if (!in) return {};
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  return j.is_discarded() ? nlohmann::json() : j;
}

int renderConfiguration(const ConfigurationJob& job, const std::function<void(const std::string&)>& enter) {
  const Exercise& ex = *job.exercise;
  const Configuration& c = *job.configuration;
  const std::string where = (ex.dir / "rubric.json").string() + ": configuration '" + c.name + "'";
  const auto failSolution = [&](const std::string& message) {
    writeResult(job, "solution", {{"error", message}});
    return 2;
  };
  enter("solution");
  std::string err;
  auto context = createHeadlessContext(job.backend, err);
  if (!context) return failSolution(err);

  // The built-in shaders: the solution's frame, and the truth the checks need, from the cache when
  // this renderer made them before for the same shaders, rubric and program.
  const std::string renderer = context->describe();
  const std::string key = ContentHash().add(job.cacheKey).add("\nbackend " + job.backend + "\nrenderer ").add(renderer).hex();
  CachedSolution built;
  const bool cached = job.cache.load(key, built);
  if (!cached) {
    built.numbers = {{"renderer", renderer}};
    std::string configError;
    const auto solutionHost = configuredHost({builtinShaderDir()}, ex, c, configError);
    if (!configError.empty()) return failSolution(where + ": " + configError);
    LabHost& host = *solutionHost;
    host.settle();
    host.renderFrame(ex.size);
    built.frame = host.readImage();
    if (auto errors = buildErrors(host); !errors.empty())
      return failSolution(where + ": the lab's own shaders did not build: " + errors.front());
    if (c.needsTruth()) {
      Measurer measurer(host);
      auto m = measurer.measureNow(ex.size, 0.0f, {});
      if (!m) return failSolution(where + ": this configuration has no ground truth to check against");
      built.truths = m->references;
      built.numbers["vs_truth"] = metricsJson(m->values);
    }
    if (auto e = job.cache.store(key, built); !e.empty()) std::fprintf(stderr, "shadelab: grade: %s\n", e.c_str());
  }
  const ImageF& solution = built.frame;
  const std::vector<ImageF>& truths = built.truths;
  nlohmann::json solutionJson = built.numbers;
  solutionJson["from_cache"] = cached;
  if (job.solutionOnly) {
    writeResult(job, "solution", solutionJson);
    return 0;
  }
  if (auto e = writePng((job.dir / (job.stem + "-solution.png")).string(), solution); !e.empty()) return failSolution(e);
  writeResult(job, "solution", solutionJson);

  // The student's folders first: their frame, compared with the solution's and with the truth.
  enter("student");
  std::vector<fs::path> roots = job.studentDirs;
  roots.push_back(builtinShaderDir());
  std::string configError;
  const auto studentHost = configuredHost(roots, ex, c, configError);
  if (!configError.empty()) return failSolution(where + ": " + configError);
  LabHost& host = *studentHost;
  host.settle();
  host.renderFrame(ex.size);
  const ImageF image = host.readImage();
  nlohmann::json student{{"errors", buildErrors(host)}, {"non_finite", countNonFinite(image)}};
  const ImageError e = compareImages(image, solution);
  student["vs_solution"] = metricsJson({{"rmse", e.rmse}, {"covered_rmse", e.coveredRmse}, {"max_error", e.maxError},
                                        {"bad_pixel_pct", e.badPixelPct}});
  if (c.needsTruth() && student["errors"].empty()) {
    const Judge& judge = *host.lab().judge();  // the solution was measured against its truth: the lab judges
    std::vector<ImageF> views;
    for (auto& view : judge.measuredViews()) views.push_back(host.renderView(ex.size, 0.0f, view.settings));
    student["vs_truth"] = metricsJson(judge.viewMetrics(views, truths));
  }
  writePng((job.dir / (job.stem + "-student.png")).string(), image);
  writePng((job.dir / (job.stem + "-diff.png")).string(), diffImage(image, solution));
  writeResult(job, "student", student);
  return 0;
}

}  // namespace shadelab

#include "app/cli/grade_render.h"

#include <cmath>
#include <fstream>
#include <optional>

#include "app/cli/session.h"
#include "app/gl/gl.h"
#include "app/grade/configuration_frames.h"
#include "app/lab/host_batch.h"
#include "app/measure/report.h"

namespace shadelab {

namespace fs = std::filesystem;

namespace {

void writeResult(const ConfigurationJob& job, const std::string& phase, const nlohmann::json& j) {
  writeTextFile((job.dir / (job.stem + "-" + phase + ".json")).string(), j.dump(2) + "\n");
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
      .add("\nstarter ")  // drawn as the exercise's first mistake
      .addTree(ex.dir / "starter")
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
  const HostBatch batch;  // this child's hosts, one after another, all draw this configuration's scene
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
  const std::string key =
      ContentHash().add(job.cacheKey).add("\nbackend " + job.backend + "\nrenderer ").add(renderer).hex();
  CachedSolution built;
  const bool cached = job.cache.load(key, built);
  if (!cached) {
    built.numbers = {{"renderer", renderer}};
    if (auto e = drawSolution(ex, c, built); !e.empty()) return failSolution(e);
    if (auto e = job.cache.store(key, built); !e.empty()) std::fprintf(stderr, "shadelab: grade: %s\n", e.c_str());
  }
  // The solution at other settings, for a frame nothing else explains: read back, or drawn once
  // and kept for the next student who needs them (grade --prepare draws them ahead).
  std::optional<SettingFrames> settings;
  const SettingFramesSource settingFrames = [&]() -> const SettingFrames* {
    if (settings) return &*settings;
    const std::string settingsKey = ContentHash().add(key).add("\nsettings").hex();
    settings.emplace();
    if (CachedFrames kept; job.cache.load(settingsKey, kept) && settingFramesFromKept(kept, *settings))
      return &*settings;
    // Kept for the class only when whole and drawn in a context the student's draw left clean.
    const bool whole = drawSettingFrames(ex, c, *settings);
    if (whole && gl::drainErrors().empty())
      if (auto e = job.cache.store(settingsKey, keptSettingFrames(*settings)); !e.empty())
        std::fprintf(stderr, "shadelab: grade: %s\n", e.c_str());
    return &*settings;
  };
  if (job.solutionOnly) {
    // Filling the cache ahead of a class (grade --prepare keeps the slips and the solution at other
    // settings too, so that no student's diagnosis has to draw them).
    if (job.slips && !built.numbers.contains("slips")) {
      if (auto e = drawSlips(ex, c, built); !e.empty()) return failSolution(e);
      if (auto e = job.cache.store(key, built); !e.empty()) std::fprintf(stderr, "shadelab: grade: %s\n", e.c_str());
    }
    if (job.slips && c.function < 0) settingFrames();
    nlohmann::json numbers = built.numbers;
    numbers["from_cache"] = cached;
    writeResult(job, "solution", numbers);
    return 0;
  }
  if (job.slips) {
    // The slips, drawn once and kept with the solution's frames for the next student who needs
    // them, then the student's frame against them.
    if (!built.numbers.contains("slips")) {
      if (auto e = drawSlips(ex, c, built); !e.empty()) return failSolution(e);
      if (auto e = job.cache.store(key, built); !e.empty()) std::fprintf(stderr, "shadelab: grade: %s\n", e.c_str());
    }
    writeResult(job, "solution", built.numbers);
    enter("student");
    nlohmann::json distances;
    if (auto e = studentSlipDistances(ex, c, job.studentDirs, built, distances); !e.empty()) return failSolution(e);
    writeResult(job, "slips", distances);
    return 0;
  }
  const ImageF& solution = built.frame;
  nlohmann::json solutionJson = built.numbers;
  solutionJson["from_cache"] = cached;
  if (c.function < 0)
    if (auto e = writePng((job.dir / (job.stem + "-solution.png")).string(), solution); !e.empty())
      return failSolution(e);
  writeResult(job, "solution", solutionJson);

  // The student's folders first: their frame, compared with the solution's and with the truth.
  enter("student");
  ImageF image;
  std::string configError;
  const nlohmann::json student = drawStudent(ex, c, job.studentDirs, built, settingFrames, image, configError);
  if (!configError.empty()) return failSolution(configError);
  if (c.function < 0) {  // a function's table is evidence, not a picture for the report
    writePng((job.dir / (job.stem + "-student.png")).string(), image);
    writePng((job.dir / (job.stem + "-diff.png")).string(), diffImage(image, solution));
  }
  writeResult(job, "student", student);
  if (job.traceInDraw) {
    enter("trace");
    if (const nlohmann::json trace = traceStudentFrame(ex, c, job.studentDirs, student, image, built); !trace.is_null())
      writeResult(job, "trace", trace);
  }
  return 0;
}

}  // namespace shadelab

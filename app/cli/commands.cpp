#include "app/cli/commands.h"

#include <cstdio>
#include <fstream>

#include "app/cli/session.h"
#include "app/grade/rubric.h"
#include "app/host/measurer.h"
#include "app/scene/scene_catalog.h"

namespace shadelab {

// Programs the frame used that did not build, with their first error: the frame shows the last
// good program or the fallback, and a headless run must say so and fail: the error as the window
// shows it, with the offending line and a caret under its column.
static std::vector<std::string> shaderFailures(LabHost& host) {
  std::vector<std::string> out;
  for (auto& p : host.lab().activePrograms())
    if (p->lastBuildFailed() || !p->hasGoodProgram())
      out.push_back(p->spec().name +
                    (p->hasGoodProgram() ? " (showing its last good build)" : " (drawing the fallback)") +
                    (p->diagnostics().empty() ? "" : ": " + p->diagnostics().front().formatWithCaret()));
  return out;
}

static std::string passSummary(const std::vector<gl::PassTiming>& passes) {
  std::string s;
  for (auto& p : passes) s += (s.empty() ? "" : ", ") + p.name + " " + formatNumber(p.gpuMs) + " ms";
  return s.empty() ? "none" : s;
}

int runRender(const Options& o) {
  if (o.out.empty()) return fail("render: --out FILE.png is required");
  Session s;
  if (auto err = openSession(o, s); !err.empty()) return fail(err);
  LabHost& host = *s.host;
  const TimedFrames t = renderTimed(host, s.size, s.time, o.warmup, o.frames);
  ImageF image = host.readImage();
  if (auto err = writePng(o.out, image); !err.empty()) return fail(err);

  nlohmann::json meta = host.stateJson();
  meta["size"] = {s.size.x, s.size.y};
  meta["time"] = s.time;
  meta["renderer"] = s.context->describe();
  meta["gpu_ms"] = t.gpuMs;
  meta["passes"] = nlohmann::json::array();
  for (auto& p : t.passes) meta["passes"].push_back({{"name", p.name}, {"gpu_ms", p.gpuMs}, {"cpu_ms", p.cpuMs}});
  meta["non_finite_values"] = countNonFinite(image);
  meta["warnings"] = host.warnings();
  const std::vector<std::string> failed = shaderFailures(host);
  meta["shader_errors"] = failed;
  for (auto& panel : host.lab().panels())  // the lab's tables, as the app shows them
    for (auto& item : panel.items)
      if (auto* table = std::get_if<PanelTable>(&item))
        meta["panels"][panel.title].push_back({{"columns", table->columns}, {"rows", table->rows}});
  if (o.measure) {
    Measurer measurer(host);
    auto m = measurer.measureNow(s.size, s.time, {{"gpu_ms", t.gpuMs}, {"cpu_ms", t.cpuMs}},
                                 [](const std::vector<JobStatus>& jobs) { progress(0, 1, describeJobs(jobs)); });
    if (!m) {
      const std::string why = referenceOf(host.lab()).description;
      return fail(std::string(host.lab().id()) + ": this configuration has no ground truth to measure against" +
                  (why.empty() ? "" : " (" + why + ")"));
    }
    nlohmann::json values = nlohmann::json::object();
    std::string line;
    for (auto& [k, v] : m->values) {
      values[k] = v;
      line += " " + k + "=" + formatNumber(v);
    }
    meta["measured"] = {{"truth", m->truth}, {"values", values}};
    std::printf("measured against %s:%s\n", m->truth.c_str(), line.c_str());
  }
  const std::string jsonPath = std::filesystem::path(o.out).replace_extension(".json").string();
  std::ofstream(jsonPath + ".tmp") << meta.dump(2) << "\n";
  std::filesystem::rename(jsonPath + ".tmp", jsonPath);

  for (auto& w : host.warnings()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  std::printf("%s: %dx%d, lab %s, scene %s, passes: %s (median of %d frames)\n", o.out.c_str(), s.size.x, s.size.y,
              std::string(host.lab().id()).c_str(), host.sceneId().c_str(), passSummary(t.passes).c_str(), o.frames);
  for (auto& f : failed) std::fprintf(stderr, "shadelab: render: %s\n", f.c_str());
  if (!failed.empty())
    return fail("render: " + std::to_string(failed.size()) +
                " program(s) of this frame did not build (the image was written)");
  return 0;
}

int runList(const Options& o) {
  std::printf("labs:\n");
  for (auto& id : labIds()) {
    auto lab = makeLab(id);
    std::printf("%s  %s\n  %s\n  default scene: %s\n  params:\n", id.c_str(), std::string(lab->title()).c_str(),
                std::string(lab->summary()).c_str(), std::string(lab->defaultScene()).c_str());
    DescribeParams d(id);
    lab->visitParams(d);
    for (auto& line : d.lines) std::printf("  %s\n", line.c_str());
    for (auto& scene : lab->scenes()) std::printf("  scene %-22s %s\n", scene.id.c_str(), scene.description.c_str());
    std::printf("  stress cases:");
    for (auto& c : stressCasesOf(*lab)) std::printf(" %s", c.name.c_str());
    std::printf("\n");
  }
  std::printf("\nscenes (or any .gltf/.glb/.obj/.off/.ply file):\n");
  for (auto& s : listScenes()) std::printf("  %-14s %s\n", s.id.c_str(), s.description.c_str());
  if (const auto missing = missingDataScenes(); !missing.empty()) {
    std::string ids;
    for (auto& id : missing) ids += (ids.empty() ? "" : ", ") + id;
    std::printf("  not here (their files are not downloaded; %s fetches them): %s\n", kGetDataCommand, ids.c_str());
  }
  std::string roots;
  for (auto& r : exerciseRoots()) roots += (roots.empty() ? "" : ", ") + r.string();
  std::printf("\nexercises (shadelab grade --exercise ID --shaders DIR; from %s):\n", roots.c_str());
  for (auto& id : listExercises()) {
    Exercise ex;
    const std::string err = loadExercise(id, ex);
    if (err.empty())
      std::printf("  %-26s %-13s %s\n", id.c_str(), ex.level.c_str(), ex.title.c_str());
    else
      std::printf("  %-26s %s\n", id.c_str(), err.c_str());
  }
  std::printf("\nheadless backends: %s\n", std::string(kHeadlessBackends).c_str());
  return 0;
}

int runCheckShaders(const Options& o) {
  if (o.dialect == "es") return runCheckShadersEs(o);
  std::string err;
  auto context = createHeadlessContext(o.backend, err);
  if (!context) return fail(err);
  ShaderLibrary shaders(shaderSearchPath(o));
  int programs = 0, failed = 0;
  for (auto& id : labIds()) {
    if (!o.lab.empty() && id != o.lab) continue;
    for (auto& spec : makeLab(id)->allPrograms()) {
      ++programs;
      auto p = shaders.program(spec);  // diagnostics go to stderr as file:line:col: error: ...
      if (!p->hasGoodProgram()) {
        ++failed;
        std::string defines;
        for (auto& [n, v] : spec.defines) defines += " " + n + "=" + v;
        std::fprintf(stderr, "FAIL %s:%s\n", spec.name.c_str(), defines.c_str());
      }
    }
  }
  std::printf("check-shaders: %d programs, %d failed (%s)\n", programs, failed, context->describe().c_str());
  return failed ? 1 : 0;
}

int runCompare(const Options& o) {
  if (o.positional.size() != 2) return fail("compare: expected two images, e.g. shadelab compare a.png b.png");
  ImageF a, b;
  if (auto err = readImage(o.positional[0], a); !err.empty()) return fail(err);
  if (auto err = readImage(o.positional[1], b); !err.empty()) return fail(err);
  if (a.size != b.size)
    return fail("compare: sizes differ (" + std::to_string(a.size.x) + "x" + std::to_string(a.size.y) + " vs " +
                std::to_string(b.size.x) + "x" + std::to_string(b.size.y) + ")");
  const ImageError e = compareImages(a, b);
  std::printf("rmse %.6f  max_error %.6f  mean_error %.6f  bad_pixel_pct %.4f (channel difference > 0.1)\n", e.rmse,
              e.maxError, e.meanError, e.badPixelPct);
  if (!o.out.empty())
    if (auto err = writePng(o.out, diffImage(a, b)); !err.empty()) return fail(err);
  return 0;
}

int runStress(const Options& o) {
  Session s;
  if (auto err = openSession(o, s); !err.empty()) return fail(err);
  LabHost& host = *s.host;
  const Settings defaults = host.currentSettings();
  const std::string defaultScene = host.sceneId();
  const auto cases = stressCasesOf(host.lab());
  const glm::ivec2 size = o.sizeGiven ? o.size : glm::ivec2(320, 180);
  int failures = 0, n = 0;
  for (auto& c : cases) {
    host.applySettings(defaults);
    std::string why;
    const std::string scene = c.scene.empty() ? defaultScene : c.scene;
    why = host.applySettings(c.settings);  // first: settings may change the scene's needs (its scale)
    if (why.empty()) why = scene != host.sceneId() ? host.selectScene(scene) : host.refreshScene();
    if (why.empty()) host.resetCamera();
    if (why.empty()) why = applyCamera(host, c.camera);
    if (why.empty()) {
      host.settle();
      host.renderFrame(size, o.time);
      const ImageF image = host.readImage();
      const size_t bad = countNonFinite(image);
      if (bad) why = std::to_string(bad) + " NaN/Inf values in the float target";
      if (why.empty() && !c.expectWarning.empty()) {
        bool warned = false;
        for (auto& w : host.warnings()) warned |= w.find(c.expectWarning) != std::string::npos;
        if (!warned) why = "expected a warning containing '" + c.expectWarning + "'";
      }
    }
    progress(++n, int(cases.size()), c.name);
    std::printf("%s %s%s%s\n", why.empty() ? "PASS" : "FAIL", c.name.c_str(), why.empty() ? "" : ": ", why.c_str());
    failures += !why.empty();
  }
  std::printf("stress %s: %d passed, %d failed\n", std::string(host.lab().id()).c_str(), int(cases.size()) - failures,
              failures);
  return failures ? 1 : 0;
}

}  // namespace shadelab

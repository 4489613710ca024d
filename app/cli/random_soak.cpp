// `shadelab random` and `shadelab soak`: configurations nobody wrote by hand.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <random>

#include "app/cli/commands.h"
#include "app/cli/session.h"
#include "app/gl/gl.h"
#include "app/host/random_settings.h"
#include "app/host/soak.h"
#include "app/util/output_files.h"

namespace shadelab {
namespace {

// Whether every pixel is black (all colour channels under half an 8-bit step).
bool allBlack(const ImageF& image) {
  for (size_t i = 0; i < image.rgba.size(); i += 4)
    if (image.rgba[i] > 0.002f || image.rgba[i + 1] > 0.002f || image.rgba[i + 2] > 0.002f) return false;
  return true;
}

}  // namespace

int runRandom(const Options& o) {
  Session s;
  if (auto err = openSession(o, s); !err.empty()) return fail(err);
  LabHost& host = *s.host;
  const glm::ivec2 size = o.sizeGiven ? o.size : glm::ivec2(160, 90);
  std::vector<std::string> labs = o.lab.empty() ? labIds() : std::vector<std::string>{o.lab};
  std::mt19937 rng(o.seed);
  int failures = 0, total = 0;
  std::vector<std::pair<double, std::string>> slowest;  // seconds (settle and one frame), reproduction
  for (auto& id : labs) {
    if (auto err = host.selectLab(id); !err.empty()) return fail(err);
    int labFailures = 0;
    for (int i = 0; i < o.count; ++i) {
      host.resetParams();
      const Settings drawn = randomSettings(host.lab(), rng);
      const auto start = std::chrono::steady_clock::now();
      std::string why = host.applySettings(drawn);
      if (why.empty()) why = host.refreshScene();
      if (why.empty()) {
        gl::drainErrors();
        host.settle();
        host.renderFrame(size, o.time);
        const ImageF image = host.readImage();
        const std::vector<std::string> warnings = host.warnings();
        if (const std::string err = gl::drainErrors(); !err.empty())
          why = "GL error " + err;
        else if (const size_t bad = countNonFinite(image); bad > 0)
          why = std::to_string(bad) + " NaN/Inf values";
        else if (allBlack(image) && warnings.empty())
          why = "a black frame and no warning saying why";
        for (auto& p : host.lab().activePrograms())
          if (why.empty() && !p->hasGoodProgram()) why = "program " + p->spec().name + " did not build";
      }
      ++total;
      const std::string repro = "--lab " + id + " " + settingsAsArgs(id, drawn);
      slowest.emplace_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), repro);
      std::sort(slowest.begin(), slowest.end(), std::greater<>());
      if (slowest.size() > 3) slowest.pop_back();
      if (!why.empty()) {
        ++failures, ++labFailures;
        std::printf("FAIL %s #%d: %s\n  reproduce: shadelab render %s --size %dx%d --out x.png\n", id.c_str(), i,
                    why.c_str(), repro.c_str(), size.x, size.y);
      }
      progress(i + 1, o.count, id);
    }
    std::printf("random %s: %d configurations, %d failed (seed %u)\n", id.c_str(), o.count, labFailures, o.seed);
  }
  for (auto& [seconds, repro] : slowest)  // not a failure: where a frame costs the most
    std::printf("slow: %.1f s for its jobs and one %dx%d frame: %s\n", seconds, size.x, size.y, repro.c_str());
  std::printf("random: %d configurations, %d failed\n", total, failures);
  return failures ? 1 : 0;
}

int runSoak(const Options& o) {
  if (!o.out.empty())  // found out now, not after the run
    if (auto err = makeParentFolder(o.out); !err.empty()) return fail(err);
  Options with = o;
  const std::filesystem::path scratch = SoakDriver::makeScratch();
  with.shaderDirs.insert(with.shaderDirs.begin(), scratch);
  Session s;
  if (auto err = openSession(with, s); !err.empty()) return fail(err);
  LabHost& host = *s.host;
  host.shaders().onDiagnostic = [](const Diagnostic&) {};  // the driver breaks shaders on purpose
  const glm::ivec2 size = o.sizeGiven ? o.size : glm::ivec2(320, 180);
  SoakDriver driver(scratch, o.seed);
  std::printf("soak: %s for %s min, seed %u, scratch shaders in %s\n", s.context->describe().c_str(),
              formatNumber(o.minutes).c_str(), o.seed, scratch.string().c_str());
  const double seconds = o.minutes * 60.0;
  double nextReport = 60.0;
  while (driver.seconds() < seconds) {
    driver.step(host);
    host.renderFrame(size, o.time);
    driver.afterFrame(host);
    if (driver.seconds() >= nextReport) {  // about once a minute (a long step delays it)
      nextReport = driver.seconds() + 60.0;
      const auto& x = driver.samples().back();
      std::printf("soak: %4.0f s  %7.1f MB  %5d GL objects  %d jobs  %ld frames\n", x.seconds, x.residentMb,
                  x.glObjects, x.jobs, x.frames);
      std::fflush(stdout);
    }
  }
  const std::filesystem::path csv =
      o.out.empty() ? scratch.parent_path() / (scratch.filename().string() + ".csv") : std::filesystem::path(o.out);
  const SoakDriver::Verdict verdict = driver.finish(csv, o.minutes >= 10.0);
  std::printf("%s", verdict.report.c_str());
  std::filesystem::remove_all(scratch);
  return verdict.passed ? 0 : 1;
}

}  // namespace shadelab

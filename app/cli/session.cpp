#include "app/cli/session.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

namespace shadelab {

ShaderSearchPath shaderSearchPath(const Options& o) {
  std::vector<std::filesystem::path> roots = o.shaderDirs;
  roots.push_back(builtinShaderDir());
  return ShaderSearchPath(roots);
}

std::string openSession(const Options& o, Session& s) {
  std::string err;
  s.context = createHeadlessContext(o.backend, err);
  if (!s.context) return err;
  Preset preset;
  if (!o.preset.empty())
    if (auto e = readPreset(o.preset, preset); !e.empty()) return e;
  // The host opens on the lab and scene it will draw (the preset's, else the options'): entering
  // the default lab first would build, upload and throw away a scene of its own.
  const std::string firstLab = preset.lab.value_or(o.lab);
  const std::string firstScene = preset.lab ? preset.scene.value_or("") : o.scene;
  s.host = std::make_unique<LabHost>(shaderSearchPath(o), firstLab, firstScene);
  LabHost& host = *s.host;
  s.size = o.size;
  s.time = o.time;
  if (!o.preset.empty()) {
    if (auto e = host.applyPreset(preset); !e.empty()) return o.preset + ": " + e;
    if (!o.sizeGiven && preset.size) s.size = *preset.size;
    if (o.time == 0.0f && preset.time) s.time = *preset.time;
  }
  const bool opened = host.lab().id() == o.lab && host.sceneId() == o.scene;  // nothing to select again
  if (auto e = configureHost(host, o.lab, opened ? std::string() : o.scene, o.sets, o.actions, o.camera); !e.empty())
    return e;
  if (!o.heightMap.empty())
    if (auto e = host.setHeightMap(o.heightMap); !e.empty()) return "--height-map: " + e;
  return {};
}

static double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
}

TimedFrames renderTimed(LabHost& host, glm::ivec2 size, float time, int warmup, int frames) {
  // The lab's jobs for these settings first (a smoothing, a bake): frames time the result, not a
  // stale one. Progress goes to stderr like a sweep's.
  host.settle([](const std::vector<JobStatus>& jobs) { progress(0, 1, describeJobs(jobs)); });
  for (int i = 0; i < warmup; ++i) host.renderFrame(size, time);
  std::vector<double> gpu, cpu;
  std::vector<std::vector<double>> perPass;
  TimedFrames out;
  for (int i = 0; i < std::max(frames, 1); ++i) {
    const auto& passes = host.renderFrame(size, time);
    double g = 0, c = 0;
    perPass.resize(std::max(perPass.size(), passes.size()));
    for (size_t p = 0; p < passes.size(); ++p) {
      g += passes[p].gpuMs;
      c += passes[p].cpuMs;
      perPass[p].push_back(passes[p].gpuMs);
    }
    gpu.push_back(g);
    cpu.push_back(c);
    out.passes = passes;
  }
  out.gpuMs = median(gpu);
  out.cpuMs = median(cpu);
  for (size_t p = 0; p < out.passes.size() && p < perPass.size(); ++p) out.passes[p].gpuMs = median(perPass[p]);
  return out;
}

int fail(const std::string& message) {
  std::fprintf(stderr, "shadelab: %s\n", message.c_str());
  return 1;
}

void progress(int done, int total, const std::string& label) {
  const int width = 24, filled = total > 0 ? width * done / total : width;
  std::string bar(size_t(filled), '#');
  bar.resize(size_t(width), '.');
  const bool tty = isatty(fileno(stderr));
  std::fprintf(stderr, "%s[%s] %d/%d %s%s", tty ? "\r\033[K" : "", bar.c_str(), done, total, label.c_str(),
               tty && done < total ? "" : "\n");
  std::fflush(stderr);
}

}  // namespace shadelab

namespace shadelab {

std::string describeJobs(const std::vector<JobStatus>& jobs) {
  std::string s;
  for (auto& j : jobs) {
    s += (s.empty() ? "" : "; ") + j.label + " " + std::to_string(int(j.progress * 100.0f + 0.5f)) + "%";
    if (!j.stage.empty()) s += " (" + j.stage + ")";
  }
  return s;
}

}  // namespace shadelab

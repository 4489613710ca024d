#include "app/host/truth.h"

#include <algorithm>

namespace shadelab {

TruthRequest describeTruth(LabHost& host, glm::ivec2 size, float time, const Settings& view) {
  TruthRequest req;
  req.spec = referenceOf(host.lab());
  req.viewSettings = host.currentSettings();
  host.applySettings(req.spec.overrides);
  host.applySettings(view);
  req.truthSettings = host.currentSettings();
  host.applySettings(req.viewSettings);
  req.camera = host.camera();
  req.size = size;
  req.time = time;
  req.key = std::string(host.lab().id()) + "|" + host.sceneId() + "#" + std::to_string(host.sceneLoads()) + "|";
  for (auto& [k, v] : req.truthSettings) req.key += k + "=" + v + ";";
  req.key += "|" + req.camera.toString() + "|" + std::to_string(size.x) + "x" + std::to_string(size.y) + "|t" +
             formatNumber(time) + "|j" + std::to_string(req.spec.jitterGrid) + (req.spec.traced ? "|traced" : "");
  return req;
}

namespace {

// `draw` under the truth's settings and the built-in shaders (a student's file must not be judged
// against itself); the settings current before (a slider may have moved since the request) come back.
template <typename Draw>
auto underTruthSettings(LabHost& host, const TruthRequest& req, Draw&& draw) {
  const ShaderLibrary::BuiltinOnly builtin(host.shaders());
  const Settings now = host.currentSettings();
  host.applySettings(req.truthSettings);
  auto result = draw();
  host.applySettings(now);
  return result;
}

}  // namespace

void drawTruthSlice(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target, glm::vec2 jitter,
                    int slice) {
  underTruthSettings(host, req,
                     [&] { return host.drawInto(target, req.camera, req.time, jitter, slice, req.spec.slices); });
}

ImageF drawTruthFrame(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target, glm::vec2 jitter) {
  for (int slice = 0; slice < std::max(req.spec.slices, 1); ++slice) drawTruthSlice(host, req, target, jitter, slice);
  return {target.size(), target.readRgba()};
}

TraceWork beginTrace(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target) {
  return underTruthSettings(host, req, [&] { return host.trace(target, req.camera, req.time); });
}

GlTraceStep beginGlTrace(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target) {
  return underTruthSettings(host, req, [&] { return host.traceOnGl(target, req.camera, req.time); });
}

ImageF renderTruthNow(LabHost& host, const TruthRequest& req) {
  const gl::RenderTarget target = gl::RenderTarget::create(req.size);
  if (req.spec.traced && req.spec.tracedOnGl) {
    GlTraceStep step = beginGlTrace(host, req, target);
    JobContext ctx;
    while (step)
      if (auto image = step(ctx)) return std::move(*image);
    return {};
  }
  if (req.spec.traced) {
    TraceWork work = beginTrace(host, req, target);
    JobContext ctx;
    return work ? work(ctx) : ImageF{};
  }
  const auto samples = jitterSamples(req.spec.jitterGrid, req.spec.pixelFilter);
  if (samples.size() == 1) return drawTruthFrame(host, req, target, samples[0].offset);
  ImageAccumulator acc(req.spec.displayEncoded);
  for (auto& s : samples) acc.add(drawTruthFrame(host, req, target, s.offset), s.weight);
  return acc.mean();
}

}  // namespace shadelab

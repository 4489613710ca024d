#include "host/measurer.h"

#include <cmath>

#include "host/truth.h"

namespace shadelab {

double Measurement::value(const std::string& key) const {
  for (auto& [k, v] : values)
    if (k == key) return v;
  return std::nan("");
}

Measurer::~Measurer() { host_.jobs().cancel(kJobKey); }

std::string Measurer::labelOf(const Settings& settings) {
  CollectAsText defaults;
  makeLab(host_.lab().id())->visitParams(defaults);
  std::string label;
  for (size_t i = 0; i < settings.size() && i < defaults.values.size(); ++i)
    if (settings[i].second != defaults.values[i].second)
      label += (label.empty() ? "" : " ") + settings[i].first + "=" + settings[i].second;
  return label.empty() ? "defaults" : label;
}

const std::vector<Measurement>& Measurer::history() {
  if (labId_ != host_.lab().id()) {
    history_.clear();
    labId_ = std::string(host_.lab().id());
  }
  return history_;
}

std::shared_ptr<const ImageF> Measurer::cachedTruth(const std::string& key) const {
  for (auto& [k, image] : truths_)
    if (k == key) return image;
  return nullptr;
}

void Measurer::cacheTruth(const std::string& key, std::shared_ptr<const ImageF> image) {
  truths_.emplace_front(key, std::move(image));
  if (truths_.size() > kCachedTruths) truths_.pop_back();
}

void Measurer::finish(Measurement m, const std::shared_ptr<const ImageF>& truth) {
  Metrics costs = std::move(m.values);
  if (truth) {
    m.values = host_.lab().metrics(m.image, *truth);
    m.reference = *truth;
  } else {
    m.values = host_.lab().meshMetrics();
  }
  for (auto& c : costs) m.values.push_back(std::move(c));
  if (onMeasured) onMeasured(m);
  history();  // drops another lab's history first
  Measurement kept = m;
  kept.image = kept.reference = ImageF{};
  history_.push_back(std::move(kept));
  last_ = std::move(m);
}

std::string Measurer::start(glm::ivec2 size, float time, Metrics costs) {
  Lab& lab = host_.lab();
  const ReferenceSpec spec = lab.reference();
  if (spec.kind == TruthKind::None) return std::string(lab.id()) + ": this configuration has no ground truth to measure against";
  Measurement m;
  m.lab = std::string(lab.id());
  m.settings = host_.currentSettings();
  m.label = labelOf(m.settings);
  m.truth = spec.truth;
  m.values = std::move(costs);
  JobRunner& jobs = host_.jobs();

  if (spec.kind == TruthKind::Mesh) {
    // The lab's own jobs compute the result and its metrics: wait for them, then read.
    jobs.submitGlSteps(kJobKey, "measuring against " + spec.truth, [this, m](JobContext& job) mutable {
      if (host_.jobs().busyOtherThan(kJobKey)) {
        job.progress(0.0f, "waiting for the result");
        return GlStep::Wait;
      }
      finish(std::move(m), nullptr);
      return GlStep::Done;
    });
    return {};
  }

  m.image = host_.renderMeasured(size, time);
  const TruthRequest req = describeTruth(host_, size, time);
  if (auto truth = cachedTruth(req.key)) {
    jobs.cancel(kJobKey);  // an older measurement would land after this one
    finish(std::move(m), truth);
    return {};
  }
  const std::string label = "truth for " + m.label;
  if (spec.traced) {
    const gl::RenderTarget target = gl::RenderTarget::create(size);
    TraceWork work = beginTrace(host_, req, target);
    if (!work) return std::string(lab.id()) + ": the lab traced no reference";
    jobs.submit(kJobKey, label, std::move(work), [this, m, key = req.key](ImageF truth) mutable {
      auto image = std::make_shared<const ImageF>(std::move(truth));
      cacheTruth(key, image);
      finish(std::move(m), image);
    });
    return {};
  }
  // Rasterised truth: one jittered frame per slice, accumulated; the target lives with the job.
  struct Accumulation {
    std::vector<JitterSample> samples;
    size_t next = 0;
    ImageAccumulator sum;
    std::optional<gl::RenderTarget> target;
    ImageF single;
  };
  auto acc = std::make_shared<Accumulation>(
      Accumulation{jitterSamples(spec.jitterGrid, spec.pixelFilter), 0, ImageAccumulator(spec.displayEncoded), {}, {}});
  jobs.submitGlSteps(kJobKey, label, [this, m, req, acc](JobContext& job) mutable {
    if (!acc->target) acc->target = gl::RenderTarget::create(req.size);
    const JitterSample s = acc->samples[acc->next++];
    ImageF frame = drawTruthFrame(host_, req, *acc->target, s.offset);
    const size_t n = acc->samples.size();
    job.progress(float(acc->next) / float(n), "truth frame " + std::to_string(acc->next) + " of " + std::to_string(n));
    if (n == 1) acc->single = std::move(frame);
    else acc->sum.add(frame, s.weight);
    if (acc->next < n) return GlStep::More;
    auto image = std::make_shared<const ImageF>(n == 1 ? std::move(acc->single) : acc->sum.mean());
    acc->target.reset();
    cacheTruth(req.key, image);
    finish(std::move(m), image);
    return GlStep::Done;
  });
  return {};
}

std::optional<Measurement> Measurer::measureNow(glm::ivec2 size, float time, Metrics costs,
                                                const std::function<void(const std::vector<JobStatus>&)>& onProgress) {
  host_.settle(onProgress);
  last_.reset();
  if (!start(size, time, std::move(costs)).empty()) return std::nullopt;
  host_.jobs().waitAll(onProgress);
  return std::exchange(last_, std::nullopt);
}

}  // namespace shadelab

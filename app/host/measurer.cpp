#include "app/host/measurer.h"

#include <algorithm>
#include <cmath>

#include "app/host/truth.h"

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

void Measurer::followLab() {
  if (labEntry_ == host_.labEntries()) return;
  // Another lab (or the same one entered again): its measurements and truths are its own. Truths
  // are kept for the lab in use only (up to kCachedTruths images of the view's size; 8 of a
  // full-HD view are 265 MB).
  history_.clear();
  truths_.clear();
  last_.reset();
  labEntry_ = host_.labEntries();
}

const std::vector<Measurement>& Measurer::history() {
  followLab();
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

void Measurer::finish(Measurement m, const std::vector<std::shared_ptr<const ImageF>>& truths) {
  Metrics costs = std::move(m.values);
  if (!truths.empty()) {
    for (auto& t : truths) m.references.push_back(*t);
    m.values = host_.lab().judge()->viewMetrics(m.images, m.references);
    m.reference = m.references.front();
  } else {
    m.values = host_.lab().judge()->meshMetrics();
  }
  for (auto& c : costs) m.values.push_back(std::move(c));
  if (onMeasured) onMeasured(m);
  history();  // drops another lab's history first
  // The numbers without the images (a copy cleared afterwards would keep each image's buffer:
  // assigning an empty vector keeps the capacity).
  history_.push_back(Measurement{m.lab, m.settings, m.label, m.truth, m.values, {}, {}, {}, {}});
  last_ = std::move(m);
}

// The lab's own jobs compute a mesh result and its metrics: wait for them, then read.
void Measurer::waitForMeshTruth(Measurement m, const ReferenceSpec& spec) {
  host_.jobs().submitGlSteps(kJobKey, "measuring against " + spec.truth, [this, m](JobContext& job) mutable {
    if (host_.jobs().busyOtherThan(kJobKey)) {
      job.progress(0.0f, "waiting for the result");
      return GlStep::Wait;
    }
    finish(std::move(m), {});
    return GlStep::Done;
  });
}

// A traced truth, which has one view (the lab's trace is that view): on the GPU a pass per GL
// step between frames, or on the CPU in a job. "" or why the lab traced none.
std::string Measurer::traceTruth(Measurement m, const ReferenceSpec& spec, const TruthRequest& request,
                                 const std::string& label) {
  const gl::RenderTarget target = gl::RenderTarget::create(request.size);
  if (spec.tracedOnGl) {  // on the GPU: a pass per GL step, between frames
    GlTraceStep step = beginGlTrace(host_, request, target);
    if (!step) return std::string(host_.lab().id()) + ": the lab traced no reference";
    host_.jobs().submitGlSteps(kJobKey, label, [this, m, step, key = request.key](JobContext& job) mutable {
      std::optional<ImageF> truth = step(job);
      if (!truth) return GlStep::More;
      auto image = std::make_shared<const ImageF>(std::move(*truth));
      cacheTruth(key, image);
      finish(std::move(m), {image});
      return GlStep::Done;
    });
    return {};
  }
  TraceWork work = beginTrace(host_, request, target);  // on the CPU, in a job
  if (!work) return std::string(host_.lab().id()) + ": the lab traced no reference";
  host_.jobs().submit(kJobKey, label, std::move(work), [this, m, key = request.key](ImageF truth) mutable {
    auto image = std::make_shared<const ImageF>(std::move(truth));
    cacheTruth(key, image);
    finish(std::move(m), {image});
  });
  return {};
}

// A rasterised truth: one jittered frame per slice, view after view; the target lives with the job.
void Measurer::accumulateTruth(Measurement m, const ReferenceSpec& spec, const std::vector<TruthRequest>& requests,
                               std::vector<std::shared_ptr<const ImageF>> cached,
                               const std::vector<MeasuredView>& views, const std::string& label) {
  struct Accumulation {
    std::vector<JitterSample> samples;
    size_t view = 0, next = 0;
    int slice = 0;  // of the frame of samples[next] (ReferenceSpec::slices)
    std::optional<ImageAccumulator> sum;
    std::optional<gl::RenderTarget> target;
    std::vector<std::shared_ptr<const ImageF>> truths;
  };
  auto acc = std::make_shared<Accumulation>();
  acc->samples = jitterSamples(spec.jitterGrid, spec.pixelFilter);
  acc->truths = std::move(cached);
  host_.jobs().submitGlSteps(kJobKey, label, [this, m, requests, acc, views](JobContext& job) mutable {
    while (acc->view < requests.size() && acc->truths[acc->view]) ++acc->view;  // cached views
    if (acc->view == requests.size()) {
      acc->target.reset();
      finish(std::move(m), acc->truths);
      return GlStep::Done;
    }
    const TruthRequest& req = requests[acc->view];
    if (!acc->target) acc->target = gl::RenderTarget::create(req.size);
    if (!acc->sum) acc->sum.emplace(views[acc->view].displayEncoded);
    const size_t n = acc->samples.size();
    const int slices = std::max(req.spec.slices, 1);
    const size_t done = acc->view * n + acc->next + 1, total = requests.size() * n;
    drawTruthSlice(host_, req, *acc->target, acc->samples[acc->next].offset, acc->slice);
    job.progress((float(done - 1) + float(acc->slice + 1) / float(slices)) / float(total),
                 "truth frame " + std::to_string(done) + " of " + std::to_string(total));
    if (++acc->slice < slices) return GlStep::More;  // the rest of this frame in the next steps
    acc->slice = 0;
    const JitterSample s = acc->samples[acc->next++];
    ImageF frame{acc->target->size(), acc->target->readRgba()};
    if (n == 1) {
      acc->truths[acc->view] = std::make_shared<const ImageF>(std::move(frame));
    } else {
      acc->sum->add(frame, s.weight);
      if (acc->next == n) acc->truths[acc->view] = std::make_shared<const ImageF>(acc->sum->mean());
    }
    if (acc->truths[acc->view]) {
      cacheTruth(req.key, acc->truths[acc->view]);
      acc->next = 0;
      acc->sum.reset();
    }
    return GlStep::More;
  });
}

std::string Measurer::start(glm::ivec2 size, float time, Metrics costs) {
  followLab();
  Lab& lab = host_.lab();
  const ReferenceSpec spec = referenceOf(lab);
  if (spec.kind == TruthKind::None)
    return std::string(lab.id()) + ": this configuration has no ground truth to measure against" +
           (spec.description.empty() ? "" : " (" + spec.description + ")");
  Measurement m;
  m.lab = std::string(lab.id());
  m.settings = host_.currentSettings();
  m.label = labelOf(m.settings);
  m.truth = spec.truth;
  m.values = std::move(costs);
  JobRunner& jobs = host_.jobs();

  if (spec.kind == TruthKind::Mesh) {
    waitForMeshTruth(std::move(m), spec);
    return {};
  }
  // Every measured view of this configuration now (the GL thread), and the truth in each view:
  // from the cache, traced in a CPU job, or accumulated from jittered frames in GL slices.
  const std::vector<MeasuredView> views = lab.judge()->measuredViews();
  for (auto& view : views) m.images.push_back(host_.renderView(size, time, view.settings));
  m.image = m.images.front();
  std::vector<TruthRequest> requests;
  std::vector<std::shared_ptr<const ImageF>> cached;
  for (auto& view : views) {
    requests.push_back(describeTruth(host_, size, time, view.settings));
    cached.push_back(cachedTruth(requests.back().key));
  }
  if (std::all_of(cached.begin(), cached.end(), [](auto& c) { return bool(c); })) {
    jobs.cancel(kJobKey);  // an older measurement would land after this one
    finish(std::move(m), cached);
    return {};
  }
  const std::string label = "truth for " + m.label;
  if (spec.traced) return traceTruth(std::move(m), spec, requests.front(), label);
  accumulateTruth(std::move(m), spec, requests, std::move(cached), views, label);
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

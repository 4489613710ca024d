// Measuring a configuration against its ground truth, one way for everyone: the app's Measure
// button and auto-measure (in the background, with a progress bar), every row of a sweep, and
// tests. A measurement is the lab's error metrics next to the costs of the same settings.
//
//   Measurer m(host);
//   m.start(size, time, {{"gpu_ms", 12.5}});      // jobs under the key "measure"
//   ... host.renderFrame() per frame delivers it; m.history() grows by one
//
// Image truths are made by host/truth.h (accumulated truth frames as GL slices, or the lab's
// trace as a CPU job) and cached by what they depend on, so moving a slider the truth ignores
// (a bias, a kernel size) costs one frame, not a new truth. Mesh truths wait for the lab's jobs
// and read its meshMetrics().
#pragma once
#include <deque>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/host/lab_host.h"
#include "app/host/truth.h"

namespace shadelab {

struct Measurement {
  std::string lab;
  Settings settings;
  std::string label;                           // the parameters that differ from the lab's defaults, "defaults" if none
  std::string truth;                           // ReferenceSpec::truth: which truth it was judged against
  Metrics values;                              // the lab's metrics, then the costs (gpu_ms, cpu_ms, the lab's own)
  ImageF image, reference;                     // image truths: the first view and its truth (empty in history())
  std::vector<ImageF> images, references;      // every measured view, and the truth in it
  double value(const std::string& key) const;  // NaN when absent
};

class Measurer {
 public:
  explicit Measurer(LabHost& host) : host_(host) {}
  ~Measurer();  // cancels a measurement in progress
  Measurer(const Measurer&) = delete;
  Measurer& operator=(const Measurer&) = delete;

  // Measures the current settings in the background; a new start supersedes one in progress.
  // `costs`: the caller's timing of these settings' frames. Returns "" or why there is nothing
  // to measure (the configuration has no ground truth).
  std::string start(glm::ivec2 size, float time, Metrics costs);
  // start() and wait for it (CLI, sweep, tests). Empty when there is nothing to measure.
  std::optional<Measurement> measureNow(glm::ivec2 size, float time, Metrics costs,
                                        const std::function<void(const std::vector<JobStatus>&)>& onProgress = {});
  bool busy() const { return host_.jobs().busy(kJobKey); }
  // This lab's measurements this session, oldest first, without images.
  const std::vector<Measurement>& history();
  void clear() { history_.clear(); }
  // After a lab switch, lets the last lab's measurements, truths and images go. start() and
  // history() call it; a window calls it every frame, so that a lab without a truth (whose panel
  // never asks for the history) does not keep the last lab's images.
  void followLab();
  size_t cachedTruths() const { return truths_.size(); }  // truths kept for this lab's next measurements
  // Called on the GL thread for every finished measurement (the window prints a line).
  std::function<void(const Measurement&)> onMeasured;

  static constexpr const char* kJobKey = "measure";

 private:
  void finish(Measurement m, const std::vector<std::shared_ptr<const ImageF>>& truths);
  // start()'s three ways to a truth, each ending in finish().
  void waitForMeshTruth(Measurement m, const ReferenceSpec& spec);
  std::string traceTruth(Measurement m, const ReferenceSpec& spec, const TruthRequest& request,
                         const std::string& label);
  void accumulateTruth(Measurement m, const ReferenceSpec& spec, const std::vector<TruthRequest>& requests,
                       std::vector<std::shared_ptr<const ImageF>> cached, const std::vector<MeasuredView>& views,
                       const std::string& label);
  std::shared_ptr<const ImageF> cachedTruth(const std::string& key) const;
  void cacheTruth(const std::string& key, std::shared_ptr<const ImageF> image);
  std::string labelOf(const Settings& settings);

  LabHost& host_;
  int labEntry_ = -1;  // LabHost::labEntries() when the measurements began
  std::vector<Measurement> history_;
  std::optional<Measurement> last_;                                           // with images, for measureNow
  std::deque<std::pair<std::string, std::shared_ptr<const ImageF>>> truths_;  // newest first
  static constexpr size_t kCachedTruths = 8;
};

}  // namespace shadelab

// Long work off the UI thread: denoising a 35k-vertex mesh, a FLANN bake, a ray-traced reference.
//
//   jobs.submit("denoise", "Laplacian on bunny",
//       [input](JobContext& job) {            // a worker thread: no GL, no lab state
//         for (int i = 0; i < n; ++i)
//           if (!job.progress(float(i) / n, "iteration " + std::to_string(i + 1))) return Result{};
//         return result;
//       },
//       [this](Result r) { upload(r); });      // the GL thread, inside deliver()
//
// Keys make "latest settings win": a job submitted under a key that already has one cancels the
// older job, whose result is then never delivered, so dragging a slider queues nothing stale.
// Work functions take their inputs by value (or shared_ptr to const) and must not touch the lab:
// a lab may be torn down while its job still runs. Cancellation is cooperative: progress()
// returns false once the job is cancelled, and the work should return at once.
//
// Work that needs GL (rendering the frames of a reference) runs on the GL thread in slices:
// submitGlSteps() calls its step function from deliver() until it says Done, so it has the same
// progress bar, Cancel button and supersession as CPU work. A step that has nothing to do yet
// (it waits for another job's result) says Wait and is asked again at the next deliver().
//
// In the window, workers run at a lower scheduling priority (nice +10, inherited by threads they
// start; setLowPriority), so a busy job takes the cores the UI thread and the rasteriser leave
// idle, not theirs. Headless runs keep normal priority: there the job's time is the measurement.
#pragma once
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <type_traits>
#include <vector>

namespace shadelab {

class JobContext {
 public:
  // Progress in [0, 1] (never moves backwards) and what the job is doing now. Returns false when
  // the job has been cancelled or superseded: stop and return.
  bool progress(float fraction, std::string_view stage = {});
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  // A stage of a longer job: from now on progress(f) reports lo + f (hi - lo), so a smoothing that
  // counts its own iterations 0..1 fills its share of the bar.
  void stage(float lo, float hi) {
    std::lock_guard lock(mutex_);
    lo_ = lo;
    hi_ = hi;
  }

 private:
  friend class JobRunner;
  std::atomic<bool> cancelled_{false};
  mutable std::mutex mutex_;
  float progress_ = 0.0f, lo_ = 0.0f, hi_ = 1.0f;
  std::string stage_;
};

enum class GlStep { Done, More, Wait };

struct JobStatus {
  std::string key;
  std::string label;   // what the job is, for the UI: "smoothing bunny (implicit, lambda 5)"
  std::string stage;   // what it does now: "iteration 3/10"
  float progress = 0;  // [0, 1]
  double seconds = 0;  // since it was submitted
  bool cancelling = false;
};

class JobRunner {
 public:
  explicit JobRunner(int workers = 1);
  ~JobRunner();  // cancels everything and joins the workers
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  // Runs work(JobContext&) -> R on a worker; done(R) runs later on the thread that calls deliver().
  template <typename Work, typename Done>
  void submit(std::string key, std::string label, Work work, Done done) {
    using R = std::invoke_result_t<Work&, JobContext&>;
    enqueue(std::move(key), std::move(label),
            [work = std::move(work), done = std::move(done)](JobContext& ctx) mutable -> std::function<void()> {
              auto result = std::make_shared<R>(work(ctx));
              return [result, done]() mutable { done(std::move(*result)); };
            });
  }
  // GL work in slices: step(ctx) runs inside deliver() on the GL thread until it returns Done.
  void submitGlSteps(std::string key, std::string label, std::function<GlStep(JobContext&)> step);

  // On the GL thread, once per frame: runs GL steps (for about `budgetMs`) and hands finished
  // results to their done callbacks, in submission order. Returns how many jobs completed.
  int deliver(double budgetMs = 8.0) { return deliver(budgetMs, nullptr); }
  // Blocks until no job is left (CLI, tests), delivering as results come; calls onProgress about
  // every `pollMs` with the jobs still running. Call it on the GL thread.
  void waitAll(const std::function<void(const std::vector<JobStatus>&)>& onProgress = {}, int pollMs = 100);

  bool busy() const;
  bool busy(std::string_view key) const;
  bool busyOtherThan(std::string_view key) const;
  std::vector<JobStatus> status() const;
  void cancel(std::string_view key);
  void cancelAll();
  // Messages of jobs whose work threw (each once), e.g. "denoise: Eigen: matrix is not positive definite".
  std::vector<std::string> takeErrors();
  // Jobs started from now on run at nice +10 (true) or the process's own priority (false).
  void setLowPriority(bool low) { lowPriority_ = low; }

 private:
  struct Job;
  using Work = std::function<std::function<void()>(JobContext&)>;
  void enqueue(std::string key, std::string label, Work work);
  int deliver(double budgetMs, bool* glWorked);
  void add(std::shared_ptr<Job> job);
  void cancelLocked(Job& job);
  void workerLoop();

  mutable std::mutex mutex_;
  std::condition_variable wake_;            // workers: a job was queued, or stop
  std::condition_variable finished_;        // waitAll: a job finished
  std::deque<std::shared_ptr<Job>> queue_;  // CPU jobs not started
  std::vector<std::shared_ptr<Job>> jobs_;  // every job not yet delivered or dropped, in submission order
  std::vector<std::string> errors_;
  std::vector<std::thread> workers_;
  bool stopping_ = false;
  std::atomic<bool> lowPriority_{false};
};

}  // namespace shadelab

#include "app/util/job_runner.h"

#include <algorithm>
#include <chrono>
#include <exception>
#include <utility>

#include "app/util/thread_priority.h"

namespace shadelab {

using Clock = std::chrono::steady_clock;

struct JobRunner::Job {
  std::string key, label;
  std::shared_ptr<JobContext> ctx = std::make_shared<JobContext>();
  Work work;                                  // CPU work, or
  std::function<GlStep(JobContext&)> glStep;  // GL slices
  std::function<void()> finish;               // set when the work is done
  bool running = false, done = false;
  Clock::time_point submitted = Clock::now();
};

bool JobContext::progress(float fraction, std::string_view stage) {
  std::lock_guard lock(mutex_);
  if (fraction == fraction) progress_ = std::max(progress_, lo_ + (hi_ - lo_) * std::clamp(fraction, 0.0f, 1.0f));
  if (!stage.empty()) stage_ = stage;
  return !cancelled();
}

JobRunner::JobRunner(int workers) {
  for (int i = 0; i < std::max(workers, 1); ++i) workers_.emplace_back([this] { workerLoop(); });
}

JobRunner::~JobRunner() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
    for (auto& job : jobs_) job->ctx->cancelled_ = true;
  }
  wake_.notify_all();
  for (auto& t : workers_) t.join();
}

void JobRunner::enqueue(std::string key, std::string label, Work work) {
  auto job = std::make_shared<Job>();
  job->key = std::move(key);
  job->label = std::move(label);
  job->work = std::move(work);
  add(std::move(job));
}

void JobRunner::submitGlSteps(std::string key, std::string label, std::function<GlStep(JobContext&)> step) {
  auto job = std::make_shared<Job>();
  job->key = std::move(key);
  job->label = std::move(label);
  job->glStep = std::move(step);
  add(std::move(job));
}

void JobRunner::add(std::shared_ptr<Job> job) {
  {
    std::lock_guard lock(mutex_);
    for (auto& old : std::vector(jobs_))
      if (old->key == job->key) cancelLocked(*old);
    jobs_.push_back(job);
    if (job->work) queue_.push_back(job);
  }
  wake_.notify_one();
}

// A queued or finished job is dropped at once; a running one when its work returns.
void JobRunner::cancelLocked(Job& job) {
  job.ctx->cancelled_ = true;
  if (job.running) return;
  std::erase_if(queue_, [&](auto& j) { return j.get() == &job; });
  std::erase_if(jobs_, [&](auto& j) { return j.get() == &job; });
}

void JobRunner::cancel(std::string_view key) {
  std::lock_guard lock(mutex_);
  for (auto& job : std::vector(jobs_))
    if (job->key == key) cancelLocked(*job);
  finished_.notify_all();
}

void JobRunner::cancelAll() {
  std::lock_guard lock(mutex_);
  for (auto& job : std::vector(jobs_)) cancelLocked(*job);
  finished_.notify_all();
}

void JobRunner::workerLoop() {
  const ThreadPriority priority;
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (stopping_) return;
      job = queue_.front();
      queue_.pop_front();
      job->running = true;
    }
    priority.lower(lowPriority_);  // for this thread and every thread the job starts
    std::function<void()> finish;
    std::string error;
    try {
      finish = job->work(*job->ctx);
    } catch (const std::exception& e) {
      error = job->key + ": " + e.what();
    } catch (...) {
      error = job->key + ": the job failed";
    }
    {
      std::lock_guard lock(mutex_);
      job->running = false;
      if (job->ctx->cancelled() || !error.empty()) {
        if (!error.empty() && !job->ctx->cancelled()) errors_.push_back(error);
        std::erase_if(jobs_, [&](auto& j) { return j == job; });
      } else {
        job->finish = std::move(finish);
        job->done = true;
      }
    }
    finished_.notify_all();
  }
}

int JobRunner::deliver(double budgetMs, bool* glWorked) {
  const auto start = Clock::now();
  std::vector<std::shared_ptr<Job>> ready, stepping;
  {
    std::lock_guard lock(mutex_);
    for (auto& job : jobs_) {
      if (job->done)
        ready.push_back(job);
      else if (job->glStep)
        stepping.push_back(job);
    }
    std::erase_if(jobs_, [](auto& j) { return j->done; });
  }
  // Results first: a GL step may be waiting for them (a measurement for the lab's new result).
  for (auto& job : ready)
    if (job->finish && !job->ctx->cancelled()) job->finish();
  const size_t delivered = ready.size();
  ready.clear();
  // GL slices, outside the lock: a step may submit or cancel jobs.
  if (glWorked) *glWorked = false;
  for (auto& job : stepping) {
    GlStep step = GlStep::Wait;
    do {
      if (job->ctx->cancelled()) break;
      step = job->glStep(*job->ctx);
      if (glWorked && step != GlStep::Wait) *glWorked = true;
    } while (step == GlStep::More &&
             std::chrono::duration<double, std::milli>(Clock::now() - start).count() < budgetMs);
    if (step == GlStep::Done) {
      std::lock_guard lock(mutex_);
      const bool stillWanted = !job->ctx->cancelled();
      std::erase_if(jobs_, [&](auto& j) { return j == job; });
      if (stillWanted) ready.push_back(job);
    }
  }
  if (delivered + ready.size() > 0) finished_.notify_all();
  return int(delivered + ready.size());
}

void JobRunner::waitAll(const std::function<void(const std::vector<JobStatus>&)>& onProgress, int pollMs) {
  auto lastReport = Clock::now();
  for (;;) {
    bool glWorked = false;
    deliver(1e9, &glWorked);
    std::unique_lock lock(mutex_);
    if (jobs_.empty()) return;
    // Nothing to do on this thread until a worker finishes: sleep until one does.
    const bool anyDone = std::any_of(jobs_.begin(), jobs_.end(), [](auto& j) { return j->done; });
    if (!glWorked && !anyDone) finished_.wait_for(lock, std::chrono::milliseconds(pollMs));
    lock.unlock();
    if (onProgress && Clock::now() - lastReport >= std::chrono::milliseconds(pollMs)) {
      onProgress(status());
      lastReport = Clock::now();
    }
  }
}

bool JobRunner::busy() const {
  std::lock_guard lock(mutex_);
  return !jobs_.empty();
}

bool JobRunner::busy(std::string_view key) const {
  std::lock_guard lock(mutex_);
  return std::any_of(jobs_.begin(), jobs_.end(), [&](auto& j) { return j->key == key && !j->ctx->cancelled(); });
}

bool JobRunner::busyOtherThan(std::string_view key) const {
  std::lock_guard lock(mutex_);
  return std::any_of(jobs_.begin(), jobs_.end(), [&](auto& j) { return j->key != key; });
}

std::vector<JobStatus> JobRunner::status() const {
  std::lock_guard lock(mutex_);
  std::vector<JobStatus> out;
  const auto now = Clock::now();
  for (auto& job : jobs_) {
    JobStatus s;
    s.key = job->key;
    s.label = job->label;
    {
      std::lock_guard ctxLock(job->ctx->mutex_);
      s.stage = job->ctx->stage_;
      s.progress = job->ctx->progress_;
    }
    s.seconds = std::chrono::duration<double>(now - job->submitted).count();
    s.cancelling = job->ctx->cancelled();
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<std::string> JobRunner::takeErrors() {
  std::lock_guard lock(mutex_);
  return std::exchange(errors_, {});
}

}  // namespace shadelab

// The job runner: progress only moves forward, a cancelled job stops at its next progress step,
// a result is delivered once and on the thread that calls deliver(), and the latest job under a
// key supersedes the older one.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "app/util/job_runner.h"

using namespace shadelab;
using namespace std::chrono_literals;

namespace {

// Spins until `pred` holds or two seconds pass.
template <typename F>
bool eventually(F pred) {
  for (int i = 0; i < 2000; ++i) {
    if (pred()) return true;
    std::this_thread::sleep_for(1ms);
  }
  return pred();
}

}  // namespace

TEST(Jobs, ProgressNeverMovesBackwards) {
  JobRunner jobs;
  std::atomic<bool> release{false};
  jobs.submit(
      "k", "test",
      [&](JobContext& job) {
        for (float f : {0.1f, 0.5f, 0.3f, 0.2f, 0.7f}) {
          job.progress(f, "step");
          std::this_thread::sleep_for(2ms);
        }
        while (!release) std::this_thread::sleep_for(1ms);
        return 0;
      },
      [](int) {});
  float last = 0.0f;
  ASSERT_TRUE(eventually([&] {
    const auto s = jobs.status();
    if (s.empty()) return false;
    EXPECT_GE(s[0].progress, last);
    last = s[0].progress;
    return last >= 0.7f;
  }));
  EXPECT_EQ(jobs.status()[0].stage, "step");
  release = true;
  jobs.waitAll();
}

TEST(Jobs, CancelStopsWithinOneProgressStep) {
  JobRunner jobs;
  std::atomic<int> step{0}, stoppedAt{-1};
  std::atomic<bool> delivered{false};
  jobs.submit(
      "k", "long",
      [&](JobContext& job) {
        for (int i = 0; i < 100000; ++i) {
          step = i;
          if (!job.progress(float(i) / 100000)) {
            stoppedAt = i;
            return i;
          }
          std::this_thread::sleep_for(1ms);
        }
        return -1;
      },
      [&](int) { delivered = true; });
  ASSERT_TRUE(eventually([&] { return step >= 5; }));
  jobs.cancel("k");
  const int atCancel = step;  // read after cancel() returned: the worker may be one call past it
  ASSERT_TRUE(eventually([&] { return stoppedAt >= 0; }));
  EXPECT_LE(stoppedAt - atCancel, 1) << "the work went on past the next progress step";
  jobs.waitAll();
  EXPECT_FALSE(delivered) << "a cancelled job's result must not be delivered";
  EXPECT_FALSE(jobs.busy());
}

TEST(Jobs, ResultDeliveredOnceOnTheDeliveringThread) {
  JobRunner jobs;
  std::thread::id workerThread, deliveryThread;
  int deliveries = 0;
  jobs.submit(
      "k", "one",
      [&](JobContext&) {
        workerThread = std::this_thread::get_id();
        return 42;
      },
      [&](int v) {
        EXPECT_EQ(v, 42);
        deliveryThread = std::this_thread::get_id();
        ++deliveries;
      });
  ASSERT_TRUE(eventually([&] {
    jobs.deliver();
    return deliveries > 0;
  }));
  for (int i = 0; i < 10; ++i) jobs.deliver();
  EXPECT_EQ(deliveries, 1);
  EXPECT_EQ(deliveryThread, std::this_thread::get_id());
  EXPECT_NE(workerThread, std::this_thread::get_id());
}

TEST(Jobs, LatestJobUnderAKeySupersedesTheOlder) {
  JobRunner jobs;
  std::vector<int> delivered;
  std::atomic<bool> firstStarted{false};
  jobs.submit(
      "slider", "first",
      [&](JobContext& job) {
        firstStarted = true;
        while (job.progress(0.5f)) std::this_thread::sleep_for(1ms);
        return 1;
      },
      [&](int v) { delivered.push_back(v); });
  ASSERT_TRUE(eventually([&] { return bool(firstStarted); }));
  for (int v = 2; v <= 5; ++v)  // a dragged slider: four more settings in quick succession
    jobs.submit(
        "slider", "next", [v](JobContext&) { return v; }, [&](int r) { delivered.push_back(r); });
  jobs.submit(
      "other", "independent", [](JobContext&) { return 7; }, [&](int r) { delivered.push_back(r); });
  jobs.waitAll();
  EXPECT_EQ(delivered, (std::vector<int>{5, 7}));
}

TEST(Jobs, GlStepsRunOnTheWaitingThreadUntilDone) {
  JobRunner jobs;
  int steps = 0;
  std::thread::id stepThread;
  jobs.submitGlSteps("gl", "frames", [&](JobContext& job) {
    stepThread = std::this_thread::get_id();
    job.progress(float(++steps) / 10, "frame " + std::to_string(steps));
    return steps == 10 ? GlStep::Done : GlStep::More;
  });
  std::vector<float> seen;
  jobs.waitAll(
      [&](const std::vector<JobStatus>& s) {
        if (!s.empty()) seen.push_back(s[0].progress);
      },
      1);
  EXPECT_EQ(steps, 10);
  EXPECT_EQ(stepThread, std::this_thread::get_id());
  EXPECT_FALSE(jobs.busy());
}

TEST(Jobs, AThrowingJobReportsItsErrorOnceAndDeliversNothing) {
  JobRunner jobs;
  bool delivered = false;
  jobs.submit(
      "bake", "bad", [](JobContext&) -> int { throw std::runtime_error("no UVs"); }, [&](int) { delivered = true; });
  jobs.waitAll();
  EXPECT_FALSE(delivered);
  EXPECT_EQ(jobs.takeErrors(), std::vector<std::string>{"bake: no UVs"});
  EXPECT_TRUE(jobs.takeErrors().empty());
}

TEST(Jobs, DestructionCancelsRunningWork) {
  std::atomic<bool> sawCancel{false};
  {
    JobRunner jobs;
    std::atomic<bool> started{false};
    jobs.submit(
        "k", "forever",
        [&](JobContext& job) {
          started = true;
          while (job.progress(0.0f)) std::this_thread::sleep_for(1ms);
          sawCancel = true;
          return 0;
        },
        [](int) {});
    ASSERT_TRUE(eventually([&] { return bool(started); }));
  }
  EXPECT_TRUE(sawCancel);
}

TEST(Jobs, AGlStepCanWaitForAWorkerResult) {
  // A measurement waits for the lab's job: its step says Wait until the result was delivered.
  JobRunner jobs;
  bool resultIn = false, measuredAfterResult = false;
  jobs.submit(
      "denoise", "smooth",
      [](JobContext&) {
        std::this_thread::sleep_for(30ms);
        return 1;
      },
      [&](int) { resultIn = true; });
  jobs.submitGlSteps("measure", "measure", [&](JobContext&) {
    if (jobs.busyOtherThan("measure") && !resultIn) return GlStep::Wait;
    measuredAfterResult = resultIn;
    return GlStep::Done;
  });
  jobs.waitAll();
  EXPECT_TRUE(measuredAfterResult);
}

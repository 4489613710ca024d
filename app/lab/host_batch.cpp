#include "app/lab/host_batch.h"

#include <mutex>
#include <vector>

namespace shadelab {
namespace {

struct Batches {
  std::mutex lock;
  int open = 0;
  std::vector<std::function<void()>> releases;
};

Batches& batches() {
  static Batches b;
  return b;
}

}  // namespace

HostBatch::HostBatch() {
  Batches& b = batches();
  const std::lock_guard<std::mutex> held(b.lock);
  ++b.open;
}

HostBatch::~HostBatch() {
  Batches& b = batches();
  std::vector<std::function<void()>> releases;
  {
    const std::lock_guard<std::mutex> held(b.lock);
    if (--b.open > 0) return;
    releases = b.releases;
  }
  for (auto& r : releases) r();  // outside the lock: a release takes its own
}

bool HostBatch::open() {
  Batches& b = batches();
  const std::lock_guard<std::mutex> held(b.lock);
  return b.open > 0;
}

void HostBatch::onClose(std::function<void()> release) {
  Batches& b = batches();
  const std::lock_guard<std::mutex> held(b.lock);
  b.releases.push_back(std::move(release));
}

}  // namespace shadelab

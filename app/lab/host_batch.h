#pragma once

#include <functional>
#include <map>
#include <mutex>

namespace shadelab {

// A run of hosts, one after another, in one process: a grading child draws the solution, each
// listed mistake and each slip with a host of its own, all of one scene. While a batch is open a
// lab may keep the CPU work of one host (a subdivided mesh, its tangent frames) for the next to
// find; outside one nothing outlives its host, so a window that leaves a lab has the memory back.
class HostBatch {
 public:
  HostBatch();
  ~HostBatch();  // the last batch to close lets go of everything kept in it
  HostBatch(const HostBatch&) = delete;
  HostBatch& operator=(const HostBatch&) = delete;

  static bool open();
  // `release` runs each time the last open batch closes; register it once, before keeping anything.
  static void onClose(std::function<void()> release);
};

// Values a lab makes the same way for every host of a batch, kept by key while one is open and let
// go when the last closes; outside a batch every get() makes its value afresh. Declare one static
// per kind of value: `static BatchMemo<Key, Value> kept; return kept.get(key, [&] { return make(); });`
template <typename Key, typename Value>
class BatchMemo {
 public:
  BatchMemo() {
    HostBatch::onClose([this] {
      const std::lock_guard<std::mutex> held(lock_);
      kept_.clear();
    });
  }
  template <typename Make>
  Value get(const Key& key, const Make& make) {
    if (!HostBatch::open()) return make();
    const std::lock_guard<std::mutex> held(lock_);
    auto [it, added] = kept_.try_emplace(key);
    if (added) it->second = make();
    return it->second;
  }

 private:
  std::mutex lock_;
  std::map<Key, Value> kept_;
};

}  // namespace shadelab

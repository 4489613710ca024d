#pragma once

#include <functional>

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

}  // namespace shadelab

// What both watchers share (file_watcher_desktop.cpp: inotify; file_watcher_web.cpp: polled stamps).
#include "app/shader/file_watcher.h"

namespace shadelab {

std::vector<std::filesystem::path> FileWatcher::takeSettled(std::chrono::steady_clock::time_point now) {
  std::vector<std::filesystem::path> ready;
  for (auto it = pending_.begin(); it != pending_.end();) {
    if (now - it->second >= debounce_) {
      ready.push_back(it->first);
      it = pending_.erase(it);
    } else {
      ++it;
    }
  }
  return ready;
}

}  // namespace shadelab

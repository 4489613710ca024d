#include "app/shader/file_watcher.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <cerrno>

namespace fs = std::filesystem;

namespace shadelab {

FileWatcher::FileWatcher(std::chrono::milliseconds debounce)
    : fd_(inotify_init1(IN_NONBLOCK | IN_CLOEXEC)), debounce_(debounce) {}

FileWatcher::~FileWatcher() {
  if (fd_ >= 0) close(fd_);
}

bool FileWatcher::addWatch(const fs::path& dir) {
  for (auto& [wd, d] : dirs_)
    if (d == dir) return true;
  const int wd =
      inotify_add_watch(fd_, dir.c_str(), IN_CLOSE_WRITE | IN_MOVED_TO | IN_CREATE | IN_DELETE | IN_MOVED_FROM);
  if (wd < 0) return false;
  dirs_[wd] = dir;
  return true;
}

void FileWatcher::watch(const fs::path& file) {
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(file, ec);
  if (!files_.insert(abs).second || fd_ < 0) return;
  if (!addWatch(abs.parent_path())) missing_.insert(abs.parent_path());
}

std::vector<fs::path> FileWatcher::poll() {
  const auto now = std::chrono::steady_clock::now();
  // Folders that appeared since the last poll: watch them, and report what is already in them.
  for (auto it = missing_.begin(); it != missing_.end();) {
    std::error_code ec;
    if (fs::is_directory(*it, ec) && addWatch(*it)) {
      for (auto& f : files_)
        if (f.parent_path() == *it && fs::exists(f, ec)) pending_[f] = now;
      it = missing_.erase(it);
    } else {
      ++it;
    }
  }
  if (fd_ >= 0) {
    alignas(inotify_event) char buf[8192];
    for (;;) {
      const ssize_t n = read(fd_, buf, sizeof buf);
      if (n <= 0) break;  // EAGAIN: nothing more for now
      for (char* p = buf; p < buf + n;) {
        auto* ev = reinterpret_cast<inotify_event*>(p);
        p += sizeof(inotify_event) + ev->len;
        auto dir = dirs_.find(ev->wd);
        if (dir == dirs_.end() || ev->len == 0) continue;
        const fs::path file = dir->second / ev->name;
        if (files_.count(file)) pending_[file] = now;
      }
    }
  }
  return takeSettled(now);
}

}  // namespace shadelab

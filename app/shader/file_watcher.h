// Watches directories with inotify and reports which watched files changed.
//
// Directories, not files: editors that save by writing a temp file and renaming it replace the
// inode, and a watch on the old inode would go quiet. IN_CLOSE_WRITE catches in-place saves,
// IN_MOVED_TO catches rename saves, IN_DELETE and IN_MOVED_FROM a file taken away (a student's
// override deleted: the built-in file serves again). A folder that does not exist yet (the
// student makes shading/ after starting the app) is looked for at every poll, a stat each, and
// watched from the moment it appears; the watched files already in it count as changed.
// Events are debounced (an editor may write twice in a row); whether the content really changed
// is decided later, by hash, by whoever reloads. This class never touches GL.
// In the browser (file_watcher_web.cpp) there is no inotify: each poll compares the watched files'
// time stamps and sizes in the page's file system, where the editor and dropped files write.
#pragma once
#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace shadelab {

class FileWatcher {
 public:
  explicit FileWatcher(std::chrono::milliseconds debounce = std::chrono::milliseconds(30));
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Starts reporting changes to `file` (its directory gets a watch if it has none).
  void watch(const std::filesystem::path& file);
  // Non-blocking: the files whose last event is older than the debounce interval.
  std::vector<std::filesystem::path> poll();

 private:
  int fd_ = -1;
  std::chrono::milliseconds debounce_;
  bool addWatch(const std::filesystem::path& dir);
  // The pending files whose last change is older than the debounce interval, taken off the list.
  std::vector<std::filesystem::path> takeSettled(std::chrono::steady_clock::time_point now);
  std::map<int, std::filesystem::path> dirs_;  // inotify wd -> directory
  std::set<std::filesystem::path> missing_;    // directories of watched files, not there yet
  std::set<std::filesystem::path> files_;      // what we report on
  std::map<std::filesystem::path, std::chrono::steady_clock::time_point> pending_;
  std::map<std::filesystem::path, std::pair<std::filesystem::file_time_type, uintmax_t>> stamps_;  // polled (web)
};

}  // namespace shadelab

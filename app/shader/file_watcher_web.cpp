#include "app/shader/file_watcher.h"

namespace fs = std::filesystem;

namespace shadelab {

namespace {

// A file's time stamp and size; a file that is not there has the default stamp.
std::pair<fs::file_time_type, uintmax_t> stampOf(const fs::path& file) {
  std::error_code ec;
  const auto time = fs::last_write_time(file, ec);
  if (ec) return {};
  const auto size = fs::file_size(file, ec);
  return {time, ec ? 0 : size};
}

}  // namespace

FileWatcher::FileWatcher(std::chrono::milliseconds debounce) : debounce_(debounce) {}

FileWatcher::~FileWatcher() = default;

bool FileWatcher::addWatch(const fs::path&) { return true; }

void FileWatcher::watch(const fs::path& file) {
  std::error_code ec;
  const fs::path abs = fs::weakly_canonical(file, ec);
  if (files_.insert(abs).second) stamps_[abs] = stampOf(abs);
}

std::vector<fs::path> FileWatcher::poll() {
  const auto now = std::chrono::steady_clock::now();
  for (auto& file : files_) {
    const auto stamp = stampOf(file);
    if (stamp != stamps_[file]) {
      stamps_[file] = stamp;
      pending_[file] = now;
    }
  }
  return takeSettled(now);
}

}  // namespace shadelab

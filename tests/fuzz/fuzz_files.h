// Helpers for fuzz targets whose reader takes files: the input is written to a scratch folder
// that belongs to this process (in /dev/shm where there is one, so no disk is touched), and the
// reader is pointed at it, exactly as it is pointed at a user's file.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace shadelab::fuzz {

inline const std::filesystem::path& scratchDir() {
  static const std::filesystem::path dir = [] {
    const std::filesystem::path base =
        std::filesystem::exists("/dev/shm") ? "/dev/shm" : std::filesystem::temp_directory_path();
    auto d = base / ("shadelab_fuzz_" + std::to_string(::getpid()));
    // A folder of this name is an earlier process's with the same pid that ended without its
    // atexit (libFuzzer leaves through _Exit on a finding or a time limit): its files are stale.
    std::error_code ec;
    std::filesystem::remove_all(d, ec);
    std::filesystem::create_directories(d);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(scratchDir(), ec);
    });
    return d;
  }();
  return dir;
}

inline std::filesystem::path writeScratch(const std::string& name, std::string_view bytes) {
  const std::filesystem::path file = scratchDir() / name;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
  return file;
}

inline std::string_view asText(const uint8_t* data, size_t size) { return {reinterpret_cast<const char*>(data), size}; }

// "first<sep>second" -> the two halves (second is empty when there is no separator).
inline std::pair<std::string_view, std::string_view> splitAt(std::string_view text, std::string_view sep) {
  const size_t at = text.find(sep);
  if (at == std::string_view::npos) return {text, {}};
  return {text.substr(0, at), text.substr(at + sep.size())};
}

}  // namespace shadelab::fuzz
